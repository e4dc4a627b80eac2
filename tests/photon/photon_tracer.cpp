// SPDX-License-Identifier: MIT
#include <prism/photon/photon_tracer.hpp>
#include <prism/prism.hpp>

#include "../effort.hpp"
#include "../furnace.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

using namespace prism;

namespace {

/// A point light of intensity I at height h over a black floor: only direct photons.
auto light_over_floor(float intensity, float height)
{
    return Scene{Lights{PointLight<float>{.position = {0, height, 0}, .intensity = Rgb<float>(intensity)}},
                 Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0)}, .kd = 1, .ka = 0}}};
}

} // namespace

TEST_CASE("calibrated: the photon estimate of a point light's irradiance, E = I h / (h^2 + x^2)^(3/2), at 10^4 and 10^6 photons")
{
    const double intensity = 10, height = 1;
    const auto scene = light_over_floor(float(intensity), float(height));
    const Vec3<float> up{0, 1, 0};
    const auto exact = [&](double x, double z) { return intensity * height / std::pow(height * height + x * x + z * z, 1.5); };
    double previous_mean = 0, previous_se = 0;
    // 10^4 photons in 16 runs (seeds) with r = 0.35; 10^6 in one run with r = 0.1.
    struct Run {
        std::size_t photons;
        double radius;
        int seeds;
    };
    for (const Run run : {Run{10000, 0.35, 16}, Run{1000000, 0.1, 1}}) {
        // Radius estimates at 12 points 0.75 apart (disjoint disks), against E averaged
        // over the same disk by quadrature (so the disk's blur is no bias). Each is a sum
        // of about `count` photons, with relative standard deviation 1/sqrt(count); the
        // mean of estimate / exact has a standard error of about 1/sqrt(sum of counts).
        double ratio_sum = 0, count_sum = 0;
        int estimates = 0;
        for (int seed = 0; seed < run.seeds; ++seed) {
            const PhotonMaps maps =
                trace_photons(scene, {.global_photons = run.photons, .caustic_photons = 0, .shadow_photons = false, .seed = std::uint64_t(seed)});
            // Half the photons go down and land: N/2 stored, each with Phi / N = 4 pi I / N.
            CHECK(std::abs(double(maps.global.size()) - double(run.photons) / 2.0) < 4 * std::sqrt(double(run.photons) / 4.0));
            for (int i = 0; i < 12; ++i) {
                const double x = 0.75 * (i % 4) - 1.125, z = 0.75 * (i / 4) - 0.75;
                double disk = 0;
                constexpr int rings = 40, spokes = 64;
                for (int a = 0; a < rings; ++a)
                    for (int b = 0; b < spokes; ++b) {
                        const double rho = run.radius * std::sqrt((a + 0.5) / rings), phi = 2 * pi<double> * (b + 0.5) / spokes;
                        disk += exact(x + rho * std::cos(phi), z + rho * std::sin(phi)) / (rings * spokes);
                    }
                ratio_sum += maps.global.irradiance_within({float(x), 0, float(z)}, up, float(run.radius)).x / disk;
                count_sum += disk * pi<double> * run.radius * run.radius / (4 * pi<double> * intensity / double(run.photons));
                ++estimates;
            }
        }
        const double mean = ratio_sum / estimates, se = 1 / std::sqrt(count_sum);
        INFO(run.photons << " photons: mean estimate / exact = " << mean << ", standard error " << se);
        CHECK(std::abs(mean - 1) < 4 * se);
        // The same mean brightness from 10^4 and 10^6 photons.
        if (previous_mean != 0) CHECK(std::abs(mean - previous_mean) < 4 * std::hypot(se, previous_se));
        previous_mean = mean;
        previous_se = se;
    }
}

