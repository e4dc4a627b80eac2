// SPDX-License-Identifier: MIT
#include <prism/core/sequences.hpp>

#include <doctest/doctest.h>

#include "../slope.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace prism;
using namespace prism::sequences;

namespace {

/// Whether the 2^m points x[first .. first + 2^m), y likewise (32-bit fractions), put
/// exactly one point in every elementary box of area 2^-m: [a 2^-j, (a + 1) 2^-j) x
/// [b 2^-(m-j), (b + 1) 2^-(m-j)) for every j from 0 to m.
bool is_02_net(const std::vector<std::uint32_t>& x, const std::vector<std::uint32_t>& y, std::size_t first, int m)
{
    const std::size_t n = std::size_t(1) << m;
    for (int j = 0; j <= m; ++j) {
        std::vector<int> count(n, 0);
        for (std::size_t i = first; i < first + n; ++i) {
            const std::uint64_t a = j == 0 ? 0 : x[i] >> (32 - j), b = m - j == 0 ? 0 : y[i] >> (32 - (m - j));
            ++count[std::size_t(a << (m - j) | b)];
        }
        if (std::any_of(count.begin(), count.end(), [](int c) { return c != 1; })) return false;
    }
    return true;
}

/// The L2 star discrepancy of points in [0, 1)^2 (Warnock 1972): the root mean square,
/// over anchored boxes [0, a) x [0, b), of the points' share in the box less its area.
double l2_star_discrepancy(const std::vector<std::array<double, 2>>& p)
{
    const double n = double(p.size());
    double single = 0, pairs = 0;
    for (const auto& a : p) single += (1 - a[0] * a[0]) * (1 - a[1] * a[1]);
    for (const auto& a : p)
        for (const auto& b : p) pairs += (1 - std::max(a[0], b[0])) * (1 - std::max(a[1], b[1]));
    return std::sqrt(1.0 / 9.0 - single / (2 * n) + pairs / (n * n));
}

} // namespace

TEST_CASE("Sobol's fast dimensions (bits reversed, lookups by byte) are the generator matrices' points, for indices of every size")
{
    // The slow, obvious twin: the XOR of the matrix's columns for the index's set bits.
    const auto by_matrix = [](std::uint32_t index, int d) {
        std::uint32_t x = 0;
        for (int k = 0; k < 32; ++k)
            if (((index >> k) & 1u) != 0) x ^= sobol_matrices[std::size_t(d)][std::size_t(k)];
        return x;
    };
    std::uint64_t z = 1;
    for (int n = 0; n < 200000; ++n) {
        z = z * 6364136223846793005ULL + 1442695040888963407ULL;
        const std::uint32_t index = n < 70000 ? std::uint32_t(n) : std::uint32_t(z >> 32) >> (n % 32); // small, then every length
        REQUIRE(sobol(index, 0) == by_matrix(index, 0));
        REQUIRE(sobol(index, 1) == by_matrix(index, 1));
    }
    CHECK(sobol(0xffffffffu, 1) == by_matrix(0xffffffffu, 1));
}

TEST_CASE("Sobol's first points, worked by hand from the polynomials and direction numbers")
{
    // Dimension 0 is van der Corput's. Dimension 1 (x + 1, m = 1): v = 0.1, 0.11, 0.101
    // in binary (v_k = v_(k-1) ^ v_(k-1) / 2); dimension 2 (x^2 + x + 1, m = 1, 3): v =
    // 0.1, 0.11, 0.011 (v3 = v2 ^ v1 ^ v1 / 4); point i the XOR of v_k for i's set bits.
    const double vdc[8] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
    const double second[8] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    const double third[8] = {0, 0.5, 0.75, 0.25, 0.375, 0.875, 0.625, 0.125};
    for (std::uint32_t i = 0; i < 8; ++i) {
        CAPTURE(i);
        CHECK(to_unit<double>(sobol(i, 0)) == vdc[i]);
        CHECK(to_unit<double>(sobol(i, 1)) == second[i]);
        CHECK(to_unit<double>(sobol(i, 2)) == third[i]);
    }
    // Direction numbers: x^3 + x + 1 with m = (1, 3, 1): v = 1/2, 3/4, 1/8, then
    // v4 = v2 ^ v1 ^ v1 / 8 (a_1 = 0, a_2 = 1) = 0.1100 ^ 0.1000 ^ 0.0001 = 0.0101.
    CHECK(to_unit<double>(sobol_matrices[3][0]) == 0.5);
    CHECK(to_unit<double>(sobol_matrices[3][1]) == 0.75);
    CHECK(to_unit<double>(sobol_matrices[3][2]) == 0.125);
    CHECK(to_unit<double>(sobol_matrices[3][3]) == 0.3125);
    // Column k is m_k 2^-k with m_k odd: its lowest one on the diagonal, the matrices
    // upper triangular with ones on the diagonal, so invertible.
    for (int d = 0; d < sobol_dimensions; ++d)
        for (int k = 0; k < 32; ++k) {
            const std::uint32_t v = sobol_matrices[std::size_t(d)][std::size_t(k)];
            REQUIRE(((v >> (31 - k)) & 1u) == 1u);
            REQUIRE((k == 31 || (v & ((1u << (31 - k)) - 1)) == 0));
        }
}

