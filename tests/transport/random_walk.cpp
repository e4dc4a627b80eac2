// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace prism;

namespace {

/// The inside of a unit sphere of diffuse albedo rho: a walk from its centre never leaves.
auto closed_room(double rho)
{
    return Scene{Lights{PointLight<double>{.position = {0, 0, 0}, .intensity = Rgb<double>(1)}},
                 Object{Sphere<double>({0, 0, 0}, 1), Diffuse<double>{.albedo = {.color = Rgb<double>(rho)}, .kd = 1, .ka = 0}}};
}

struct WalkCounts {
    double mean_vertices = 0;
    int fewest = std::numeric_limits<int>::max();
    double largest_power = 0;
};

/// `count` walks from the room's centre: the surfaces each meets, and the largest power
/// any carries at a surface.
template <Transport Mode, class SceneT>
WalkCounts walk_counts(const SceneT& scene, WalkLimits limits, int count)
{
    Random rng(3, 5);
    const SpectralBands<double> bands(1);
    WalkCounts out;
    for (int i = 0; i < count; ++i) {
        int vertices = 0;
        const Ray<double> ray{{0, 0, 0}, uniform_sphere<double>(rng)};
        random_walk<Mode>(scene, StraightAir{}, bands, ray, Rgb<double>(1), rng, limits, WalkHooks{.on_surface = [&]<class M>(const M&, const WalkVertex<double>& at) {
            ++vertices;
            out.largest_power = std::max(out.largest_power, max_component(at.power));
            return true;
        }});
        out.mean_vertices += vertices;
        out.fewest = std::min(out.fewest, vertices);
    }
    out.mean_vertices /= count;
    return out;
}

/// The surfaces a camera path meets on average in a closed room of albedo rho, roulette
/// from its (k + 1)-th: it scatters at its first k + 1 surfaces unharmed, then carries
/// t = rho^(k+1); path_roulette keeps it with p = sqrt(t) and divides its throughput by p,
/// and every surface after multiplies the throughput by rho: the mean is k + 1 plus the
/// sum over m of the chance of surviving m roulettes, the product of the p's.
double camera_vertices(double rho, int k)
{
    double expected = k + 1, alive = 1, t = std::pow(rho, k + 1);
    for (int m = 0; m < 100000 && alive > 1e-17; ++m) {
        const double p = std::min(1.0, std::sqrt(t));
        alive *= p;
        expected += alive;
        t = rho * t / p;
    }
    return expected;
}

} // namespace

TEST_CASE("a photon plays Russian roulette at every bounce, a camera path only after WalkLimits::roulette_depth surfaces")
{
    // In a closed room of albedo rho a photon survives each bounce with probability rho:
    // it meets 1 / (1 - rho) surfaces on average. A camera path scatters at its first k
    // surfaces unharmed, carrying rho^(k+1) after the k-th scattering (index k); roulette
    // then keeps it with the square root of its throughput (camera_vertices). (With the
    // throughput itself, k + 1 + rho^(k+1) / (1 - rho) surfaces; before that, a camera
    // path played the photon's roulette: 1 / (1 - rho) whatever its depth.)
    const double rho = 0.5;
    const auto scene = closed_room(rho);
    const int n = 200000;
    const double sd_geometric = std::sqrt(rho) / (1 - rho); // of a count of 1 + Geometric(1 - rho)
    const WalkCounts photon = walk_counts<Transport::importance>(scene, {.max_bounces = 1000, .roulette_depth = 3}, n);
    CHECK(std::abs(photon.mean_vertices - 1 / (1 - rho)) < 5 * sd_geometric / std::sqrt(n));
    CHECK(photon.fewest == 1);
    for (int k : {0, 1, 2, 5}) {
        CAPTURE(k);
        const WalkCounts camera = walk_counts<Transport::radiance>(scene, {.max_bounces = 1000, .roulette_depth = k}, n);
        const double expected = camera_vertices(rho, k);
        CHECK(std::abs(camera.mean_vertices - expected) < 5 * (sd_geometric + 1) / std::sqrt(n));
        CHECK(camera.fewest == k + 1);
        CHECK(camera.largest_power <= 1 + 1e-12); // throughput over its survival probability, never more than 1
    }
    // The depth limit still ends every walk: max_bounces + 1 surfaces at most.
    const WalkCounts capped = walk_counts<Transport::radiance>(scene, {.max_bounces = 3, .roulette_depth = 10}, 1000);
    CHECK(capped.mean_vertices == 4);
}

