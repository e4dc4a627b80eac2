// SPDX-License-Identifier: MIT
// Low-discrepancy sequences, as 32-bit fractions: Sobol's first four dimensions, Owen's
// scrambling of them by hashing (Burley 2020, "Practical Hash-based Owen Scrambling",
// JCGT 9(4)), and Halton's radical inverses in the first 64 prime bases, scrambled digit
// by digit.
//
// A point depends only on its index, its dimension and a seed: threads, crops and
// machines may take any share of a sequence and get the same bits.
//
// Sobol's points come from generator matrices over GF(2): point i of dimension d is the
// XOR of the columns C_d[k] for the set bits k of i. Dimension 0 is van der Corput's
// (i's bits reversed); 1 to 3 come from the primitive polynomials x + 1, x^2 + x + 1 and
// x^3 + x + 1 with the initial direction numbers (1), (1, 3) and (1, 3, 1) (Joe and Kuo
// 2008). Dimensions 0 and 1 are a (0, 2)-sequence: any 2^m points from a multiple of
// 2^m put one point in each elementary box of area 2^-m.
//
// Owen's scrambling permutes the digits of a coordinate, each by a permutation that
// depends on the digits above it; the points stay a net of the same quality and become
// random, the error of a smooth integrand falling as N^-3/2. Burley's hash does it in a
// few multiplications: reverse the bits, apply Laine and Karras's hash (whose output bit
// k depends only on input bits 0 to k), reverse back.
#pragma once

#include <prism/core/math.hpp>

#include <array>
#include <cstdint>
#include <limits>