TEST_CASE("Sobol's dimensions 0 and 1 are a (0, 2)-sequence, and stay one under Owen's scrambling")
{
    const int most = 12;
    std::vector<std::uint32_t> x(3u << most), y(3u << most);
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        x[i] = sobol(i, 0);
        y[i] = sobol(i, 1);
    }
    for (int m = 0; m <= most; ++m)
        for (std::size_t block = 0; block < 3; ++block) REQUIRE(is_02_net(x, y, block << m, m));
    // Dimensions 2 and 3 are not, with dimension 0 (their t is above 0): the test can fail.
    std::vector<std::uint32_t> z(x.size());
    for (std::uint32_t i = 0; i < z.size(); ++i) z[i] = sobol(i, 3);
    CHECK(!is_02_net(x, z, 0, 4));
    for (const std::uint32_t seed : {1u, 77u, 0xdeadbeefu}) {
        std::vector<std::uint32_t> sx(x.size()), sy(y.size());
        for (std::size_t i = 0; i < x.size(); ++i) {
            sx[i] = owen_scramble(x[i], seed);
            sy[i] = owen_scramble(y[i], seed * 3 + 1);
        }
        for (int m = 0; m <= most; ++m) REQUIRE(is_02_net(sx, sy, 0, m));
    }
}

TEST_CASE("Owen's scrambling by hashing: each bit depends only on the bits above it, and every bit is flipped half the time")
{
    std::mt19937 engine(5);
    const auto random = [&] { return std::uint32_t(engine()); };
    for (int trial = 0; trial < 20000; ++trial) {
        const std::uint32_t seed = random(), a = random();
        const int m = int(random() % 32);
        const std::uint32_t top = m == 0 ? 0 : ~std::uint32_t(0) << (32 - m);
        const std::uint32_t b = (a & top) | (random() & ~top); // the same m leading bits
        REQUIRE(((owen_scramble(a, seed) ^ owen_scramble(b, seed)) & top) == 0);
    }
    // Over seeds, each output bit of a fixed point is flipped with probability 1/2 (the
    // scrambled point is uniform): 4 standard deviations of 100 000 coin tosses.
    const int n = 100000;
    for (const std::uint32_t x : {0u, 0x80000000u, 0x12345678u}) {
        std::array<int, 32> flips{};
        for (int s = 0; s < n; ++s) {
            const std::uint32_t y = owen_scramble(x, seed_of(std::uint64_t(s), 9)) ^ x;
            for (int k = 0; k < 32; ++k) flips[std::size_t(k)] += int((y >> k) & 1u);
        }
        for (int k = 0; k < 32; ++k) CHECK(std::abs(flips[std::size_t(k)] - n / 2) < 4 * std::sqrt(n / 4.0));
    }
}

TEST_CASE("an index scrambled as a fraction is shuffled block by block: the first 2^m shuffled indices are an aligned block of 2^m")
{
    // Burley's padding: each group of dimensions reads the sequence at its own shuffle of
    // the index; a prefix of 2^m samples then reads an aligned block, which is a net.
    for (const std::uint32_t seed : {3u, 1234567u, 0xffffffffu})
        for (int m = 0; m <= 12; ++m) {
            std::vector<std::uint32_t> shuffled;
            for (std::uint32_t i = 0; i < (1u << m); ++i) shuffled.push_back(owen_scramble(i, seed));
            std::sort(shuffled.begin(), shuffled.end());
            REQUIRE(shuffled.back() - shuffled.front() == (1u << m) - 1);
            REQUIRE(std::adjacent_find(shuffled.begin(), shuffled.end()) == shuffled.end());
            REQUIRE(shuffled.front() % (1u << m) == 0);
        }
}

