// SPDX-License-Identifier: MIT
#include <prism/core/quadrature.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

using namespace prism;

TEST_CASE("Gauss-Legendre: the published nodes and weights, and every polynomial of degree 2n - 1 exactly")
{
    // Abramowitz and Stegun, table 25.4: n = 2, +-1/sqrt(3), 1; n = 3, 0 (8/9) and +-sqrt(3/5) (5/9);
    // n = 5, 0.9061798459386640 (0.2369268850561891), 0.5384693101056831 (0.4786286704993665), 0 (0.5688888888888889).
    const GaussLegendre two(2), three(3), five(5);
    CHECK(two.node(1) == doctest::Approx(1 / std::sqrt(3.0)).epsilon(1e-15));
    CHECK(two.weight(0) == doctest::Approx(1).epsilon(1e-15));
    CHECK(three.node(1) == doctest::Approx(0).scale(1).epsilon(1e-15));
    CHECK(three.node(2) == doctest::Approx(std::sqrt(0.6)).epsilon(1e-15));
    CHECK(three.weight(1) == doctest::Approx(8.0 / 9).epsilon(1e-15));
    CHECK(three.weight(0) == doctest::Approx(5.0 / 9).epsilon(1e-15));
    CHECK(five.node(4) == doctest::Approx(0.9061798459386640).epsilon(1e-15));
    CHECK(five.weight(4) == doctest::Approx(0.2369268850561891).epsilon(1e-14));
    CHECK(five.node(3) == doctest::Approx(0.5384693101056831).epsilon(1e-15));
    CHECK(five.weight(3) == doctest::Approx(0.4786286704993665).epsilon(1e-14));
    CHECK(five.weight(2) == doctest::Approx(0.5688888888888889).epsilon(1e-14));
    CHECK(GaussLegendre(1).node(0) == 0.0);
    CHECK(GaussLegendre(1).weight(0) == 2.0);
    // x^k on [0.5, 2]: (2^(k+1) - 0.5^(k+1)) / (k + 1), exact up to k = 2n - 1, not at 2n
    // (for few nodes: with many, the error at 2n is below double's rounding).
    for (const int n : {1, 2, 3, 7, 16, 33, 64}) {
        const GaussLegendre rule(n);
        double sum = 0;
        for (int k = 0; k < n; ++k) sum += rule.weight(k);
        CHECK(sum == doctest::Approx(2).epsilon(1e-13));
        for (int k = 0; k <= 2 * n && k <= 40; ++k) {
            const double exact = (std::pow(2.0, k + 1) - std::pow(0.5, k + 1)) / (k + 1);
            const double found = rule.integrate(0.5, 2.0, [&](double x) { return std::pow(x, k); });
            CAPTURE(n);
            CAPTURE(k);
            if (k <= 2 * n - 1) CHECK(found == doctest::Approx(exact).epsilon(1e-12));
            else if (n <= 3) CHECK(std::abs(found / exact - 1) > 1e-5);
        }
    }
    // A smooth function converges fast: exp on [0, 1] to 1e-14 with 8 nodes.
    CHECK(GaussLegendre(8).integrate(0.0, 1.0, [](double x) { return std::exp(x); }) == doctest::Approx(std::exp(1.0) - 1).epsilon(1e-14));
    CHECK_THROWS_WITH_AS(GaussLegendre(0), doctest::Contains("GaussLegendre count must be in [1, 64], got 0"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(GaussLegendre(65), doctest::Contains("got 65"), std::invalid_argument);
}
