// SPDX-License-Identifier: MIT
// The numbers one camera sample draws, by dimension: a point of [0, 1)^n whose coordinates
// are named by their index, so that every sample of a pixel reads the same dimension for
// the same decision (the pixel's footprint, the lens, then each bounce's light and lobe).
//
// A number depends only on (kind, seed, pixel, sample index, dimension): any thread, crop,
// range of samples or machine gets the same bits, and any prefix of a pixel's samples is
// an unbiased estimate (each sample's point is uniform on its own).
//
// SamplerKind::sobol is Burley's padded Owen-scrambled Sobol sequence (2020): dimensions
// are taken in pairs, pair k reads Sobol's dimensions 0 and 1, a (0, 2)-sequence, at the
// sample index shuffled by a nested uniform scramble of its own (so the pairs are
// independent of each other), each coordinate Owen-scrambled with a seed of its own. Every
// prefix of 2^m samples of a pixel is then stratified in every pair: one point in each
// elementary box of area 2^-m. SamplerKind::independent is a uniform number per
// (pixel, sample, dimension) from a hash: what every estimator drew before, in spirit.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/sequences.hpp>

#include <array>
#include <cstdint>

namespace prism {

/// Which points the samples draw.
enum class SamplerKind : std::uint8_t {
    independent, ///< a uniform number for each (pixel, sample, dimension), unrelated to the others
    sobol,       ///< Owen-scrambled Sobol points, padded by pairs of dimensions (Burley 2020)
};

/// The scrambles' seeds of pair k of a pixel's samples: the sample index's, then each
/// coordinate's. They depend on the render's seed, the pixel and k, not on the sample.
[[nodiscard]] constexpr std::array<std::uint32_t, 3> pair_seeds(std::uint64_t key, std::uint32_t k) noexcept
{
    const std::uint64_t salt = 3 * std::uint64_t(k);
    return {sequences::seed_of(key, salt), sequences::seed_of(key, salt + 1), sequences::seed_of(key, salt + 2)};
}

/// The seeds of one pixel's first `cached` pairs, hashed when a sample first asks for them
/// and kept for the pixel's other samples (three 64-bit hashes a pair, otherwise paid by
/// every sample: a fifth of a Sobol path's time on the area-lit box). One thread's, for one
/// pixel at a time; the Samplers that read it must not outlive it.
class PixelSeeds {
public:
    /// Pairs kept: the camera's two and five bounces'.
    static constexpr std::uint32_t cached = 32;

    /// The seeds of pixel `pixel` of the render of `seed`.
    constexpr PixelSeeds(std::uint64_t seed, std::uint64_t pixel) noexcept : key_(key_of(seed, pixel)) {}

    /// pair_seeds(key, k), hashed once.
    [[nodiscard]] constexpr std::array<std::uint32_t, 3> of(std::uint32_t k) noexcept
    {
        if (k >= cached) return pair_seeds(key_, k);
        if (((known_ >> k) & 1u) == 0) {
            seeds_[k] = pair_seeds(key_, k);
            known_ |= std::uint32_t(1) << k;
        }
        return seeds_[k];
    }

    /// The pixel's key (Sampler::key_of).
    [[nodiscard]] constexpr std::uint64_t key() const noexcept { return key_; }

    /// The key of a pixel of a render, whence its scrambles' seeds (pair_seeds): unrelated
    /// for neighbouring pixels and seeds.
    [[nodiscard]] static constexpr std::uint64_t key_of(std::uint64_t seed, std::uint64_t pixel) noexcept
    {
        return mix(mix(seed + 0x9e3779b97f4a7c15ULL) ^ (pixel * 0xd1b54a32d192ed03ULL));
    }

    /// SplitMix64's finaliser: a bijection of 64-bit words that scatters every input bit.
    [[nodiscard]] static constexpr std::uint64_t mix(std::uint64_t z) noexcept
    {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

private:
    std::uint64_t key_;
    std::uint32_t known_ = 0; ///< bit k: seeds_[k] is hashed
    std::array<std::array<std::uint32_t, 3>, cached> seeds_{};
};

/// The numbers of one sample of one pixel.
class Sampler {
public:
    /// Independent numbers of pixel 0, sample 0, seed 0.
    constexpr Sampler() noexcept = default;

    /// Sample `sample` of pixel `pixel` in the render of `seed`.
    constexpr Sampler(SamplerKind kind, std::uint64_t seed, std::uint64_t pixel, std::uint32_t sample) noexcept
        : kind_(kind), key_(key_of(seed, pixel)), sample_(sample), reversed_sample_(sequences::reverse_bits(sample))
    {
    }

    /// The same sample, its seeds read from (and kept in) its pixel's `seeds`, which must
    /// outlive it: the same bits, for less.
    constexpr Sampler(SamplerKind kind, PixelSeeds& seeds, std::uint32_t sample) noexcept
        : kind_(kind), key_(seeds.key()), sample_(sample), reversed_sample_(sequences::reverse_bits(sample)), seeds_(&seeds)
    {
    }

    /// The point of dimensions 2k and 2k + 1, as 32-bit fractions.
    [[nodiscard]] constexpr std::array<std::uint32_t, 2> bits(std::uint32_t k) const noexcept
    {
        if (kind_ == SamplerKind::sobol) {
            // index = owen_scramble(sample, s0), then owen_scramble(sobol(index, d), s1 + d),
            // with the bit reversals that cancel left out: owen_scramble(x, s) is
            // reverse(laine_karras(reverse(x), s)) and sobol(index, 0) is reverse(index),
            // so three reversals a pair, not eight (the sample's own is kept).
            using namespace sequences;
            const std::array<std::uint32_t, 3> seed = seeds_ != nullptr ? seeds_->of(k) : pair_seeds(key_, k);
            const std::uint32_t index = reverse_bits(laine_karras(reversed_sample_, seed[0]));
            return {reverse_bits(laine_karras(index, seed[1])), reverse_bits(laine_karras(sobol1_reversed(index), seed[2]))};
        }
        const std::uint64_t bits = PixelSeeds::mix(key_ ^ (std::uint64_t(sample_) << 32 | k));
        return {std::uint32_t(bits), std::uint32_t(bits >> 32)};
    }

    /// The point of dimensions 2k and 2k + 1, in [0, 1)^2.
    template <Scalar T = double>
    [[nodiscard]] constexpr std::array<T, 2> pair(std::uint32_t k) const noexcept
    {
        const std::array<std::uint32_t, 2> b = bits(k);
        return {sequences::to_unit<T>(b[0]), sequences::to_unit<T>(b[1])};
    }

    /// The number of dimension 2k: pair k's first coordinate.
    template <Scalar T = double>
    [[nodiscard]] constexpr T single(std::uint32_t k) const noexcept
    {
        return pair<T>(k)[0];
    }

    /// Which points these are.
    [[nodiscard]] constexpr SamplerKind kind() const noexcept { return kind_; }

    /// The key of a pixel of a render (PixelSeeds::key_of).
    [[nodiscard]] static constexpr std::uint64_t key_of(std::uint64_t seed, std::uint64_t pixel) noexcept { return PixelSeeds::key_of(seed, pixel); }

private:
    SamplerKind kind_ = SamplerKind::independent;
    std::uint64_t key_ = 0;
    std::uint32_t sample_ = 0;
    std::uint32_t reversed_sample_ = 0; ///< sample_'s bits reversed
    PixelSeeds* seeds_ = nullptr;       ///< the pixel's kept seeds, if it has them
};

} // namespace prism
