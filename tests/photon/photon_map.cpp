// SPDX-License-Identifier: MIT
// PhotonMap's density estimates against photon sets whose irradiance is known exactly.
#include <prism/photon/photon_map.hpp>
#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace prism;

namespace {

/// N photons uniform on the square [-1, 1]^2 of the floor y = 0, arriving from above,
/// carrying E * area / N each: their irradiance is E everywhere inside.
PhotonMap uniform_floor(std::size_t n, float e, std::uint64_t seed)
{
    Random rng(seed, 1u);
    std::vector<Photon> photons(n);
    for (Photon& p : photons)
        p = {{2 * rng.uniform<float>() - 1, 0, 2 * rng.uniform<float>() - 1}, Rgb<float>(e * 4.0f / float(n)), {0, 1, 0}, {0, 1, 0}, Photon::direct};
    return PhotonMap(std::move(photons));
}

/// Photons on a regular grid of spacing h over [x0, x1] x [z0, z1] of the floor, each
/// carrying power P, arriving from `from`: irradiance P / h^2 away from the edges.
void floor_grid(std::vector<Photon>& out, float x0, float x1, float h, float power, Vec3<float> from)
{
    for (float x = x0 + h / 2; x < x1; x += h)
        for (float z = -1 + h / 2; z < 1; z += h) out.push_back({{x, 0, z}, Rgb<float>(power), from, {0, 1, 0}, 0});
}

} // namespace

TEST_CASE("every filter is calibrated: a uniform photon density gives back its irradiance")
{
    const float e = 3.0f;
    const PhotonMap map = uniform_floor(400000, e, 7);
    const Vec3<float> up{0, 1, 0};
    // Within r = 0.2 about 12 600 photons: the box estimate's relative standard deviation
    // is 1/sqrt(12 600) = 0.9 %, the cone's sqrt(E[w^2]) / E[w] = sqrt(1/6) / (1/3) times
    // that, 1.1 %. Five points average it down to 0.5 %: 3 % is six standard deviations.
    // Jensen's (2001) Gaussian constants alpha = 0.918, beta = 1.953 have mean 0.531 over
    // the disk: divided by pi r^2 alone they would give 0.53 E.
    for (const Filter filter : {Filter::box, Filter::cone, Filter::gaussian}) {
        double sum = 0;
        for (const float x : {-0.5f, -0.2f, 0.0f, 0.3f, 0.6f})
            sum += map.irradiance({x, 0, 0.1f}, up, {.radius = 0.2f, .filter = filter}).x;
        CAPTURE(int(filter));
        CHECK(sum / 5 == doctest::Approx(e).epsilon(0.03));
    }
    // The floor's photons (on its top face) do not light its underside.
    CHECK(map.irradiance({0, 0, 0}, {0, -1, 0}, {.radius = 0.2f}).x == 0.0f);
    // Excluded flags leave them out.
    CHECK(map.irradiance({0, 0, 0}, up, {.radius = 0.2f, .excluded = Photon::direct}).x == 0.0f);
}

TEST_CASE("k-nearest estimates: calibrated, and the search limit is the disk when fewer are found")
{
    const float e = 2.0f;
    const PhotonMap map = uniform_floor(200000, e, 8);
    const Vec3<float> up{0, 1, 0};
    // 400 nearest: each estimate has a relative standard deviation of about 1/sqrt(400)
    // = 5 %; ten points average to 1.6 %.
    for (const Filter filter : {Filter::box, Filter::cone, Filter::gaussian}) {
        double sum = 0;
        for (int i = 0; i < 10; ++i)
            sum += map.irradiance({-0.6f + 0.13f * float(i), 0, -0.2f}, up, {.k = 400, .radius = 1.0f, .filter = filter}).x;
        CAPTURE(int(filter));
        CHECK(sum / 10 == doctest::Approx(e).epsilon(0.08));
    }
    // Ten photons of power 1 within 0.5 of the origin and no other: asking for 50 finds
    // the ten, and the disk is the whole search radius, E = 10 / (pi 0.5^2).
    std::vector<Photon> few;
    for (int i = 0; i < 10; ++i) few.push_back({{0.04f * float(i), 0, 0}, Rgb<float>(1), {0, 1, 0}, {0, 1, 0}, 0});
    few.push_back({{3, 0, 0}, Rgb<float>(1), {0, 1, 0}, {0, 1, 0}, 0});
    const PhotonMap sparse(std::move(few));
    CHECK(sparse.irradiance({0, 0, 0}, up, {.k = 50, .radius = 0.5f}).x == doctest::Approx(10 / (pi<float> * 0.25f)));
    // Asking for 4: the disk reaches the 4th at 0.12, which lies on its rim and is left
    // out: 3 / (pi 0.12^2).
    CHECK(sparse.irradiance({0, 0, 0}, up, {.k = 4, .radius = 0.5f}).x == doctest::Approx(3 / (pi<float> * 0.12f * 0.12f)));
    CHECK(PhotonMap{}.irradiance({0, 0, 0}, up, {.k = 4, .radius = 0.5f}).x == 0.0f);
}

