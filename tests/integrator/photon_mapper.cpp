// SPDX-License-Identifier: MIT
#include <prism/integrator/photon_mapper.hpp>
#include <prism/prism.hpp>

#include "../airlight.hpp"
#include "../effort.hpp"
#include "../furnace.hpp"
#include "../glossy_scenes.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace prism;

TEST_CASE("the photon mapper's direct light is Whitted's: one radiometric convention")
{
    // A lit floor alone: every photon bouncing off it escapes, so the global map holds
    // only direct photons (left out of the indirect estimate) and there are no caustics.
    const Scene scene{Lights{PointLight<float>{.position = {0.5f, 3, -1}, .intensity = Rgb<float>(20)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = {0.7f, 0.5f, 0.3f}}, .kd = 0.9f, .ka = 0}}};
    const Whitted whitted(scene);
    const PhotonMapper mapper(scene, {.tracing = {.global_photons = 20000, .caustic_photons = 0}, .gather_rays = 0});
    Random rng(1u, 1u);
    for (float x : {-1.0f, 0.0f, 0.7f, 2.0f}) {
        const Ray<float> ray{{x, 1, 2}, normalize(Vec3<float>{0, -1, -1})};
        const Rgb<float> a = whitted.radiance(ray), b = mapper.radiance(ray, rng);
        for (int c = 0; c < 3; ++c) CHECK(b[c] == doctest::Approx(a[c]).epsilon(1e-5));
    }
}

TEST_CASE("indirect light: a white wall facing a lit red floor turns red")
{
    // A white wall 3 high at x = 0, its face toward +x; the light is high behind it at
    // (-2, 6, 0), so it never sees that face, but lights the red floor beyond x = 2
    // (past the wall's shadow). Whatever lights the face came off the floor: red.
    const Scene scene{
        Lights{PointLight<float>{.position = {-2, 6, 0}, .intensity = Rgb<float>(200)}},
        Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = {0.8f, 0.05f, 0.05f}}, .kd = 1, .ka = 0}},
        Object{Box<float>({-0.2f, 0, -5}, {0, 3, 5}), Diffuse<float>{.albedo = {.color = Rgb<float>(0.8f)}, .kd = 1, .ka = 0}}};
    const Ray<float> at_face{{3, 1, 0.3f}, normalize(Vec3<float>{-1, 0, -0.1f})};
    // Whitted, with direct light only, sees the face black.
    CHECK(Whitted(scene).radiance(at_face) == Rgb<float>(0.0f));
    const PhotonMapper mapper(scene, {.tracing = {.global_photons = 200000, .caustic_photons = 0}, .global = {.radius = 0.3f, .excluded = Photon::direct | Photon::caustic}, .gather_rays = 0});
    Random rng(2u, 2u);
    const Rgb<float> wall = mapper.radiance(at_face, rng);
    CHECK(wall.x > 0.005f);
    CHECK(wall.x > 5 * wall.y); // colour bleeding: the wall takes the floor's red
    // Final gathering sees the same light.
    const PhotonMapper gathering(scene, {.tracing = {.global_photons = 200000, .caustic_photons = 0}, .gather_rays = 256});
    const Rgb<float> gathered = gathering.radiance(at_face, rng);
    CHECK(gathered.x > 5 * gathered.y);
    CHECK(gathered.x == doctest::Approx(wall.x).epsilon(0.3)); // two estimates of one integral, within their noise
}

TEST_CASE("glass casts a full shadow for shadow rays: the light through it comes from the caustic map")
{
    // A glass ball of radius 1 at height 2.5 under a light at height 6: its paraxial focus
    // (0.5 R behind its far side) is at 1, so the floor below gets a bright spot.
    const auto scene_with = [](auto glass) {
        return Scene{Lights{PointLight<float>{.position = {0, 6, 0}, .intensity = Rgb<float>(30)}},
                     Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                     Object{Sphere<float>({0, 2.5f, 0}, 1), glass}};
    };
    const auto scene = scene_with(Dielectric<float>{.ior = 1.5f});
    const Ray<float> down{{0, 0.4f, 0.3f}, {0, -1, 0}}; // looks at the floor under the ball, past its shadow's centre
    // Whitted lets the shadow ray through the glass (kt, refraction ignored).
    CHECK(Whitted(scene).radiance(down).x > 0.1f);
    // The photon mapper without caustic photons sees a full shadow.
    Random rng(3u, 3u);
    const PhotonMapper dark(scene, {.tracing = {.global_photons = 0, .caustic_photons = 0}, .gather_rays = 0});
    CHECK(dark.radiance(down, rng) == Rgb<float>(0.0f));
    // With them, the focused light: brighter than the unshadowed floor (E = I / h^2 = 30 / 36).
    const PhotonMapper lit(scene, {.tracing = {.global_photons = 0, .caustic_photons = 200000}, .caustic = {.radius = 0.05f}, .gather_rays = 0});
    const float open_floor = 0.5f / pi<float> * 30.0f / 36.0f;
    CHECK(lit.radiance({{0, 0.4f, 0}, {0, -1, 0}}, rng).x > 2 * open_floor);
}

TEST_CASE("shadow rays saved where photons agree (Jensen and Christensen 1995): same light, fewer rays")
{
    // A slab over a floor: a sharp shadow. On a grid of floor points, the photons decide
    // most points, and where they decide they agree with the shadow ray.
    const Scene scene{Lights{PointLight<float>{.position = {0, 5, 0}, .intensity = Rgb<float>(25)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                      Object{Box<float>({-1, 2, -1}, {1, 2.2f, 1}), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}}};
    using Mapper = PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
    const Mapper::Config base{.tracing = {.global_photons = 200000, .caustic_photons = 0}, .gather_rays = 0};
    Mapper::Config saving = base;
    saving.visibility_k = 32;
    const Mapper plain(scene, base), fast(scene, saving);
    int decided = 0, wrong = 0, points = 0;
    for (float x = -4; x <= 4; x += 0.1f)
        for (float z = -4; z <= 4; z += 0.25f) {
            ++points;
            const auto said = fast.visibility_from_photons(Vec3<float>{x, 0, z}, Vec3<float>{0, 1, 0});
            if (!said) continue;
            ++decided;
            const Ray<float> shadow{{x, 1e-3f, z}, Vec3<float>{0, 5, 0} - Vec3<float>{x, 1e-3f, z}};
            wrong += *said != (scene.transmittance(shadow, 0.999f) == Rgb<float>(1));
        }
    INFO(decided << " of " << points << " decided, " << wrong << " wrongly");
    CHECK(decided > points * 8 / 10);
    CHECK(wrong <= points / 200);
    // A point well inside the shadow and one well outside render the same either way.
    Random rng(4u, 4u);
    for (const Vec3<float> at : {Vec3<float>{0.3f, 0, 0.2f}, Vec3<float>{3, 0, -2}}) {
        const Ray<float> ray{at + Vec3<float>{0, 1, 1}, Vec3<float>{0, -1, -1}};
        CHECK(fast.radiance(ray, rng).x == doctest::Approx(plain.radiance(ray, rng).x).epsilon(1e-5));
    }
    // Two lights: shadow photons cannot say which light they block.
    const Scene two{Lights{PointLight<float>{}, PointLight<float>{.position = {1, 1, 1}}},
                    Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{}}};
    using Two = PhotonMapper<std::remove_cvref_t<decltype(two)>>;
    CHECK_THROWS_AS(Two(two, {.visibility_k = 8}), std::invalid_argument);
}

