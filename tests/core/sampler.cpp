// SPDX-License-Identifier: MIT
#include <prism/core/sampler.hpp>

#include <doctest/doctest.h>

#include "../slope.hpp"

#include "../chi2.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using namespace prism;

namespace {

/// The root mean square error, over `pixels` pixels, of the mean of f over each pixel's
/// first n samples of pair k, against f's integral.
template <class F>
double rms_error(SamplerKind kind, std::uint32_t n, std::uint32_t k, int pixels, F&& f, double integral)
{
    double squares = 0;
    for (int p = 0; p < pixels; ++p) {
        double sum = 0;
        for (std::uint32_t s = 0; s < n; ++s) {
            const auto [u, v] = Sampler(kind, 7, std::uint64_t(p), s).pair(k);
            sum += f(u, v);
        }
        squares += (sum / n - integral) * (sum / n - integral);
    }
    return std::sqrt(squares / pixels);
}

} // namespace

TEST_CASE("a sampler's numbers depend only on (kind, seed, pixel, sample, dimension), and lie from 0 up to but not at 1")
{
    for (const SamplerKind kind : {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol, SamplerKind::halton}) {
        const auto pixel = [&](std::uint64_t seed, std::uint32_t x) { return PixelKey::in_image(kind, seed, x, 3, 1200, 800, 64); };
        const Sampler a(kind, pixel(3, 1000), 17), b(kind, pixel(3, 1000), 17), other_pixel(kind, pixel(3, 1001), 17), other_seed(kind, pixel(4, 1000), 17);
        for (std::uint32_t k = 0; k < 8; ++k) {
            CHECK(a.pair<double>(k) == b.pair<double>(k));
            CHECK(a.pair<double>(k) != other_pixel.pair<double>(k));
            CHECK(a.pair<double>(k) != other_seed.pair<double>(k));
        }
        for (std::uint32_t s = 0; s < 4096; ++s)
            for (std::uint32_t k = 0; k < 4; ++k)
                for (const float x : Sampler(kind, 1, 5, s).pair<float>(k)) {
                    REQUIRE(x >= 0.0f);
                    REQUIRE(x < 1.0f);
                }
    }
}

TEST_CASE("a sample reading its pixel's kept seeds (PixelSeeds) draws the same bits as one that hashes them, in any order of pairs")
{
    for (const SamplerKind kind : {SamplerKind::sobol, SamplerKind::independent})
        for (const std::uint64_t pixel : {std::uint64_t(0), std::uint64_t(12345), std::uint64_t(1) << 40}) {
            PixelSeeds seeds(99, pixel);
            CHECK(seeds.pixel().key() == PixelKey::key_of(99, pixel));
            for (std::uint32_t sample = 0; sample < 40; ++sample) {
                const Sampler kept(kind, seeds, sample), hashed(kind, 99, pixel, sample);
                // Pairs past the kept ones (32 on) and back, as a path's bounces jump.
                for (const std::uint32_t k : {0u, 1u, 8u, 2u, 31u, 32u, 40u, 14u, 3u, 20u, 1000u})
                    CHECK_MESSAGE(kept.bits(k) == hashed.bits(k), "kind ", int(kind), " pixel ", pixel, " sample ", sample, " pair ", k);
            }
        }
}

TEST_CASE("a zsobol sample reading its pixel's kept seeds draws the same bits as one that hashes them; outside an image it is Sobol's")
{
    for (const std::uint64_t spp : {1u, 6u, 64u})
        for (const auto [x, y] : {std::array<std::uint32_t, 2>{0, 0}, {17, 3}, {199, 120}}) {
            const PixelKey pixel = PixelKey::in_image(SamplerKind::zsobol, 5, x, y, 200, 121, spp);
            PixelSeeds seeds(pixel);
            for (std::uint32_t sample = 0; sample < spp; ++sample) {
                const Sampler kept(SamplerKind::zsobol, seeds, sample), hashed(SamplerKind::zsobol, pixel, sample);
                for (const std::uint32_t k : {0u, 1u, 8u, 2u, 31u, 32u, 40u, 3u})
                    CHECK_MESSAGE(kept.bits(k) == hashed.bits(k), "pixel ", x, ", ", y, " sample ", sample, " pair ", k);
            }
        }
    // A pixel of no image (a photon map's) draws Sobol's padded points; the other kinds'
    // pixels in an image are their flat index's.
    for (std::uint32_t sample = 0; sample < 20; ++sample) {
        CHECK(Sampler(SamplerKind::zsobol, 3, 77, sample).bits(4) == Sampler(SamplerKind::sobol, 3, 77, sample).bits(4));
        for (const SamplerKind kind : {SamplerKind::sobol, SamplerKind::independent})
            CHECK(Sampler(kind, PixelKey::in_image(kind, 3, 7, 2, 30, 20, 64), sample).bits(4) == Sampler(kind, 3, 2 * 30 + 7, sample).bits(4));
    }
}

