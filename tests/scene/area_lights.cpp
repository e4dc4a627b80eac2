// SPDX-License-Identifier: MIT
// Area lights against closed forms: the irradiance under a disk, a rectangle and a sphere
// that emit, by every integrator that sees direct light, and the sampling of the scene's
// emitters against the density multiple importance sampling is told.
#include <prism/scene/area_lights.hpp>
#include <prism/prism.hpp>

#include "../chi2.hpp"
#include "../effort.hpp"
#include "../support.hpp"

#include <cmath>
#include <string>

using namespace prism;

namespace {

constexpr double floor_albedo = 0.5;

/// A floor of albedo 0.5 at y = 0 under the emitter `light`: the only other object.
template <class Shape>
auto lit_floor(Shape light, double radiance, bool two_sided = false)
{
    return Scene{Lights{}, Object{std::move(light), Emissive<double>{.radiance = Rgb<double>(radiance), .two_sided = two_sided}},
                 Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(floor_albedo)}}}};
}

/// The radiance every integrator that sees direct light gives the floor at (x, 0, z), seen
/// from straight above: the mean of n estimates each (Whitted and the photon mapper on
/// their jittered grids, the path tracer by each of its three strategies).
template <class SceneT>
void check_area_light_everywhere(const SceneT& scene, double x, double z, double expected, const std::string& what)
{
    const Ray<double> down{{x, 1e-3, z}, {0, -1, 0}};
    // (Under a sanitizer an eighth of the estimates, and 1.4 %: tests/effort.hpp.)
    const auto mean_of = [&](const auto& integrator, long n) { return test::mean_radiance(integrator, down, n, Random(17, 3)); };
    const double whitted = mean_of(Whitted(scene), 20000);
    CHECK_MESSAGE(whitted == doctest::Approx(expected).epsilon(test::resolved(0.005)), what, ": Whitted");
    for (const AreaLightStrategy strategy : {AreaLightStrategy::mis, AreaLightStrategy::light_samples, AreaLightStrategy::bounces}) {
        const double path = mean_of(PathTracer(scene, {.area_lights = strategy}), 400000);
        CHECK_MESSAGE(path == doctest::Approx(expected).epsilon(test::resolved(0.005)), what, ": path tracer, strategy ", int(strategy));
    }
    const PhotonMapper mapper(scene, {.tracing = {.global_photons = 20000, .caustic_photons = 0}});
    const double mapped = mean_of(mapper, 20000);
    CHECK_MESSAGE(mapped == doctest::Approx(expected).epsilon(test::resolved(0.005)), what, ": photon mapper");
    MESSAGE(what, ": expected ", expected, ", Whitted ", whitted, ", photon mapper ", mapped);
}

/// The irradiance at the origin from a rectangle of radiance L parallel to the floor at
/// height h, with a corner above the origin and sides a, b (the differential form factor
/// to a parallel rectangle, times pi L).
double parallel_corner_irradiance(double radiance, double a, double b, double h)
{
    const double x = a / h, y = b / h;
    return radiance / 2 *
           (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) + y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)));
}

} // namespace

TEST_CASE("a disk light: E = pi L r^2 / (r^2 + h^2) on its axis, in every integrator")
{
    const double L = 3, r = 0.4, h = 1.2;
    const auto scene = lit_floor(Disk<double>({0, h, 0}, {0, -1, 0}, r), L);
    check_area_light_everywhere(scene, 0, 0, floor_albedo / pi<double> * (pi<double> * L * r * r / (r * r + h * h)), "disk");
}

