// SPDX-License-Identifier: MIT
#include <prism/integrator/specular.hpp>
#include <prism/material/conductor.hpp>
#include <prism/material/dielectric.hpp>

#include <doctest/doctest.h>

#include <cmath>

using prism::Vec3;

TEST_CASE("the specular split: Fresnel times kr and kt for glass, all reflected past the critical angle, kr for metal")
{
    const prism::Dielectric<double> glass{.ior = 1.5, .kr = 1, .kt = 0.9};
    const Vec3<double> n{0, 1, 0};
    // Normal incidence going in: R = 0.04.
    const auto in = prism::specular_split(glass, Vec3<double>{0, -1, 0}, n, true);
    CHECK(in.kr.x == doctest::Approx(0.04));
    CHECK(in.kt.x == doctest::Approx(0.9 * 0.96));
    REQUIRE(in.refracted);
    // 45 degrees going out of glass: past 41.8 degrees, total internal reflection.
    const auto out = prism::specular_split(glass, prism::normalize(Vec3<double>{1, -1, 0}), n, false);
    CHECK_FALSE(out.refracted);
    CHECK(out.kr.x == 1);
    CHECK(out.kt.x == 0);
    const prism::Mirror<double> mirror{{.kr = {0.9, 0.5, 0.1}}};
    const auto m = prism::specular_split(mirror, prism::normalize(Vec3<double>{1, -1, 0}), n, true);
    CHECK(m.kr.y == 0.5);
    CHECK_FALSE(m.refracted);
}
