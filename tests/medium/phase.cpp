// SPDX-License-Identifier: MIT
#include <prism/medium/phase.hpp>

#include "../bsdf_checks.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

using namespace prism;

namespace {

/// The integral of f(cos) over the sphere, 2 pi times Simpson's rule in cos on [-1, 1].
template <class F>
double over_sphere(F&& f, int n = 200000)
{
    const double h = 2.0 / n;
    double sum = f(-1.0) + f(1.0);
    for (int i = 1; i < n; ++i) sum += f(-1.0 + i * h) * (i % 2 ? 4 : 2);
    return 2 * pi<double> * sum * h / 3;
}

} // namespace

TEST_CASE("Henyey-Greenstein integrates to 1 over the sphere, its mean cosine is g, and g = 0 is isotropic")
{
    for (const double g : {-0.7, -0.2, 0.0, 0.3, 0.9}) {
        CAPTURE(g);
        const HenyeyGreenstein<double> hg{g};
        CHECK(over_sphere([&](double c) { return hg.value(c); }) == doctest::Approx(1.0).epsilon(1e-6));
        CHECK(over_sphere([&](double c) { return c * hg.value(c); }) == doctest::Approx(g).epsilon(1e-6).scale(1));
    }
    const HenyeyGreenstein<double> isotropic{0};
    for (const double c : {-1.0, -0.3, 0.0, 0.8, 1.0}) CHECK(isotropic.value(c) == doctest::Approx(1 / (4 * pi<double>)));
    // Sampling's isotropic branch (|g| < 1e-3) meets the general one continuously.
    Random rng(3, 1);
    const Vec3<double> d{0, 0, 1};
    double gap = 0;
    for (int i = 0; i < 1000; ++i) {
        const double u1 = rng.uniform<double>(), u2 = rng.uniform<double>();
        const auto near0 = HenyeyGreenstein<double>{0.0009}.sample(d, u1, u2), past = HenyeyGreenstein<double>{0.0011}.sample(d, u1, u2);
        gap = std::max(gap, std::abs(near0.direction.z - past.direction.z));
    }
    CHECK(gap < 0.005);
}

TEST_CASE("Henyey-Greenstein's sampling follows its density (chi-square), and each sample carries the density's value")
{
    for (const double g : {-0.6, 0.0, 0.5, 0.95}) {
        CAPTURE(g);
        const HenyeyGreenstein<double> hg{g};
        const Vec3<double> d = normalize(Vec3<double>(0.3, -0.4, 0.8));
        Random rng(11, 4);
        double worst = 0, off_unit = 0;
        const test::Chi2 chi2 = test::chi2_polar(
            [&] {
                const auto s = hg.sample(d, rng.uniform<double>(), rng.uniform<double>());
                worst = std::max(worst, std::abs(s.pdf - hg.value(dot(s.direction, d))) / s.pdf);
                off_unit = std::max(off_unit, std::abs(length(s.direction) - 1));
                return s.direction;
            },
            [&](const Vec3<double>& w) { return hg.value(dot(w, d)); }, d, 500000);
        CAPTURE(chi2.statistic);
        CHECK(chi2.p_value > 0.01);
        CHECK(worst < 1e-9);
        CHECK(off_unit < 1e-12);
    }
}

TEST_CASE("Henyey-Greenstein refuses g outside (-1, 1) by name")
{
    CHECK_THROWS_WITH_AS(HenyeyGreenstein<float>{1.0f}.validate(), doctest::Contains("HenyeyGreenstein g"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(HenyeyGreenstein<float>{-1.5f}.validate(), doctest::Contains("-1.5"), std::invalid_argument);
    CHECK_THROWS_AS(HenyeyGreenstein<float>{std::nanf("")}.validate(), std::invalid_argument);
    CHECK_NOTHROW(HenyeyGreenstein<float>{0.99f}.validate());
}
