// SPDX-License-Identifier: MIT
#include <prism/light/environment_light.hpp>
#include <prism/prism.hpp>

#include "../support.hpp"
#include "../effort.hpp"
#include "../emission_checks.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace prism;

namespace {

/// A floor of albedo a under a sky of radiance 1, seen straight down: E = pi, L = a, in
/// every integrator that sees direct light (the mean of n estimates).
template <class SceneT>
void check_sky_everywhere(const SceneT& scene, double expected, const std::string& what)
{
    const Ray<double> down{{0.1, 1, 0.2}, {0, -1, 0}};
    // (Under a sanitizer an eighth of the estimates, and 1.4 %: tests/effort.hpp.)
    const auto mean_of = [&](const auto& integrator, long n) { return test::mean_radiance(integrator, down, n, Random(23, 1)); };
    CHECK_MESSAGE(mean_of(Whitted(scene, {.area_light_grid = 8}), 20000) == doctest::Approx(expected).epsilon(test::resolved(0.005)), what, ": Whitted");
    for (const AreaLightStrategy strategy : {AreaLightStrategy::mis, AreaLightStrategy::light_samples, AreaLightStrategy::bounces})
        CHECK_MESSAGE(mean_of(PathTracer(scene, {.area_lights = strategy}), 400000) == doctest::Approx(expected).epsilon(test::resolved(0.005)), what,
                      ": path tracer, strategy ", int(strategy));
    const PhotonMapper mapper(scene, {.tracing = {.global_photons = 20000, .caustic_photons = 0}});
    CHECK_MESSAGE(mean_of(mapper, 20000) == doctest::Approx(expected).epsilon(test::resolved(0.005)), what, ": photon mapper");
}

} // namespace

TEST_CASE("a white floor under a sky of radiance 1 reads its albedo, in every integrator (the furnace's closed form)")
{
    for (const double albedo : {1.0, 0.5}) {
        const Scene scene{Lights{EnvironmentLight<double>{.radiance = Rgb<double>(1)}},
                          Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(albedo)}}}};
        check_sky_everywhere(scene, albedo, "albedo " + std::to_string(albedo));
    }
}

TEST_CASE("the sky is seen where rays leave the scene, beside the background, and it is sampled as densely as it says")
{
    const Scene scene{Lights{EnvironmentLight<double>{.radiance = Rgb<double>(0.5, 1, 2)}},
                      Object{Sphere<double>({0, 0, 0}, 1), Diffuse<double>{}}};
    Random rng(1, 1);
    const Ray<double> up{{0, 2, 0}, {0, 1, 0}};
    CHECK(Whitted(scene).radiance(up, rng) == Rgb<double>(0.5, 1, 2));
    CHECK(PathTracer(scene).radiance(up, rng) == Rgb<double>(0.5, 1, 2));
    const EnvironmentLight<double> sky{.radiance = Rgb<double>(1)};
    double mean_cos = 0;
    for (int i = 0; i < 100000; ++i) {
        const LightSample<double> s = sky.sample({0, 0, 0}, {rng.uniform<double>(), rng.uniform<double>()});
        CHECK(s.pdf == sky.pdf(s.wi));
        CHECK(s.distance == infinity<double>);
        mean_cos += s.wi.y;
    }
    CHECK(std::abs(mean_cos / 100000) < 0.01); // uniform over the sphere
}

TEST_CASE("the sky's photons light a floor with E = pi L, entering through the disk that covers the scene")
{
    // A bounded floor: photons need something bounded to aim at.
    const Scene scene{Lights{EnvironmentLight<double>{.radiance = Rgb<double>(2)}},
                      Object{Quad<double>({-5, 0, 5}, {10, 0, 0}, {0, 0, -10}), Diffuse<double>{.albedo = {.color = Rgb<double>(0)}}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = test::samples(1000000), .caustic_photons = 0, .shadow_photons = false, .seed = 6});
    const Rgb<float> e = maps.global.irradiance_within({0, 0, 0}, {0, 1, 0}, 2.0f);
    MESSAGE("irradiance from the photons: ", e.x, " (2 pi = ", 2 * pi<double>, ")");
    CHECK(e.x == doctest::Approx(2 * pi<double>).epsilon(test::resolved(0.02)));
    CHECK_THROWS_WITH_AS(EnvironmentLight<double>{.radiance = Rgb<double>(-1)}.validate(), doctest::Contains("EnvironmentLight radiance"),
                         std::invalid_argument);
}

TEST_CASE("a uniform sky's emission carries L 4 pi pi R^2 through the disks of the scene's sphere")
{
    using namespace prism;
    const EnvironmentLight<double> light{.radiance = {1, 2, 3}};
    const Rgb<double> power = test::emitted_power(light, BoundingSphere<double>{{0, 0, 0}, 2}, 1000);
    for (int k = 0; k < 3; ++k) CHECK(power[k] == doctest::Approx(light.radiance[k] * 4 * pi<double> * pi<double> * 4).epsilon(1e-9));
}
