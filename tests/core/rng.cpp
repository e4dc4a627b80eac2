// SPDX-License-Identifier: MIT
#include <prism/core/rng.hpp>

#include <doctest/doctest.h>

#include <array>
#include <utility>
#include <vector>
#include <cmath>

TEST_CASE("Pcg32 matches the reference pcg32 sequence")
{
    // pcg32-demo from the PCG reference implementation (pcg-c-basic), seeded with
    // initstate 42, initseq 54: the first six outputs.
    prism::Pcg32 rng(42u, 54u);
    const std::array<std::uint32_t, 6> expected{0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e};
    for (std::uint32_t value : expected) CHECK(rng.next_u32() == value);
}

TEST_CASE_TEMPLATE("uniform samples lie in 0 <= u < 1 with the right mean and variance", T, float, double)
{
    prism::Pcg32 rng(7u, 3u);
    constexpr int n = 200000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        const T u = rng.uniform<T>();
        REQUIRE(u >= T(0));
        REQUIRE(u < T(1));
        sum += u;
        sum2 += double(u) * u;
    }
    // Mean 1/2 with standard error sqrt(1/12/n) = 6.5e-4: allow five of them.
    CHECK(std::abs(sum / n - 0.5) < 5 * std::sqrt(1.0 / 12 / n));
    CHECK(std::abs(sum2 / n - (sum / n) * (sum / n) - 1.0 / 12) < 1e-3);
}

TEST_CASE("streams are independent and reproducible")
{
    prism::Pcg32 a(1u, 10u), b(1u, 11u), c(1u, 10u);
    int equal = 0;
    for (int i = 0; i < 1000; ++i) {
        const auto x = a.next_u32();
        equal += x == b.next_u32();
        CHECK(x == c.next_u32());
    }
    CHECK(equal < 3);
}

TEST_CASE("sobol02 is a (0,2)-sequence: 2^m points fill every elementary box of area 2^-m once")
{
    // The definition, checked for m = 10 and every box shape 2^-a x 2^-(m - a), on the
    // first 1024 points and on points 3072..4095, scrambled and not.
    constexpr int m = 10, n = 1 << m;
    for (const auto& [sx, sy] : {std::pair{0u, 0u}, std::pair{0x9e3779b9u, 0x7f4a7c15u}})
        for (const std::uint32_t first : {0u, 3u * n}) {
            int bad = 0;
            for (int a = 0; a <= m; ++a) {
                std::vector<int> count(n, 0);
                for (std::uint32_t i = first; i < first + n; ++i) {
                    const auto [x, y] = prism::sobol02<double>(i, sx, sy);
                    REQUIRE(x >= 0.0);
                    REQUIRE(x < 1.0);
                    REQUIRE(y < 1.0);
                    const int bx = int(x * (1 << a)), by = int(y * (1 << (m - a)));
                    ++count[static_cast<std::size_t>(bx * (1 << (m - a)) + by)];
                }
                for (int c : count) bad += c != 1;
            }
            CHECK(bad == 0);
        }
    // In float a coordinate never rounds up to 1.
    const auto [x, y] = prism::sobol02<float>(0, 0xffffffffu, 0xffffffffu);
    CHECK(x < 1.0f);
    CHECK(y < 1.0f);
}