TEST_CASE("the photon mapper refuses what Whitted refuses, and estimators out of range")
{
    // Regression: max_depth -1, min_weight NaN or -1, radius Inf, disk Inf, an out-of-range
    // Filter and visibility_k 100000 (silently clamped) were all accepted.
    const Scene scene{Lights{PointLight<float>{.position = {0, 3, 0}, .intensity = Rgb<float>(20)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{}}};
    using Mapper = PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
    using Config = Mapper::Config;
    const auto refused = [&](Config config, const char* name) {
        config.tracing.global_photons = config.tracing.caustic_photons = 100;
        CHECK_THROWS_WITH_AS(Mapper(scene, config), doctest::Contains(name), std::invalid_argument);
    };
    Config c{};
    c.max_depth = -1, refused(c, "max_depth"), c = {};
    c.min_weight = std::nanf(""), refused(c, "min_weight"), c = {};
    c.min_weight = -1, refused(c, "min_weight"), c = {};
    c.caustic.radius = infinity<float>, refused(c, "caustic radius"), c = {};
    // Found by fuzzing: a radius whose square underflows gave NaN estimates.
    c.caustic.radius = 1e-20f, refused(c, "caustic radius must be in [1.1e-19, 1.8e19]"), c = {};
    c.global.radius = 2e19f, refused(c, "global radius must be in [1.1e-19, 1.8e19]"), c = {};
    c.global.max_height_ratio = infinity<float>, refused(c, "global max_height_ratio"), c = {};
    c.caustic.filter = static_cast<Filter>(7), refused(c, "filter"), c = {};
    c.visibility_k = 100000, refused(c, "visibility_k"), c = {};
    c.tracing.max_bounces = -1, refused(c, "max_bounces"), c = {};
    c.tracing.max_medium_bounces = -1, refused(c, "max_medium_bounces"), c = {};
    // Regression: a negative radius squared passed the range check, and its estimates read 0.
    c.caustic.radius = -0.1f, refused(c, "caustic radius must be in [1.1e-19, 1.8e19]"), c = {};
    c.volume_radius = -0.05f, refused(c, "volume_radius must be in [1.1e-19, 1.8e19]"), c = {};
    c.indirect_volume_radius = -0.5f, refused(c, "indirect_volume_radius must be 0 or in [1.1e-19, 1.8e19]"), c = {};
    c.max_length = 0, refused(c, "max_length must be in [1, 16]"), c = {};
    c.max_length = 17, refused(c, "max_length must be in [1, 16] (a photon records up to 15 segments) or unlimited"), c = {};
    // The irradiance cache holds paths of every length.
    c.tracing.global_photons = c.tracing.caustic_photons = 100;
    c.max_length = 4;
    Mapper limited(scene, c);
    CHECK_THROWS_WITH_AS(limited.cache_irradiance({}, {.width = 8, .height = 8}), doctest::Contains("max_length must be unlimited, got 4"), std::invalid_argument);
}

TEST_CASE("the photon mapper's furnace: 1.0 within 0.5 %, read directly and by final gathering, with one light or four")
{
    // Before the photons kept their surface's normal, the estimate tested each photon's
    // arrival direction against the query's normal and dropped grazing photons on the
    // curved wall (direct read 0.997), the final gather's precomputed irradiance took
    // the arrival direction for the normal (0.987), and 8-bit mantissas rounded every
    // photon of the light's one power up by 0.25 %. (Under a sanitizer an eighth of the
    // photons and samples, and 1.4 %: tests/effort.hpp.)
    for (const bool four : {false, true}) {
        const auto scene = test::furnace_scene(four);
        using Mapper = PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
        for (const int gather : {0, 32}) {
            CAPTURE(four);
            CAPTURE(gather);
            const Mapper mapper(scene, {.tracing = {.global_photons = std::size_t(test::samples(200000)), .caustic_photons = 0, .max_bounces = 64, .seed = 2},
                                        .global = {.radius = 0.1f, .excluded = Photon::direct | Photon::caustic},
                                        .gather_rays = gather});
            const double mean = test::furnace_mean(four, [&](const Ray<float>& ray, Random& rng) { return mapper.radiance(ray, rng); },
                                                   int(test::samples(gather > 0 ? 2000 : 10000)), true, 3);
            MESSAGE("mean ", mean);
            CHECK(mean == doctest::Approx(1.0).epsilon(test::resolved(0.005)));
        }
    }
}

TEST_CASE("regression: the final gather sees no light through a wall (a ball inside a closed ball lit from outside)")
{
    // Found by the random-scene test: a gather ray meeting a surface no photon reaches
    // (here the top of a small ball inside a closed big one) read the precomputed
    // irradiance of the nearest sample facing its way, however far: the lit top of the
    // big ball, 0.3 above it through the wall: 3.6 % of the lit floor's brightness. A
    // sample now answers only within the disk its estimate came from: 0.5 % is left,
    // where a sparse sample's disk reaches through the wall.
    const Scene scene{Lights{PointLight<float>{.position = {0, 8, 0}, .intensity = Rgb<float>(200)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{}}, Object{Sphere<float>({0, 2, 0}, 1.5f), Diffuse<float>{}},
                      Object{Sphere<float>({0, 2.9f, 0}, 0.3f), Diffuse<float>{}}};
    const PhotonMapper mapper(scene, {.tracing = {.global_photons = 40000, .caustic_photons = 0, .seed = 1}, .gather_rays = 64});
    const auto mean = [&](const Camera<float>& camera) {
        const Film film = render(camera, mapper, {.width = 16, .height = 16, .spp = 1, .progress = false});
        double sum = 0;
        for (const auto& p : film.pixels()) sum += p.x;
        return sum / double(film.pixels().size());
    };
    // The inside of the big ball, which no light reaches, and the lit floor outside it.
    const double inside = mean({.position = {0.5f, 1.5f, 0}, .look_at = {0, 3, 0.01f}, .fov = 120});
    const double outside = mean({.position = {4, 2, 0}, .look_at = {4, 0, 0.01f}, .fov = 30});
    MESSAGE("inside " << inside << ", outside " << outside);
    CHECK(outside > 0.1);
    CHECK(inside < 0.01 * outside);
}

TEST_CASE("the photon mapper in the two-lobe furnace: every path, read directly and by final gathering, within 1 %")
{
    // The caustic map holds the light the coat mirrors back through the centre (L S+ D),
    // the global map the rest. Before, the caustic pass stopped at the first surface with
    // a diffuse lobe (so no photon ever took the coat into the caustic map, and the
    // direct read, which leaves caustic-flagged photons to that map, lost them), and a
    // gather ray added the base of the first two-lobe surface it met but not what its
    // coat mirrors. Sized: over photon seeds 10 to 15, 50 000 photons in each map and 2500
    // camera samples (500 with 32 gather rays each) read within 0.19 % (0.14 % gathered) of
    // their mean, the gathered mean 0.16 % low, so 1 % is more than 5 of those from where
    // they fall. (Under a sanitizer an eighth of both, and 2.8 %: tests/effort.hpp.)
    const auto scene = test::coated_furnace_scene();
    using Mapper = PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
    const auto photons = std::size_t(test::samples(50000));
    for (const int gather : {0, 32}) {
        CAPTURE(gather);
        const Mapper mapper(scene, {.tracing = {.global_photons = photons, .caustic_photons = photons, .max_bounces = 64, .seed = 2},
                                    .caustic = {.radius = 0.1f},
                                    .global = {.radius = 0.1f, .excluded = Photon::direct | Photon::caustic},
                                    .gather_rays = gather,
                                    .max_depth = 16});
        const test::SampleStats stats = test::coated_furnace_samples([&](const Ray<float>& ray, Random& rng) { return mapper.radiance(ray, rng); },
                                                                     int(test::samples(gather > 0 ? 500 : 2500)), 3);
        MESSAGE("mean ", stats.mean, " (closed form ", test::CoatedFurnace::all, ")");
        CHECK(stats.mean == doctest::Approx(test::CoatedFurnace::all).epsilon(test::resolved(0.01)));
    }
}

TEST_CASE("the photon mapper on glossy surfaces: the sky furnace by shadow rays, and a caustic through a mirror weighed by the floor's BSDF")
{
    // Under a uniform sky a convex glossy sphere reads its lobe's albedo, all of it direct
    // light (the final gather's rays escape to a sky that lights nothing after a bounce).
    const RoughConductor<float> metal{.fresnel = {.kr = Rgb<float>(0.9f)}, .roughness = 0.5f};
    const auto sky = test::glossy_furnace(metal);
    // (Under a sanitizer an eighth of the samples and photons, and the tolerances widened
    // by sqrt(8): tests/effort.hpp.)
    const PhotonMapper sky_mapper(sky, {.tracing = {.global_photons = 20000, .caustic_photons = 0}, .gather_rays = 8, .area_light_grid = 8});
    for (const double theta : {0.0, 60.0}) {
        Random rng(3, 3);
        double sum = 0;
        const long samples = test::samples(4000);
        for (long i = 0; i < samples; ++i) sum += sky_mapper.radiance(test::furnace_ray<float>(theta), rng).x;
        CAPTURE(theta);
        CHECK(sum / double(samples) == doctest::Approx(test::furnace_albedo(metal, theta)).epsilon(test::resolved(0.01)));
    }
    // The caustic map's estimate on a glossy floor weighs each photon by the BSDF
    // between its arrival and the camera: the mirror image's light, as Whitted finds it.
    const Phong<float> floor{.diffuse = {.color = {0.3f, 0.2f, 0.1f}}, .specular = Rgb<float>(0.5f), .exponent = 6};
    const auto with_mirror = test::floor_by_mirror(floor);
    const auto with_image = test::floor_by_image(floor);
    const PhotonMapper mapper(with_mirror,
                              {.tracing = {.global_photons = 0, .caustic_photons = test::samples(2000000)}, .caustic = {.radius = 0.03f}, .gather_rays = 0});
    const Whitted exact(with_image);
    double caustic = 0, expected = 0;
    for (const float x : {-0.8f, -0.4f, 0.0f, 0.4f})
        for (const float z : {-0.3f, 0.3f}) {
            const Vec3<float> eye{-0.2f, 2.5f, 0.2f};
            const Ray<float> ray{eye, normalize(Vec3<float>{x, 0, z} - eye)};
            Random rng(1, 1);
            caustic += mapper.radiance_parts(ray, rng).caustic.x;
            expected += exact.radiance(ray).x;
        }
    CHECK(caustic / expected == doctest::Approx(1).epsilon(test::resolved(0.03)));
}

TEST_CASE("light through a frosted slab: the photon mapper's one draw per sample agrees with the path tracer's two-sided light samples")
{
    // A point light behind a frosted glass slab, the camera in front: every bit of its light
    // is transmitted through both rough faces. The path tracer finds it by light samples
    // from inside the slab toward the far side, the photon mapper by drawing from the lobe
    // at the near face and light samples at the far one.
    const Scene scene{Lights{PointLight<float>{.position = {0.3f, 0.2f, -2}, .intensity = Rgb<float>(5)}},
                      Object{Box<float>({-1, -1, -0.1f}, {1, 1, 0.1f}), RoughDielectric<float>{.ior = 1.5f, .roughness = 0.4f}}};
    const Camera<float> camera{.position = {0, 0, 3}, .look_at = {0, 0, 0}, .fov = 30};
    // (Under a sanitizer an eighth of the samples, and 8.5 %: tests/effort.hpp.)
    const RenderConfig config{.width = 8, .height = 8, .spp = int(test::samples(1024)), .threads = 2, .seed = 2, .progress = false};
    const Film traced = render(camera, PathTracer(scene), config);
    const Film mapped = render(camera, PhotonMapper(scene, {.tracing = {.global_photons = 1000, .caustic_photons = 1000}, .gather_rays = 0}), config);
    double a = 0, b = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) a += traced.at(x, y).x, b += mapped.at(x, y).x;
    MESSAGE("through the slab: path tracer ", a / 64, ", photon mapper ", b / 64);
    CHECK(a > 0.01);
    CHECK(b / a == doctest::Approx(1).epsilon(test::resolved(0.03)));
}

TEST_CASE("regression: a caustic through a frosted ball; photons hold no place on the glass, and every method agrees with the path tracer")
{
    // A frosted ball just above a floor, a point light behind it: its caustic falls on the
    // floor in front. Photons used to be stored on the glass, where the floor's estimates
    // (reaching 0.1 up) read those inside the ball's bottom as light arriving at the
    // floor: here 15 % too bright read directly, 45 % under the bench's ball
    // (bench/surfaces.cpp). And the caustic map held nothing, since a bounce through
    // frosted glass did not count toward a caustic: the final gather read 85 % too dark.
    const Scene scene{Lights{PointLight<float>{.position = {0, 5, -2}, .intensity = Rgb<float>(20)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                      Object{Sphere<float>({0, 1.03f, 0}, 1), RoughDielectric<float>{.ior = 1.5f, .roughness = 0.3f}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 100000, .caustic_photons = 100000, .shadow_photons = false});
    CHECK(maps.caustic.size() > 10000);
    std::size_t on_glass = 0;
    for (const PhotonMap* map : {&maps.global, &maps.caustic})
        for (const Photon& p : map->photons()) on_glass += std::abs(p.position.y) > 1e-3f;
    CHECK(on_glass == 0);
    // The floor in front of the ball, with its caustic.
    const Camera<float> camera{.position = {0, 4, 4}, .look_at = {0, 0, 1.2f}, .fov = 14};
    const auto mean = [](const Film& film) {
        double sum = 0;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) sum += film.at(x, y).x;
        return sum / 64;
    };
    // (Under a sanitizer an eighth of the paths and photons, and the tolerance widened by
    // sqrt(8): tests/effort.hpp.)
    const double traced = mean(render(camera, PathTracer(scene), {.width = 8, .height = 8, .spp = int(test::samples(4096)), .threads = 2, .seed = 3, .progress = false}));
    const RenderConfig few{.width = 8, .height = 8, .spp = 16, .threads = 2, .seed = 3, .progress = false};
    const PhotonTracerConfig tracing{.global_photons = test::samples(200000), .caustic_photons = test::samples(200000)};
    const double direct = mean(render(camera, PhotonMapper(scene, {.tracing = tracing, .gather_rays = 0}), few));
    const double gathered = mean(render(camera, PhotonMapper(scene, {.tracing = tracing, .gather_rays = 32}), few));
    MESSAGE("in front of the frosted ball: path tracer ", traced, ", photon map read directly ", direct, ", final gather ", gathered);
    CHECK(direct / traced == doctest::Approx(1).epsilon(test::resolved(0.06)));
    CHECK(gathered / traced == doctest::Approx(1).epsilon(test::resolved(0.06)));
}

TEST_CASE("in fog the photon mapper agrees with the path tracer: the beam estimate along rays through the air, the volume estimate in the gather at the floor")
{
    // A small glowing ball over a grey floor in a box of coloured fog. Rays through the
    // fog above the floor see only the light the fog scatters toward them (the beam
    // radiance estimate of the volume photons); rays at the floor see its direct light and
    // the fog's in-scattered light through the final gather, whose rays read the volume
    // photons where they scatter. The path tracer is the reference (its spread over seeds
    // 0.3 %). Measured over photon seeds 0 to 2 (1 million photons, radius 0.1): the beam
    // within 1.5 % of the path tracer; the floor 2.5 to 3 % low, from the volume
    // estimate's sphere reaching below the floor where gather rays scatter near it (2 %
    // at radius 0.05). 4 % holds both, each channel relative (scale 0).
    using T = float;
    const Scene scene{Lights{}, Object{Sphere<T>({0, 2, 0}, 0.25f), Emissive<T>{.radiance = Rgb<T>(1.0f)}},
                      Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(0.5f)}, .kd = 1, .ka = 0}}};
    const FilledAir<Fog<T>> fog{.medium = {.absorption = Rgb<T>(0.05f, 0.1f, 0.02f), .scattering = Rgb<T>(0.3f, 0.2f, 0.4f), .phase = {.g = 0.3f}},
                                .region = {{-3, 0, -3}, {3, 4, 3}}};
    const PathTracer tracer(scene, {}, fog);
    PhotonMapper<std::remove_cvref_t<decltype(scene)>, FilledAir<Fog<T>>>::Config config;
    // (Under a sanitizer an eighth of the paths, and the 1 % of noise in the 4 % widened to
    // 2.8 %: tests/effort.hpp. The photons stay: at an eighth the beam read 6 % low.)
    config.tracing.global_photons = 1000000;
    config.tracing.caustic_photons = 0;
    config.volume_radius = 0.1f;
    config.gather_rays = 64;
    const PhotonMapper mapper(scene, config, fog);
    CHECK(mapper.maps().volume.size() > 500000);
    const auto compare = [&](auto&& ray, int rays, int camera_samples) {
        Rgb<double> pt(0), pm(0);
        Random rng(1, 2);
        const int paths = int(test::samples(20000));
        for (int k = 0; k < rays; ++k) {
            for (int i = 0; i < paths; ++i) pt += Rgb<double>(tracer.radiance(ray(k), rng));
            for (int i = 0; i < camera_samples; ++i) pm += Rgb<double>(mapper.radiance(ray(k), rng));
        }
        pt /= double(rays * paths);
        pm /= double(rays * camera_samples);
        for (int c = 0; c < 3; ++c) {
            CAPTURE(c);
            CHECK(pm[c] == doctest::Approx(pt[c]).epsilon(0.03 + test::resolved(0.01)).scale(0));
        }
    };
    // Through the air only, passing the light at 1.2 to 1.5: the beam (no surface behind).
    compare([](int k) { return Ray<T>{{-3.5f, 0.8f, -1.0f + 0.1f * T(k)}, normalize(Vec3<T>(1, 0.05f, 0))}; }, 21, 1);
    // At the floor, 1 to 2 from below the light, through the fog: direct, gathered and beam.
    compare([](int k) { return Ray<T>{{-2.5f, 1.0f, -0.5f + 0.1f * T(k)}, normalize(Vec3<T>(1, -0.8f, 0))}; }, 11, 8);
}