TEST_CASE("a light without falloff (POV-Ray's fade_power 0): photons estimate E = I cos, not I cos / r^2")
{
    const float intensity = 2, height = 1.5f;
    const Scene scene{Lights{PointLight<float>{.position = {0, height, 0}, .intensity = Rgb<float>(intensity), .falloff = Falloff::none}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0)}, .kd = 1, .ka = 0}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 400000, .caustic_photons = 0, .shadow_photons = false});
    // Photons per unit area fall as cos / r^2 (within 0.25 about 7000 under the light,
    // 1000 at x = 1.5: 3 % noise); each carries (4 pi I / N) r^2, cancelling the 1 / r^2.
    for (const float x : {0.0f, 0.8f, 1.5f}) {
        const float exact = intensity * height / std::sqrt(height * height + x * x);
        CAPTURE(x);
        CHECK(maps.global.irradiance_within({x, 0, 0}, {0, 1, 0}, 0.25f).x == doctest::Approx(exact).epsilon(0.12));
    }
}

TEST_CASE("global photons from a parallel light through its projection disk: E = E0 cos")
{
    // Sunlight at cos = 2 / sqrt 5 onto a black slab 4 x 4: the disk facing the light
    // covers the slab's bounding sphere, and the photons that land estimate E0 cos.
    const float e0 = 3;
    const Scene scene{Lights{DirectionalLight<float>{.direction = {1, -2, 0}, .irradiance = Rgb<float>(e0)}},
                      Object{Box<float>({-2, -0.1f, -2}, {2, 0, 2}), Diffuse<float>{.albedo = {.color = Rgb<float>(0)}, .kd = 1, .ka = 0}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 200000, .caustic_photons = 0, .shadow_photons = false});
    // About 7000 photons per unit area: 500 within r = 0.15, 4.5 % noise per point, 1.6 %
    // for the mean of eight.
    double sum = 0;
    for (int i = 0; i < 8; ++i) sum += maps.global.irradiance_within({-1.4f + 0.4f * float(i), 0, 0.3f}, {0, 1, 0}, 0.15f).x;
    CHECK(sum / 8 == doctest::Approx(e0 * 2 / std::sqrt(5.0)).epsilon(0.07));
    // Nothing lands on the slab's underside.
    CHECK(maps.global.irradiance_within({0, -0.1f, 0}, {0, -1, 0}, 0.15f).x == 0.0f);
}

TEST_CASE("energy: in a closed diffuse room the stored power sums to Phi (1 + rho + rho^2 + ...)")
{
    // A light inside a box of albedo 0.5: every photon hits a wall, and survives each
    // bounce with the reflectance. Expected stored power: Phi * sum_{k=0}^{16} rho^k.
    const float rho = 0.5f, intensity = 1;
    const Scene scene{Lights{PointLight<float>{.position = {0.1f, 0.2f, -0.1f}, .intensity = Rgb<float>(intensity)}},
                      Object{Box<float>({-1, -1, -1}, {1, 1, 1}), Diffuse<float>{.albedo = {.color = Rgb<float>(rho)}, .kd = 1, .ka = 0}}};
    const std::size_t photons = 100000;
    const PhotonMaps maps = trace_photons(scene, {.global_photons = photons, .caustic_photons = 0, .max_bounces = 16, .shadow_photons = false});
    double total = 0;
    for (const Photon& p : maps.global.photons()) total += p.power().x;
    const double phi = 4 * pi<double> * intensity;
    const double expected = phi * (1 - std::pow(rho, 17)) / (1 - rho);
    // Each photon's stored total is Phi/N times a geometric count of bounces (mean 2,
    // variance rho / (1 - rho)^2 = 2): the sum's relative error is about sqrt(2 / N) / 2.
    CHECK(std::abs(total / expected - 1) < 4 * std::sqrt(2.0 / double(photons)) / 2);
    // Every stored photon came from inside, onto an inward-facing wall.
    int outward = 0;
    for (const Photon& p : maps.global.photons()) outward += prism::length(Vec3<float>(p.position)) < 0.99f;
    CHECK(outward == 0);
    // Each photon records its segments from the light: the direct ones 1, and each bounce
    // one more, so the power stored at k segments is Phi rho^(k - 1) (to the photons' noise).
    std::array<double, 18> by_segments{};
    for (const Photon& p : maps.global.photons()) {
        CHECK(p.segments() >= 1);
        CHECK(((p.flags & Photon::direct) != 0) == (p.segments() == 1));
        by_segments[std::size_t(p.segments())] += p.power().x;
    }
    for (int k = 1; k <= 4; ++k) {
        CAPTURE(k);
        CHECK(by_segments[std::size_t(k)] == doctest::Approx(phi * std::pow(rho, k - 1)).epsilon(0.03));
    }
}

