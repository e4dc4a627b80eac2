// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>

using doctest::Approx;
using namespace prism;

namespace {

/// A floor albedo that records where it was hit: red = x / 100.
struct XRecorder {
    using scalar_type = double;
    [[nodiscard]] Rgb<double> albedo(const Vec3<double>& p) const noexcept { return {p.x / 100, 0, 0}; }
    void validate() const {}
};

/// A floor lit from straight above with E = pi: a point's radiance is its albedo.
auto recording_floor()
{
    return Scene{Lights{DirectionalLight<double>{.direction = {0, -1, 0}, .irradiance = Rgb<double>(std::numbers::pi)}},
                 Object{Plane<double>({0, 1, 0}, 0), Diffuse<double, XRecorder>{.albedo = {}, .kd = 1, .ka = 0}}};
}

} // namespace

TEST_CASE("Whitted through graded air: a ray in n^2 = a + b y lands where its exact parabola meets the floor")
{
    // n^2 = 1 - 0.02 y: the index falls with height, so a rising ray bends back down along
    // y(x) = y0 + tan(theta0) x + b x^2 / (4 K^2), K = n(y0) cos(theta0).
    const double a = 1, b = -0.02, y0 = 1, theta0 = 0.2;
    const GradedAir<LinearSquareIndex<double>> air{.field = {.a = a, .b = b},
                                                   .region = {{-100, -1, -100}, {100, 10, 100}},
                                                   .stepping = {.tolerance = 1e-9, .first_step = 0.01, .max_step = 5}};
    const auto scene = recording_floor();
    const Whitted integrator(scene, {}, air);
    const double k = std::sqrt(a + b * y0) * std::cos(theta0), c = b / (4 * k * k), t = std::tan(theta0);
    const double x_exact = (-t - std::sqrt(t * t - 4 * c * y0)) / (2 * c);
    CHECK(x_exact == Approx(42.58).epsilon(1e-3));
    const Rgb<double> seen = integrator.radiance(Ray<double>{{0, y0, 0}, {std::cos(theta0), std::sin(theta0), 0}});
    CHECK(100 * seen.x == Approx(x_exact).epsilon(1e-6));
    // Straight air: the rising ray never comes down.
    const Whitted straight(scene);
    CHECK(straight.radiance(Ray<double>{{0, y0, 0}, {std::cos(theta0), std::sin(theta0), 0}}) == scene.background);
    // Aimed down, it lands at y0 / tan(theta).
    CHECK(100 * straight.radiance(Ray<double>{{0, y0, 0}, {std::cos(theta0), -std::sin(theta0), 0}}).x == Approx(y0 / t).epsilon(1e-9));
}

TEST_CASE("Graded air of uniform index sees what straight air sees")
{
    const auto scene = recording_floor();
    const GradedAir<LinearIndex<double>> uniform{.field = {.n0 = 1, .slope = 0}, .region = {{-100, -1, -100}, {100, 10, 100}},
                                                 .stepping = {.tolerance = 1e-6, .first_step = 0.5, .max_step = 3}};
    const Whitted curved(scene, {}, uniform);
    const Whitted straight(scene);
    for (double angle : {0.05, 0.2, 0.7, 1.4}) {
        const Ray<double> ray{{-3, 2, 1}, {std::cos(angle), -std::sin(angle), 0.1}};
        CHECK(curved.radiance(ray).x == Approx(straight.radiance(ray).x).epsilon(1e-12));
    }
}

TEST_CASE("The inferior mirage in Whitted: over a road 30 K hot, a ray aimed 0.3 degrees down sees the sky")
{
    const Scene road{Lights{DirectionalLight<double>{.direction = {0, -1, 0.2}}},
                     Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0.2)}}}};
    const GradedAir<HeatedLayer<double>> hot{.field = {.drop = 3e-5, .thickness = 0.3},
                                             .region = {{-2000, -1, -2000}, {2000, 4, 2000}},
                                             .stepping = {.tolerance = 1e-6, .first_step = 0.1, .max_step = 20}};
    const Whitted mirage(road, {}, hot);
    const Whitted plain(road);
    const double down = 0.3 * std::numbers::pi / 180;
    const Ray<double> ray{{0, 1.5, 0}, {std::cos(down), -std::sin(down), 0}};
    CHECK(plain.radiance(ray) != road.background); // straight, it meets the road 286 m away
    CHECK(mirage.radiance(ray) == road.background); // curved, it turns 0.235 m above it and rises
    // Aimed more steeply than the mirage's critical angle (about sqrt(2 drop) = 0.44 deg), it lands.
    const double steep = 1.0 * std::numbers::pi / 180;
    CHECK(mirage.radiance(Ray<double>{{0, 1.5, 0}, {std::cos(steep), -std::sin(steep), 0}}) != road.background);
}

