// SPDX-License-Identifier: MIT
#include <prism/transport/first_surface.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

using namespace prism;

TEST_CASE("first_surface: a diffuse floor's albedo, the normal facing the ray and the path's length; 1 for a mirror; nothing for a miss")
{
    const Scene scene{Lights{PointLight<float>{.position = {0, 5, 0}, .intensity = Rgb<float>(1)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = {0.6f, 0.5f, 0.4f}}}},
                      Object{Sphere<float>({3, 1, 0}, 1), Mirror<float>{{.kr = Rgb<float>(0.9f)}}}};
    // Down onto the floor from height 2 along a direction of length 2: the path is 2 long.
    const auto floor = first_surface(scene, StraightAir{}, Ray<float>{{0, 2, 0}, {0, -2, 0}});
    REQUIRE(floor.has_value());
    CHECK(floor->albedo == Rgb<float>(0.6f, 0.5f, 0.4f));
    CHECK(floor->normal == Vec3<float>(0, 1, 0));
    CHECK(floor->distance == doctest::Approx(2.0f));
    // Onto the mirror ball: delta lobes only, albedo 1.
    const auto ball = first_surface(scene, StraightAir{}, Ray<float>{{3, 5, 0}, {0, -1, 0}});
    REQUIRE(ball.has_value());
    CHECK(ball->albedo == Rgb<float>(1));
    CHECK(ball->distance == doctest::Approx(3.0f));
    // Up into the sky.
    CHECK(!first_surface(scene, StraightAir{}, Ray<float>{{0, 2, 0}, {0, 1, 0}}).has_value());
}