TEST_CASE("a volumetric caustic through a frosted ball in haze: the beam estimate of the caustic pass's volume photons agrees with the path tracer")
{
    // A point light over a frosted glass ball (roughness 0.3, so that a path tracer finds
    // the caustic: from the haze a path meets the ball, and from the ball's far face a
    // light sample refracts out to the light), in haze over a black floor. 30 rays cross
    // the focused light below the ball; the mean of their radiance by the photon mapper
    // (volume photons L {S | frosted}+ M by the beam estimate) against the path tracer's.
    // The path tracer read 0.0622 with 500 000 paths a ray (standard error 0.7 %). The
    // beam estimate's spread is the global pass's: over photon seeds 0 to 3 it read 0.0616
    // to 0.0658 with a million global photons, -1 % to +6 % (0.0587 to 0.0653 with half a
    // million, 0.0635 to 0.0664 with two; the caustic pass's count, half a million to two,
    // moved it by 0.1 %). 75 000 paths a ray give the path tracer a standard error of
    // 1.3 %: 10 % held is the 6 % and 3 standard errors (under a sanitizer, an eighth of
    // the paths and the 3 standard errors widened to match; the photons stay, whose beam
    // estimate read 19 % high at an eighth). Before the path tracer took the air's
    // transmittance on light samples leaving the glass, it read about 40 % more.
    using T = float;
    const Scene scene{Lights{PointLight<T>{.position = {0, 4.5f, 0}, .intensity = Rgb<T>(20)}},
                      Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(0)}, .kd = 1, .ka = 0}},
                      Object{Sphere<T>({0, 1.6f, 0}, 0.6f), RoughDielectric<T>{.ior = 1.5f, .roughness = 0.3f}}};
    using Air = FilledAir<Fog<T>>;
    const Air haze{.medium = {.absorption = Rgb<T>(0.01f), .scattering = Rgb<T>(0.12f), .phase = {.g = 0.3f}}, .region = {{-5, 0, -3}, {5, 6, 6}}};
    const PathTracer tracer(scene, {}, haze);
    PhotonMapper<std::remove_cvref_t<decltype(scene)>, Air>::Config config;
    config.tracing.global_photons = 1000000;
    config.tracing.caustic_photons = 500000;
    config.gather_rays = 0;
    config.volume_radius = 0.05f;
    const PhotonMapper mapper(scene, config, haze);
    double traced = 0, squares = 0, mapped = 0;
    const int rays = 30, paths = int(test::samples(75000));
    Random rng(3, 4);
    for (int k = 0; k < rays; ++k) {
        const Ray<T> ray{{-3, 0.1f + 0.03f * T(k), 1.7f + 0.02f * T(k)}, normalize(Vec3<T>(3, 0, -2))};
        for (int i = 0; i < paths; ++i) {
            const double v = tracer.radiance(ray, rng).x;
            traced += v;
            squares += v * v;
        }
        for (int i = 0; i < 16; ++i) mapped += mapper.radiance(ray, rng).x / 16;
    }
    const double n = double(rays) * paths;
    traced /= n;
    mapped /= rays;
    MESSAGE("across the neck: path tracer ", traced, " +- ", std::sqrt((squares / n - traced * traced) / n), ", beam estimate ", mapped);
    CHECK(mapped / traced == doctest::Approx(1).epsilon(0.06 + test::resolved(0.04)).scale(0));
}

