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
//
// SamplerKind::halton is Halton's sequence, the photon emission of progressive photon
// mapping's published implementations: dimension d of sample i is i's radical inverse in
// the d-th prime base, Owen-scrambled digit by digit (sequences::scrambled_radical_inverse),
// its seed the pixel's and the dimension's; one point in all of a sample's first 64
// dimensions together, where Sobol's padding makes each pair a net of its own. Every prefix
// of b^m samples is stratified in intervals of b^-m of the base-b dimension. A digit costs
// a division and a hash, so a point about log_b of its index of them (Sobol's: one hash).
//
// SamplerKind::zsobol (Ahmed and Wonka 2020, "Screen-Space Blue-Noise Diffusion of Monte
// Carlo Sampling Error via Hierarchical Ordering of Pixels"; pbrt-v4's ZSobolSampler) lays
// one Sobol sequence over the whole image: pixel z in Morton order takes the block of
// indices [z 2^m, (z + 1) 2^m), 2^m the render's samples per pixel rounded up to a power of
// two. Each pixel's points are then as good as Sobol's above, and every aligned 2^l x 2^l
// square of pixels shares one net of 4^l 2^m points, so that neighbours' errors cancel:
// the image's error is blue noise, its low frequencies (what a viewer sees, and what a
// downsampled or denoised image keeps) far below white noise's at the same RMSE. The
// Morton digits are permuted, each by one of the 24 orders of a 2 x 2 square drawn from a
// hash of the digits above it (so the first of four pixels is not always the top left),
// and the index within the pixel by a nested uniform scramble seeded by the pixel: every
// sample is uniform on its own, as the other kinds'. The blocks take the index's low 32
// bits, which are all a 32-bit point reads: past 2^32 / 2^m pixels the image is tiled by
// independent blocks. The blue noise is the whole layout's: a render that takes a prefix
// of it (a time budget's rounds, a preview, a range of passes) has each pixel stratified
// as Sobol's, but neighbours' prefixes do not share a net.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/sequences.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

namespace prism {

/// Which points the samples draw.
enum class SamplerKind : std::uint8_t {
    independent, ///< a uniform number for each (pixel, sample, dimension), unrelated to the others
    sobol,       ///< Owen-scrambled Sobol points, padded by pairs of dimensions (Burley 2020)
    zsobol,      ///< Sobol points laid over the image in scrambled Morton order: blue-noise error (Ahmed and Wonka 2020)
    halton,      ///< Halton's points, one prime base a dimension, Owen-scrambled digit by digit: photon emission as in progressive photon mapping
};

/// Every kind, the default first.
inline constexpr std::array<SamplerKind, 4> sampler_kinds = {SamplerKind::zsobol, SamplerKind::sobol, SamplerKind::halton, SamplerKind::independent};

/// The kind's name, as the examples' --sampler takes it.
[[nodiscard]] constexpr const char* sampler_name(SamplerKind kind) noexcept
{
    switch (kind) {
    case SamplerKind::independent: return "independent";
    case SamplerKind::sobol: return "sobol";
    case SamplerKind::zsobol: return "zsobol";
    case SamplerKind::halton: return "halton";
    }
    return "unknown";
}

/// The scrambles' seeds of pair k of a key's samples: the sample index's, then each
/// coordinate's. They depend on the render's seed, the pixel (or for zsobol the image) and
/// k, not on the sample.
[[nodiscard]] constexpr std::array<std::uint32_t, 3> pair_seeds(std::uint64_t key, std::uint32_t k) noexcept
{
    const std::uint64_t salt = 3 * std::uint64_t(k);
    return {sequences::seed_of(key, salt), sequences::seed_of(key, salt + 1), sequences::seed_of(key, salt + 2)};
}

/// What a sample's pair k reads: the point is Sobol's at index block | (the sample's index,
/// nested-scrambled with `index`, masked to the pixel's share), each coordinate
/// Owen-scrambled with `u` and `v`.
struct PairSeeds {
    std::uint32_t index = 0; ///< the sample index's nested uniform scramble
    std::uint32_t u = 0;     ///< the first coordinate's Owen scramble
    std::uint32_t v = 0;     ///< the second's
    std::uint32_t block = 0; ///< zsobol: the pixel's first index in the image's sequence (its low 32 bits); 0 otherwise

