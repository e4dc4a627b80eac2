// SPDX-License-Identifier: MIT
#include <prism/optics/beer.hpp>

#include <doctest/doctest.h>

TEST_CASE("Beer-Lambert: I(x) = I0 exp(-c x) per channel, and composes over distance")
{
    const prism::Rgb<double> sigma{0.5, 1.0, 0.0};
    const auto t = prism::beer_lambert(sigma, 2.0);
    CHECK(t.x == doctest::Approx(0.36787944117)); // e^-1
    CHECK(t.y == doctest::Approx(0.13533528324)); // e^-2
    CHECK(t.z == 1.0);
    const auto at_half = prism::beer_lambert(sigma, 1.0);
    CHECK(at_half.y * at_half.y == doctest::Approx(t.y));
}