TEST_CASE("a rectangle light: the parallel form factor's closed form, on and off its axis, in every integrator")
{
    const double L = 2, h = 0.8;
    // The rectangle [-0.5, 0.7] x [-0.3, 0.4] at height h, facing down (x cross z = -y).
    const auto scene = lit_floor(Quad<double>({-0.5, h, -0.3}, {1.2, 0, 0}, {0, 0, 0.7}), L);
    // Below an inside point, four corner rectangles; beside it, differences of them.
    const double under = parallel_corner_irradiance(L, 0.5, 0.3, h) + parallel_corner_irradiance(L, 0.7, 0.3, h) + parallel_corner_irradiance(L, 0.5, 0.4, h) +
                         parallel_corner_irradiance(L, 0.7, 0.4, h);
    check_area_light_everywhere(scene, 0, 0, floor_albedo / pi<double> * under, "rectangle, under it");
    // At x = 1.2: the rectangle spans [-1.7, -0.5] in x from there.
    const double beside = parallel_corner_irradiance(L, 1.7, 0.3, h) - parallel_corner_irradiance(L, 0.5, 0.3, h) + parallel_corner_irradiance(L, 1.7, 0.4, h) -
                          parallel_corner_irradiance(L, 0.5, 0.4, h);
    check_area_light_everywhere(scene, 1.2, 0, floor_albedo / pi<double> * beside, "rectangle, beside it");
}

TEST_CASE("a sphere light: E = pi L sin^2 theta for a surface facing it, near and far, in every integrator")
{
    const double L = 1.5, R = 0.3;
    for (const double D : {0.45, 2.0}) {
        const auto scene = lit_floor(Sphere<double>({0, D, 0}, R), L);
        const double sin2 = R * R / (D * D);
        check_area_light_everywhere(scene, 0, 0, floor_albedo / pi<double> * pi<double> * L * sin2, "sphere at " + std::to_string(D));
    }
}

TEST_CASE("a mesh light: two triangles light the floor as the quad they make, and its photons carry pi L A")
{
    const double L = 2, h = 0.8;
    MeshBuffers<double> square;
    square.positions = {{-0.5, h, -0.3}, {0.7, h, -0.3}, {0.7, h, 0.4}, {-0.5, h, 0.4}};
    square.triangles = {{0, 1, 2}, {0, 2, 3}}; // wound to face down: (x) cross (x + z) = -y
    const auto scene = lit_floor(TriangleMesh<double>(square), L);
    const double under = parallel_corner_irradiance(L, 0.5, 0.3, h) + parallel_corner_irradiance(L, 0.7, 0.3, h) + parallel_corner_irradiance(L, 0.5, 0.4, h) +
                         parallel_corner_irradiance(L, 0.7, 0.4, h);
    check_area_light_everywhere(scene, 0, 0, floor_albedo / pi<double> * under, "two triangles");
    // Every photon leaves the light and lands on the floor: their power is the light's.
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 100000, .caustic_photons = 0, .shadow_photons = false, .seed = 4});
    double total = 0;
    for (const Photon& p : maps.global.photons()) total += p.power().x;
    CHECK(total == doctest::Approx(pi<double> * L * 1.2 * 0.7).epsilon(1.0 / 128));
}

TEST_CASE("an area light shines from its front, and from its back only when two-sided")
{
    const double L = 3, r = 0.4, h = 1.2;
    const double expected = floor_albedo * L * r * r / (r * r + h * h);
    const Ray<double> down{{0, 1e-3, 0}, {0, -1, 0}};
    Random rng(1, 1);
    // Facing up, away from the floor: one-sided it lights nothing below it.
    const auto away = lit_floor(Disk<double>({0, h, 0}, {0, 1, 0}, r), L);
    CHECK(Whitted(away).radiance(down, rng).x == 0);
    CHECK(PathTracer(away).radiance(down, rng).x == 0);
    const auto both = lit_floor(Disk<double>({0, h, 0}, {0, 1, 0}, r), L, true);
    double sum = 0;
    const PathTracer path(both);
    const long n = test::samples(200000); // (under a sanitizer an eighth, and 1.4 %: tests/effort.hpp)
    for (long i = 0; i < n; ++i) sum += path.radiance(down, rng).x;
    CHECK(sum / double(n) == doctest::Approx(expected).epsilon(test::resolved(0.005)));
    // Seen by the camera: its radiance from the front, nothing from behind.
    CHECK(Whitted(away).radiance({{0, 2, 0}, {0, -1, 0}}, rng).x == L);
    CHECK(Whitted(away).radiance({{0, 0.5, 0}, {0, 1, 0}}, rng).x == 0);
    CHECK(Whitted(both).radiance({{0, 0.5, 0}, {0, 1, 0}}, rng).x == L);
}