    /// Equal when all four are.
    friend constexpr bool operator==(const PairSeeds&, const PairSeeds&) = default;
};

/// Which points a pixel's samples draw: its key, whence its scrambles, and under zsobol its
/// place in the image's sequence.
class PixelKey {
public:
    /// Pixel 0 of seed 0.
    constexpr PixelKey() noexcept : PixelKey(0, 0) {}

    /// Pixel `pixel` of the render of `seed`, its points its own (a pixel of no image, as a
    /// photon map's: zsobol draws Sobol's padded points there).
    constexpr PixelKey(std::uint64_t seed, std::uint64_t pixel) noexcept : key_(key_of(seed, pixel)) {}

    /// Pixel (x, y) of a width x height render of `seed` taking `spp` samples per pixel:
    /// under zsobol its block of the image's sequence, otherwise PixelKey(seed, y * width + x).
    [[nodiscard]] static constexpr PixelKey in_image(SamplerKind kind, std::uint64_t seed, std::uint32_t x, std::uint32_t y, std::uint32_t width,
                                                     std::uint32_t height, std::uint64_t spp) noexcept
    {
        if (kind != SamplerKind::zsobol) return PixelKey(seed, std::uint64_t(y) * width + x);
        PixelKey pixel(seed, ~std::uint64_t(0)); // one key for the image: its points are one sequence
        // (Asked once a pixel: counted and spread without loops.)
        const std::uint32_t side = std::max(width, height);
        pixel.levels_ = std::uint8_t(side <= 1 ? 0 : int(std::bit_width(side - 1))); // the least L with 2^L >= side
        pixel.log2_spp_ = std::uint8_t(spp <= 1 ? 0 : std::min<int>(31, int(std::bit_width(spp - 1))));
        pixel.mask_ = (std::uint32_t(1) << pixel.log2_spp_) - 1;
        // Morton order: x's bit b at 2b, y's at 2b + 1, for the bits b below levels_.
        const std::uint64_t below = (std::uint64_t(1) << pixel.levels_) - 1;
        pixel.morton_ = spread_bits(x & below) | spread_bits(y & below) << 1;
        pixel.in_image_ = true;
        return pixel;
    }

    /// The 32 bits of `v` at the even bits of the result (bit b at 2b), zeros between.
    [[nodiscard]] static constexpr std::uint64_t spread_bits(std::uint64_t v) noexcept
    {
        v &= 0xffffffffULL;
        v = (v | v << 16) & 0x0000ffff0000ffffULL;
        v = (v | v << 8) & 0x00ff00ff00ff00ffULL;
        v = (v | v << 4) & 0x0f0f0f0f0f0f0f0fULL;
        v = (v | v << 2) & 0x3333333333333333ULL;
        v = (v | v << 1) & 0x5555555555555555ULL;
        return v;
    }

    /// Pair k's seeds, hashed. Out of line: asked once a pixel and pair (PixelSeeds keeps
    /// them), its hashes and the Morton loop would only swell every draw's inlined code.
    [[nodiscard, gnu::noinline]] constexpr PairSeeds seeds(std::uint32_t k) const noexcept
    {
        const std::array<std::uint32_t, 3> seed = pair_seeds(key_, k);
        if (!in_image_) return {seed[0], seed[1], seed[2], 0};
        // The Morton digits from the top, each permuted by an order of the 2 x 2 square
        // drawn from the digits above it, the level and the pair.
        std::uint64_t permuted = 0;
        for (std::uint32_t level = levels_; level-- > 0;) {
            const std::uint64_t above = morton_ >> (2 * level + 2);
            const std::uint64_t h = mix(mix(above + 0x9e3779b97f4a7c15ULL) ^ (std::uint64_t(seed[0]) << 32 | level));
            const std::uint32_t digit = std::uint32_t(morton_ >> (2 * level)) & 3u;
            permuted |= std::uint64_t(square_orders[std::size_t(h % 24)][digit]) << (2 * level);
        }
        const std::uint32_t index_seed = std::uint32_t(mix(mix(morton_ ^ 0xd1b54a32d192ed03ULL) ^ seed[0]) >> 32);
        return {index_seed, seed[1], seed[2], std::uint32_t(permuted << log2_spp_)};
    }