/// The photon mapper's volume furnace: a box of fog from -1 to 1 under a uniform sky,
/// `photons` global photons (the tracer's default limits; under a sanitizer an eighth, and
/// the tests' tolerances widened by sqrt(8): tests/effort.hpp), a volume radius of 0.1; the mean
/// of 81 parallel camera rays along +x starting at x = -3, on a grid of 9 x 9 from
/// (y0, z0) with steps dy and dz, or of `jittered` rays about each point of the grid
/// (uniform within 0.05 of it in y and z).
template <class Air>
Rgb<double> photon_mapper_volume_furnace(const Air& air, float y0, float dy, float z0, float dz, std::uint64_t seed, float volume_radius = 0.1f,
                                         float indirect_volume_radius = 0.0f, int jittered = 0, long photons = 2000000)
{
    using T = float;
    // (The scene's one object is tiny and just above the box: photons are aimed at the scene and the fog together.)
    const auto sky = Scene{Lights{EnvironmentLight<T>{}}, Object{Sphere<T>({0, 1.2f, 0}, 1e-3f), Diffuse<T>{}}};
    typename PhotonMapper<std::remove_cvref_t<decltype(sky)>, Air>::Config config;
    config.tracing.global_photons = test::samples(photons);
    config.tracing.caustic_photons = 0;
    config.gather_rays = 0;
    config.volume_radius = volume_radius;
    config.indirect_volume_radius = indirect_volume_radius;
    const PhotonMapper mapper(sky, config, air);
    Rgb<double> sum(0);
    Random rng(5, seed);
    if (jittered == 0) {
        for (int k = 0; k < 81; ++k) sum += Rgb<double>(mapper.radiance(Ray<T>{{-3, y0 + dy * T(k % 9), z0 + dz * T(k / 9)}, {1, 0, 0}}, rng));
        return sum / 81.0;
    }
    Random jitter(9, seed);
    for (int k = 0; k < 81; ++k)
        for (int j = 0; j < jittered; ++j) {
            const T oy = T(0.1) * (jitter.uniform<T>() - T(0.5)), oz = T(0.1) * (jitter.uniform<T>() - T(0.5));
            sum += Rgb<double>(mapper.radiance(Ray<T>{{-3, y0 + oy + dy * T(k % 9), z0 + oz + dz * T(k / 9)}, {1, 0, 0}}, rng));
        }
    return sum / (81.0 * jittered);
}