TEST_CASE("GradedAir refuses what it cannot trace")
{
    const auto scene = recording_floor();
    CHECK_THROWS_WITH_AS(Whitted(scene, {}, GradedAir<LinearIndex<double>>{.field = {.n0 = 1, .slope = 0.01}}), doctest::Contains("GradedAir region"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(Whitted(scene, {}, GradedAir<LinearIndex<double>>{.field = {.n0 = 1, .slope = 0.01}, .region = {{0, 0, 0}, {1, 1, 1}}, .max_steps = 0}),
                         doctest::Contains("max_steps"), std::invalid_argument);
}

TEST_CASE("Photons through graded air land along their exact parabolas")
{
    // A point light 1 above the floor in n^2 = 1 - 0.005 y. A photon launched at
    // u = tan(theta0) lands at the distance r where 0 = y0 + u r + b r^2 (1 + u^2) / (4 n0^2),
    // arriving with slope u + b r (1 + u^2) / (2 n0^2): for each landed photon, one of the
    // two launch angles that reach r must give the slope it arrived with.
    const double b = -0.005, y0 = 1, n0sq = 1 + b * y0;
    const Scene scene{Lights{PointLight<double>{.position = {0, y0, 0}, .intensity = Rgb<double>(1)}},
                      Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0)}}}};
    const GradedAir<LinearSquareIndex<double>> air{.field = {.a = 1, .b = b}, .region = {{-500, -1, -500}, {500, 150, 500}},
                                                   .stepping = {.tolerance = 1e-8, .first_step = 0.01, .max_step = 5}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 20000, .caustic_photons = 0, .shadow_photons = false}, air);
    int checked = 0;
    double worst = 0;
    for (const Photon& photon : maps.global.photons()) {
        const double r = std::hypot(double(photon.position.x), double(photon.position.z));
        if (r < 0.5 || r > 390) continue; // the farthest any photon reaches is 399
        const Vec3<double> d = -Vec3<double>(photon.toward_source());
        const double slope = d.y / std::hypot(d.x, d.z);
        const double qa = b * r * r / (4 * n0sq), qb = r, qc = y0 + qa;
        const double disc = qb * qb - 4 * qa * qc;
        REQUIRE(disc >= 0);
        double best = 1e300;
        for (const double u : {(-qb + std::sqrt(disc)) / (2 * qa), (-qb - std::sqrt(disc)) / (2 * qa)})
            best = std::min(best, std::abs(slope - (u + b * r * (1 + u * u) / (2 * n0sq))));
        worst = std::max(worst, best / (1 + std::abs(slope)));
        ++checked;
    }
    INFO(checked, " photons checked");
    CHECK(checked > 2000);
    CHECK(worst < 1e-3); // the stored direction's precision (16-bit octahedral) is about 3e-5
}

TEST_CASE("Shadow rays in graded air stay straight (documented): a wall on the straight line shades the point")
{
    const Scene scene{Lights{DirectionalLight<double>{.direction = {1, -1, 0}, .irradiance = Rgb<double>(3)}},
                      Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}}},
                      Object{Box<double>({-2, 0, -5}, {-1.9, 3, 5}), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}}}};
    const GradedAir<LinearSquareIndex<double>> air{.field = {.a = 1, .b = -0.02}, .region = {{-50, -1, -50}, {50, 10, 50}}};
    const Whitted curved(scene, {}, air);
    const Whitted straight(scene);
    const Ray<double> down{{0, 2, 0}, {0, -1, 0}}; // vertical: the stratified air does not bend it
    CHECK(curved.radiance(down) == straight.radiance(down));
    CHECK(straight.radiance(down).x == Approx(0.5 * scene.ambient.x).epsilon(1e-12)); // in the wall's shadow: ambient only
}