TEST_CASE("in a fog a walk scatters as in a closed room: a photon 1 / (1 - albedo) times with its power kept, a camera path as in the room of that albedo")
{
    // Unbounded grey fog of albedo a around the walk's start: every flight ends in the
    // fog (no surface is ever reached), so the medium's scatterings play the room's walls.
    // The scene's one object is far off and tiny, to give the scene an object.
    const double albedo = 0.6;
    const auto scene = Scene{Lights{PointLight<double>{.position = {0, 0, 0}, .intensity = Rgb<double>(1)}},
                             Object{Sphere<double>({0, 1e6, 0}, 1e-6), Diffuse<double>{}}};
    const FilledAir<Fog<double>> air{.medium = {.absorption = Rgb<double>(1 - albedo), .scattering = Rgb<double>(albedo), .phase = {.g = 0.7}}};
    const SpectralBands<double> bands(1);
    const auto count = [&]<Transport Mode>(WalkLimits limits, int n, double& largest) {
        Random rng(5, 9);
        double vertices = 0;
        for (int i = 0; i < n; ++i) {
            random_walk<Mode>(scene, air, bands, Ray<double>{{0, 0, 0}, uniform_sphere<double>(rng)}, Rgb<double>(1), rng, limits,
                              WalkHooks{.on_surface = [](const auto&, const auto&) { return true; },
                                        .on_medium = [&](const auto&, const WalkMediumVertex<double>& at) {
                                            ++vertices;
                                            largest = std::max(largest, max_component(at.power));
                                            return true;
                                        }});
        }
        return vertices / n;
    };
    const int n = 200000;
    const double sd = std::sqrt(albedo) / (1 - albedo);
    double photon_power = 0;
    // A photon's vertex power is what it carries times the albedo (the draw's weight).
    CHECK(std::abs(count.template operator()<Transport::importance>({.max_bounces = 1000}, n, photon_power) - 1 / (1 - albedo)) < 5 * sd / std::sqrt(n));
    CHECK(photon_power == doctest::Approx(albedo));
    for (const int k : {0, 2}) {
        CAPTURE(k);
        double largest = 0;
        const double expected = camera_vertices(albedo, k);
        CHECK(std::abs(count.template operator()<Transport::radiance>({.max_bounces = 1000, .roulette_depth = k}, n, largest) - expected) < 5 * (sd + 1) / std::sqrt(n));
        CHECK(largest <= 1 + 1e-12);
    }
}