TEST_CASE("the photon mapper's volume furnace: a box of fog that does not absorb, under a uniform sky, reads the sky's radiance")
{
    // Radiance 1 from every direction around a box of coloured fog that scatters but
    // absorbs nothing: a camera ray through it reads the sky through the fog's
    // transmittance plus the beam estimate of the light the fog scatters toward it, 1 in
    // all. 81 rays cross the box parallel, 0.15 apart. Photons must be followed through
    // hundreds of scatterings in the densest channel (optical depth 8 across). Regression:
    // when scatterings in media counted toward the 16 bounces at surfaces, the default
    // limits read 7 % low there (PhotonTracerConfig::max_medium_bounces now). Measured at
    // 2 million photons: 0.998, 0.993, 1.002 (the beam estimates' noise about 0.5 %), so
    // 1 % is held; at 8 million, 0.9985, 0.9985, 0.9989, within 0.5 %, but four times as
    // slow in every test stage.
    using Air = FilledAir<Fog<float>>;
    const Air air{.medium = {.scattering = {1.0f, 2.0f, 4.0f}, .phase = {.g = 0.6f}}, .region = {Vec3<float>(-1), Vec3<float>(1)}};
    const Rgb<double> mean = photon_mapper_volume_furnace(air, -0.6f, 0.15f, -0.6f, 0.15f, 6);
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        MESSAGE("channel ", c, ": ", mean[c]);
        CHECK(mean[c] == doctest::Approx(1).epsilon(test::resolved(0.01)).scale(0));
    }
}