TEST_CASE("The lecture notes' layered air in Whitted approaches the exact landing point at first order in the layer height")
{
    // n^2 = 1 - 0.02 y; a ray from y = 3 heading 0.2 rad below the horizon follows the
    // parabola y0 + tan(theta0) x + b x^2 / (4 K^2) down to the floor. Layers between
    // y = -1 and 4 (the floor at y = 0 on a layer boundary for every count here).
    const double a = 1, b = -0.02, y0 = 3, theta0 = -0.2;
    const double k = std::sqrt(a + b * y0) * std::cos(theta0), c = b / (4 * k * k), t = std::tan(theta0);
    const double x_exact = (-t - std::sqrt(t * t - 4 * c * y0)) / (2 * c);
    const auto scene = recording_floor();
    const Ray<double> ray{{0, y0, 0}, {std::cos(theta0), std::sin(theta0), 0}};
    double previous = 1e300;
    for (int layers : {10, 100, 1000, 10000}) {
        const Whitted layered(scene, {}, LayeredAir<LinearSquareIndex<double>>{.field = {.a = a, .b = b}, .bottom = -1, .top = 4, .layers = layers});
        const double error = std::abs(100 * layered.radiance(ray).x - x_exact);
        INFO(layers, " layers: error ", error);
        CHECK(error < previous);
        CHECK(error < 20.0 / layers); // first order in h = 5 / layers
        CHECK(error > 0.01 / layers); // and no better: the layers are an approximation
        previous = error;
    }
}

namespace {

/// The length of the parabola y = c0 + c1 x + c2 x^2 from x0 to x1: with u = c1 + 2 c2 x,
/// the integral of sqrt(1 + u^2) dx is (u sqrt(1 + u^2) + asinh(u)) / (4 c2).
double parabola_length(double c1, double c2, double x0, double x1)
{
    const auto f = [&](double x) {
        const double u = c1 + 2 * c2 * x;
        return (u * std::sqrt(1 + u * u) + std::asinh(u)) / (4 * c2);
    };
    return f(x1) - f(x0);
}

} // namespace

TEST_CASE("a path through graded air shows its straight pieces in order: joined end to end, their lengths the parabola's length to the floor")
{
    // The parabola of the first test (n^2 = 1 - 0.02 y, from height 1 at 0.2 rad): its
    // pieces must follow on from each other, each `before` the sum of those before it,
    // the last ending at the landing point, and together as long as the parabola's arc
    // (closed form) to the stepper's tolerance.
    const double a = 1, b = -0.02, y0 = 1, theta0 = 0.2;
    const GradedAir<LinearSquareIndex<double>> air{.field = {.a = a, .b = b},
                                                   .region = {{-100, -1, -100}, {100, 10, 100}},
                                                   .stepping = {.tolerance = 1e-9, .first_step = 0.01, .max_step = 5}};
    const auto scene = recording_floor();
    const double k = std::sqrt(a + b * y0) * std::cos(theta0), c = b / (4 * k * k), t = std::tan(theta0);
    const double x_exact = (-t - std::sqrt(t * t - 4 * c * y0)) / (2 * c);
    const Ray<double> start{{0, y0, 0}, {std::cos(theta0), std::sin(theta0), 0}};
    Vec3<double> end = start.origin;
    double sum = 0;
    int pieces = 0, out_of_order = 0;
    Ray<double> segment{};
    double path = 0;
    const auto hit = first_hit_in_air(scene, air, start, segment, &path, [&](const Ray<double>& piece, double piece_length, double before) {
        if (length(piece.origin - end) > 1e-9 || std::abs(before - sum) > 1e-9 * (1 + sum) || std::abs(length(piece.direction) - 1) > 1e-12) ++out_of_order;
        end = piece.at(piece_length);
        sum += piece_length;
        ++pieces;
        return true;
    });
    REQUIRE(hit);
    CHECK(out_of_order == 0);
    CHECK(pieces > 10);
    CHECK(end.x == doctest::Approx(x_exact).epsilon(1e-6));
    CHECK(end.y == doctest::Approx(0).scale(1e-6));
    CHECK(sum == doctest::Approx(path).epsilon(1e-12));
    // Chords are shorter than their arcs by L^3 / (24 R^2): 10^-4 of the length with
    // chords up to 5 long on a curve of radius 96 (measured 42.9517 against 42.9558).
    const double arc = parabola_length(t, c, 0, x_exact);
    CHECK(sum == doctest::Approx(arc).epsilon(2e-4));
    CHECK(sum < arc);
    CHECK(sum > length(end - start.origin) * 1.008); // (the curve, not the straight line between its ends: 0.85 % longer)
    // Stopped on its third piece, the path meets nothing.
    int shown = 0;
    CHECK(!first_hit_in_air(scene, air, start, segment, nullptr, [&](const Ray<double>&, double, double) { return ++shown < 3; }));
    CHECK(shown == 3);
}
