// SPDX-License-Identifier: MIT
#include <prism/material/dielectric.hpp>
#include <prism/scene/object.hpp>
#include <prism/geometry/sphere.hpp>

#include <doctest/doctest.h>

#include <cmath>

using prism::Dielectric;

static_assert(prism::transmits<Dielectric<float>> && prism::reflects<Dielectric<float>>);
static_assert(prism::is_delta<Dielectric<double, prism::SchlickFresnel>>);

TEST_CASE("the Fresnel policy decides the reflectance")
{
    const Dielectric<double> exact{.ior = 1.5};
    const Dielectric<double, prism::SchlickFresnel> schlick{.ior = 1.5};
    CHECK(exact.fresnel(1.0, 1.0, 1.5) == doctest::Approx(0.04));
    CHECK(schlick.fresnel(1.0, 1.0, 1.5) == doctest::Approx(0.04));
    const double cos_t = std::sqrt(1 - (1 - 0.3 * 0.3) / (1.5 * 1.5));
    CHECK(exact.fresnel(0.3, cos_t, 1.5) != schlick.fresnel(0.3, cos_t, 1.5));
}

TEST_CASE("bad input names the parameter")
{
    const prism::Sphere<float> s({0, 0, 0}, 1);
    CHECK_THROWS_WITH_AS(prism::Object(s, Dielectric<float>{.ior = 0}), doctest::Contains("Dielectric ior"), std::invalid_argument);
    CHECK_THROWS_AS(prism::Object(s, Dielectric<float>{.ior = -1.5f}), std::invalid_argument);
    CHECK_THROWS_AS(prism::Object(s, Dielectric<float>{.ior = std::nanf("")}), std::invalid_argument);
    // Regression: an index of 1e-45 (a .mtl's Ni) passed, and refraction gave NaN.
    CHECK_THROWS_WITH_AS(prism::Object(s, Dielectric<float>{.ior = 1e-45f}), doctest::Contains("Dielectric ior must be an index of refraction from 0.01 to 100"),
                         std::invalid_argument);
    CHECK_THROWS_AS(prism::Object(s, Dielectric<float>{.ior = 101}), std::invalid_argument);
    CHECK_NOTHROW(prism::Object(s, Dielectric<float>{.ior = 100}));
    CHECK_NOTHROW(prism::Object(s, Dielectric<float>{.ior = 0.01f}));
    CHECK_THROWS_WITH_AS(prism::Object(s, Dielectric<float>{.interior = {.absorption = {0, -1, 0}}}), doctest::Contains("absorption"),
                         std::invalid_argument);
}
