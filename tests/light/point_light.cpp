// SPDX-License-Identifier: MIT
#include <prism/light/point_light.hpp>

#include "../effort.hpp"
#include "../emission_checks.hpp"

#include <doctest/doctest.h>

TEST_CASE("a point light's irradiance falls off as I / r^2, unless told not to")
{
    const prism::PointLight<double> light{.position = {0, 4, 3}, .intensity = {10, 20, 30}};
    const auto s = light.sample({0, 0, 0});
    CHECK(s.distance == doctest::Approx(5));
    CHECK(s.wi.y == doctest::Approx(0.8));
    CHECK(s.irradiance.x == doctest::Approx(10.0 / 25));
    CHECK(light.power().z == doctest::Approx(4 * std::acos(-1.0) * 30)); // Phi = 4 pi I
    const prism::PointLight<double> flat{.position = {0, 4, 3}, .intensity = {10, 20, 30}, .falloff = prism::Falloff::none};
    CHECK(flat.sample({0, 0, 0}).irradiance.x == doctest::Approx(10));
    CHECK_THROWS_WITH_AS((prism::PointLight<float>{.position = {0, std::nanf(""), 0}}.validate()), doctest::Contains("PointLight position"),
                         std::invalid_argument);
    CHECK_THROWS_AS((prism::PointLight<float>{.intensity = {-1, 0, 0}}.validate()), std::invalid_argument);
}

TEST_CASE("a point light's emission carries its power 4 pi I, uniform over the sphere of directions")
{
    using namespace prism;
    const PointLight<double> light{.position = {1, 2, 3}, .intensity = {1, 2, 0.5}};
    const Rgb<double> power = test::emitted_power(light, BoundingSphere<double>{{0, 0, 0}, 5}, 20000);
    for (int k = 0; k < 3; ++k) CHECK(power[k] == doctest::Approx(light.power()[k]).epsilon(1e-9));
}