    /// The bits of a sample's index that are the pixel's: all, or under zsobol the low
    /// log2 of its samples rounded up to a power of two.
    [[nodiscard]] constexpr std::uint32_t sample_mask() const noexcept { return mask_; }

    /// The key (key_of): the pixel's, or under zsobol the image's.
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
    /// The 24 orders of a 2 x 2 square's cells: entry [p][d] is where cell d goes.
    static constexpr std::array<std::array<std::uint8_t, 4>, 24> square_orders = [] {
        std::array<std::array<std::uint8_t, 4>, 24> orders{};
        std::array<std::uint8_t, 4> order = {0, 1, 2, 3};
        for (auto& o : orders) {
            o = order;
            std::next_permutation(order.begin(), order.end());
        }
        return orders;
    }();

    std::uint64_t key_;
    std::uint64_t morton_ = 0;     ///< zsobol: the pixel's Morton index
    std::uint32_t mask_ = ~0u;     ///< sample_mask()
    std::uint8_t levels_ = 0;      ///< zsobol: Morton digits, log2 of the image's larger side rounded up
    std::uint8_t log2_spp_ = 0;    ///< zsobol: log2 of the samples per pixel, rounded up
    bool in_image_ = false;        ///< whether this is a zsobol pixel
};

/// The seeds of one pixel's first `cached` pairs, hashed when a sample first asks for them
/// and kept for the pixel's other samples (three 64-bit hashes a pair, and a zsobol pixel's
/// permuted Morton index, otherwise paid by every sample: a fifth of a Sobol path's time
/// on the area-lit box). One thread's, for one pixel at a time; the Samplers that read it
/// must not outlive it.
class PixelSeeds {
public:
    /// Pairs kept: the camera's two and five bounces'.
    static constexpr std::uint32_t cached = 32;

    /// The seeds of `pixel`.
    constexpr explicit PixelSeeds(const PixelKey& pixel) noexcept : pixel_(pixel) {}

    /// The seeds of pixel `pixel` of the render of `seed` (PixelKey(seed, pixel)).
    constexpr PixelSeeds(std::uint64_t seed, std::uint64_t pixel) noexcept : pixel_(seed, pixel) {}

    /// pixel().seeds(k), hashed once.
    [[nodiscard]] constexpr PairSeeds of(std::uint32_t k) noexcept
    {
        if (k >= cached) return pixel_.seeds(k);
        if (((known_ >> k) & 1u) == 0) {
            const PairSeeds hashed = pixel_.seeds(k);
            seeds_[k] = {hashed.index, hashed.u, hashed.v, hashed.block};
            known_ |= std::uint32_t(1) << k;
        }
        return {seeds_[k][0], seeds_[k][1], seeds_[k][2], seeds_[k][3]};
    }

    /// Whose seeds these are.
    [[nodiscard]] constexpr const PixelKey& pixel() const noexcept { return pixel_; }

private:
    PixelKey pixel_;
    std::uint32_t known_ = 0; ///< bit k: seeds_[k] is hashed
    /// Pair k's PairSeeds, as plain words: an array of PairSeeds, whose members have
    /// initializers, is cleared on construction (512 bytes a pixel, a rep stos that cost
    /// a Whitted render of the Cornell box 3 % of its time). Not cleared: a seed is read
    /// only once hashed, and known_ says which.
    std::array<std::array<std::uint32_t, 4>, cached> seeds_;
};

/// The numbers of one sample of one pixel.
class Sampler {
public:
    /// Independent numbers of pixel 0, sample 0, seed 0.
    constexpr Sampler() noexcept = default;