TEST_CASE("the Halton sampler's pairs are one point of Halton's sequence: dimension d the radical inverse in the d-th prime base, scrambled")
{
    for (const std::uint32_t sample : {0u, 1u, 5u, 1000u, 65535u, 0x80000001u}) {
        const Sampler sampler(SamplerKind::halton, 17, 4242, sample);
        for (std::uint32_t k = 0; k < Sampler::halton_pairs; ++k) {
            const auto seeds = pair_seeds(PixelKey::key_of(17, 4242), k);
            const std::array<std::uint32_t, 2> expected = {sequences::scrambled_radical_inverse(sample, sequences::primes[2 * k], seeds[1]),
                                                           sequences::scrambled_radical_inverse(sample, sequences::primes[2 * k + 1], seeds[2])};
            REQUIRE(sampler.bits(k) == expected);
        }
        // Past Halton's 64 dimensions, independent numbers: not the sequence's pattern.
        CHECK(sampler.bits(Sampler::halton_pairs) == Sampler(SamplerKind::independent, 17, 4242, sample).bits(Sampler::halton_pairs));
    }
    // Two dimensions of different bases together: the first 2^a 3^c points of pair 0 put one
    // point in each box of 2^-a by 3^-c (Halton's stratification), for any pixel.
    for (const std::uint64_t pixel : {0u, 9u})
        for (const auto [a, c] : {std::array<int, 2>{3, 2}, {1, 4}, {5, 1}}) {
            const int columns = 1 << a, rows = int(std::pow(3, c)), n = columns * rows;
            std::vector<int> count(std::size_t(n), 0);
            for (int s = 0; s < n; ++s) {
                const auto [u, v] = Sampler(SamplerKind::halton, 3, pixel, std::uint32_t(s)).pair(0);
                ++count[std::size_t(int(u * columns) * rows + int(v * rows))];
            }
            CHECK(std::ranges::count(count, 1) == n);
        }
}

TEST_CASE("the Halton sampler's large bases are not on lines: the first samples of two dimensions are uncorrelated")
{
    // Regression: with digits scrambled by shifts, the first 64 points of bases 283 and 293
    // are (i + c) / 283 and (i + c') / 293 up to a wrap, nearly on a line; a path tracer
    // reading them at its later bounces was noisier than with independent numbers. The
    // correlation of u and v over a pixel's first 64 samples, its mean over 400 pixels:
    // about 0 (its standard error 1 / sqrt(63 * 400) = 0.006) for unrelated numbers.
    for (const std::uint32_t k : {2u, 20u, 31u}) {
        double sum = 0;
        for (std::uint64_t pixel = 0; pixel < 400; ++pixel) {
            double su = 0, sv = 0, suu = 0, svv = 0, suv = 0;
            for (std::uint32_t s = 0; s < 64; ++s) {
                const auto [u, v] = Sampler(SamplerKind::halton, 5, pixel, s).pair(k);
                su += u, sv += v, suu += u * u, svv += v * v, suv += u * v;
            }
            sum += (suv / 64 - su * sv / 4096) / std::sqrt((suu / 64 - su * su / 4096) * (svv / 64 - sv * sv / 4096));
        }
        CAPTURE(k);
        CHECK(std::abs(sum / 400) < 0.03);
    }
    // The permutations are permutations: every element of [0, n) once.
    for (const std::uint32_t n : {1u, 2u, 3u, 5u, 64u, 311u, 1000u})
        for (const std::uint32_t key : {0u, 1u, 0xdeadbeefu}) {
            std::vector<int> seen(n, 0);
            for (std::uint32_t i = 0; i < n; ++i) ++seen[sequences::permutation_element(i, n, key)];
            REQUIRE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
        }
}

TEST_CASE("the Sobol sampler's pair is Burley's scrambles composed as written: the index scrambled, each coordinate scrambled")
{
    // The slow, obvious twin of Sampler::bits, which leaves out the bit reversals that cancel.
    for (const std::uint32_t sample : {0u, 1u, 5u, 1000u, 65535u, 0x80000001u})
        for (std::uint32_t k = 0; k < 20; ++k) {
            const Sampler sampler(SamplerKind::sobol, 17, 4242, sample);
            const std::uint64_t key = PixelKey::key_of(17, 4242);
            const std::uint32_t index = sequences::owen_scramble(sample, sequences::seed_of(key, 3 * std::uint64_t(k)));
            const std::array<std::uint32_t, 2> expected = {sequences::owen_scramble(sequences::sobol(index, 0), sequences::seed_of(key, 3 * std::uint64_t(k) + 1)),
                                                           sequences::owen_scramble(sequences::sobol(index, 1), sequences::seed_of(key, 3 * std::uint64_t(k) + 2))};
            REQUIRE(sampler.bits(k) == expected);
        }
}

