// SPDX-License-Identifier: MIT
#include <prism/accel/hash_grid.hpp>
#include <prism/core/random.hpp>

#include "../effort.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace prism;

TEST_CASE("a hash grid finds every point within its radius exactly once, as brute force does, clustered or spread")
{
    Random rng(4, 9);
    for (const double spread : {0.05, 1.0, 40.0}) {
        CAPTURE(spread);
        std::vector<Vec3<double>> points(int(test::samples(20000)));
        for (auto& p : points) p = Vec3<double>(rng.uniform<double>(), rng.uniform<double>(), rng.uniform<double>()) * spread;
        // Some points exactly on one another and on cell boundaries.
        points[1] = points[0];
        points[2] = Vec3<double>(0.0);
        const double radius = 0.03;
        const HashGrid<double> grid(points, radius);
        CHECK(grid.size() == points.size());
        for (int q = 0; q < 300; ++q) {
            const Vec3<double> x = q < 3 ? points[std::size_t(q)] : Vec3<double>(rng.uniform<double>(), rng.uniform<double>(), rng.uniform<double>()) * spread;
            std::vector<std::uint32_t> found, expected;
            grid.within(x, [&](std::uint32_t i, double d2) {
                found.push_back(i);
                CHECK(d2 == length_squared(points[i] - x));
            });
            for (std::size_t i = 0; i < points.size(); ++i)
                if (length_squared(points[i] - x) <= radius * radius) expected.push_back(std::uint32_t(i));
            std::sort(found.begin(), found.end());
            REQUIRE(found == expected); // each once: two of the 8 cubes sharing a bucket read it once
        }
    }
}

TEST_CASE("a hash grid refuses a bad radius and points that are not finite, takes points spread to the horizon, and an empty grid finds nothing")
{
    const std::vector<Vec3<float>> points{{0, 0, 0}, {1, std::numeric_limits<float>::quiet_NaN(), 0}};
    CHECK_THROWS_WITH_AS(HashGrid<float>(points, 0.1f), doctest::Contains("point 1 is not finite"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(HashGrid<float>(std::span(points.data(), 1), 0.0f), doctest::Contains("radius must be finite and > 0, got 0"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(HashGrid<float>(std::span(points.data(), 1), std::numeric_limits<float>::infinity()), doctest::Contains("radius must be finite"),
                         std::invalid_argument);
    // Points spread over more cubes than 64 bits count (a floor to the horizon): far ones
    // share cubes, and each is still found where it is.
    const std::vector<Vec3<float>> far{{0, 0, 0}, {1e30f, 0, 0}, {1e30f, 1e-4f, 0}, {-3e38f, 0, 0}};
    const HashGrid<float> spread(far, 1e-3f);
    for (std::size_t i = 0; i < far.size(); ++i) {
        int found = 0;
        spread.within(far[i], [&](std::uint32_t k, float) { found += 1 + int(k == i) * 100; });
        CHECK(found == (i == 1 || i == 2 ? 102 : 101));
    }
    int visited = 0;
    HashGrid<float>().within({0, 0, 0}, [&](std::uint32_t, float) { ++visited; });
    const HashGrid<float> one(std::span(points.data(), 1), 0.5f);
    one.within({std::numeric_limits<float>::quiet_NaN(), 0, 0}, [&](std::uint32_t, float) { ++visited; });
    one.within({3e30f, 0, 0}, [&](std::uint32_t, float) { ++visited; });
    CHECK(visited == 0);
    one.within({0.2f, 0.2f, 0.2f}, [&](std::uint32_t, float) { ++visited; });
    CHECK(visited == 1);
}