TEST_CASE("in fog filling graded air a walk scatters along its curved path: it reaches the floor unscattered with exp(-sigma_t) of the parabola's length")
{
    // n^2 = 1 - 0.02 y bends a ray leaving height 1 at 0.2 rad back down to the floor along
    // the parabola y = 1 + tan(0.2) x + c x^2 (tests/transport/travel.cpp), 42.956 long
    // (closed form). A grey fog fills the air: the fraction of walks that reach the floor
    // before scattering is exp(-sigma_t 42.956) = 0.179, within 4 standard errors (0.0012),
    // and the length each reports is the arc's. (The straight ray would rise forever; a
    // flight drawn over the first piece alone would pass 0.96 of the time.)
    const double a = 1, b = -0.02, y0 = 1, theta0 = 0.2, sigma = 0.04;
    const auto scene = Scene{Lights{PointLight<double>{.position = {0, 50, 0}, .intensity = Rgb<double>(1)}}, Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{}}};
    const GradedAir<LinearSquareIndex<double>> graded{.field = {.a = a, .b = b}, .region = {{-100, -1, -100}, {100, 10, 100}},
                                                      .stepping = {.tolerance = 1e-9, .first_step = 0.01, .max_step = 1}};
    const FilledAir<Fog<double>, GradedAir<LinearSquareIndex<double>>> air{.medium = {.absorption = Rgb<double>(sigma / 2), .scattering = Rgb<double>(sigma / 2)},
                                                                           .base = graded};
    const double k = std::sqrt(a + b * y0) * std::cos(theta0), c = b / (4 * k * k), t = std::tan(theta0);
    const double x_exact = (-t - std::sqrt(t * t - 4 * c * y0)) / (2 * c);
    const auto arc_to = [&](double x) { const double u = t + 2 * c * x; return (u * std::sqrt(1 + u * u) + std::asinh(u)) / (4 * c); };
    const double arc = arc_to(x_exact) - arc_to(0);
    CHECK(arc == doctest::Approx(42.956).epsilon(1e-4));
    const SpectralBands<double> bands(1);
    Random rng(8, 1);
    const int n = 100000;
    int reached = 0, scattered = 0, far = 0;
    double path = 0;
    for (int i = 0; i < n; ++i) {
        random_walk<Transport::radiance>(scene, air, bands, Ray<double>{{0, y0, 0}, {std::cos(theta0), std::sin(theta0), 0}}, Rgb<double>(1), rng, {},
                                         WalkHooks{.on_surface = [&](const auto&, const WalkVertex<double>& at) {
                                             ++reached;
                                             if (std::abs(at.crossing().point.x - x_exact) > 1e-4) ++far;
                                             path = at.travelled;
                                             return false;
                                         },
                                         .on_medium = [&](const auto&, const WalkMediumVertex<double>&) {
                                             ++scattered;
                                             return false;
                                         }});
    }
    const double expected = std::exp(-sigma * arc), standard_error = std::sqrt(expected * (1 - expected) / n);
    CAPTURE(reached);
    CHECK(reached + scattered == n);
    CHECK(far == 0);
    CHECK(path == doctest::Approx(arc).epsilon(1e-5));
    CHECK(std::abs(double(reached) / n - expected) < 4 * standard_error);
}

TEST_CASE("WalkLimits::max_length: a walk reaches exactly that many vertices, at surfaces and in fog alike, each told its length and the last flagged")
{
    // A closed white room filled with fog that does not absorb, and no roulette: nothing
    // ends a walk but the limit, so every walk has max_length vertices, of both kinds.
    const auto scene = closed_room(1.0);
    const FilledAir<Fog<double>> air{.medium = {.scattering = Rgb<double>(1.5), .phase = {.g = 0.3}}};
    const SpectralBands<double> bands(1);
    Random rng(7, 1);
    for (const int limit : {1, 2, 5}) {
        CAPTURE(limit);
        int wrong_lengths = 0, wrong_last = 0, surfaces = 0, in_fog = 0;
        for (int i = 0; i < 2000; ++i) {
            int vertices = 0;
            const auto seen = [&](int length, bool last) {
                ++vertices;
                wrong_lengths += length != vertices;
                wrong_last += last != (vertices == limit);
            };
            random_walk<Transport::radiance>(scene, air, bands, Ray<double>{{0, 0, 0}, uniform_sphere<double>(rng)}, Rgb<double>(1), rng,
                                             {.roulette_depth = 1000, .max_length = limit},
                                             WalkHooks{.on_surface = [&](const auto&, const WalkVertex<double>& at) {
                                                           ++surfaces;
                                                           seen(at.length, at.last);
                                                           return true;
                                                       },
                                                       .on_medium = [&](const auto&, const WalkMediumVertex<double>& at) {
                                                           ++in_fog;
                                                           seen(at.length, at.last);
                                                           return true;
                                                       }});
            REQUIRE(vertices == limit);
        }
        CHECK(wrong_lengths == 0);
        CHECK(wrong_last == 0);
        CHECK(surfaces > 0);
        CHECK(in_fog > 0);
    }
}
