// SPDX-License-Identifier: MIT
#include <prism/integrator/irradiance_cache.hpp>
#include <prism/prism.hpp>

#include "../effort.hpp"
#include "../furnace.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace prism;

TEST_CASE("the stratified gather: E = pi L under a uniform sky, and the gradients of fields known in closed form")
{
    Random rng(1u, 1u);
    const Vec3<double> up{0, 0, 1};
    // A uniform sky of radiance 2: E = 2 pi, exactly (every cell carries its share),
    // and no gradient.
    const auto uniform = gather_hemisphere<true, double>(up, 16, 50, rng, [](const Vec3<double>&) { return std::pair{Rgb<double>(2.0), infinity<double>}; });
    CHECK(uniform.irradiance.x == doctest::Approx(2 * pi<double>).epsilon(1e-12));
    for (int a = 0; a < 3; ++a) {
        CHECK(length(uniform.rotational[std::size_t(a)]) < 1e-9);
        CHECK(length(uniform.translational[std::size_t(a)]) < 1e-9);
    }
    // A sky L = 1 + w.x: E(n) = pi + (2 pi / 3) n.x, so tilting the normal from z
    // toward x by d (n x n' = (0, d, 0)) raises E by (2 pi / 3) d: the rotational
    // gradient is (0, 2 pi / 3, 0).
    const auto sky = gather_hemisphere<true, double>(up, 32, 100, rng, [](const Vec3<double>& w) { return std::pair{Rgb<double>(1 + w.x), infinity<double>}; });
    CHECK(sky.irradiance.x == doctest::Approx(pi<double>).epsilon(1e-3));
    CHECK(sky.rotational[1].x == doctest::Approx(2 * pi<double> / 3).epsilon(0.005));
    CHECK(std::abs(sky.rotational[0].x) < 0.05);
    // A ceiling at height 1 whose radiance grows along x, L = 1 + 0.5 x: at the origin
    // E(x0) = pi (1 + 0.5 x0) (the odd part cancels), so the translational gradient is
    // (pi / 2, 0, 0).
    const auto ceiling = gather_hemisphere<true, double>(up, 32, 100, rng, [](const Vec3<double>& w) {
        const double t = 1 / w.z;
        return std::pair{Rgb<double>(1 + 0.5 * w.x * t), t};
    });
    CHECK(ceiling.irradiance.x == doctest::Approx(pi<double>).epsilon(0.01));
    CHECK(ceiling.translational[0].x == doctest::Approx(pi<double> / 2).epsilon(0.1));
    CHECK(std::abs(ceiling.translational[1].x) < 0.1);
    // The nearest hit above 10 degrees: the ceiling straight up, 1 away (to a cell).
    CHECK(ceiling.nearest == doctest::Approx(1.0).epsilon(0.01));
}

TEST_CASE("an irradiance record reaches R / kappa, fades to 0 at its edge, and carries its gradients")
{
    IrradianceCache<double> cache(1.0);
    HemisphereGather<double> g;
    g.irradiance = Rgb<double>(2.0);
    g.translational = {Rgb<double>(0.5), Rgb<double>(0.0), Rgb<double>(0.0)};
    cache.add({IrradianceRecord<double>{{0, 0, 0}, {0, 0, 1}, g, 1.0}});
    CHECK(cache.irradiance({0, 0, 0}, {0, 0, 1})->x == doctest::Approx(2.0));
    CHECK(cache.irradiance({0.5, 0, 0}, {0, 0, 1})->x == doctest::Approx(2.25)); // E + 0.5 dE/dx
    CHECK(!cache.irradiance({1.01, 0, 0}, {0, 0, 1}));                           // beyond R
    CHECK(!cache.irradiance({0, 0, 0}, normalize(Vec3<double>{0.2, 0, 1})));     // turned by 11 degrees
    CHECK(cache.irradiance({0.3, 0, 0.5}, {0, 0, 1}).has_value());               // above the record: it sees what p sees
    CHECK(!cache.irradiance({0.3, 0, -0.5}, {0, 0, 1}));                         // the record lies in front of p
    // A neighbour added 0.2 away with R = 0.1 clamps the first to 0.3: (0.35, 0, 0) is
    // then out of its reach.
    cache.add({IrradianceRecord<double>{{0.2, 0, 0}, {0, 0, 1}, HemisphereGather<double>{}, 0.1}});
    CHECK(cache.records()[0].radius == doctest::Approx(0.3));
    CHECK(cache.irradiance({-0.35, 0, 0}, {0, 0, 1}) == std::nullopt);
}

