// SPDX-License-Identifier: MIT
#include <prism/material/diffuse.hpp>

#include <doctest/doctest.h>

static_assert(prism::has_diffuse<prism::Diffuse<float>> && !prism::is_delta<prism::Diffuse<float>>);
static_assert(!prism::reflects<prism::Diffuse<float>> && !prism::transmits<prism::Diffuse<double>>);

TEST_CASE("diffuse factors are validated")
{
    CHECK_NOTHROW(prism::Diffuse<float>{}.validate());
    CHECK_THROWS_WITH_AS(prism::Diffuse<float>{.kd = -1}.validate(), doctest::Contains("Diffuse kd"), std::invalid_argument);
    const prism::Diffuse<float> nan_albedo{.albedo = {.color = {std::nanf(""), 0, 0}}};
    CHECK_THROWS_WITH_AS(nan_albedo.validate(), doctest::Contains("Solid color"), std::invalid_argument);
}
