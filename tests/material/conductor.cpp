// SPDX-License-Identifier: MIT
#include <prism/material/conductor.hpp>

#include <doctest/doctest.h>

static_assert(prism::reflects<prism::Mirror<float>> && !prism::transmits<prism::Mirror<float>>);
static_assert(prism::is_delta<prism::Metal<double>>);

TEST_CASE("constant kr and complex-index conductors")
{
    const prism::Mirror<double> mirror{{.kr = {0.9, 0.8, 0.7}}};
    CHECK(mirror.reflectance(1.0) == prism::Rgb<double>{0.9, 0.8, 0.7});
    CHECK(mirror.reflectance(0.01) == mirror.reflectance(1.0)); // the notes' approximation
    const prism::Metal<double> gold{{.eta = {0.47, 0.47, 0.47}, .k = {2.83, 2.83, 2.83}}};
    CHECK(gold.reflectance(1.0).x == doctest::Approx(0.8151389));
    CHECK(gold.reflectance(0.02).x > gold.reflectance(1.0).x);
    const prism::Metal<float> bad_metal{{.eta = {0, 1, 1}}};
    const prism::Mirror<float> bad_mirror{{.kr = {-1, 0, 0}}};
    CHECK_THROWS_WITH_AS(bad_metal.validate(), doctest::Contains("ComplexIor eta"), std::invalid_argument);
    CHECK_THROWS_AS(bad_mirror.validate(), std::invalid_argument);
}
