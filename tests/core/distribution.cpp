// SPDX-License-Identifier: MIT
#include <prism/core/distribution.hpp>
#include <prism/core/random.hpp>

#include <doctest/doctest.h>

#include "../chi2.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

using prism::AliasTable;

TEST_CASE("an alias table picks each item with its weight's share (chi-square), and hands back a uniform rest")
{
    // Weights over six orders of magnitude, zeros among them, and one item holding most.
    const std::vector<double> weights{3, 0, 1e-6, 7.5, 0.25, 100, 0, 2, 1e-3, 40};
    double sum = 0;
    for (const double w : weights) sum += w;
    const AliasTable<double> table(weights);
    REQUIRE(table.size() == weights.size());
    for (std::size_t i = 0; i < weights.size(); ++i) CHECK(table.probability(i) == doctest::Approx(weights[i] / sum).epsilon(1e-12));
    prism::Random rng(5, 5);
    constexpr long n = 2000000;
    std::vector<double> observed(weights.size(), 0.0), expected(weights.size(), 0.0);
    // The rest of each pick, binned per item: uniform in [0, 1) again.
    std::vector<double> rest_observed(10, 0.0);
    for (long k = 0; k < n; ++k) {
        const auto pick = table.pick(rng.uniform<double>());
        observed[pick.index] += 1;
        CHECK_MESSAGE(pick.probability == table.probability(pick.index), "pick ", k);
        REQUIRE((pick.rest >= 0 && pick.rest < 1));
        if (pick.index == 5) rest_observed[std::size_t(pick.rest * 10)] += 1;
    }
    for (std::size_t i = 0; i < weights.size(); ++i) expected[i] = weights[i] / sum * n;
    CHECK(observed[1] == 0);
    CHECK(observed[6] == 0);
    const test::Chi2 items = test::chi2_test(observed, expected);
    MESSAGE("items: chi2 ", items.statistic, " with ", items.degrees, " degrees, p = ", items.p_value);
    CHECK(items.p_value > 1e-3);
    const std::vector<double> rest_expected(10, observed[5] / 10);
    const test::Chi2 rest = test::chi2_test(rest_observed, rest_expected);
    MESSAGE("rest of item 5: chi2 ", rest.statistic, ", p = ", rest.p_value);
    CHECK(rest.p_value > 1e-3);
}

TEST_CASE("an alias table picks in float as in double, over 10^4 items (an emitting mesh's triangles)")
{
    std::vector<double> weights(10000);
    prism::Random rng(6, 6);
    for (double& w : weights) w = rng.uniform<double>() * rng.uniform<double>();
    const AliasTable<float> table(weights);
    std::vector<double> observed(weights.size(), 0.0), expected(weights.size(), 0.0);
    double sum = 0;
    for (const double w : weights) sum += w;
    constexpr long n = 4000000;
    for (long k = 0; k < n; ++k) observed[table.pick(rng.uniform<float>()).index] += 1;
    for (std::size_t i = 0; i < weights.size(); ++i) expected[i] = weights[i] / sum * n;
    const test::Chi2 c = test::chi2_test(observed, expected);
    MESSAGE("10^4 items in float: chi2 ", c.statistic, " with ", c.degrees, " degrees, p = ", c.p_value);
    CHECK(c.p_value > 1e-3);
}