TEST_CASE("the scene's emitters are sampled as densely as AreaLights::pdf says: by power, then each by its own rule (chi-square)")
{
    // A sphere, a disk and a rectangle around the point, of different powers.
    const Scene scene{Lights{}, Object{Sphere<double>({1.5, 0.5, 0}, 0.5), Emissive<double>{.radiance = Rgb<double>(1)}},
                      Object{Disk<double>({0, 2, 0.5}, {0, -1, 0}, 0.6), Emissive<double>{.radiance = Rgb<double>(2, 3, 4)}},
                      Object{Quad<double>({-2, -0.5, -1}, {0, 1.5, 0}, {0, 0, 2}), Emissive<double>{.radiance = Rgb<double>(0.5)}}};
    const Vec3<double> p(0.1, 0.2, 0.05);
    const auto lights = scene.area_lights();
    const auto sample = [&](double u, double v) { return lights.sample(p, {u, v}).wi; };
    const auto pdf = [&](const Vec3<double>& w) {
        const auto hit = scene.closest_hit({p, w}, {0.0, infinity<double>});
        return hit ? lights.pdf(*hit, p) : 0.0;
    };
    const test::Chi2 c = test::chi2_directions(sample, pdf, {0, 1, 0}, 1000000, 60, 80, 10);
    MESSAGE("chi2 ", c.statistic, " with ", c.degrees, " degrees, p = ", c.p_value, "; missing mass ", c.missing / 1e6, ", stray ", c.stray);
    CHECK(c.p_value > 1e-3);
    CHECK(std::abs(c.missing) < 2e-3 * 1e6);
    CHECK(c.stray < 100);
    // Under the renders' Sobol points the density holds too (the light choice and the
    // point on it share one pair), and under Halton's (bases 2 and 3), which photons may
    // draw their lights' points from. The counts scatter far less than a multinomial's, so
    // the statistic falls far below its degrees of freedom; a density wrong by 5 % over
    // half the sphere would still add about 1200 to it.
    for (const SamplerKind points : {SamplerKind::sobol, SamplerKind::halton}) {
        const test::Chi2 low = test::chi2_directions(sample, pdf, {0, 1, 0}, 1000000, 60, 80, 10, -1, 7, points);
        MESSAGE("under ", std::string(sampler_name(points)), " points: chi2 ", low.statistic, " with ", low.degrees, " degrees, p = ", low.p_value);
        CHECK(low.p_value > 1e-3);
        CHECK(low.stray < 10);
    }
    // Each sample's density is what pdf() gives the point a ray toward it meets, to rounding.
    Random rng(9, 9);
    for (int i = 0; i < 20000; ++i) {
        const LightSample<double> s = lights.sample(p, {rng.uniform<double>(), rng.uniform<double>()});
        const auto hit = scene.closest_hit({p, s.wi}, {0.0, infinity<double>});
        REQUIRE(hit);
        CHECK(hit->crossing.t == doctest::Approx(s.distance).epsilon(1e-9));
        CHECK(lights.pdf(*hit, p) == doctest::Approx(s.pdf).epsilon(1e-9));
    }
}

