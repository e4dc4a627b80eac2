// SPDX-License-Identifier: MIT
#include <prism/optics/microfacet.hpp>

#include "../bsdf_checks.hpp"

#include <doctest/doctest.h>

using prism::TrowbridgeReitz;
using prism::Vec3;

TEST_CASE("Trowbridge-Reitz: D at the pole and Smith's Lambda against their closed forms")
{
    const TrowbridgeReitz<double> ggx(0.3, 0.6);
    CHECK(ggx.d({0, 0, 1}) == doctest::Approx(1 / (prism::pi<double> * 0.3 * 0.6)));
    // alpha 1, 60 degrees: tan^2 = 3, Lambda = (sqrt(1 + 3) - 1) / 2 = 0.5.
    const TrowbridgeReitz<double> one(1, 1);
    CHECK(one.lambda(test::polar(60, 20)) == doctest::Approx(0.5));
    CHECK(one.g1(test::polar(60, 20)) == doctest::Approx(2.0 / 3));
    CHECK(one.g(test::polar(60, 0), test::polar(60, 90)) == doctest::Approx(0.5));
    // Anisotropic: along x the width is alpha_x alone.
    CHECK(ggx.lambda(test::polar(45, 0)) == doctest::Approx((std::sqrt(1 + 0.09) - 1) / 2));
    CHECK(ggx.lambda(test::polar(45, 90)) == doctest::Approx((std::sqrt(1 + 0.36) - 1) / 2));
    CHECK(prism::TrowbridgeReitz<float>::from(prism::Roughness<float>(0.5f)).alpha_x() == 0.25f);
    CHECK(TrowbridgeReitz<float>(1e-4f, 5e-4f).smooth());
    CHECK_FALSE(TrowbridgeReitz<float>(1e-4f, 2e-3f).smooth());
}

TEST_CASE("Trowbridge-Reitz: the projected normals cover the surface once, and each direction sees one unit of visible normals")
{
    for (const auto& [ax, ay] : {std::pair{0.05, 0.05}, std::pair{0.3, 0.3}, std::pair{1.0, 1.0}, std::pair{0.1, 0.6}}) {
        CAPTURE(ax);
        CAPTURE(ay);
        const TrowbridgeReitz<double> ggx(ax, ay);
        const double projected = test::sphere_integral([&](const Vec3<double>& m) { return m.z > 0 ? ggx.d(m) * m.z : 0.0; }, {0, 0, 1});
        CHECK(projected == doctest::Approx(1).epsilon(1e-3));
        for (const double theta : {0.0, 40.0, 75.0, 88.0}) {
            CAPTURE(theta);
            const Vec3<double> w = test::polar(theta, 30);
            const double visible = test::sphere_integral([&](const Vec3<double>& m) { return m.z > 0 ? ggx.visible_d(w, m) : 0.0; }, {0, 0, 1});
            CHECK(visible == doctest::Approx(1).epsilon(2e-3));
        }
    }
}

TEST_CASE("Trowbridge-Reitz: visible normals are drawn by their density (chi-square)")
{
    for (const auto& [ax, ay] : {std::pair{0.2, 0.2}, std::pair{0.7, 0.7}, std::pair{0.15, 0.5}}) {
        for (const double theta : {0.0, 50.0, 85.0}) {
            CAPTURE(ax);
            CAPTURE(ay);
            CAPTURE(theta);
            const TrowbridgeReitz<double> ggx(ax, ay);
            const Vec3<double> w = test::polar(theta, 110);
            prism::Random rng(5, 1);
            const test::Chi2 chi2 = test::chi2_polar(
                [&] {
                    const double u = rng.uniform<double>();
                    return ggx.sample_visible(w, u, rng.uniform<double>());
                },
                [&](const Vec3<double>& m) { return ggx.visible_d(w, m); }, {0, 0, 1}, 400000);
            CAPTURE(chi2.statistic);
            CHECK(chi2.p_value > 1e-3);
            CHECK(std::abs(chi2.missing) < 400);
        }
    }
}