TEST_CASE("regression: the photon mapper's volume furnace in a ball of smoke (the fog inside an index-1 ball) reads the sky's radiance, with caustic photons and without")
{
    // The box furnace's fog inside an index-1 Dielectric ball of radius 1, clear air
    // outside: 81 parallel camera rays through the ball read 1. Its boundary bends and
    // reflects nothing, yet photons took it for a specular bounce, so that every photon
    // in the ball was a volumetric caustic, the caustic pass's: without caustic photons
    // the ball read 0.64 to 0.89, with 200 000 of them 0.97 to 0.99. Now a photon passes
    // the boundary as if it were not there (may_match_index): the global pass lights the
    // fog, the caustic pass adds nothing, and the two read the same bits.
    // The beam estimate is biased low near the ball's curved surface, where part of each
    // disc about the camera ray lies outside the fog, most in the densest channel, whose
    // light scatters within 0.25 of the surface: at 4 million photons blue read 0.945 at
    // a volume radius of 0.1, 0.974 at 0.05, 0.984 at 0.025 (red and green within 1.2 %
    // at 0.05). At 0.05 and 1 million photons the photons' noise adds as much: over photon
    // seeds 0 to 3, blue read 0.984, 0.959, 0.981 with independent photons and 0.960,
    // 0.958, 0.991, 0.977 with Sobol photons, green 0.972 to 0.995 (a spread of about 1.3 %
    // in blue, 0.8 % in green). Held at the bias and three times that: 3.5 % in red and
    // green, 7 % in blue, far above the 0.64 to 0.89 of the bug.
    using T = float;
    const Fog<T> fog{.scattering = {1.0f, 2.0f, 4.0f}, .phase = {.g = 0.6f}};
    const auto ball = Scene{Lights{EnvironmentLight<T>{}}, Object{Sphere<T>({0, 0, 0}, 1), Dielectric<T, ExactFresnel, Fog<T>>{.ior = 1, .interior = fog}}};
    const auto furnace = [&](std::size_t caustic) {
        typename PhotonMapper<std::remove_cvref_t<decltype(ball)>>::Config config;
        config.tracing.global_photons = test::samples(1000000);
        config.tracing.caustic_photons = caustic;
        config.gather_rays = 0;
        config.volume_radius = 0.05f;
        const PhotonMapper mapper(ball, config);
        Rgb<double> mean(0);
        Random rng(5, 7);
        for (int k = 0; k < 81; ++k) mean += Rgb<double>(mapper.radiance(Ray<T>{{-3, -0.6f + 0.15f * T(k % 9), -0.6f + 0.15f * T(k / 9)}, {1, 0, 0}}, rng)) / 81.0;
        return mean;
    };
    const Rgb<double> without = furnace(0), with = furnace(test::samples(200000));
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        MESSAGE("channel ", c, ": ", without[c], " without caustic photons, ", with[c], " with");
        CHECK(without[c] == doctest::Approx(1).epsilon(test::resolved(c == 2 ? 0.07 : 0.035)).scale(0));
        CHECK(with[c] == without[c]);
    }
}

TEST_CASE("regression: a final gather from a surface inside a ball of smoke scatters in the smoke about it")
{
    // A white diffuse ball of radius 0.5 inside a ball of smoke of radius 0.8 (fog that
    // does not absorb, inside an index-1 Dielectric) under a sky of radiance 1: the light
    // the ball's surface receives off the smoke (its indirect part) read by the final gather
    // (16 rays) and read from the global map at the point (no gather) are the same light.
    // The gather's rays started in no object, so that they crossed the smoke about the
    // ball unscattered: 0.318 where the map reads 0.570 in blue (found by the consistency
    // matrix, tests/matrix.hpp). Now 0.538: the two estimates' biases (the kernels' radii
    // by the ball's surface and the smoke's) differ by 6 %; 10 % is held.
    using T = float;
    const Fog<T> fog{.scattering = {0.6f, 0.9f, 1.2f}, .phase = {.g = 0.3f}};
    const auto scene = Scene{Lights{EnvironmentLight<T>{}}, Object{Sphere<T>({0, 0, 0}, 0.5f), Diffuse<T>{.albedo = {.color = Rgb<T>(1)}}},
                             Object{Sphere<T>({0, 0, 0}, 0.8f), Dielectric<T, ExactFresnel, Fog<T>>{.ior = 1, .interior = fog}}};
    const auto indirect = [&](int gather_rays) {
        typename PhotonMapper<std::remove_cvref_t<decltype(scene)>>::Config config;
        config.tracing.global_photons = test::samples(400000);
        config.tracing.caustic_photons = 0;
        config.global.radius = 0.1f;
        config.volume_radius = 0.1f;
        config.gather_rays = gather_rays;
        const PhotonMapper mapper(scene, config);
        Random rng(3, 9);
        double sum = 0;
        for (int k = 0; k < 400; ++k) {
            const T y = -0.3f + 0.6f * T(k % 20) / 19, x = -0.3f + 0.6f * T(k / 20) / 19; // rays that meet the white ball
            sum += mapper.radiance_parts(Ray<T>{{x, y, 3}, {0, 0, -1}}, rng).indirect.z / 400;
        }
        return sum;
    };
    const double gathered = indirect(16), read = indirect(0);
    MESSAGE("the white ball's indirect light in blue: gathered ", gathered, ", read from the map ", read);
    CHECK(gathered == doctest::Approx(read).epsilon(test::resolved(0.1)).scale(0));
}

