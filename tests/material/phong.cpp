// SPDX-License-Identifier: MIT
#include <prism/material/phong.hpp>

#include "../bsdf_checks.hpp"

#include <doctest/doctest.h>

using prism::Vec3;

static_assert(prism::has_glossy<prism::Phong<float>> && !prism::has_diffuse<prism::Phong<float>>);

TEST_CASE("modified Phong: its lobe's albedo at normal incidence is ks, and sampling follows the pdf")
{
    // Normal incidence: int ks (n + 2) / 2 pi cos^n cos dw = ks (n + 2) int_0^1 mu^(n+1) dmu = ks.
    for (const double n : {0.0, 5.0, 60.0, 400.0}) {
        CAPTURE(n);
        const prism::PhongLobe<double> glossy{prism::Rgb<double>(0), prism::Rgb<double>(0.7), n};
        CHECK(test::albedo_by_quadrature(glossy, {0, 0, 1}) == doctest::Approx(0.7).epsilon(2e-3));
        // Oblique, the lobe is cut by the horizon: less, never more.
        CHECK(test::albedo_by_quadrature(glossy, test::polar(70, 0)) < 0.7);
    }
    for (const double n : {3.0, 40.0, 500.0})
        for (const double theta : {0.0, 45.0, 85.0}) {
            CAPTURE(n);
            CAPTURE(theta);
            const prism::PhongLobe<double> lobe{prism::Rgb<double>(0.3), prism::Rgb<double>(0.6), n};
            const Vec3<double> wo = test::polar(theta, 60);
            const test::LobeSampling s = test::check_lobe_sampling(lobe, wo, 3e-3);
            CHECK(s.albedo == doctest::Approx(test::albedo_by_quadrature(lobe, wo)).epsilon(test::resolved(5e-3)));
            CHECK(s.albedo <= 0.9 + test::resolved(1e-3));
            const auto a = test::polar(30, 10), b = test::polar(55, 170);
            CHECK(lobe.f(a, b).x == doctest::Approx(lobe.f(b, a).x).epsilon(1e-12));
        }
}

TEST_CASE("modified Phong: parameters that would create energy are refused, naming them")
{
    const prism::Phong<float> bright{.diffuse = {.color = prism::Rgb<float>(0.6f)}, .specular = prism::Rgb<float>(0.5f)};
    CHECK_THROWS_WITH_AS(bright.validate(), doctest::Contains("Phong diffuse + specular"), std::invalid_argument);
    const prism::Phong<float> negative{.exponent = -1};
    CHECK_THROWS_WITH_AS(negative.validate(), doctest::Contains("Phong exponent"), std::invalid_argument);
    // Regression: an exponent of 10^9 (or a .mtl's Ns 3e38) passed, and its highlight,
    // narrower than float directions resolve, vanished (or its samples were NaN).
    const prism::Phong<float> needle{.exponent = 1e9f};
    CHECK_THROWS_WITH_AS(needle.validate(), doctest::Contains("Phong exponent must be from 0 to 1e6 (a sharper lobe is a mirror: use Mirror), got 1e+09"),
                         std::invalid_argument);
    CHECK_NOTHROW(prism::Phong<float>{.exponent = 1e6f}.validate());
    const prism::Phong<float> fine{.diffuse = {.color = prism::Rgb<float>(0.5f)}, .specular = prism::Rgb<float>(0.5f)};
    CHECK_NOTHROW(fine.validate());
}