TEST_CASE("a glass ball's caustic map: photons focused into a peak below it, symmetric about the axis")
{
    // Light straight above a glass ball of radius 1 at height 2.5 over a floor: the
    // caustic lies on the floor under the ball's centre.
    const Scene scene{Lights{PointLight<float>{.position = {0, 12, 0}, .intensity = Rgb<float>(100)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                      Object{Sphere<float>({0, 2.5f, 0}, 1), Dielectric<float>{.ior = 1.5f}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 0, .caustic_photons = 200000, .shadow_photons = false});
    REQUIRE(maps.caustic.size() > 50000);
    const Vec3<float> up{0, 1, 0};
    const float centre = maps.caustic.irradiance_within({0, 0, 0}, up, 0.1f).x;
    const float ring = maps.caustic.irradiance_within({0.9f, 0, 0}, up, 0.1f).x;
    CHECK(centre > 5 * ring); // focused
    // Symmetric: the four points at the same distance from the axis agree within noise.
    const float e[4] = {maps.caustic.irradiance_within({0.3f, 0, 0}, up, 0.1f).x, maps.caustic.irradiance_within({-0.3f, 0, 0}, up, 0.1f).x,
                        maps.caustic.irradiance_within({0, 0, 0.3f}, up, 0.1f).x, maps.caustic.irradiance_within({0, 0, -0.3f}, up, 0.1f).x};
    const float mean = 0.25f * (e[0] + e[1] + e[2] + e[3]);
    for (float v : e) CHECK(std::abs(v - mean) < 0.2f * mean);
    for (const Photon& p : maps.caustic.photons()) CHECK((p.flags & Photon::caustic) != 0);
}

TEST_CASE("shadow photons lie behind an occluder; the maps are the same bits for any thread count")
{
    const Scene scene{Lights{PointLight<float>{.position = {0, 5, 0}, .intensity = Rgb<float>(10)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                      Object{Box<float>({-1, 2, -1}, {1, 2.2f, 1}), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}}};
    const PhotonMaps one = trace_photons(scene, {.global_photons = 50000, .caustic_photons = 0, .seed = 5, .threads = 1});
    const PhotonMaps two = trace_photons(scene, {.global_photons = 50000, .caustic_photons = 0, .seed = 5, .threads = 2});
    REQUIRE(one.global.size() == two.global.size());
    CHECK(one.global.photons() == two.global.photons()); // field by field: the struct has padding
    // Under the slab: only shadow photons among the direct-or-shadow ones; in the open: only direct.
    const auto [direct_under, shadow_under] = one.global.direct_and_shadow({0, 0, 0}, {0, 1, 0}, 50, 1.0f);
    const auto [direct_open, shadow_open] = one.global.direct_and_shadow({3, 0, 0}, {0, 1, 0}, 50, 1.0f);
    CHECK(direct_under == 0);
    CHECK(shadow_under > 0);
    CHECK(direct_open > 0);
    CHECK(shadow_open == 0);
}

TEST_CASE("a glass ball focuses a parallel beam R (2 - n) / (2 (n - 1)) behind its far side")
{
    // n = 1.5, R = 1: 0.5 behind the far side. Paraxial rays through the Sphere, refracted
    // twice, cross the axis there (geometry and optics, no photon map).
    const double n = 1.5, r = 1.0, focal = r * (2 - n) / (2 * (n - 1));
    const Sphere<double> ball({0, 0, 0}, r);
    for (double height : {1e-3, 3e-3}) {
        Ray<double> ray{{height, 5, 0}, {0, -1, 0}};
        for (double eta : {n, 1 / n}) {
            const auto c = ball.crossings(ray, {0, infinity<double>});
            REQUIRE(!c.empty());
            const Vec3<double> facing = c[0].facing_normal();
            const auto bent = refract(ray.direction, facing, eta);
            REQUIRE(bent);
            ray = spawn_ray(c[0].point, c[0].error, c[0].normal, *bent);
        }
        const double axis_y = ray.origin.y - ray.origin.x * ray.direction.y / ray.direction.x;
        CHECK(-r - axis_y == doctest::Approx(focal).epsilon(1e-4));
    }

    // The caustic map of sunlight through the ball, on a screen at that focus: photons
    // are densest on the axis and spread symmetrically about it.
    const Scene scene{Lights{DirectionalLight<float>{.direction = {0, -1, 0}, .irradiance = Rgb<float>(1)}},
                      Object{Plane<float>({0, 1, 0}, float(-r - focal)), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                      Object{Sphere<float>({0, 0, 0}, float(r)), Dielectric<float>{.ior = float(n)}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 0, .caustic_photons = 300000, .shadow_photons = false});
    // The photons leave a disk as wide as the ball: all meet it, and all but those
    // reflected (about 8 % of the power) pass through.
    REQUIRE(maps.caustic.size() > 250000);
    const Vec3<float> up{0, 1, 0};
    const float y = float(-r - focal);
    const float centre = maps.caustic.irradiance_within({0, y, 0}, up, 0.02f).x;
    float ring[4];
    const float offsets[4][2] = {{0.15f, 0}, {-0.15f, 0}, {0, 0.15f}, {0, -0.15f}};
    for (int i = 0; i < 4; ++i) ring[i] = maps.caustic.irradiance_within({offsets[i][0], y, offsets[i][1]}, up, 0.02f).x;
    const float ring_mean = 0.25f * (ring[0] + ring[1] + ring[2] + ring[3]);
    CHECK(centre > 3 * ring_mean); // the peak is on the axis
    for (float v : ring) CHECK(std::abs(v - ring_mean) < 0.25f * ring_mean); // symmetric
    // Calibrated: the ball passes E pi R^2 (less Fresnel reflection) onto the screen.
    double total = 0;
    for (const Photon& p : maps.caustic.photons()) total += p.power().x;
    CHECK(total < std::acos(-1.0) * r * r);
    CHECK(total > 0.8 * std::acos(-1.0) * r * r);
}

TEST_CASE("bad photon counts and bounces are refused by name, not wrapped or clamped")
{
    // Regression: max_bounces -1 gave 0 photons, a count of size_t(-5) wrapped to 0, and 2^41
    // photons ended in a bare std::bad_alloc.
    const auto scene = light_over_floor(1, 1);
    CHECK_THROWS_WITH_AS((void)trace_photons(scene, {.max_bounces = -1}), doctest::Contains("max_bounces"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((void)trace_photons(scene, {.global_photons = std::size_t(-5)}), doctest::Contains("global_photons"), std::invalid_argument);
    try {
        (void)trace_photons(scene, {.caustic_photons = std::size_t(1) << 41});
        FAIL("2^41 photons were accepted");
    } catch (const std::invalid_argument& e) {
        CHECK(std::string(e.what()).find("caustic_photons") != std::string::npos);
        CHECK(std::string(e.what()).find("GiB") != std::string::npos);
    }
    // Past this machine's memory but within the index: what it needs, as a bad_alloc.
    const double memory = detail::physical_memory();
    REQUIRE(memory > 0);
    const double twice = 2 * memory / sizeof(Photon);
    if (twice < double(detail::max_photons))
        CHECK_THROWS_WITH_AS((void)trace_photons(scene, {.global_photons = std::size_t(twice)}), doctest::Contains("GiB"), std::bad_alloc);
}

TEST_CASE("a light whose power overflows float is refused, not traced into empty maps")
{
    // Regression: intensity 3e38 is finite, but 4 pi I is not: the maps came out empty.
    CHECK_THROWS_WITH_AS(PointLight<float>{.intensity = Rgb<float>(3e38f)}.validate(), doctest::Contains("power"), std::invalid_argument);
    const Scene sun{Lights{DirectionalLight<float>{.irradiance = Rgb<float>(3e37f)}},
                    Object{Sphere<float>({0, 0, 0}, 1e9f), Diffuse<float>{}}};
    CHECK_THROWS_WITH_AS((void)trace_photons(sun, {.global_photons = 10, .caustic_photons = 0}), doctest::Contains("overflows"), std::invalid_argument);
}

TEST_CASE("Caustic photons aimed at targets whose cones overlap carry what unaimed photons on the same paths carry")
{
    // Two glass balls, one partly in front of the other as the light sees them: a
    // direction toward both belongs to one target only (before, it was counted for both).
    const Scene scene{Lights{PointLight<double>{.position = {0, 8, 0}, .intensity = Rgb<double>(50)}},
                      Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0)}}},
                      Object{Sphere<double>({0, 1, 0}, 1), Dielectric<double>{.ior = 1.5}},
                      Object{Sphere<double>({0.8, 3.2, 0.3}, 0.7), Dielectric<double>{.ior = 1.5}}};
    // (Under a sanitizer an eighth of the photons: the bound below is in standard errors.)
    const PhotonMaps maps = trace_photons(scene, {.global_photons = test::samples(2000000), .caustic_photons = test::samples(200000), .shadow_photons = false});
    double aimed = 0, unaimed = 0;
    for (const Photon& p : maps.caustic.photons()) aimed += p.power().x;
    std::size_t count = 0;
    for (const Photon& p : maps.global.photons())
        if (p.flags & Photon::caustic) {
            unaimed += p.power().x;
            ++count;
        }
    // The unaimed sum has a relative standard error of about 1 / sqrt(count) (each such
    // photon carries the same power): 4 sigma.
    INFO("aimed ", aimed, ", unaimed ", unaimed, " from ", count, " photons");
    CHECK(count > std::size_t(test::samples(10000)));
    CHECK(std::abs(aimed - unaimed) < 4 * unaimed / std::sqrt(double(count)));
}

TEST_CASE("shares of a distributed trace, put end to end, make trace_photons' maps; a bad share is refused")
{
    const Scene scene{Lights{PointLight<float>{.position = {0, 5, 0}, .intensity = Rgb<float>(10)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                      Object{Sphere<float>({0, 1.5f, 0}, 0.5f), Dielectric<float>{.ior = 1.5f}}};
    const PhotonTracerConfig config{.global_photons = 9001, .caustic_photons = 7003, .seed = 3, .threads = 2};
    for (const std::size_t pass : {std::size_t(0), std::size_t(2)}) {
        const PhotonMaps whole = trace_photons(scene, config, StraightAir{}, pass);
        REQUIRE(whole.caustic.size() > 100); // the ball's caustic
        for (const std::size_t parts : {std::size_t(1), std::size_t(3), std::size_t(7)}) {
            std::vector<Photon> global, caustic;
            for (std::size_t part = 0; part < parts; ++part) {
                const PhotonShare share = trace_photon_share(scene, config, StraightAir{}, pass, part, parts);
                global.insert(global.end(), share.global.begin(), share.global.end());
                caustic.insert(caustic.end(), share.caustic.begin(), share.caustic.end());
            }
            // The tree orders its photons: the same photons in, the same tree out.
            CHECK(global.size() == whole.global.size());
            CHECK(PhotonMap(global, 2).photons() == whole.global.photons());
            CHECK(PhotonMap(caustic, 1).photons() == whole.caustic.photons());
        }
    }
    CHECK_THROWS_WITH_AS((void)trace_photon_share(scene, config, StraightAir{}, 0, 3, 3), doctest::Contains("part 3 of 3"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((void)trace_photon_share(scene, config, StraightAir{}, 0, 0, 0), doctest::Contains("part 0 of 0"), std::invalid_argument);
}

TEST_CASE("photons off a two-lobe surface keep their power: a lobe is picked with its own reflectance, and the coat's light reaches the caustic map")
{
    // In the two-lobe furnace (tests/furnace.hpp) each bounce picks the base with
    // probability rho_d = 0.5, the coat with rho_s = 0.2, and absorbs otherwise, so every
    // stored photon carries the light's power over the photon count (4 pi^2 / N), as in a
    // grey scene of one lobe. Before, a lobe was picked by its share of rho_d + rho_s and
    // then survived by its own reflectance, and a photon's power grew 1.4 or 3.5 times
    // per bounce. And the caustic map had no photon at all: its pass stopped at the first
    // surface with a diffuse lobe, before any photon could take the coat.
    const auto scene = test::coated_furnace_scene();
    constexpr std::size_t count = 100000;
    const PhotonMaps maps = trace_photons(scene, {.global_photons = count, .caustic_photons = count, .max_bounces = 64, .seed = 9});
    const double each = 4 * pi<double> * pi<double> / double(count);
    for (const PhotonMap* map : {&maps.global, &maps.caustic}) {
        double largest = 0, total = 0;
        for (const Photon& photon : map->photons()) {
            largest = std::max(largest, double(photon.power().x));
            total += double(photon.power().x);
        }
        CHECK(largest <= each * (1 + 1e-4));
        // The caustic map holds the light's power Phi each time the coat alone has
        // mirrored it k >= 1 times: Phi (rho_s + rho_s^2 + ...) = Phi rho_s / (1 - rho_s).
        if (map == &maps.caustic) CHECK(total == doctest::Approx(4 * pi<double> * pi<double> * test::coat_mirror / (1 - test::coat_mirror)).epsilon(0.02));
    }
}

TEST_CASE("volume photons: a parallel light's photons cover a box of fog, and what the fog first scatters is E A (1 - exp(-sigma_t h)) sigma_s / sigma_t")
{
    // Light falling straight down (irradiance 1) on a 2 x 2 x 2 box of fog in the scene's
    // air, the scene's one object tiny and beside the box: the parallel photons must start over
    // the fog's region, not only around the objects (before, they covered the tiny ball
    // and missed the fog). First scatterings only (max_medium_bounces 0): every photon entering
    // the top face scatters inside with probability 1 - exp(-sigma_t 2), storing its power
    // times sigma_s / sigma_t.
    const auto scene = Scene{Lights{DirectionalLight<double>{.direction = {0, -1, 0}, .irradiance = Rgb<double>(1)}},
                             Object{Sphere<double>({1.5, 0, 0}, 1e-3), Diffuse<double>{}}};
    const FilledAir<Fog<double>> fog{.medium = {.absorption = Rgb<double>(0.25), .scattering = {0.25, 0.5, 0.75}}, .region = {{-1, -1, -1}, {1, 1, 1}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 400000, .caustic_photons = 0, .max_bounces = 0, .max_medium_bounces = 0}, fog);
    Rgb<double> total(0);
    std::size_t flagged = 0;
    for (const Photon& photon : maps.volume.photons()) {
        total += Rgb<double>(photon.power());
        flagged += (photon.flags & Photon::volume) != 0;
    }
    CHECK(flagged == maps.volume.size());
    const Rgb<double> sigma_t = fog.medium.extinction(), expected = 4.0 * (Rgb<double>(1) - exp(-2.0 * sigma_t)) * fog.medium.scattering / sigma_t;
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        CHECK(total[c] == doctest::Approx(expected[c]).epsilon(0.01).scale(0));
    }
    CHECK(maps.global.size() == 0); // the photons that pass the box leave the scene
}

TEST_CASE("dispersion in fog: photons fanned out by a flint wedge keep their wavelength where they scatter, blue bent further than red by Snell's law")
{
    // Parallel white light along +x enters a wedge of Schott F2 square on (no refraction)
    // and leaves by a face tilted 30 degrees, bending down by about 24 degrees; beyond the
    // wedge, fog. Each photon took one wavelength band at the first face, and the caustic
    // pass stores it where it first scatters in the fog (L S S M), its direction the one
    // it left the wedge by. Snell's law at the tilted face gives that direction's y for
    // each index: the photons' colours must sort their directions as F2's indices do,
    // blue below red, by about the spread Snell gives between 450 and 650 nm.
    using T = double;
    const Vec3<T> exit_normal{std::cos(pi<T> / 6), std::sin(pi<T> / 6), 0};
    const Scene scene{Lights{DirectionalLight<T>{.direction = {1, 0, 0}, .irradiance = Rgb<T>(1)}},
                      Object{intersection_of(Plane<T>::through({0, 0, 0}, {-1, 0, 0}), Plane<T>::through({1, 0, 0}, exit_normal),
                                             Box<T>({-0.01, -1, -1}, {2, 1, 1})),
                             DispersiveDielectric<T>{.glass = glass::f2<double>}}};
    const FilledAir<Fog<T>> fog{.medium = {.scattering = Rgb<T>(0.3)}, .region = {{2, -3, -1}, {5, 1.5, 1}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 0, .caustic_photons = 400000, .max_bounces = 8, .seed = 2}, fog);
    // The direction's y after the tilted face for index n: incidence 30 degrees from its normal.
    const auto leaving_y = [&](double n) {
        const double sin_t = n * 0.5, cos_t = std::sqrt(1 - sin_t * sin_t);
        const Vec3<double> tangent = normalize(Vec3<double>(1, 0, 0) - 0.5 * std::sqrt(3.0) * Vec3<double>(exit_normal));
        return cos_t * exit_normal.y + sin_t * tangent.y;
    };
    const double red_y = leaving_y(glass::f2<double>.index(650)), blue_y = leaving_y(glass::f2<double>.index(450));
    double sum_red = 0, sum_blue = 0;
    std::size_t red = 0, blue = 0, white = 0, caustic = 0;
    for (const Photon& photon : maps.volume.photons()) {
        if ((photon.flags & Photon::caustic) == 0) continue;
        ++caustic;
        const Rgb<float> p = photon.power();
        const double y = -double(photon.toward_source().y);
        if (p.x == p.y && p.y == p.z) ++white;
        else if (p.x > 2 * p.z) sum_red += y, ++red;
        else if (p.z > 2 * p.x) sum_blue += y, ++blue;
    }
    MESSAGE(caustic, " caustic volume photons, ", red, " red, ", blue, " blue; mean y red ", sum_red / double(red), ", blue ", sum_blue / double(blue),
            "; Snell at 650 nm ", red_y, ", at 450 nm ", blue_y);
    CHECK(caustic > 50000);
    CHECK(white == 0);
    REQUIRE(red > 5000);
    REQUIRE(blue > 5000);
    // The classes' means lie between Snell's directions for the spectrum's ends, blue the lower.
    const double mean_red = sum_red / double(red), mean_blue = sum_blue / double(blue);
    CHECK(mean_blue < mean_red);
    CHECK(mean_red - mean_blue > 0.3 * (red_y - blue_y));
    for (const double mean : {mean_red, mean_blue}) {
        CHECK(mean < leaving_y(glass::f2<double>.index(720)) + 1e-3);
        CHECK(mean > leaving_y(glass::f2<double>.index(390)) - 1e-3);
    }
}