TEST_CASE("light leaks at a corner: the wall's photons face another way; a disk keeps a ledge's photons off the floor")
{
    // A dark floor (x > 0, 0.01 per photon on a 0.02 grid: E = 25) meets a bright wall
    // x = 0 whose photons arrive from (0.6, 0.8, 0), up and to the right: they would pass
    // a test of their arrival direction against the floor's normal, and leak onto the
    // floor next to the wall. Their surface faces (1, 0.2, 0), 79 degrees from the
    // floor's (a wall leaning back a little): out, at the default 60 degrees.
    std::vector<Photon> photons;
    const float h = 0.02f;
    floor_grid(photons, 0, 1, h, 0.01f, {0, 1, 0});
    for (float y = h / 2; y < 1; y += h)
        for (float z = -1 + h / 2; z < 1; z += h) photons.push_back({{0, y, z}, Rgb<float>(0.1f), {0.6f, 0.8f, 0}, normalize(Vec3<float>{1, 0.2f, 0}), 0});
    // A bright ledge 0.05 above the floor beyond the wall (x < 0), facing up as the floor does.
    for (float x = -1 + h / 2; x < 0; x += h)
        for (float z = -1 + h / 2; z < 1; z += h) photons.push_back({{x, 0.05f, z}, Rgb<float>(0.1f), {0, 1, 0}, {0, 1, 0}, 0});
    const PhotonMap map(std::move(photons));
    const Vec3<float> up{0, 1, 0};
    const float floor_e = 0.01f / (h * h);
    // At 0.25 from the wall, a sphere of 0.2 reaches neither the wall nor the ledge.
    CHECK(map.irradiance({0.25f, 0, 0}, up, {.radius = 0.2f}).x == doctest::Approx(floor_e).epsilon(0.05));
    // At 0.1 from the wall (0.15 from the nearest ledge photon), the wall's photons are
    // out, but a sphere of 0.2 reaches the ledge's, which face up: a leak.
    const float sphere = map.irradiance({0.1f, 0, 0}, up, {.radius = 0.2f}).x;
    CHECK(sphere > 2 * floor_e);
    // A disk 0.04 r thick keeps only photons below 0.008: the floor's, covering 80 % of
    // the disk (its edge cuts a segment of r^2 acos(1/2) - 0.1 sqrt(0.03) = 0.0246 from
    // pi r^2 = 0.1257). It reads 0.8045 E: what a point this near an edge sees, darker,
    // but no leak; and so does the sphere once the ledge is 0.25 away.
    const float disk = map.irradiance({0.1f, 0, 0}, up, {.radius = 0.2f, .max_height_ratio = 0.04f}).x;
    CHECK(disk == doctest::Approx(0.8045f * floor_e).epsilon(0.04));
    // With every surface facing up's way admitted (surface_cos 0), the wall leaks too: a
    // point 0.19 from it (and 0.206 from the ledge) sees the wall's photons only then.
    const float kept_out = map.irradiance({0.19f, 0, 0}, up, {.radius = 0.2f}).x;
    CHECK(kept_out == doctest::Approx(map.irradiance({0.19f, 0, 0}, up, {.radius = 0.2f, .max_height_ratio = 0.04f}).x));
    CHECK(map.irradiance({0.19f, 0, 0}, up, {.radius = 0.2f, .surface_cos = 0.0f}).x > 1.5f * kept_out);
}