TEST_CASE("under the Sobol sampler every prefix of 2^m samples of a pixel is stratified in every pair of dimensions")
{
    for (const std::uint64_t pixel : {0u, 1u, 99999u})
        for (std::uint32_t k = 0; k < 6; ++k)
            for (int m = 0; m <= 10; ++m) {
                const std::uint32_t n = 1u << m;
                for (int j = 0; j <= m; ++j) { // boxes of 2^-j by 2^-(m - j)
                    std::vector<int> count(n, 0);
                    for (std::uint32_t s = 0; s < n; ++s) {
                        const auto [u, v] = Sampler(SamplerKind::sobol, 11, pixel, s).pair(k);
                        const auto a = std::uint32_t(u * double(1u << j)), b = std::uint32_t(v * double(1u << (m - j)));
                        ++count[(a << (m - j)) | b];
                    }
                    REQUIRE(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; }));
                }
            }
}

namespace {

/// Whether `points` (a multiple of 2^m of them, m = log2 of their count) put the same
/// number in every elementary box of area 2^-m of every shape: a (0, m, 2)-net.
bool is_net(const std::vector<std::array<double, 2>>& points)
{
    int m = 0;
    while ((std::size_t(1) << m) < points.size()) ++m;
    if ((std::size_t(1) << m) != points.size()) return false;
    for (int j = 0; j <= m; ++j) { // boxes of 2^-j by 2^-(m - j)
        std::vector<int> count(points.size(), 0);
        for (const auto& [u, v] : points)
            ++count[(std::size_t(u * double(1u << j)) << (m - j)) | std::size_t(v * double(std::size_t(1) << (m - j)))];
        if (!std::all_of(count.begin(), count.end(), [](int c) { return c == 1; })) return false;
    }
    return true;
}

} // namespace

TEST_CASE("under zsobol each pixel's 2^m samples are as Sobol's, and every aligned square of 4^l pixels shares one net: blue noise")
{
    // Ahmed and Wonka's construction: pixels in Morton order take consecutive blocks of one
    // sequence, so the 4^l 2^m samples of a 2^l x 2^l square of pixels at a multiple of
    // 2^l are one (0, m + 2l, 2)-net in every pair, and each pixel's prefixes of 2^j
    // samples are (0, j, 2)-nets. An image of 48 x 40 (not a power of two), spp 2^m.
    const std::uint32_t width = 48, height = 40;
    for (const std::uint32_t m : {0u, 1u, 3u})
        for (std::uint32_t k = 0; k < 4; ++k) {
            const auto points = [&](std::uint32_t x0, std::uint32_t y0, std::uint32_t side, std::uint32_t samples) {
                std::vector<std::array<double, 2>> p;
                for (std::uint32_t y = y0; y < y0 + side; ++y)
                    for (std::uint32_t x = x0; x < x0 + side; ++x)
                        for (std::uint32_t s = 0; s < samples; ++s)
                            p.push_back(Sampler(SamplerKind::zsobol, PixelKey::in_image(SamplerKind::zsobol, 8, x, y, width, height, 1u << m), s).pair(k));
                return p;
            };
            for (const auto [x, y] : {std::array<std::uint32_t, 2>{0, 0}, {13, 7}, {47, 39}})
                for (std::uint32_t j = 0; j <= m; ++j) REQUIRE(is_net(points(x, y, 1, 1u << j)));
            for (const std::uint32_t side : {2u, 4u, 8u})
                for (const auto [x, y] : {std::array<std::uint32_t, 2>{0, 0}, {8, 16}, {40, 32}}) REQUIRE(is_net(points(x, y, side, 1u << m)));
            // Not aligned: the square straddles two of the Morton order's blocks.
            CHECK_FALSE(is_net(points(1, 1, 4, 1u << m)));
        }
}

TEST_CASE("under zsobol the first of four pixels is not always the same corner: the Morton digits are permuted")
{
    // Which pixel of a 2 x 2 square takes its first Sobol block (the smallest index):
    // over the image's squares and the pairs, every corner, about equally.
    std::array<int, 4> first{};
    for (std::uint32_t k = 0; k < 8; ++k)
        for (std::uint32_t y = 0; y < 64; y += 2)
            for (std::uint32_t x = 0; x < 64; x += 2) {
                std::uint32_t best = ~0u;
                int corner = 0;
                for (int c = 0; c < 4; ++c) {
                    const PixelKey pixel = PixelKey::in_image(SamplerKind::zsobol, 1, x + std::uint32_t(c & 1), y + std::uint32_t(c >> 1), 64, 64, 1);
                    if (pixel.seeds(k).block < best) best = pixel.seeds(k).block, corner = c;
                }
                ++first[std::size_t(corner)];
            }
    for (const int count : first) CHECK(std::abs(count - 2048) < 4 * std::sqrt(2048.0)); // 8192 squares, a quarter each
}

