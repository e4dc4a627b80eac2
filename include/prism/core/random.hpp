// SPDX-License-Identifier: MIT
// Random: the numbers one sample's estimate draws, in the order it draws them. A camera
// sample's come from its pixel's Sampler (core/sampler.hpp) by named dimension: the pixel's
// footprint (pair 0), the lens (pair 1), then each bounce of the path its own block of
// pairs_per_bounce pairs, so that the same decision of every sample of a pixel (the light
// point at the first surface, the lobe's direction at the second) reads the same
// dimensions and the samples' points are spread over them. Draws past a bounce's block,
// and every draw of an independent Random (a photon's, a test's), come from a PCG stream.
//
// uniform() takes one number (the two coordinates of a pair in turn); uniform2() a whole
// pair, so that a 2-D decision (a point on a light, a lobe's direction) gets a point of
// the sampler's 2-D stratification.
//
// Every number is a function of (sampler kind, seed, pixel, sample index, the draws
// before it): any thread, crop, pass range or MPI rank draws the same bits, and each
// sample's numbers are uniform and independent on their own, so any prefix of a pixel's
// samples is an unbiased estimate.
#pragma once

#include <prism/core/rng.hpp>
#include <prism/core/sampler.hpp>
#include <prism/core/sequences.hpp>

#include <array>
#include <cstdint>

namespace prism {

/// The numbers one sample draws: its Sampler's dimensions, bounce by bounce, then a PCG stream.
class Random {
public:
    /// Pairs a camera sample takes before its path's first bounce: the pixel's footprint, the lens.
    static constexpr std::uint32_t camera_pairs = 2;
    /// Pairs of the sampler each bounce of a path may draw (light choice and point, lobe and
    /// direction, roulette, the medium's flight and phase); its further draws are PCG's.
    static constexpr std::uint32_t pairs_per_bounce = 6;

    /// An independent stream (PCG's default seed).
    constexpr Random() noexcept = default;

    /// An independent stream: PCG's at `seed` on `stream`.
    constexpr Random(std::uint64_t seed, std::uint64_t stream) noexcept : pcg_(seed, stream) {}

    /// A camera sample's numbers: `sampler`'s (from its pixel's footprint on), then `pcg`'s.
    /// An independent sampler draws everything from `pcg`.
    constexpr Random(const Sampler& sampler, const Pcg32& pcg) noexcept
        : sampler_(sampler), pcg_(pcg), end_(sampler.kind() == SamplerKind::independent ? 0 : camera_pairs)
    {
    }

    /// The next number, uniform in [0, 1), never 1.
    template <Scalar T = float>
    constexpr T uniform() noexcept
    {
        if (has_second_) {
            has_second_ = false;
            return sequences::to_unit<T>(second_);
        }
        if (pair_ < end_) {
            const std::array<std::uint32_t, 2> b = sampler_.bits(pair_++);
            second_ = b[1];
            has_second_ = true;
            return sequences::to_unit<T>(b[0]);
        }
        return pcg_.uniform<T>();
    }

    /// The next point, uniform in [0, 1)^2: a whole pair of the sampler's.
    template <Scalar T = float>
    constexpr std::array<T, 2> uniform2() noexcept
    {
        has_second_ = false;
        if (pair_ < end_) {
            const std::array<std::uint32_t, 2> b = sampler_.bits(pair_++);
            return {sequences::to_unit<T>(b[0]), sequences::to_unit<T>(b[1])};
        }
        const T u = pcg_.uniform<T>();
        return {u, pcg_.uniform<T>()};
    }

    /// Leave the sampler's next pair undrawn, as if drawn (a camera sample at the pixel's
    /// centre skips its footprint's): the draws after it read what they would have.
    constexpr void skip_pair() noexcept
    {
        has_second_ = false;
        if (pair_ < end_) ++pair_;
        else (void)pcg_.next_u32(), (void)pcg_.next_u32();
    }

    /// A uniform 32-bit word, from the PCG stream.
    constexpr std::uint32_t next_u32() noexcept { return pcg_.next_u32(); }

    /// From here on, bounce `b`'s block of the sampler's dimensions (b counts from 0, the
    /// camera ray's first surface). Nothing for an independent stream.
    constexpr void bounce(int b) noexcept
    {
        if (sampler_.kind() == SamplerKind::independent || b < 0) return;
        pair_ = camera_pairs + std::uint32_t(b) * pairs_per_bounce;
        end_ = pair_ + pairs_per_bounce;
        has_second_ = false;
    }

private:
    Sampler sampler_{};
    Pcg32 pcg_{};
    std::uint32_t pair_ = 0;  ///< the sampler's next pair
    std::uint32_t end_ = 0;   ///< the pair the current block ends before (0: none of the sampler's)
    std::uint32_t second_ = 0; ///< the drawn pair's second coordinate, while has_second_
    bool has_second_ = false;
};

} // namespace prism
