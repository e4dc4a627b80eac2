// SPDX-License-Identifier: MIT
// A 128-bit signed integer, two's complement, with only what exact sums need: made from
// and read as two 64-bit words, negated, added with overflow detected (or as the lower
// half of a wider sum, with its carry), and rounded once to double. Two implementations with the same bits: the compiler's __int128 where it
// has one (GCC and Clang on 64-bit targets), and two 64-bit words anywhere (MSVC has no
// 128-bit integer). Int128 is the first, or the second where there is no __int128 or
// PRISM_PORTABLE_INT128 is defined; both are compiled and compared in every test build.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace prism {
namespace detail {

/// The portable 128-bit integer: two 64-bit words.
class WordsInt128 {
public:
    constexpr WordsInt128() noexcept = default;

    /// The integer whose two's-complement bits are high 2^64 + low.
    [[nodiscard]] static constexpr WordsInt128 from_words(std::uint64_t low, std::uint64_t high) noexcept
    {
        WordsInt128 x;
        x.low_ = low;
        x.high_ = high;
        return x;
    }
    [[nodiscard]] static constexpr WordsInt128 from_int64(std::int64_t v) noexcept
    {
        return from_words(std::uint64_t(v), v < 0 ? ~std::uint64_t(0) : 0);
    }
    [[nodiscard]] constexpr std::uint64_t low() const noexcept { return low_; }
    [[nodiscard]] constexpr std::uint64_t high() const noexcept { return high_; }
    [[nodiscard]] constexpr bool negative() const noexcept { return (high_ >> 63) != 0; }

    /// -x, modulo 2^128 (the lowest value is its own negation).
    [[nodiscard]] constexpr WordsInt128 operator-() const noexcept
    {
        return from_words(~low_ + 1, ~high_ + std::uint64_t(low_ == 0));
    }

    /// Add `other`; false (and this unchanged) when the sum is not a 128-bit integer.
    [[nodiscard]] constexpr bool add(const WordsInt128& other) noexcept
    {
        const std::uint64_t low = low_ + other.low_;
        const std::uint64_t high = high_ + other.high_ + std::uint64_t(low < low_);
        // Overflow: both operands have a sign the sum does not.
        if ((((high_ ^ high) & (other.high_ ^ high)) >> 63) != 0) return false;
        low_ = low;
        high_ = high;
        return true;
    }

    /// Add `other`'s bits as unsigned 128-bit numbers, modulo 2^128; true when the sum
    /// carried out of bit 127 (the lower half of a wider sum).
    [[nodiscard]] constexpr bool add_with_carry(const WordsInt128& other) noexcept
    {
        const std::uint64_t low = low_ + other.low_;
        const std::uint64_t partial = high_ + other.high_;
        const std::uint64_t high = partial + std::uint64_t(low < low_);
        const bool carry = partial < high_ || high < partial;
        low_ = low;
        high_ = high;
        return carry;
    }

    /// The nearest double (ties to even), as a conversion of __int128 gives it.
    [[nodiscard]] double to_double() const noexcept
    {
        const WordsInt128 magnitude = negative() ? -*this : *this; // the lowest: 2^127, read unsigned
        std::uint64_t high = magnitude.high_, low = magnitude.low_;
        if (high == 0 && low == 0) return 0.0;
        // Shift the leading one to bit 127; its top 64 bits are then `high`.
        const int zeros = high != 0 ? std::countl_zero(high) : 64 + std::countl_zero(low);
        if (zeros >= 64) {
            high = low << (zeros - 64);
            low = 0;
        } else if (zeros > 0) {
            high = (high << zeros) | (low >> (64 - zeros));
            low <<= zeros;
        }
        // 53 bits kept; the 11 below and `low` decide the rounding.
        std::uint64_t mantissa = high >> 11;
        const std::uint64_t rest = high & 0x7ff, half = 0x400;
        if (rest > half || (rest == half && (low != 0 || (mantissa & 1) != 0))) ++mantissa; // 2^53 at most: exact
        const double value = std::ldexp(double(mantissa), 75 - zeros);
        return negative() ? -value : value;
    }

    friend constexpr bool operator==(const WordsInt128&, const WordsInt128&) = default;

private:
    std::uint64_t low_ = 0, high_ = 0;
};

#if defined(__SIZEOF_INT128__)
/// The compiler's 128-bit integer, behind WordsInt128's interface.
class NativeInt128 {
public:
    // -Wpedantic names __int128 an extension.
    __extension__ using Bits = __int128;
    __extension__ using UnsignedBits = unsigned __int128;

    constexpr NativeInt128() noexcept = default;

    [[nodiscard]] static constexpr NativeInt128 from_words(std::uint64_t low, std::uint64_t high) noexcept
    {
        NativeInt128 x;
        x.bits_ = Bits((UnsignedBits(high) << 64) | low);
        return x;
    }
    [[nodiscard]] static constexpr NativeInt128 from_int64(std::int64_t v) noexcept
    {
        NativeInt128 x;
        x.bits_ = v;
        return x;
    }
    [[nodiscard]] constexpr std::uint64_t low() const noexcept { return std::uint64_t(UnsignedBits(bits_)); }
    [[nodiscard]] constexpr std::uint64_t high() const noexcept { return std::uint64_t(UnsignedBits(bits_) >> 64); }
    [[nodiscard]] constexpr bool negative() const noexcept { return bits_ < 0; }

    [[nodiscard]] constexpr NativeInt128 operator-() const noexcept
    {
        NativeInt128 x;
        x.bits_ = Bits(UnsignedBits(0) - UnsignedBits(bits_)); // wraps, as WordsInt128's does
        return x;
    }

    [[nodiscard]] constexpr bool add(const NativeInt128& other) noexcept
    {
        Bits sum{};
        if (__builtin_add_overflow(bits_, other.bits_, &sum)) return false;
        bits_ = sum;
        return true;
    }

    [[nodiscard]] constexpr bool add_with_carry(const NativeInt128& other) noexcept
    {
        const auto a = UnsignedBits(bits_), sum = a + UnsignedBits(other.bits_);
        bits_ = Bits(sum); // modulo 2^128 (C++20)
        return sum < a;
    }

    [[nodiscard]] double to_double() const noexcept { return double(bits_); }

    friend constexpr bool operator==(const NativeInt128&, const NativeInt128&) = default;

private:
    Bits bits_ = 0;
};
#endif

} // namespace detail

#if defined(__SIZEOF_INT128__) && !defined(PRISM_PORTABLE_INT128)
using Int128 = detail::NativeInt128;
#else
using Int128 = detail::WordsInt128;
#endif

} // namespace prism