TEST_CASE("the final gather's furnace with and without the irradiance cache, and the cache is the same for any thread count")
{
    for (const bool four : {false, true}) {
        CAPTURE(four);
        const auto scene = test::furnace_scene(four);
        using Mapper = PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
        // (Under a sanitizer an eighth of the photons, and 1.4 %: tests/effort.hpp.)
        Mapper::Config config{.tracing = {.global_photons = test::samples(200000), .caustic_photons = 0, .max_bounces = 64, .seed = 2}, .gather_rays = 64};
        config.irradiance_cache.rays = 256;
        Mapper mapper(scene, config);
        const Camera<float> camera{.position = {0, 0, 0}, .look_at = {0, 0, 1}, .fov = 90};
        constexpr int size = 32;
        const RenderConfig render_config{.width = size, .height = size, .threads = 2, .progress = false};
        mapper.cache_irradiance(camera, render_config);
        CHECK(mapper.irradiance_cache().size() > 4);
        const Film image = render(camera, mapper, render_config);
        const CameraRays<float> rays = camera.rays(size, size);
        double ratio = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                ratio += image.at(x, y).x / test::furnace_radiance(Vec3<double>(rays.ray(float(x) + 0.5f, float(y) + 0.5f).direction), four, true);
        CHECK(ratio / (size * size) == doctest::Approx(1.0).epsilon(test::resolved(0.005)));
        if (four) continue;
        Mapper one(scene, config);
        one.cache_irradiance(camera, {.width = size, .height = size, .threads = 1, .progress = false});
        REQUIRE(one.irradiance_cache().size() == mapper.irradiance_cache().size());
        for (std::size_t i = 0; i < one.irradiance_cache().size(); ++i) {
            CHECK(one.irradiance_cache().records()[i].p == mapper.irradiance_cache().records()[i].p);
            CHECK(one.irradiance_cache().records()[i].gather.irradiance == mapper.irradiance_cache().records()[i].gather.irradiance);
        }
    }
}

TEST_CASE("the irradiance cache in the two-lobe furnace: every path, within 1 %")
{
    const auto scene = test::coated_furnace_scene();
    using Mapper = PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
    // (Under a sanitizer an eighth of the photons, and 2.8 %: tests/effort.hpp.)
    Mapper::Config config{.tracing = {.global_photons = test::samples(200000), .caustic_photons = test::samples(200000), .max_bounces = 64, .seed = 2},
                          .caustic = {.radius = 0.1f},
                          .gather_rays = 64,
                          .max_depth = 16};
    config.irradiance_cache.rays = 256;
    Mapper mapper(scene, config);
    const Camera<float> camera{.position = {0.01f, 0.02f, 0.03f}, .look_at = {0.3f, 0.2f, 1}, .fov = 90};
    const RenderConfig render_config{.width = 32, .height = 32, .threads = 2, .progress = false};
    mapper.cache_irradiance(camera, render_config);
    CHECK(mapper.irradiance_cache().size() > 4);
    const double mean = test::image_mean(render(camera, mapper, render_config));
    MESSAGE("mean ", mean, " (closed form ", test::CoatedFurnace::all, ")");
    CHECK(mean == doctest::Approx(test::CoatedFurnace::all).epsilon(test::resolved(0.01)));
}

TEST_CASE("regression: in fog filling the air the cache gives what the final gather gives (its records carry no translational gradient there)")
{
    // The consistency matrix's scene of a diffuse ball over a grey floor under a point
    // light, in fog filling the air, 8 x 8 pixels: the photon mapper's final gather with
    // the cache in front and without. Gather rays scatter a short way off in the fog, and
    // the records' translational gradients, which take those distances for distances to
    // surfaces, swung far past the light: the cached image read 0.204 where the gathered
    // one reads 0.113 (the matrix read 2 to 5 times the path tracer); without gradients,
    // 0.1131. Now a record in the air's fog carries none.
    using T = float;
    const Scene scene{Lights{PointLight<T>{.position = {0.6f, 1.6f, 0.9f}, .intensity = Rgb<T>(3)}},
                      Object{Quad<T>({-3, -0.85f, 3}, {6, 0, 0}, {0, 0, -6}), Diffuse<T>{.albedo = {.color = Rgb<T>(0.5f)}}},
                      Object{Sphere<T>({0, 0, 0}, 0.5f), Diffuse<T>{.albedo = {.color = {0.7f, 0.5f, 0.3f}}}}};
    const FilledAir<Fog<T>> air{.medium = {.absorption = Rgb<T>(0.1f), .scattering = {0.6f, 0.9f, 1.2f}, .phase = {.g = 0.3f}},
                                .region = {Vec3<T>(-2, -0.9f, -2), Vec3<T>(2, 2, 2)}};
    using Mapper = PhotonMapper<std::remove_cvref_t<decltype(scene)>, FilledAir<Fog<T>>>;
    Mapper::Config config{.tracing = {.global_photons = test::samples(100000), .caustic_photons = 0, .seed = 3}, .gather_rays = 16};
    config.irradiance_cache.rays = 512;
    const Camera<T> camera{.position = {0.3f, 0.5f, 3.2f}, .look_at = {0, -0.2f, 0}, .fov = 45};
    const RenderConfig render_config{.width = 8, .height = 8, .spp = 16, .threads = 2, .seed = 5, .progress = false};
    const auto mean = [](const Film& film) {
        double sum = 0;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) sum += film.at(x, y).z / 64.0;
        return sum;
    };
    const Mapper gathering(scene, config, air);
    const double gathered = mean(render(camera, gathering, render_config));
    Mapper caching(scene, config, air);
    caching.cache_irradiance(camera, render_config);
    const double cached = mean(render(camera, caching, render_config));
    MESSAGE("blue: gathered ", gathered, ", cached ", cached, " (", caching.irradiance_cache().size(), " records)");
    CHECK(caching.irradiance_cache().size() > 10);
    CHECK(cached == doctest::Approx(gathered).epsilon(test::resolved(0.05)).scale(0));
}
