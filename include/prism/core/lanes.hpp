// SPDX-License-Identifier: MIT
// SIMD lanes by GCC's vector extensions (which clang shares), for the kernels that test
// several boxes or triangles at once (accel/bvh_node.hpp, geometry/triangle.hpp): a
// scalar in every lane, one lane of a vector in every lane of another, a lane mask as
// bits, and the lane by lane minimum and maximum of SSE's own rule for NaN. Only where
// PRISM_VECTOR_EXTENSIONS is 1.
#pragma once

#include <prism/core/config.hpp>

#include <cstddef>
#include <utility>

#if PRISM_VECTOR_EXTENSIONS
namespace prism::detail {

/// The number of lanes of the vector type V.
template <class V>
inline constexpr std::size_t lane_count = sizeof(V) / sizeof(V{}[0]);

// (Each writes its vector to `out`: a function that returns a vector wider than the
// target's registers changes the ABI, and GCC warns of it even where it is inlined.)

/// `x` in every lane of `out`: one broadcast. (`V{} + x` says the same but adds 0 to x
/// first, which the compiler must keep for a -0.)
template <class V, class T>
[[gnu::always_inline]] inline void splat(V& out, T x) noexcept
{
    [&out, x]<std::size_t... I>(std::index_sequence<I...>) { out = V{((void)I, x)...}; }(std::make_index_sequence<lane_count<V>>{});
}

/// Lane `Lane` of `v` in every lane of `out` (a vector of v's element type, as wide or
/// twice as wide): one shuffle, with no trip through a scalar.
template <int Lane, class Wide, class V>
[[gnu::always_inline]] inline void splat_lane(Wide& out, const V& v) noexcept
{
    [&out, &v]<std::size_t... I>(std::index_sequence<I...>) { out = __builtin_shufflevector(v, v, ((void)I, Lane)...); }(
        std::make_index_sequence<lane_count<Wide>>{});
}

/// A comparison's lanes (all bits set or none) as a bit each, lane 0 the lowest: one
/// movmskps or movmskpd where the lanes fill an SSE or AVX register.
template <class Mask>
[[nodiscard, gnu::always_inline]] inline unsigned lane_bits(const Mask& m) noexcept
{
    constexpr std::size_t n = lane_count<Mask>;
#if defined(__SSE__)
    if constexpr (sizeof(Mask) == 16 && n == 4) {
        typedef float F __attribute__((vector_size(16)));
        return unsigned(__builtin_ia32_movmskps((F)m));
    }
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(Mask) == 16 && n == 2) {
        typedef double D __attribute__((vector_size(16)));
        return unsigned(__builtin_ia32_movmskpd((D)m));
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(Mask) == 32 && n == 8) {
        typedef float F __attribute__((vector_size(32)));
        return unsigned(__builtin_ia32_movmskps256((F)m));
    }
    if constexpr (sizeof(Mask) == 32 && n == 4) {
        typedef double D __attribute__((vector_size(32)));
        return unsigned(__builtin_ia32_movmskpd256((D)m));
    }
#endif
    unsigned bits = 0;
    for (std::size_t lane = 0; lane < n; ++lane) bits |= m[lane] != 0 ? 1u << lane : 0u;
    return bits;
}

/// Lane by lane `a < b ? a : b` into `out`, the second operand wherever either is NaN or
/// the two are equal (so a -0 and a +0 give b): minps or minpd, which compute exactly
/// this; the compiler leaves a select of a comparison as three instructions.
template <class V>
[[gnu::always_inline]] inline void lane_min(V& out, const V& a, const V& b) noexcept
{
    constexpr std::size_t n = lane_count<V>;
#if defined(__SSE__)
    if constexpr (sizeof(V) == 16 && n == 4) {
        typedef float F __attribute__((vector_size(16)));
        out = (V)__builtin_ia32_minps((F)a, (F)b);
        return;
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(V) == 32 && n == 4) {
        typedef double D __attribute__((vector_size(32)));
        out = (V)__builtin_ia32_minpd256((D)a, (D)b);
        return;
    }
#endif
    out = a < b ? a : b;
}

/// Lane by lane `a > b ? a : b` into `out`, b wherever either is NaN or they are equal:
/// maxps or maxpd.
template <class V>
[[gnu::always_inline]] inline void lane_max(V& out, const V& a, const V& b) noexcept
{
    constexpr std::size_t n = lane_count<V>;
#if defined(__SSE__)
    if constexpr (sizeof(V) == 16 && n == 4) {
        typedef float F __attribute__((vector_size(16)));
        out = (V)__builtin_ia32_maxps((F)a, (F)b);
        return;
    }
#endif
#if defined(__AVX__)
    if constexpr (sizeof(V) == 32 && n == 4) {
        typedef double D __attribute__((vector_size(32)));
        out = (V)__builtin_ia32_maxpd256((D)a, (D)b);
        return;
    }
#endif
    out = a > b ? a : b;
}

} // namespace prism::detail
#endif
