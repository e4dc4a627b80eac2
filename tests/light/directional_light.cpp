// SPDX-License-Identifier: MIT
#include <prism/light/directional_light.hpp>

#include "../effort.hpp"
#include "../emission_checks.hpp"

#include <doctest/doctest.h>

TEST_CASE("a directional light arrives from the opposite of its direction, at any distance")
{
    const prism::DirectionalLight<double> sun{.direction = {0, -2, 0}, .irradiance = {3, 3, 3}};
    const auto s = sun.sample({100, -5, 7});
    CHECK(s.wi == prism::Vec3<double>{0, 1, 0});
    CHECK(s.distance == std::numeric_limits<double>::infinity());
    CHECK(s.irradiance.x == 3);
    CHECK_THROWS_WITH_AS((prism::DirectionalLight<float>{.direction = {0, 0, 0}}.validate()), doctest::Contains("direction"),
                         std::invalid_argument);
}

TEST_CASE("a parallel light's emission carries E pi R^2 through the disk of the scene's sphere facing it")
{
    using namespace prism;
    const DirectionalLight<double> light{.direction = {0.3, -1, 0.2}, .irradiance = {1, 0.5, 2}};
    const BoundingSphere<double> sphere{{1, 0, -1}, 4};
    const Rgb<double> power = test::emitted_power(light, sphere, 1000);
    for (int k = 0; k < 3; ++k) CHECK(power[k] == doctest::Approx(light.irradiance[k] * pi<double> * 16).epsilon(1e-9));
    // Its rays start upstream of the sphere, within the disk's radius of its axis.
    Random rng(1, 1);
    const Vec3<double> axis = normalize(light.direction);
    for (int i = 0; i < 1000; ++i) {
        const auto e = light.emission(sphere, {rng.uniform<double>(), rng.uniform<double>()}, {0.5, 0.5});
        const Vec3<double> v = e.ray.origin - sphere.center;
        CHECK(dot(v, axis) <= -sphere.radius);
        CHECK(length(v - dot(v, axis) * axis) <= sphere.radius * (1 + 1e-12));
    }
}
