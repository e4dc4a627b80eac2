// SPDX-License-Identifier: MIT
#include <prism/light/directional_light.hpp>

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
