// SPDX-License-Identifier: MIT
#include <prism/core/int128.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>

using namespace prism;
using detail::WordsInt128;

namespace {

constexpr std::uint64_t all_ones = ~std::uint64_t(0);
constexpr std::uint64_t top_bit = std::uint64_t(1) << 63;

} // namespace

TEST_CASE("WordsInt128 negates, adds and refuses to overflow as two's-complement arithmetic does")
{
    static_assert(WordsInt128::from_int64(-1) == WordsInt128::from_words(all_ones, all_ones));
    static_assert(-WordsInt128::from_int64(5) == WordsInt128::from_int64(-5));
    static_assert(-WordsInt128::from_words(0, 1) == WordsInt128::from_words(0, all_ones)); // -2^64
    static_assert(-WordsInt128{} == WordsInt128{});
    const auto lowest = WordsInt128::from_words(0, top_bit), highest = WordsInt128::from_words(all_ones, all_ones >> 1);
    CHECK(-lowest == lowest); // wraps, as the lowest two's-complement value does
    CHECK(lowest.negative());
    CHECK(!highest.negative());

    auto x = WordsInt128::from_words(all_ones, 0); // 2^64 - 1, then a carry into the high word
    REQUIRE(x.add(WordsInt128::from_int64(1)));
    CHECK(x == WordsInt128::from_words(0, 1));
    REQUIRE(x.add(WordsInt128::from_int64(-1))); // and a borrow back
    CHECK(x == WordsInt128::from_words(all_ones, 0));

    auto h = highest;
    CHECK(!h.add(WordsInt128::from_int64(1)));
    CHECK(h == highest); // unchanged
    auto l = lowest;
    CHECK(!l.add(WordsInt128::from_int64(-1)));
    CHECK(l == lowest);
    CHECK(!l.add(lowest));
    REQUIRE(h.add(lowest));
    CHECK(h == WordsInt128::from_int64(-1));
}

TEST_CASE("WordsInt128 rounds to the nearest double, ties to even, with the bits below the high word counted")
{
    const auto value = [](std::uint64_t low, std::uint64_t high) { return WordsInt128::from_words(low, high).to_double(); };
    const std::uint64_t p53 = std::uint64_t(1) << 53;
    CHECK(value(0, 0) == 0.0);
    CHECK(value(p53 + 1, 0) == 0x1p53);          // a tie: to the even 2^53
    CHECK(value(p53 + 3, 0) == 0x1p53 + 4);      // a tie: to the even 2^53 + 4
    CHECK(value(all_ones, 0) == 0x1p64);             // rounds up into the next power
    CHECK(value(1, 1) == 0x1p64);                // 2^64 + 1
    // 2^117 + 2^64 is a tie between 2^117 and 2^117 + 2^65 (both have 53 bits): to even.
    CHECK(value(0, (std::uint64_t(1) << 53) + 1) == 0x1p117);
    // One more in the low word breaks the tie upward.
    CHECK(value(1, (std::uint64_t(1) << 53) + 1) == 0x1p117 + 0x1p65);
    CHECK(value(0, top_bit) == -0x1p127);            // the lowest value
    CHECK(value(all_ones, all_ones >> 1) == 0x1p127);    // the highest rounds up to 2^127
    CHECK(WordsInt128::from_int64(-3).to_double() == -3.0);
    CHECK(WordsInt128::from_int64(std::int64_t(-(p53 + 1))).to_double() == -0x1p53);
}

#if defined(__SIZEOF_INT128__)
TEST_CASE("WordsInt128 gives the compiler's __int128 bits: negation, sums, overflow and rounding to double")
{
    // Random operands with random leading zeros or ones, so every magnitude is met.
    std::mt19937_64 random(5);
    std::uniform_int_distribution<int> shift(0, 127);
    const auto operand = [&] {
        std::uint64_t low = random(), high = random();
        const int s = shift(random);
        if (s >= 64) {
            low = s == 127 ? 0 : low >> (s - 64);
            high = 0;
        } else if (s > 0) {
            low = (low >> s) | (high << (64 - s));
            high >>= s;
        }
        if (random() & 1) {
            low = ~low;
            high = ~high;
        }
        return std::pair{low, high};
    };
    for (int i = 0; i < 1000000; ++i) {
        const auto [a_low, a_high] = operand();
        const auto [b_low, b_high] = operand();
        auto words = WordsInt128::from_words(a_low, a_high);
        auto native = detail::NativeInt128::from_words(a_low, a_high);
        const auto negated = -words;
        const auto native_negated = -native;
        REQUIRE(negated.low() == native_negated.low());
        REQUIRE(negated.high() == native_negated.high());
        REQUIRE(words.negative() == native.negative());
        REQUIRE(words.to_double() == native.to_double());
        const bool words_added = words.add(WordsInt128::from_words(b_low, b_high));
        const bool native_added = native.add(detail::NativeInt128::from_words(b_low, b_high));
        REQUIRE(words_added == native_added);
        REQUIRE(words.low() == native.low());
        REQUIRE(words.high() == native.high());
    }
}
#endif
