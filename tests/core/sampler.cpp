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
    for (const SamplerKind kind : {SamplerKind::independent, SamplerKind::sobol}) {
        const Sampler a(kind, 3, 1000, 17), b(kind, 3, 1000, 17), other_pixel(kind, 3, 1001, 17), other_seed(kind, 4, 1000, 17);
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
            CHECK(seeds.key() == Sampler::key_of(99, pixel));
            for (std::uint32_t sample = 0; sample < 40; ++sample) {
                const Sampler kept(kind, seeds, sample), hashed(kind, 99, pixel, sample);
                // Pairs past the kept ones (32 on) and back, as a path's bounces jump.
                for (const std::uint32_t k : {0u, 1u, 8u, 2u, 31u, 32u, 40u, 14u, 3u, 20u, 1000u})
                    CHECK_MESSAGE(kept.bits(k) == hashed.bits(k), "kind ", int(kind), " pixel ", pixel, " sample ", sample, " pair ", k);
            }
        }
}

TEST_CASE("the Sobol sampler's pair is Burley's scrambles composed as written: the index scrambled, each coordinate scrambled")
{
    // The slow, obvious twin of Sampler::bits, which leaves out the bit reversals that cancel.
    for (const std::uint32_t sample : {0u, 1u, 5u, 1000u, 65535u, 0x80000001u})
        for (std::uint32_t k = 0; k < 20; ++k) {
            const Sampler sampler(SamplerKind::sobol, 17, 4242, sample);
            const std::uint64_t key = Sampler::key_of(17, 4242);
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

TEST_CASE("each sample's point is uniform on its own, so any prefix is unbiased: chi-square over pixels, for either sampler")
{
    // Sample 5 (of a prefix of 6, not a power of two) and pair 3, over 20 000 pixels, in a
    // 8 x 8 grid of cells; and the two pairs together (u of pair 0 against u of pair 1):
    // pairs are independent.
    for (const SamplerKind kind : {SamplerKind::independent, SamplerKind::sobol}) {
        std::vector<double> cells(64, 0), joint(64, 0);
        const int pixels = 20000;
        for (int p = 0; p < pixels; ++p) {
            const Sampler sampler(kind, 2, std::uint64_t(p), 5);
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
    std::vector<double> ns, sobol_error, random_error;
    for (std::uint32_t n = 16; n <= 1024; n *= 4) {
        ns.push_back(double(n));
        sobol_error.push_back(rms_error(SamplerKind::sobol, n, 2, 200, f, integral));
        random_error.push_back(rms_error(SamplerKind::independent, n, 2, 200, f, integral));
    }
    const double sobol_slope = test::log_log_slope(ns, sobol_error), random_slope = test::log_log_slope(ns, random_error);
    MESSAGE("RMS error slopes: Sobol ", sobol_slope, " (", sobol_error.back(), " at 1024), independent ", random_slope, " (", random_error.back(), ")");
    CHECK(sobol_slope < -1.25); // -1.39 here: -3/2 less its logarithmic factors
    CHECK(random_slope > -0.65);
    CHECK(random_slope < -0.35);
    CHECK(sobol_error.back() < 0.05 * random_error.back());
}
