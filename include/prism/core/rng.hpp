// SPDX-License-Identifier: MIT
// PCG32 random numbers: small state, many independent streams (one per pixel); and the
// scrambled Sobol (0,2)-sequence for stratified points in the unit square.
#pragma once

#include <prism/core/math.hpp>

#include <array>
#include <cstdint>
#include <limits>

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

/// Point i of the Sobol (0,2)-sequence in [0, 1)^2, each coordinate scrambled by XOR with
/// its own 32-bit word (random digit scrambling, which keeps the stratification). Any 2^m
/// consecutive points from a multiple of 2^m put exactly one point in every elementary
/// box of area 2^-m (Sobol 1967; the generator of Kollig and Keller 2002). A point
/// depends only on i, so threads can take any share of the sequence.
template <Scalar T = double>
[[nodiscard]] constexpr std::array<T, 2> sobol02(std::uint32_t i, std::uint32_t scramble_x, std::uint32_t scramble_y) noexcept
{
    std::uint32_t x = 0, y = 0;
    for (std::uint32_t v = 1u << 31, bit = 0; i != 0; i >>= 1, v ^= v >> 1, ++bit) {
        if (i & 1u) {
            x ^= 1u << (31 - bit); // van der Corput: the bits of i reversed
            y ^= v;
        }
    }
    x ^= scramble_x;
    y ^= scramble_y;
    // Keep the top bits that T holds exactly, so a coordinate is never rounded up to 1.
    constexpr int bits = std::numeric_limits<T>::digits < 32 ? std::numeric_limits<T>::digits : 32;
    constexpr T scale = T(1) / T(std::uint64_t(1) << bits);
    return {T(x >> (32 - bits)) * scale, T(y >> (32 - bits)) * scale};
}

} // namespace prism