TEST_CASE("regression: a glossy lobe's mirror part makes caustics: a floor lit by a mostly-mirror mix reads in the photon mapper what the reference reads")
{
    // tests/glossy_scenes.hpp's floor by a mirror, the mirror a mix of a dark Lambert (a
    // tenth) and a mirror (nine tenths: a glossy lobe with a delta part): the floor the
    // camera sees is lit directly and by the light's image (L S D), which is the caustic
    // map's. The caustic pass aimed at mirrors and glass only and followed no glossy
    // lobe's mirror, and the global map flags such photons caustic, so the map read
    // directly left that light out: 0.395 where the reference reads 0.439 (10 % low).
    using T = float;
    using Shiny = RoughConductor<T>; // at roughness 0, a mirror: the mix's delta part
    const Mix<T, Diffuse<T>, Shiny> mostly_mirror{.first = {.albedo = {.color = Rgb<T>(0.2f)}}, .second = {.fresnel = {.kr = Rgb<T>(1)}, .roughness = Roughness<T>(0)}, .weight = 0.9f};
    const Scene scene{Lights{PointLight<T>{.position = test::mirror_light, .intensity = Rgb<T>(4)}},
                      Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(0.5f)}}}, Object{Quad<T>({1, 0, -3}, {0, 3, 0}, {0, 0, 6}), mostly_mirror}};
    typename PhotonMapper<std::remove_cvref_t<decltype(scene)>>::Config config;
    config.tracing.global_photons = test::samples(200000);
    config.tracing.caustic_photons = test::samples(200000);
    config.caustic.radius = 0.05f;
    config.gather_rays = 0;
    const RenderConfig render_config{.width = 8, .height = 8, .spp = int(test::samples(256)), .threads = 2, .seed = 4, .progress = false};
    const auto mean = [](const Film& film) {
        double sum = 0;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) sum += film.at(x, y).x / 64.0;
        return sum;
    };
    const double mapped = mean(render(test::floor_camera(), PhotonMapper(scene, config), render_config));
    const double reference = mean(render(test::floor_camera(), Reference(scene), render_config));
    MESSAGE("the floor: photon mapper ", mapped, ", reference ", reference);
    CHECK(mapped == doctest::Approx(reference).epsilon(test::resolved(0.03)).scale(0));
}

TEST_CASE("the photon mapper's beam estimate reads the global pass's volume photons at indirect_volume_radius, the volumetric caustics' at volume_radius")
{
    // The furnace's photons all come from the global pass (the sky lights the fog with no
    // glass between): read at indirect_volume_radius = 0.1 they give the furnace's 1 even
    // though volume_radius is 0.01 (were they read at 0.01, the few found would be scaled
    // by 100 times the area: a noisy, wrong image).
    using Air = FilledAir<Fog<float>>;
    const Air air{.medium = {.scattering = {1.0f, 2.0f, 4.0f}, .phase = {.g = 0.6f}}, .region = {Vec3<float>(-1), Vec3<float>(1)}};
    const Rgb<double> mean = photon_mapper_volume_furnace(air, -0.6f, 0.15f, -0.6f, 0.15f, 6, 0.01f, 0.1f);
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        MESSAGE("channel ", c, ": ", mean[c]);
        CHECK(mean[c] == doctest::Approx(1).epsilon(test::resolved(0.01)).scale(0));
    }
}

TEST_CASE("the photon mapper's volume furnace in fog filling graded air: curved photons and camera rays of many pieces read the sky's radiance, to 1.5 %")
{
    // The box of fog above, filling air of n^2 = 1 - 0.002 y cut into pieces of at most
    // 0.25 by the stepper: photons fly and camera rays gather beam estimates piece by
    // piece, each seen through the fog before it. (A weak gradient: in a strong one the
    // photons crowd where the index is high, as n^2, which prism's radiance does not model;
    // here n^2 is within 0.2 % of 1.) A million photons: over photon seeds 0 and 6 to 9
    // every channel read within 0.8 % of 1 (two million: up to 1.010, at twice the time),
    // so 1.5 % is held.
    using Graded = GradedAir<LinearSquareIndex<float>>;
    using Air = FilledAir<Fog<float>, Graded>;
    const Graded graded{.field = {.a = 1, .b = -0.002f}, .region = {Vec3<float>(-2), Vec3<float>(2)}, .stepping = {.tolerance = 1e-5f, .first_step = 0.05f, .max_step = 0.25f}};
    const Air air{.medium = {.scattering = {1.0f, 2.0f, 4.0f}, .phase = {.g = 0.6f}}, .region = {Vec3<float>(-1), Vec3<float>(1)}, .base = graded};
    const Rgb<double> mean = photon_mapper_volume_furnace(air, -0.6f, 0.15f, -0.6f, 0.15f, 6, 0.1f, 0.0f, 0, 1000000);
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        MESSAGE("channel ", c, ": ", mean[c]);
        CHECK(mean[c] == doctest::Approx(1).epsilon(test::resolved(0.015)).scale(0));
    }
}

TEST_CASE("the photon mapper's volume furnace in ground fog of varying density reads the sky's radiance, to 1 %")
{
    // As above, the box filled with ground fog (density 2.5 at the bottom, thinning by e
    // every 0.5 up): photons fly by spectral tracking, camera rays see through residual
    // ratio tracking. (Plain ratio tracking read 0.93 here in a grey fog of constant
    // density: right on average, but each camera ray's transmittance a coin toss.) Each
    // ray's transmittance is one estimate, so rays are many: 8 jittered about each of the
    // 81 points, whose disks stay inside the box, and a million photons. Over photon seeds
    // 0 to 3 every channel read within 0.7 % of 1 (with 16 rays a point and two million
    // photons, four times the time, within 0.65 %). On the 81 fixed rays alone it read
    // 1.011, 1.015, 1.018, the rows' means scattering from 0.988 to 1.050; with rays whose
    // disks crossed the box's floor, where no photons are, 0.989 to 0.995. 1 % is held.
    const HeightFog<float> ground{.box = {Vec3<float>(-1), Vec3<float>(1)}, .floor = -1, .base = 2.5f, .scale_height = 0.5f};
    const FilledAir<VaryingFog<HeightFog<float>>> air{.medium = VaryingFog(ground, Rgb<float>(0), Rgb<float>(0.5f, 1.0f, 2.0f), {.g = 0.6f})};
    const Rgb<double> mean = photon_mapper_volume_furnace(air, -0.8f, 0.2f, -0.6f, 0.15f, 1, 0.1f, 0.0f, 8, 1000000);
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        MESSAGE("channel ", c, ": ", mean[c]);
        CHECK(mean[c] == doctest::Approx(1).epsilon(test::resolved(0.01)).scale(0));
    }
}

