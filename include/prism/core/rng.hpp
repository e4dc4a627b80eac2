// SPDX-License-Identifier: MIT
// PCG32 random numbers: small state, many independent streams (one per sample, one per
// photon), what a sample draws past its sampler's dimensions (core/random.hpp).
#pragma once

#include <prism/core/math.hpp>

#include <cstdint>

namespace prism {

/// PCG-XSH-RR 32-bit generator (O'Neill 2014, "PCG: A Family of Simple Fast
/// Space-Efficient Statistically Good Algorithms for Random Number Generation").
/// Each (seed, stream) pair gives an independent sequence, so a pixel's samples depend
/// only on the scene seed and the pixel index, never on which thread renders it.
class Pcg32 {
public:
    constexpr Pcg32() noexcept : Pcg32(0x853c49e6748fea9bULL, 0xda3e39cb94b95bdbULL) {}

    /// A generator at `seed` on stream `stream`: each pair gives its own sequence.
    constexpr Pcg32(std::uint64_t seed, std::uint64_t stream) noexcept : inc_((stream << 1u) | 1u)
    {
        next_u32();
        state_ += seed;
        next_u32();
    }

    /// Uniform 32-bit integer.
    constexpr std::uint32_t next_u32() noexcept
    {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
    }

    /// Uniform in [0, 1), never 1 (24 or 53 random bits).
    template <Scalar T = float>
    constexpr T uniform() noexcept
    {
        if constexpr (sizeof(T) <= 4) {
            return T(next_u32() >> 8) * T(0x1p-24);
        } else {
            const std::uint64_t hi = next_u32() >> 5; // 27 bits
            const std::uint64_t lo = next_u32() >> 6; // 26 bits
            return T((hi << 26) | lo) * T(0x1p-53);
        }
    }

private:
    std::uint64_t state_ = 0;
    std::uint64_t inc_ = 1;
};

} // namespace prism
