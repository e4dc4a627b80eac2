// SPDX-License-Identifier: MIT
#include <prism/transport/direct.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

using namespace prism;

TEST_CASE("lights arriving at a point: behind ones skipped, occluded ones with v = 0, glass by Beer-Lambert")
{
    const Scene scene{Lights{PointLight<double>{.position = {0, 4, 0}}, PointLight<double>{.position = {0, -4, 0}},
                             PointLight<double>{.position = {3, 4, 0}}},
                      Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{}},
                      Object{Box<double>({-1, 1, -1}, {1, 2, 1}), Dielectric<double>{.interior = {.absorption = Rgb<double>(1)}}},
                      Object{Sphere<double>({1.5, 2, 0}, 0.5), Diffuse<double>{}}};
    const auto hit = scene.closest_hit({{0, 1e-3, 0}, {0, -1, 0}}, {0, infinity<double>}); // the origin on the floor
    REQUIRE(hit);
    int visited = 0;
    for_each_light_arriving(scene, hit->crossing, [&](const LightSample<double>& s, const Rgb<double>& v, double cos) {
        ++visited;
        if (s.wi.x == 0) CHECK(v.x == doctest::Approx(std::exp(-1.0))); // straight up through 1 of absorbing glass
        else CHECK(v.x == 0);                                          // toward (3, 4, 0): the ball is in the way
        CHECK(cos > 0);
    });
    CHECK(visited == 2); // the light below the floor is behind it
}