    /// Sample `sample` of `pixel`: the sample must be below 2^31, and under zsobol below
    /// the samples per pixel its key was made for.
    constexpr Sampler(SamplerKind kind, const PixelKey& pixel, std::uint32_t sample) noexcept
        : kind_(kind), pixel_(pixel), sample_(sample), reversed_sample_(sequences::reverse_bits(sample))
    {
    }

    /// Sample `sample` of pixel `pixel` in the render of `seed` (PixelKey(seed, pixel)).
    constexpr Sampler(SamplerKind kind, std::uint64_t seed, std::uint64_t pixel, std::uint32_t sample) noexcept
        : Sampler(kind, PixelKey(seed, pixel), sample)
    {
    }

    /// The same sample, its seeds read from (and kept in) its pixel's `seeds`, which must
    /// outlive it: the same bits, for less.
    constexpr Sampler(SamplerKind kind, PixelSeeds& seeds, std::uint32_t sample) noexcept : Sampler(kind, seeds.pixel(), sample)
    {
        seeds_ = &seeds;
    }

    /// Pairs that draw Halton's points (one prime base a dimension); later pairs of a
    /// Halton sample draw independent numbers.
    static constexpr std::uint32_t halton_pairs = std::uint32_t(sequences::primes.size() / 2);

    /// The point of dimensions 2k and 2k + 1, as 32-bit fractions.
    [[nodiscard]] constexpr std::array<std::uint32_t, 2> bits(std::uint32_t k) const noexcept
    {
        if (kind_ == SamplerKind::halton) {
            if (k < halton_pairs) return halton_bits(k);
        }
        else if (kind_ != SamplerKind::independent) {
            // index = block | owen_scramble(sample, seed.index), then
            // owen_scramble(sobol(index, d), seed of d), with the bit reversals that cancel
            // left out: owen_scramble(x, s) is reverse(laine_karras(reverse(x), s)) and
            // sobol(index, 0) is reverse(index), so three reversals a pair, not eight (the
            // sample's own is kept).
            using namespace sequences;
            const PairSeeds seed = seeds_ != nullptr ? seeds_->of(k) : pixel_.seeds(k);
            const std::uint32_t index = seed.block | (reverse_bits(laine_karras(reversed_sample_, seed.index)) & pixel_.sample_mask());
            return {reverse_bits(laine_karras(index, seed.u)), reverse_bits(laine_karras(sobol1_reversed(index), seed.v))};
        }
        const std::uint64_t bits = PixelKey::mix(pixel_.key() ^ (std::uint64_t(sample_) << 32 | k));
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

private:
    /// bits(k) of a Halton sample: one sequence in every dimension at once, dimension d
    /// base primes[d] at the sample's own index, each coordinate scrambled with a seed of
    /// its own. Out of line, as the radical inverses are.
    [[nodiscard, gnu::noinline]] constexpr std::array<std::uint32_t, 2> halton_bits(std::uint32_t k) const noexcept
    {
        const PairSeeds seed = seeds_ != nullptr ? seeds_->of(k) : pixel_.seeds(k);
        return {sequences::scrambled_radical_inverse(sample_, sequences::primes[2 * k], seed.u),
                sequences::scrambled_radical_inverse(sample_, sequences::primes[2 * k + 1], seed.v)};
    }

    SamplerKind kind_ = SamplerKind::independent;
    PixelKey pixel_{};
    std::uint32_t sample_ = 0;
    std::uint32_t reversed_sample_ = 0; ///< sample_'s bits reversed
    PixelSeeds* seeds_ = nullptr;       ///< the pixel's kept seeds, if it has them
};

} // namespace prism