TEST_CASE("an alias table refuses weights it cannot pick by, naming the item")
{
    const auto message = [](const std::vector<double>& w) {
        try {
            (void)AliasTable<float>(w, "emitter power");
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK(message({1, -1}) == "prism: emitter power 1 must be finite and >= 0, got -1");
    CHECK(message({1, NAN}).find("prism: emitter power 1 must be finite") == 0);
    CHECK(message({0, 0}).find("positive, finite sum, got 0 over 2") != std::string::npos);
    CHECK(message({}).find("positive, finite sum") != std::string::npos);
    CHECK(message({1e308, 1e308}).find("positive, finite sum, got inf") != std::string::npos);
}

TEST_CASE("chi-square check of the test's own p-values: a fair die passes, a loaded one fails")
{
    // The test statistic's tail against a known case: chi2 = 11.07 at 5 degrees is p = 0.05.
    CHECK(test::gamma_q(2.5, 11.07 / 2) == doctest::Approx(0.05).epsilon(1e-3));
    CHECK(test::gamma_q(10, 5) == doctest::Approx(0.968171).epsilon(1e-5)); // chi2 = 10 at 20 degrees
    prism::Random rng(1, 2);
    std::vector<double> fair(6, 0.0), loaded(6, 0.0);
    for (int k = 0; k < 60000; ++k) {
        fair[std::size_t(rng.uniform<double>() * 6)] += 1;
        const double u = rng.uniform<double>();
        loaded[std::size_t(std::min(5.0, u * u * 6.6))] += 1; // not uniform
    }
    const std::vector<double> expected(6, 10000);
    CHECK(test::chi2_test(fair, expected).p_value > 1e-3);
    CHECK(test::chi2_test(loaded, expected).p_value < 1e-10);
}

TEST_CASE("a two-dimensional alias table picks each cell with its weight's share (chi-square): by row, then by column")
{
    // A 7 x 5 grid with an empty row, zeros and weights over four orders of magnitude.
    const std::size_t w = 7, h = 5;
    std::vector<double> weights(w * h);
    prism::Random rng(8, 8);
    for (std::size_t i = 0; i < weights.size(); ++i) weights[i] = i / w == 2 || i % 5 == 1 ? 0 : std::pow(10.0, 4 * rng.uniform<double>());
    double sum = 0;
    for (const double x : weights) sum += x;
    const prism::AliasTable2D<double> table(w, h, weights);
    CHECK(table.width() == w);
    CHECK(table.height() == h);
    std::vector<double> observed(w * h, 0.0), expected(w * h, 0.0), rest_x(10, 0.0), rest_y(10, 0.0);
    constexpr long n = 2000000;
    for (long k = 0; k < n; ++k) {
        const auto pick = table.pick({rng.uniform<double>(), rng.uniform<double>()});
        REQUIRE((pick.x < w && pick.y < h));
        observed[pick.y * w + pick.x] += 1;
        CHECK(pick.probability == doctest::Approx(weights[pick.y * w + pick.x] / sum).epsilon(1e-12));
        if (pick.x == 0 && pick.y == 0) rest_x[std::size_t(pick.rest.x * 10)] += 1, rest_y[std::size_t(pick.rest.y * 10)] += 1;
    }
    for (std::size_t i = 0; i < weights.size(); ++i) {
        expected[i] = weights[i] / sum * n;
        CHECK(table.probability(i % w, i / w) == doctest::Approx(weights[i] / sum).epsilon(1e-12));
        if (weights[i] == 0) CHECK(observed[i] == 0);
    }
    const test::Chi2 cells = test::chi2_test(observed, expected);
    MESSAGE("cells: chi2 ", cells.statistic, " with ", cells.degrees, " degrees, p = ", cells.p_value);
    CHECK(cells.p_value > 1e-3);
    // The rests of the picks of one cell: each uniform again.
    for (const auto* rest : {&rest_x, &rest_y}) {
        const test::Chi2 c = test::chi2_test(*rest, std::vector<double>(10, observed[0] / 10));
        CHECK(c.p_value > 1e-3);
    }
    const auto message = [](std::size_t width, std::size_t height, const std::vector<double>& ws) {
        try {
            (void)prism::AliasTable2D<float>(width, height, ws, "pixel weight");
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK(message(2, 2, {1, 2, 3}) == "prism: pixel weight: 3 weights for a grid of 2 x 2");
    CHECK(message(2, 2, {1, 2, 3, -4}) == "prism: pixel weight (1, 1) must be finite and >= 0, got -4");
    CHECK(message(2, 2, {0, 0, 0, 0}).find("positive, finite sum") != std::string::npos);
    CHECK(message(0, 0, {}) == "prism: pixel weight: 0 weights for a grid of 0 x 0");
}
