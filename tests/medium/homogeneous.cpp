// SPDX-License-Identifier: MIT
#include <prism/medium/homogeneous.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

TEST_CASE("a homogeneous medium keeps exp(-sigma d) per channel, and refuses a negative coefficient by name")
{
    const prism::Homogeneous<double> water{.absorption = {0.45, 0.06, 0.01}}; // 1/m, roughly water's red, green, blue
    const auto t = water.transmittance(2.0);
    CHECK(t.x == doctest::Approx(std::exp(-0.9)));
    CHECK(t.z == doctest::Approx(std::exp(-0.02)));
    CHECK(prism::Homogeneous<float>{}.transmittance(1e30f) == prism::Rgb<float>(1.0f)); // clear: nothing lost at any distance
    // Halving: d = ln 2 / sigma keeps exactly half.
    CHECK(water.transmittance(std::log(2.0) / 0.45).x == doctest::Approx(0.5));
    CHECK_THROWS_WITH_AS((prism::Homogeneous<float>{.absorption = {0, -1, 0}}.validate()), doctest::Contains("Homogeneous absorption"),
                         std::invalid_argument);
}