TEST_CASE("an emitter that cannot be sampled is refused: unbounded, or of infinite power")
{
    const auto build = [](auto shape, double radiance) {
        return Scene{Lights{}, Object{shape, Emissive<double>{.radiance = Rgb<double>(radiance)}}};
    };
    CHECK_THROWS_WITH_AS(build(Quad<double>({0, 0, 0}, {1e70, 0, 0}, {0, 0, 1e70}), 1e300), doctest::Contains("overflows"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((Object{Sphere<double>({0, 0, 0}, 1), Emissive<double>{.radiance = Rgb<double>(-1)}}), doctest::Contains("Emissive radiance"),
                         std::invalid_argument);
}

TEST_CASE("photons aimed from an area light at a sphere carry the power the light sends into it (brute-force integral)")
{
    // A disk light facing down-right, and a target sphere below it.
    const Disk<double> disk({0, 2, 0}, {0.3, -1, 0}, 0.5);
    const double L = 3;
    const Scene scene{Lights{}, Object{disk, Emissive<double>{.radiance = Rgb<double>(L)}}};
    const auto lights = scene.area_lights();
    const BoundingSphere<double> target{{0.8, 0, 0.2}, 0.4};
    PhotonAim<double> aim{&target, nullptr};
    aim.power = lights.photon_power(aim);
    Random rng(8, 8);
    double carried = 0;
    const int n = 400000;
    for (int i = 0; i < n; ++i) carried += lights.emit_photon(aim, rng.uniform<double>(), rng.uniform<double>(), rng).weight.x;
    carried *= aim.power.x / n;
    // L cos over the disk's area and the directions into the sphere, by the midpoint rule
    // (polar points over the disk, a grid over the directions toward the sphere).
    double exact = 0;
    const int radial = 60, around = 60, dirs = 120;
    const auto [s, t] = orthonormal_frame(disk.normal());
    for (int a = 0; a < radial; ++a)
        for (int b = 0; b < around; ++b) {
            const double rho = 0.5 * (a + 0.5) / radial, phi = 2 * pi<double> * (b + 0.5) / around;
            const Vec3<double> x = disk.center() + rho * std::cos(phi) * s + rho * std::sin(phi) * t;
            const double dA = 0.5 / radial * rho * 2 * pi<double> / around;
            const Vec3<double> to = target.center - x;
            const double cos_max = std::sqrt(1 - target.radius * target.radius / length_squared(to));
            const Vec3<double> axis = normalize(to);
            const auto [u, v] = orthonormal_frame(axis);
            double into = 0;
            for (int i = 0; i < dirs; ++i)
                for (int j = 0; j < dirs; ++j) {
                    const double z = 1 - (i + 0.5) / dirs * (1 - cos_max), psi = 2 * pi<double> * (j + 0.5) / dirs, r = std::sqrt(1 - z * z);
                    const Vec3<double> w = r * std::cos(psi) * u + r * std::sin(psi) * v + z * axis;
                    into += std::max(0.0, dot(w, disk.normal())) * (1 - cos_max) / dirs * 2 * pi<double> / dirs;
                }
            exact += L * into * dA;
        }
    MESSAGE("power into the sphere: photons ", carried, ", integral ", exact);
    CHECK(carried == doctest::Approx(exact).epsilon(0.01));
}

// The mesh's leaf order repeats a leaf's last triangle to fill its block of four: the
// emitting surface first counted those repeats as triangles and left as many out.
TEST_CASE("an emitting mesh of 1280 triangles is drawn on by each triangle's area, once: its photons carry pi L A of its true area")
{
    const MeshBuffers<double> ball = icosphere<double>({0, 2, 0}, 0.5, 3);
    double area = 0;
    for (const TriangleIndices& f : ball.triangles)
        area += 0.5 * length(cross(ball.positions[f[1]] - ball.positions[f[0]], ball.positions[f[2]] - ball.positions[f[0]]));
    const TriangleMesh<double> mesh(ball);
    REQUIRE(mesh.triangle_count() == 1280);
    REQUIRE(mesh.bvh().primitives().size() > 1280); // padded
    const MeshSurface<double, 8> surface(mesh);
    CHECK(surface.area() == doctest::Approx(area).epsilon(1e-12));
    const double L = 2;
    const Scene scene{Lights{}, Object{mesh, Emissive<double>{.radiance = Rgb<double>(L)}},
                      Object{Sphere<double>({0, 0, 0}, 30), Diffuse<double>{.albedo = {.color = Rgb<double>(0)}}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 100000, .caustic_photons = 0, .shadow_photons = false, .seed = 5});
    double total = 0;
    for (const Photon& p : maps.global.photons()) total += p.power().x;
    CHECK(total == doctest::Approx(pi<double> * L * area).epsilon(1.0 / 128));
    // Points drawn on it lie on its triangles: as far from the centre as its vertices, or nearer (flat faces).
    Random rng(2, 2);
    for (int i = 0; i < 20000; ++i) {
        const SurfacePoint<double> p = surface.sample_area({rng.uniform<double>(), rng.uniform<double>()});
        CHECK(length(p.point - Vec3<double>(0, 2, 0)) <= 0.5 + 1e-12);
        CHECK(length(p.point - Vec3<double>(0, 2, 0)) >= 0.49);
    }
}

TEST_CASE("area lights' emission carries their power (one-sided and two-sided, by power), drawn with the densities emission_pdf gives back")
{
    using namespace prism;
    const auto scene = Scene{Lights{}, Object{Quad<double>({0, 2, 0}, {1, 0, 0}, {0, 0, 1}), Emissive<double>{.radiance = {3, 2, 1}}},
                             Object{Sphere<double>({3, 1, 0}, 0.5), Emissive<double>{.radiance = Rgb<double>(2), .two_sided = true}}};
    const AreaLights<std::remove_cvref_t<decltype(scene)>> lights = scene.area_lights();
    Random rng(8, 1);
    Rgb<double> sum(0.0);
    const int n = int(test::samples(400000));
    int mismatched = 0, back = 0;
    for (int i = 0; i < n; ++i) {
        const auto [a, b] = rng.uniform2<double>();
        const auto [c, d] = rng.uniform2<double>();
        const auto e = lights.emission(rng.uniform<double>(), {a, b}, {c, d});
        REQUIRE(e.emission.pdf_area > 0);
        sum += e.emission.radiance * (e.emission.cos / (e.emission.pdf_area * e.emission.pdf_direction));
        const EmissionPdf<double> pdf = lights.emission_pdf(e.at, e.emission.ray.direction);
        if (!(std::abs(pdf.area - e.emission.pdf_area) <= 1e-12 * pdf.area && std::abs(pdf.direction - e.emission.pdf_direction) <= 1e-9 * pdf.direction)) ++mismatched;
        back += dot(e.emission.ray.direction, e.at.crossing.normal) < 0;
    }
    CHECK(mismatched == 0);
    const Rgb<double> power = lights.photon_power({}); // pi L A, twice for the two-sided sphere
    for (int k = 0; k < 3; ++k) CHECK(sum[k] / n == doctest::Approx(power[k]).epsilon(test::resolved(0.01)));
    CHECK(back > 0); // the two-sided sphere emits inward too
    // sample_point is sample, with the point it drew; pdf() gives its density back.
    for (int i = 0; i < 200; ++i) {
        const Vec3<double> p{rng.uniform<double>() * 4 - 1, 0, rng.uniform<double>() * 2 - 1};
        const Vec2<double> u{rng.uniform<double>(), rng.uniform<double>()};
        const auto drawn = lights.sample_point(p, u);
        const LightSample<double> s = lights.sample(p, u);
        CHECK(drawn.sample.irradiance == s.irradiance);
        CHECK(drawn.sample.pdf == s.pdf);
        if (s.pdf > 0 && max_component(s.irradiance) > 0) CHECK(lights.pdf(drawn.at, p) == doctest::Approx(s.pdf).epsilon(1e-6));
    }
}