TEST_CASE("the photon mapper's single scattering: a point light's airlight integral to 0.5 % with no photon, and a narrow spot beam as the path tracer reads it")
{
    // tests/airlight.hpp's point light in unbounded fog, no photons: single_scattering's
    // equiangular samples alone read the airlight integral.
    using T = float;
    const auto airlit = test::airlight_scene();
    PhotonMapper<std::remove_cvref_t<decltype(airlit)>, FilledAir<Fog<T>>>::Config config;
    config.tracing = {.global_photons = 0, .caustic_photons = 0};
    config.gather_rays = 0;
    config.single_scattering = true;
    const PhotonMapper mapper(airlit, config, test::airlight_fog());
    {
        Random rng(1, 2);
        Rgb<double> sum{0};
        const int n = int(test::samples(400000));
        for (int i = 0; i < n; ++i) sum += Rgb<double>(mapper.radiance(test::airlight_ray(), rng));
        for (int c = 0; c < 3; ++c) {
            CAPTURE(c);
            CHECK(sum[c] / n == doctest::Approx(test::airlight(c)).epsilon(test::resolved(0.005)).scale(0));
        }
    }
    // A spot light of 5 degrees in thin haze, a ray crossing its beam from the side over a
    // black floor: the samples kept to the cone against the path tracer's equiangular
    // samples over the whole ray (single scattering only: no diffuse bounce, no photon).
    // The path tracer's standard error at 400 000 samples is 0.67 % (its own test), the
    // photon mapper's far smaller: 2.5 % holds the difference at 3.5 standard errors.
    const auto spot = Scene{Lights{SpotLight<T>{.position = {0, 3, 0}, .direction = {0, -1, 0}, .intensity = Rgb<T>(50), .inner_angle = 4, .outer_angle = 5}},
                            Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(0.0f)}, .kd = 1, .ka = 0}}};
    const FilledAir<Fog<T>> haze{.medium = {.scattering = Rgb<T>(0.05f), .phase = {.g = 0.3f}}};
    PhotonMapper<std::remove_cvref_t<decltype(spot)>, FilledAir<Fog<T>>>::Config beam;
    beam.tracing = {.global_photons = 0, .caustic_photons = 0};
    beam.gather_rays = 0;
    beam.single_scattering = true;
    const PhotonMapper kept(spot, beam, haze);
    const PathTracer tracer(spot, {.max_diffuse_bounces = 0}, haze);
    const Ray<T> ray{{-3, 1.5f, 0.05f}, {1, 0, 0}};
    Random rng(3, 4);
    double by_mapper = 0, by_tracer = 0, squares = 0;
    const int n = int(test::samples(400000));
    for (int i = 0; i < n; ++i) {
        const double x = kept.radiance(ray, rng).x;
        by_mapper += x;
        squares += x * x;
        by_tracer += tracer.radiance(ray, rng).x;
    }
    by_mapper /= n;
    by_tracer /= n;
    const double error = std::sqrt((squares / n - by_mapper * by_mapper) / n) / by_mapper;
    MESSAGE("beam: photon mapper ", by_mapper, " (standard error ", 100 * error, " %), path tracer ", by_tracer);
    CHECK(by_mapper > 0);
    CHECK(by_mapper == doctest::Approx(by_tracer).epsilon(test::resolved(0.025)));
    CHECK(error < 0.002);
}

TEST_CASE("max_length: in the furnace the photon mappers read the light of paths of at most n segments, 1 - 0.5^(n - 1), directly, by final gathering and progressively")
{
    // The light at the centre gives the wall 0.5 by direct light (2 segments), and each
    // bounce half the last: paths of at most n segments read 1 - 0.5^(n - 1). A camera
    // vertex t segments from the camera joins photons of at most n - t segments (Photon's
    // segments), its shadow rays count where t + 1 <= n, and a gather walk's vertices are
    // held to n segments in all.
    const auto scene = test::furnace_scene(false);
    using Mapper = PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
    for (const int n : {1, 2, 3, 4, 6})
        for (const int gather : {0, 32}) {
            CAPTURE(n);
            CAPTURE(gather);
            const Mapper mapper(scene, {.tracing = {.global_photons = std::size_t(test::samples(100000)), .caustic_photons = 0, .max_bounces = 64, .seed = 2},
                                        .global = {.radius = 0.1f, .excluded = Photon::direct | Photon::caustic},
                                        .gather_rays = gather,
                                        .max_length = n});
            const double mean = test::furnace_mean(false, [&](const Ray<float>& ray, Random& rng) { return mapper.radiance(ray, rng); },
                                                   int(test::samples(gather > 0 ? 1000 : 4000)), true, 3);
            CHECK(mean == doctest::Approx(1 - std::pow(0.5, n - 1)).epsilon(test::resolved(0.01)).scale(0.1));
        }
    // Progressive photon mapping's passes, each a photon mapper held to n.
    using S = std::remove_cvref_t<decltype(scene)>;
    ProgressiveConfig<S> progressive;
    progressive.pass.tracing = {.global_photons = std::size_t(test::samples(20000)), .caustic_photons = 0, .max_bounces = 64, .seed = 2};
    progressive.pass.global.radius = 0.2f;
    progressive.pass.max_length = 3;
    const Camera<float> camera{.position = {0.01f, 0.02f, 0.03f}, .look_at = {0.01f, 0.02f, -1}, .fov = 60};
    const Film film = render(camera, ProgressivePhotonMapper<S>(scene, progressive), {.width = 16, .height = 16, .spp = 8, .progress = false});
    double sum = 0;
    for (const Rgb<float>& p : film.pixels()) sum += double(p.x);
    CHECK(sum / 256 == doctest::Approx(0.75).epsilon(test::resolved(0.01)));
}

TEST_CASE("max_length: a glass ball's caustic on the floor (L S S D E, 4 segments) is the caustic map's at max_length 4 and none of it at 3")
{
    const auto scene = Scene{Lights{PointLight<float>{.position = {0, 6, 0}, .intensity = Rgb<float>(30)}},
                             Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                             Object{Sphere<float>({0, 2.5f, 0}, 1), Dielectric<float>{.ior = 1.5f}}};
    using Mapper = PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
    const auto caustic_at = [&](int n) {
        const Mapper mapper(scene, {.tracing = {.global_photons = 0, .caustic_photons = 100000, .seed = 1}, .caustic = {.radius = 0.05f}, .gather_rays = 0, .max_length = n});
        for (const Photon& p : mapper.maps().caustic.photons()) {
            CAPTURE(p.segments());
            REQUIRE((p.segments() >= 2 && p.segments() <= n - 1)); // (2: reflected off the ball)
        }
        Random rng(3u, 3u);
        return mapper.radiance_parts({{0, 0.4f, 0}, {0, -1, 0}}, rng).caustic.x;
    };
    const Mapper unlimited(scene, {.tracing = {.global_photons = 0, .caustic_photons = 100000, .seed = 1}, .caustic = {.radius = 0.05f}, .gather_rays = 0});
    Random rng(3u, 3u);
    const float all = unlimited.radiance_parts({{0, 0.4f, 0}, {0, -1, 0}}, rng).caustic.x;
    CHECK(all > 0.1f);
    CHECK(caustic_at(3) == 0.0f);
    // Light through the ball that reflects inside it first has 5 segments and more: a
    // few per cent of the caustic.
    CHECK(caustic_at(4) == doctest::Approx(all).epsilon(0.1));
    CHECK(caustic_at(4) < all);
}