TEST_CASE("Halton's radical inverses, by hand, and scrambled: the first b^k points fill every interval of length b^-k once")
{
    const double base2[5] = {0, 0.5, 0.25, 0.75, 0.125};
    const double base3[7] = {0, 1.0 / 3, 2.0 / 3, 1.0 / 9, 4.0 / 9, 7.0 / 9, 2.0 / 9};
    for (std::uint64_t i = 0; i < 5; ++i) CHECK(radical_inverse(i, 0) == base2[i]);
    for (std::uint64_t i = 0; i < 7; ++i) CHECK(radical_inverse(i, 1) == doctest::Approx(base3[i]).epsilon(1e-15));
    CHECK(radical_inverse(5 * 5 * 5 - 1, 2) == doctest::Approx(124.0 / 125).epsilon(1e-15));
    CHECK(primes[63] == 311);
    for (std::size_t d = 1; d < primes.size(); ++d)
        for (std::uint32_t f = 2; f * f <= primes[d]; ++f) REQUIRE(primes[d] % f != 0);
    for (const std::size_t d : {0, 1, 2, 5, 20, 63}) {
        const std::uint32_t b = primes[d];
        for (const std::uint32_t seed : {0u, 42u}) {
            std::uint32_t n = 1;
            for (int k = 0; k < 4 && n * b <= 20000; ++k) {
                n *= b;
                // From index 0, and from a later multiple of b^k: each block of b^k.
                for (const std::uint32_t first : {0u, 7 * n}) {
                    std::vector<int> count(n, 0);
                    for (std::uint32_t i = first; i < first + n; ++i) ++count[std::size_t(to_unit<double>(scrambled_radical_inverse(i, b, seed)) * double(n))];
                    REQUIRE(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; }));
                }
            }
        }
    }
    // The seed moves the points (in base 2 and in the others).
    CHECK(scrambled_radical_inverse(1, 2, 0) != scrambled_radical_inverse(1, 2, 1));
    CHECK(scrambled_radical_inverse(1, 3, 0) != scrambled_radical_inverse(1, 3, 1));
    // Scrambled, a point's mean over seeds is 1/2 and its variance 1/12 (uniform):
    // 100 000 seeds, 4 standard errors; and the last interval's edge is never 1.
    for (const std::uint32_t index : {0u, 7u, 123456789u}) {
        double sum = 0, squares = 0;
        for (std::uint32_t s = 0; s < 100000; ++s) {
            const double v = to_unit<double>(scrambled_radical_inverse(index, 3, seed_of(s, 1)));
            sum += v;
            squares += v * v;
        }
        CHECK(std::abs(sum / 100000 - 0.5) < 4 * std::sqrt(1.0 / 12 / 100000));
        CHECK(std::abs(squares / 100000 - 1.0 / 3) < 4 * std::sqrt(4.0 / 45 / 100000));
    }
}

TEST_CASE("scrambled radical inverses integrate a smooth function with an error falling as N^-3/2 at N = b^m: stratified sampling")
{
    // The mean of x e^x (integral 1) over the first 3^m points, its RMS over 200 seeds
    // (a relative standard error of 5 % a point: the slope to about 0.03).
    std::vector<double> ns, errors;
    for (std::uint32_t n = 9; n <= 729; n *= 3) {
        double squares = 0;
        for (std::uint32_t seed = 0; seed < 200; ++seed) {
            double sum = 0;
            for (std::uint32_t i = 0; i < n; ++i) {
                const double x = to_unit<double>(scrambled_radical_inverse(i, 3, seed_of(seed, 9)));
                sum += x * std::exp(x);
            }
            squares += (sum / n - 1) * (sum / n - 1);
        }
        ns.push_back(double(n));
        errors.push_back(std::sqrt(squares / 200));
    }
    const double slope = test::log_log_slope(ns, errors);
    MESSAGE("base 3: RMS error slope ", slope, ", ", errors.back(), " at 729 points");
    CHECK(slope < -1.35);
}

TEST_CASE("the star discrepancy of scrambled Sobol points falls about as 1 / N, of random points as N^-1/2")
{
    std::vector<double> ns, sobol_d, random_d;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (int m = 6; m <= 11; ++m) {
        const std::size_t n = std::size_t(1) << m;
        std::vector<std::array<double, 2>> s(n), r(n);
        double sd = 0, rd = 0;
        const int seeds = 4; // the mean over a few scramblings
        for (int k = 0; k < seeds; ++k) {
            for (std::uint32_t i = 0; i < n; ++i) {
                s[i] = {to_unit<double>(owen_scramble(sobol(i, 0), seed_of(std::uint64_t(k), 1))), to_unit<double>(owen_scramble(sobol(i, 1), seed_of(std::uint64_t(k), 2)))};
                r[i] = {u(random), u(random)};
            }
            sd += l2_star_discrepancy(s) / seeds;
            rd += l2_star_discrepancy(r) / seeds;
        }
        ns.push_back(double(n));
        sobol_d.push_back(sd);
        random_d.push_back(rd);
    }
    const double sobol_slope = test::log_log_slope(ns, sobol_d), random_slope = test::log_log_slope(ns, random_d);
    MESSAGE("L2 star discrepancy slopes: scrambled Sobol ", sobol_slope, ", random ", random_slope);
    CHECK(sobol_slope < -0.85);
    CHECK(random_slope > -0.65);
    CHECK(random_slope < -0.35);
    CHECK(sobol_d.back() < 0.1 * random_d.back());
}