namespace prism::sequences {

/// The dimensions of Sobol's sequence given here.
inline constexpr int sobol_dimensions = 4;

/// Generator matrix columns of Sobol's first four dimensions: column k of dimension d
/// is the 32-bit fraction bit k of the index adds.
inline constexpr std::array<std::array<std::uint32_t, 32>, sobol_dimensions> sobol_matrices = [] {
    std::array<std::array<std::uint32_t, 32>, sobol_dimensions> c{};
    for (int k = 0; k < 32; ++k) c[0][std::size_t(k)] = std::uint32_t(1) << (31 - k);
    // Dimensions 1 to 3: degree s, the polynomial's inner coefficients a_1 .. a_(s-1)
    // (x^s + a_1 x^(s-1) + ... + a_(s-1) x + 1), the first s direction numbers m_k
    // (odd, below 2^k), and Bratley and Fox's recurrence for the rest:
    // v_k = a_1 v_(k-1) ^ ... ^ a_(s-1) v_(k-s+1) ^ v_(k-s) ^ (v_(k-s) >> s).
    struct Polynomial {
        int s;
        std::array<int, 2> a;
        std::array<std::uint32_t, 3> m;
    };
    constexpr Polynomial polynomials[3] = {{1, {0, 0}, {1, 0, 0}}, {2, {1, 0}, {1, 3, 0}}, {3, {0, 1}, {1, 3, 1}}};
    for (int d = 1; d < sobol_dimensions; ++d) {
        const Polynomial& p = polynomials[d - 1];
        auto& v = c[std::size_t(d)];
        for (int k = 0; k < p.s; ++k) v[std::size_t(k)] = p.m[std::size_t(k)] << (31 - k);
        for (int k = p.s; k < 32; ++k) {
            std::uint32_t x = v[std::size_t(k - p.s)] ^ (v[std::size_t(k - p.s)] >> p.s);
            for (int j = 1; j < p.s; ++j)
                if (p.a[std::size_t(j - 1)] != 0) x ^= v[std::size_t(k - j)];
            v[std::size_t(k)] = x;
        }
    }
    return c;
}();

/// The bits of x in reverse order.
[[nodiscard, gnu::always_inline]] constexpr std::uint32_t reverse_bits(std::uint32_t x) noexcept
{
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

/// Sobol's dimension 1 by bytes of the index, its bits reversed: entry [b][v] is the XOR
/// of the columns 8b to 8b + 7 whose bits are set in v, reversed, so that a point is four
/// lookups, not a loop of one unpredictable branch per bit of the index (which cost more
/// than the rest of a path's sampling: a scrambled index has all 32 bits in play), and
/// comes reversed, as Owen's scrambling (owen_scramble) takes it.
inline constexpr std::array<std::array<std::uint32_t, 256>, 4> sobol1_reversed_bytes = [] {
    std::array<std::array<std::uint32_t, 256>, 4> t{};
    for (std::size_t b = 0; b < 4; ++b)
        for (std::size_t v = 0; v < 256; ++v) {
            std::uint32_t x = 0;
            for (std::size_t k = 0; k < 8; ++k)
                if (((v >> k) & 1u) != 0) x ^= sobol_matrices[1][8 * b + k];
            t[b][v] = reverse_bits(x);
        }
    return t;
}();

/// Point `index` of Sobol's dimension 1, its bits reversed (sobol1_reversed_bytes).
[[nodiscard]] constexpr std::uint32_t sobol1_reversed(std::uint32_t index) noexcept
{
    return sobol1_reversed_bytes[0][index & 0xffu] ^ sobol1_reversed_bytes[1][(index >> 8) & 0xffu] ^ sobol1_reversed_bytes[2][(index >> 16) & 0xffu] ^
           sobol1_reversed_bytes[3][index >> 24];
}

/// Point `index` of Sobol's sequence in dimension d (below sobol_dimensions), as a
/// 32-bit fraction: the index's bits reversed in dimension 0, four lookups in dimension 1
/// (sobol1_reversed), the generator matrix's columns otherwise.
[[nodiscard]] constexpr std::uint32_t sobol(std::uint32_t index, int d) noexcept
{
    if (d == 0) return reverse_bits(index);
    if (d == 1) return reverse_bits(sobol1_reversed(index));
    std::uint32_t x = 0;
    for (int k = 0; index != 0; ++k, index >>= 1)
        if ((index & 1u) != 0) x ^= sobol_matrices[std::size_t(d)][std::size_t(k)];
    return x;
}

/// Laine and Karras's hash with Burley's constants: a bijection of 32-bit words whose
/// output bit k depends only on input bits 0 to k and the seed.
[[nodiscard]] constexpr std::uint32_t laine_karras(std::uint32_t x, std::uint32_t seed) noexcept
{
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

/// Owen's nested uniform scrambling of a 32-bit fraction, the permutations drawn from
/// `seed`: each bit flipped or not by a hash of the bits above it. Scrambling the index
/// of a sequence the same way shuffles it so that every aligned block of 2^m indices is
/// mapped onto an aligned block of 2^m (Burley's padding, which keeps each prefix's
/// stratification).
[[nodiscard]] constexpr std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) noexcept
{
    return reverse_bits(laine_karras(reverse_bits(x), seed));
}

/// A 32-bit seed from a 64-bit key and a salt (a strong 64-bit mixer, so that nearby
/// keys give unrelated seeds).
[[nodiscard]] constexpr std::uint32_t seed_of(std::uint64_t key, std::uint64_t salt) noexcept
{
    std::uint64_t z = key + 0x9e3779b97f4a7c15ULL * (salt + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return std::uint32_t((z ^ (z >> 31)) >> 32);
}

/// A 32-bit fraction as a T in [0, 1): its top bits that T holds exactly, so that it is
/// never rounded up to 1.
template <Scalar T>
[[nodiscard]] constexpr T to_unit(std::uint32_t x) noexcept
{
    constexpr int bits = std::numeric_limits<T>::digits < 32 ? std::numeric_limits<T>::digits : 32;
    return T(x >> (32 - bits)) * (T(1) / T(std::uint64_t(1) << bits));
}

/// The first 64 primes: Halton's bases, one a dimension.
inline constexpr std::array<std::uint32_t, 64> primes = {2,   3,   5,   7,   11,  13,  17,  19,  23,  29,  31,  37,  41,  43,  47,  53,
                                                          59,  61,  67,  71,  73,  79,  83,  89,  97,  101, 103, 107, 109, 113, 127, 131,
                                                          137, 139, 149, 151, 157, 163, 167, 173, 179, 181, 191, 193, 197, 199, 211, 223,
                                                          227, 229, 233, 239, 241, 251, 257, 263, 269, 271, 277, 281, 283, 293, 307, 311};

/// Element i of a pseudo-random permutation of [0, n) drawn by `key` (Kensler 2013,
/// "Correlated Multi-Jittered Sampling"): a bijective hash of the bits below n's next
/// power of two, applied again while the result lies at or past n (cycle walking: fewer
/// than two rounds on average), then a rotation by the key.
[[nodiscard]] constexpr std::uint32_t permutation_element(std::uint32_t i, std::uint32_t n, std::uint32_t key) noexcept
{
    std::uint32_t mask = n - 1;
    mask |= mask >> 1;
    mask |= mask >> 2;
    mask |= mask >> 4;
    mask |= mask >> 8;
    mask |= mask >> 16;
    do { // each step a bijection of [0, mask]: xor with a constant, multiplication by an odd number, xor with the bits above
        i ^= key;
        i *= 0xe170893du;
        i ^= key >> 16;
        i ^= (i & mask) >> 4;
        i ^= key >> 8;
        i *= 0x0929eb3fu;
        i ^= key >> 23;
        i ^= (i & mask) >> 1;
        i *= 1u | key >> 27;
        i *= 0x6935fa69u;
        i ^= (i & mask) >> 11;
        i *= 0x74dcb303u;
        i ^= (i & mask) >> 2;
        i *= 0x9e501cc3u;
        i ^= (i & mask) >> 2;
        i *= 0xc860a3dfu;
        i &= mask;
        i ^= i >> 5;
    } while (i >= n);
    return (i + key) % n;
}

/// The radical inverse of `index` in base b (2 to 2^16), Owen-scrambled, as a 32-bit
/// fraction: digit k of the point (weight b^-(k+1)) is the index's digit under a
/// permutation of [0, b) drawn (permutation_element) from a hash of the seed, k and the
/// digits below it (the point's digits above it), so that each point is uniform and each
/// aligned block of b^m indices puts one point in each interval of b^-m, at a place within
/// it of its own. The permutations must be far from linear: under shifts or affine maps
/// of the digits, the first points of two large bases (i / 61, i / 67, ...) stay on
/// lines, and a path tracer's later bounces, which read them, came out noisier than
/// under independent numbers. Every digit down to 32 bits is scrambled, the index's zeros
/// past its last digit too: another index that shares its digits so far reads the same
/// permutations. So a point costs a division, a hash and a permutation for each of about
/// 32 / log2(b) digits: 21 in base 3, 4 in base 311. Base 2 is Owen's scrambling by Laine
/// and Karras's hash (owen_scramble of the reversed index), all 32 digits in one. Out of
/// line: a loop of that cost gains nothing inlined into every estimator that could draw it.
[[nodiscard, gnu::noinline]] constexpr std::uint32_t scrambled_radical_inverse(std::uint32_t index, std::uint32_t b, std::uint32_t seed) noexcept
{
    if (b == 2) return owen_scramble(reverse_bits(index), seed);
    const double inverse_base = 1.0 / double(b);
    double value = 0, weight = inverse_base;
    std::uint64_t below = 0; // the index's digits so far, as a number in base b (below b^k < 2^41)
    for (std::uint64_t k = 0; weight >= 0x1p-33; ++k) {
        const std::uint32_t digit = index % b;
        index /= b;
        value += double(permutation_element(digit, b, seed_of(k << 48 ^ below, seed))) * weight;
        below = below * b + digit;
        weight *= inverse_base;
    }
    const double fraction = value * 0x1p32;
    return fraction < 0x1p32 ? std::uint32_t(fraction) : 0xffffffffu;
}

/// The radical inverse of `index` in base `primes[d]`: its base-b digits mirrored about
/// the point, in double (the digits of a 64-bit index fill its 53 bits).
[[nodiscard]] constexpr double radical_inverse(std::uint64_t index, int d) noexcept
{
    const std::uint64_t b = primes[std::size_t(d)];
    const double inverse_base = 1.0 / double(b);
    double scale = inverse_base, value = 0;
    for (; index != 0; index /= b) {
        value += double(index % b) * scale;
        scale *= inverse_base;
    }
    return value < 1.0 ? value : 0x1.fffffffffffffp-1;
}

} // namespace prism::sequences
