// SPDX-License-Identifier: MIT
#include <prism/render/render.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>

#include <cstring>
#include <limits>

using namespace prism;

namespace {

auto busy_scene()
{
    Scene scene{Lights{PointLight<float>{.position = {2, 5, 3}, .intensity = Rgb<float>(40)}},
                Object{Plane<float>({0, 1, 0}, 0), Diffuse<float, Checker<float>>{}},
                Object{Sphere<float>({0, 1, 0}, 1), Dielectric<float>{.ior = 1.5f, .interior = {.absorption = {0.2f, 0.1f, 0.0f}}}},
                Object{Sphere<float>({2, 0.7f, -1}, 0.7f), Mirror<float>{}}};
    scene.background = {0.3f, 0.5f, 0.9f};
    return scene;
}

} // namespace

TEST_CASE("the same bits for 1, 2 and 8 threads")
{
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    const Camera<float> camera{.position = {0, 2, 6}, .look_at = {0, 1, 0}, .fov = 50};
    RenderConfig config{.width = 96, .height = 64, .spp = 5, .seed = 42, .progress = false, .tile_size = 8};
    config.threads = 1;
    const Film one = render(camera, integrator, config);
    for (unsigned threads : {2u, 8u}) {
        config.threads = threads;
        const Film many = render(camera, integrator, config);
        CHECK(std::memcmp(one.pixels().data(), many.pixels().data(), one.pixels().size() * sizeof(one.pixels()[0])) == 0);
    }
    // A different seed moves the jittered samples.
    config.seed = 43;
    const Film other = render(camera, integrator, config);
    CHECK(std::memcmp(one.pixels().data(), other.pixels().data(), one.pixels().size() * sizeof(one.pixels()[0])) != 0);
    CHECK(one.rejected() == 0);
}

TEST_CASE("stratified sub-pixel samples cover the pixel once per stratum")
{
    Pcg32 rng(1u, 1u);
    CHECK(detail::pixel_sample<float>(0, 1, rng) == std::pair{0.5f, 0.5f});
    int hits[3][3] = {};
    for (int s = 0; s < 9; ++s) {
        const auto [u, v] = detail::pixel_sample<float>(s, 9, rng);
        ++hits[int(u * 3)][int(v * 3)];
    }
    for (auto& row : hits)
        for (int h : row) CHECK(h == 1);
    // One sample not at the centre (a pass of progressive photon mapping, whose passes
    // average over the pixel): uniform over it, so 10 000 of them fill every ninth.
    int ninths[3][3] = {};
    for (int i = 0; i < 10000; ++i) {
        const auto [u, v] = detail::pixel_sample<float>(0, 1, rng, false);
        REQUIRE(u >= 0.0f);
        REQUIRE(u < 1.0f);
        ++ninths[int(u * 3)][int(v * 3)];
    }
    for (auto& row : ninths)
        for (int h : row) CHECK(std::abs(h - 1111) < 120); // 3.5 standard deviations
}

TEST_CASE("bad render settings are rejected")
{
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    CHECK_THROWS_WITH_AS((void)render(Camera<float>{}, integrator, {.spp = 0}), doctest::Contains("spp"), std::invalid_argument);
    CHECK_THROWS_AS((void)render(Camera<float>{}, integrator, {.width = -4}), std::invalid_argument);
}

TEST_CASE("a tile as large as int renders the same image")
{
    // Issue 10: tile_size = INT_MAX overflowed the tile arithmetic (UBSan) and rendered black.
    const auto scene = busy_scene();
    const Whitted integrator(scene);
    const Camera<float> camera{.position = {0, 1, 6}, .look_at = {0, 0.5f, 0}};
    const Film tiled = render(camera, integrator, {.width = 40, .height = 30, .progress = false});
    const Film whole = render(camera, integrator, {.width = 40, .height = 30, .progress = false, .tile_size = std::numeric_limits<int>::max()});
    CHECK(std::memcmp(tiled.pixels().data(), whole.pixels().data(), tiled.pixels().size() * sizeof(tiled.pixels()[0])) == 0);
    float sum = 0;
    for (const auto& p : whole.pixels()) sum += p.x + p.y + p.z;
    CHECK(sum > 0);
}
