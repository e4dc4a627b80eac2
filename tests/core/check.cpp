// SPDX-License-Identifier: MIT
#include <prism/core/check.hpp>

#include <doctest/doctest.h>

#include <limits>

TEST_CASE("validation names the parameter and the value")
{
    CHECK_THROWS_WITH_AS(prism::detail::require_positive("Sphere radius", -2.0), "prism: Sphere radius must be finite and > 0, got -2",
                         std::invalid_argument);
    CHECK_THROWS_AS(prism::detail::require_finite("x", std::numeric_limits<float>::quiet_NaN()), std::invalid_argument);
    CHECK_THROWS_AS(prism::detail::require_nonzero("n", prism::Vec3<float>(0.0f)), std::invalid_argument);
    CHECK_NOTHROW(prism::detail::require_non_negative("c", prism::Vec3<double>(0.0)));
}