TEST_CASE("each sample's point is uniform on its own, so any prefix is unbiased: chi-square over pixels, for either sampler")
{
    // Sample 5 (of a prefix of 6, not a power of two) and pair 3, over 20 000 pixels, in a
    // 8 x 8 grid of cells; and the two pairs together (u of pair 0 against u of pair 1):
    // pairs are independent.
    for (const SamplerKind kind : {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol, SamplerKind::halton}) {
        std::vector<double> cells(64, 0), joint(64, 0);
        const int pixels = 20000; // under zsobol a 200 x 100 image of 8 samples a pixel
        for (int p = 0; p < pixels; ++p) {
            const Sampler sampler(kind, PixelKey::in_image(kind, 2, std::uint32_t(p % 200), std::uint32_t(p / 200), 200, 100, 8), 5);
            const auto [u, v] = sampler.pair(3);
            cells[std::size_t(int(u * 8) * 8 + int(v * 8))] += 1;
            joint[std::size_t(int(sampler.single(0) * 8) * 8 + int(sampler.single(1) * 8))] += 1;
        }
        const std::vector<double> expected(64, pixels / 64.0);
        CHECK(test::chi2_test(cells, expected).p_value > 1e-3);
        CHECK(test::chi2_test(joint, expected).p_value > 1e-3);
    }
}

TEST_CASE("the Sobol sampler's error on a smooth integrand falls as N^-3/2, the independent sampler's as N^-1/2")
{
    // f(u, v) = u v e^u over the unit square: 1/2 (the integral of u e^u over [0, 1] is
    // 1, that of v is 1/2).
    const auto f = [](double u, double v) { return u * v * std::exp(u); };
    const double integral = 0.5;
    std::vector<double> ns, sobol_error, random_error, halton_error;
    for (std::uint32_t n = 16; n <= 1024; n *= 4) {
        ns.push_back(double(n));
        sobol_error.push_back(rms_error(SamplerKind::sobol, n, 2, 200, f, integral));
        random_error.push_back(rms_error(SamplerKind::independent, n, 2, 200, f, integral));
        halton_error.push_back(rms_error(SamplerKind::halton, n, 2, 200, f, integral));
    }
    const double sobol_slope = test::log_log_slope(ns, sobol_error), random_slope = test::log_log_slope(ns, random_error);
    const double halton_slope = test::log_log_slope(ns, halton_error);
    MESSAGE("RMS error slopes: Sobol ", sobol_slope, " (", sobol_error.back(), " at 1024), independent ", random_slope, " (", random_error.back(),
            "), Halton in bases 11 and 13 ", halton_slope, " (", halton_error.back(), ")");
    CHECK(sobol_slope < -1.25); // -1.39 here: -3/2 less its logarithmic factors
    CHECK(halton_slope < -0.9); // -0.98 here: at counts that are not powers of 11 and 13, the part block leaves 1 / N
    CHECK(halton_error.back() < 0.2 * random_error.back());
    CHECK(random_slope > -0.65);
    CHECK(random_slope < -0.35);
    CHECK(sobol_error.back() < 0.05 * random_error.back());
}

TEST_CASE("a zsobol key's Morton spread and sample mask equal their bit-by-bit loops")
{
    // spread_bits against the loop in_image used to run: bit b of v at bit 2b.
    prism::Random rng(43u, 1u);
    for (int i = 0; i < 100000; ++i) {
        const std::uint64_t v = i < 64 ? (std::uint64_t(1) << (i % 32)) - (i >= 32) : rng.next_u32();
        std::uint64_t loop = 0;
        for (std::uint32_t b = 0; b < 32; ++b) loop |= ((v >> b) & 1u) << (2 * b);
        REQUIRE(prism::PixelKey::spread_bits(v) == loop);
    }
    // The sample mask: 2^s - 1 for the least s <= 31 with 2^s >= spp.
    for (std::uint64_t spp = 0; spp < (std::uint64_t(1) << 34); spp = spp < 70000 ? spp + 1 : spp * 3 + 1) {
        std::uint32_t s = 0;
        while (s < 31 && (std::uint64_t(1) << s) < spp) ++s;
        const prism::PixelKey key = prism::PixelKey::in_image(prism::SamplerKind::zsobol, 1, 3, 5, 640, 480, spp);
        REQUIRE(key.sample_mask() == (std::uint32_t(1) << s) - 1);
    }
}