TEST_CASE("the far side of a thin wall is not this side, and a curved surface keeps its grazing photons")
{
    // A sheet y = 0 lit on both sides: 1 per photon on a 0.02 grid above (E = 2500, from
    // straight above) and 3 per photon below (E = 7500, arriving grazing at 80 degrees).
    // Each side sees its own photons only (Mitsuba's photon mapper counted both).
    std::vector<Photon> photons;
    const float h = 0.02f;
    floor_grid(photons, -1, 1, h, 1.0f, {0, 1, 0});
    const Vec3<float> grazing_below = normalize(Vec3<float>{std::sin(1.396f), -std::cos(1.396f), 0});
    for (float x = -1 + h / 2; x < 1; x += h)
        for (float z = -1 + h / 2; z < 1; z += h) photons.push_back({{x, 0, z}, Rgb<float>(3), grazing_below, {0, -1, 0}, 0});
    const PhotonMap map(std::move(photons));
    CHECK(map.irradiance({0.1f, 0, 0.2f}, {0, 1, 0}, {.radius = 0.2f}).x == doctest::Approx(1 / (h * h)).epsilon(0.03));
    CHECK(map.irradiance({0.1f, 0, 0.2f}, {0, -1, 0}, {.radius = 0.2f}).x == doctest::Approx(3 / (h * h)).epsilon(0.03));
    // Inside a unit sphere, photons on its wall arriving at 85 degrees from their own
    // normal, in every azimuth, uniform over the sphere: against a query normal up to
    // 0.2 rad away, about 1 in 10 would arrive from "behind". All count.
    Random rng(11u, 11u);
    std::vector<Photon> wall(200000);
    for (Photon& p : wall) {
        const Vec3<float> at = uniform_sphere<float>(rng), n = -at;
        const auto [t, b] = orthonormal_frame(n);
        const float phi = 2 * pi<float> * rng.uniform<float>(), theta = 1.4835f;
        const Vec3<float> from = normalize(n * std::cos(theta) + (t * std::cos(phi) + b * std::sin(phi)) * std::sin(theta));
        p = {at, Rgb<float>(1), from, n, 0};
    }
    const PhotonMap sphere(std::move(wall));
    const float e = 200000 / (4 * pi<float>); // uniform: N photons of power 1 over 4 pi
    double sum = 0;
    for (int i = 0; i < 50; ++i) {
        const Vec3<float> at = uniform_sphere<float>(rng);
        sum += sphere.irradiance(at, -at, {.radius = 0.2f}).x; // 2 000 photons per estimate, 2.2 % each
    }
    CHECK(sum / 50 == doctest::Approx(e).epsilon(0.015)); // arrival-direction test: 0.9 e
}

TEST_CASE("regression from fuzzing: a radius whose square underflows estimates nothing, not NaN")
{
    // tests/fuzz/regressions/photon_map/estimate: one photon, k = 0, radius 4.2e-45,
    // the Gaussian filter: 0 / 0 before.
    const PhotonMap map(std::vector<Photon>{Photon({0, 0, 0}, Rgb<float>(1.0f), {0, 1, 0}, {0, 1, 0}, 0)});
    for (const Filter filter : {Filter::box, Filter::cone, Filter::gaussian}) {
        const Rgb<float> e = map.irradiance({0, 0, 0}, {0, 1, 0}, {.radius = 4.2039e-45f, .filter = filter});
        CHECK(e == Rgb<float>(0.0f));
    }
    // A radius whose square is a normal float still sees the photon.
    CHECK(map.irradiance({0, 0, 0}, {0, 1, 0}, {.radius = 1e-10f}).x > 0.0f);
}

TEST_CASE("a precomputed irradiance sample answers only within the disk its estimate came from")
{
    // 10^4 photons on the square [-1, 1]^2 of the floor, E = 2: a sample's 64 nearest
    // reach about 0.09. Inside the square the lookup reads E; 0.5 beyond its edge, where
    // no photon landed, it reads nothing (it read E before: the nearest sample facing up).
    PhotonMap map = uniform_floor(10000, 2.0f, 3);
    map.precompute_irradiance<64>(4);
    CHECK(map.precomputed_irradiance({0, 0, 0}, {0, 1, 0}).x == doctest::Approx(2.0).epsilon(0.25));
    CHECK(map.precomputed_irradiance({1.5f, 0, 0}, {0, 1, 0}).x == 0.0f);
    CHECK(map.precomputed_irradiance({0, 0.5f, 0}, {0, 1, 0}).x == 0.0f); // above the floor, out of every disk
}
