// SPDX-License-Identifier: MIT
#include <prism/render/accumulation.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace prism;

TEST_CASE("ExactSum keeps every float sample from 2^-41 to the largest float exactly, and rounds smaller ones to 2^-64")
{
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> exponent(-41, 128);
    for (int i = 0; i < 100000; ++i) {
        const float x = float(std::exp2(exponent(random)));
        if (!std::isfinite(x)) continue;
        REQUIRE(ExactSum::of(x).value() == double(x));
        REQUIRE(ExactSum::of(-x).value() == -double(x));
        REQUIRE(ExactSum::of(x).narrow() == (x < 0x1p63f));
    }
    constexpr float largest = std::numeric_limits<float>::max();
    CHECK(ExactSum::of(largest).value() == double(largest));
    CHECK(ExactSum::of(-largest).value() == -double(largest));
    CHECK(ExactSum::of(0x1p-64) == ExactSum::from_bits(Int128::from_int64(1)));
    CHECK(ExactSum::of(0x1p-66) == ExactSum::from_bits(Int128::from_int64(0)));  // a quarter of the step: down
    CHECK(ExactSum::of(0x3p-66) == ExactSum::from_bits(Int128::from_int64(1)));  // three quarters: up
    CHECK(ExactSum::of(0x1p-65) == ExactSum::from_bits(Int128::from_int64(1)));  // a half: away from zero
    CHECK(ExactSum::of(-0x1p-65) == ExactSum::from_bits(Int128::from_int64(-1)));
    CHECK(ExactSum::takes(largest));
    CHECK(ExactSum::takes(-double(largest)));
    CHECK(!ExactSum::takes(std::nextafter(double(largest), 1e300))); // a double past float: its mean could be no float
    CHECK(!ExactSum::takes(std::numeric_limits<double>::quiet_NaN()));
    CHECK(!ExactSum::takes(std::numeric_limits<double>::infinity()));
}

// round(ldexp(x, 64)) as a 256-bit integer, from doubles alone: the integral double's
// four 64-bit words (each exact), negated in two's complement when x < 0.
[[nodiscard]] static ExactSum rounded_reference(double x)
{
    double v = std::abs(std::round(std::ldexp(x, 64)));
    std::uint64_t words[4] = {};
    for (int k = 3; k >= 0; --k) {
        const double word = std::floor(std::ldexp(v, -64 * k));
        words[k] = std::uint64_t(word);
        v -= std::ldexp(word, 64 * k);
    }
    if (std::signbit(x)) {
        bool carry = true; // ~words + 1
        for (std::uint64_t& w : words) {
            w = ~w + std::uint64_t(carry);
            carry = carry && w == 0;
        }
    }
    return ExactSum::from_bits(Int128::from_words(words[0], words[1]), Int128::from_words(words[2], words[3]));
}

TEST_CASE("ExactSum::of, done in integers, equals the library's round(ldexp(x, 64)) for doubles of every size")
{
    // The reference: the formula of() replaced (the library's calls), on doubles of
    // every exponent from denormals to the limit, both signs, with random mantissas and
    // with halves and their neighbours (the rounding's edge), and in constant evaluation.
    const auto reference = rounded_reference;
    std::mt19937_64 random(11);
    std::uniform_int_distribution<int> exponent(-1074, 127);
    std::uniform_int_distribution<std::uint64_t> mantissa(0, (std::uint64_t(1) << 53) - 1);
    for (int i = 0; i < 1000000; ++i) {
        const double x = std::ldexp(double(mantissa(random)), exponent(random) - 52);
        if (!(x <= ExactSum::limit)) continue;
        REQUIRE(ExactSum::of(x) == reference(x));
        REQUIRE(ExactSum::of(-x) == reference(-x));
    }
    for (int k = -120; k <= 127; ++k)
        for (const double x : {std::ldexp(1.0, k), std::ldexp(3.0, k - 1), std::ldexp(5.0, k - 2)})
            for (const double y : {x, std::nextafter(x, 0.0), std::nextafter(x, 1e300), -x})
                if (std::abs(y) <= ExactSum::limit) REQUIRE(ExactSum::of(y) == reference(y));
    for (const double x : {0.0, -0.0, std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(), ExactSum::limit, -ExactSum::limit})
        CHECK(ExactSum::of(x) == reference(x));
    static_assert(ExactSum::of(0.75) == ExactSum::from_bits(Int128::from_words(std::uint64_t(3) << 62, 0)) &&
                  ExactSum::of(-0x1p-65) == ExactSum::from_bits(Int128::from_int64(-1)));
    static_assert(ExactSum::of(0x1p100).high() == Int128::from_words(std::uint64_t(1) << 36, 0) && ExactSum::of(0x1p100).low() == Int128{});
    // The portable words give the same sums, and the same doubles of them.
    using Portable = BasicExactSum<detail::WordsInt128>;
    static_assert(Portable::of(0.75) == Portable::from_bits(detail::WordsInt128::from_words(std::uint64_t(3) << 62, 0)));
    const auto same = [](const Portable& p, const ExactSum& e) {
        return Int128::from_words(p.low().low(), p.low().high()) == e.low() && Int128::from_words(p.high().low(), p.high().high()) == e.high();
    };
    for (int i = 0; i < 100000; ++i) {
        const double x = std::ldexp(double(mantissa(random)), exponent(random) - 52);
        if (!(x <= ExactSum::limit)) continue;
        for (const double y : {x, -x}) {
            REQUIRE(same(Portable::of(y), reference(y)));
            REQUIRE(Portable::of(y).value() == ExactSum::of(y).value());
            Portable p = Portable::of(y);
            ExactSum e = ExactSum::of(y);
            REQUIRE(p.add(Portable::of(-0.75 * y)));
            REQUIRE(e.add(ExactSum::of(-0.75 * y)));
            REQUIRE(same(p, e));
        }
    }
}

TEST_CASE("ExactSum::of_float, from a float's own bits, is of() of the float as a double")
{
    // Every exponent (denormals, the normal range, up to the largest float), random
    // significands, the rounding's edges below 2^-64 (halves and their neighbours), and
    // every float of a run across 1 and across 2^52.
    std::mt19937 random(23);
    std::uniform_int_distribution<std::uint32_t> fraction(0, (1u << 23) - 1);
    int compared = 0;
    for (std::uint32_t biased = 0; biased < 255; ++biased)
        for (int i = 0; i < 2000; ++i) {
            const float x = std::bit_cast<float>(biased << 23 | (i < 2 ? std::uint32_t(i) * ((1u << 23) - 1) : fraction(random)));
            REQUIRE(ExactSum::of_float(x) == ExactSum::of(double(x)));
            ++compared;
        }
    for (int k = -100; k <= -60; ++k)
        for (const float x : {std::ldexp(1.0f, k), std::ldexp(3.0f, k - 1), std::ldexp(5.0f, k - 2)})
            for (const float y : {x, std::nextafter(x, 0.0f), std::nextafter(x, 1.0f)}) REQUIRE(ExactSum::of_float(y) == ExactSum::of(double(y)));
    for (const float start : {0.5f, 0x1p52f})
        for (float x = start, i = 0; i < 100000; ++i, x = std::nextafter(x, 1e30f)) REQUIRE(ExactSum::of_float(x) == ExactSum::of(double(x)));
    for (const float x : {0.0f, std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(), std::numeric_limits<float>::max()})
        CHECK(ExactSum::of_float(x) == ExactSum::of(double(x)));
    CHECK(compared == 255 * 2000);
    static_assert(ExactSum::of_float(0.75f) == ExactSum::of(0.75));
}

TEST_CASE("ExactSum rounds a sum past 2^63 once to the nearest double, ties to even")
{
    // 2^120's neighbours are 2^68 apart: a quarter, a half and three quarters of the
    // step above it, and a half and a hair; and the same below zero and past 2^127.
    const auto sum = [](std::initializer_list<double> xs) {
        ExactSum s;
        for (const double x : xs) REQUIRE(s.add(ExactSum::of(x)));
        return s.value();
    };
    const double big = 0x1p120;
    CHECK(sum({big, 0x1p66}) == big);                               // a quarter: down
    CHECK(sum({big, 0x1p67}) == big);                               // a half: to even (down)
    CHECK(sum({big, 0x1p67, 0x1p-60}) == big + 0x1p68);             // a half and a hair: up
    CHECK(sum({big, 0x3p66}) == big + 0x1p68);                      // three quarters: up
    CHECK(sum({big, 0x1p68, 0x1p67}) == big + 0x1p69);              // a half above an odd mantissa: to even (up)
    CHECK(sum({-big, -0x1p67, -0x1p-60}) == -(big + 0x1p68));
    CHECK(sum({-big, 0x1p66}) == -big);
    CHECK(sum({0x1p127, 0x1p127, 0x1p127, 1.0}) == 0x3p127);
    CHECK(sum({double(std::numeric_limits<float>::max()), double(std::numeric_limits<float>::max()), -double(std::numeric_limits<float>::max())}) ==
          double(std::numeric_limits<float>::max()));
    // Past 2^63, the portable words give the same double.
    using Portable = BasicExactSum<detail::WordsInt128>;
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> exponent(-20, 127);
    for (int i = 0; i < 20000; ++i) {
        ExactSum e;
        Portable p;
        for (int k = 0; k < 4; ++k) {
            const double x = (k % 2 == 0 ? 1 : -0.3) * std::exp2(exponent(random));
            REQUIRE(e.add(ExactSum::of(x)));
            REQUIRE(p.add(Portable::of(x)));
        }
        REQUIRE(e.value() == p.value());
    }
}

TEST_CASE("ExactSum adds without rounding, so any order and grouping gives the same bits")
{
    // (2^40 - 1) + 2^-40 - (2^40 - 1) is 2^-40; in double the small term is lost (it
    // needs 80 bits beside the large one), and the sum comes out 0.
    const double big = 0x1p40 - 1, small = 0x1p-40;
    ExactSum sum;
    REQUIRE(sum.add(ExactSum::of(big)));
    REQUIRE(sum.add(ExactSum::of(small)));
    REQUIRE(sum.add(ExactSum::of(-big)));
    CHECK(sum.value() == small);
    CHECK((big + small) - big != small); // what a double sum gives
    // The same past 2^63: 3e38 + 2^-40 - 3e38.
    ExactSum wide;
    REQUIRE(wide.add(ExactSum::of(3e38)));
    REQUIRE(wide.add(ExactSum::of(small)));
    CHECK(!wide.narrow());
    REQUIRE(wide.add(ExactSum::of(-3e38)));
    CHECK(wide.narrow());
    CHECK(wide.value() == small);

    // A pixel's samples from 1e-10 to 1e30, summed whole, in two parts, and shuffled.
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> exponent(-10, 30);
    std::vector<float> samples(4096);
    for (float& s : samples) s = float(std::pow(10.0, exponent(random)));
    const auto total = [](auto first, auto last) {
        ExactSum s;
        for (auto i = first; i != last; ++i) REQUIRE(s.add(ExactSum::of(*i)));
        return s;
    };
    const ExactSum whole = total(samples.begin(), samples.end());
    for (std::size_t cut : {1u, 1000u, 2047u, 4095u}) {
        ExactSum parts = total(samples.begin(), samples.begin() + std::ptrdiff_t(cut));
        REQUIRE(parts.add(total(samples.begin() + std::ptrdiff_t(cut), samples.end())));
        CHECK(parts == whole);
    }
    std::shuffle(samples.begin(), samples.end(), random);
    CHECK(total(samples.begin(), samples.end()) == whole);
    // The same samples in double, in the two orders, differ: the reason for ExactSum.
    double forward = 0, backward = 0;
    std::sort(samples.begin(), samples.end());
    for (float s : samples) forward += s;
    for (auto s = samples.rbegin(); s != samples.rend(); ++s) backward += *s;
    CHECK(forward != backward);
}

TEST_CASE("ExactSum and Accumulation refuse to overflow instead of wrapping")
{
    const Int128 highest = Int128::from_words(~std::uint64_t(0), ~std::uint64_t(0) >> 1);
    const ExactSum highest_but_5 = ExactSum::from_bits(Int128::from_int64(-6), highest); // 2^255 - 6
    ExactSum s = highest_but_5;
    CHECK(!s.add(ExactSum::from_bits(Int128::from_int64(6))));
    CHECK(s == highest_but_5); // unchanged
    CHECK(s.add(ExactSum::from_bits(Int128::from_int64(5))));
    // An Accumulation holds a little less: the largest sum less 2^128.
    Int128 lower = highest;
    REQUIRE(lower.add(Int128::from_int64(-1)));
    const ExactSum held = ExactSum::from_bits(Int128::from_int64(-6), lower);
    Accumulation sums(1, 1, {0, 0, 1, 1});
    const ExactSum near[3] = {held, {}, {}};
    sums.add(0, 0, near, 1);
    CHECK(!sums.overflowed());
    CHECK(sums.sum(0, 0, 0) == held);
    CHECK_NOTHROW((void)sums.image());
    sums.add(0, 0, near, 1);
    CHECK(sums.overflowed());
    CHECK_THROWS_WITH_AS((void)sums.image(), doctest::Contains("overflowed"), std::invalid_argument);
    Accumulation edge(1, 1, {0, 0, 1, 1});
    const ExactSum past[3] = {highest_but_5, {}, {}};
    edge.add(0, 0, past, 1);
    CHECK(edge.overflowed());
}

TEST_CASE("an Accumulation stores a sum's upper bits only once some sum passes 2^63, and then holds every finite float sample")
{
    // Regression: a sample of 2^40 or more was left out, only counted as rejected.
    constexpr float largest = std::numeric_limits<float>::max();
    Accumulation sums(3, 2, {0, 0, 3, 2});
    const auto add = [&](int x, int y, double r) {
        const ExactSum s[3] = {ExactSum::of(r), ExactSum::of(1.0), {}};
        sums.add(x, y, s, 1);
    };
    add(0, 0, 0x1p62);
    add(0, 0, 0x1p62); // 2^63 exactly: the lower half's sign bit, not a narrow sum
    CHECK(sums.wide());
    CHECK(sums.sum(0, 0, 0).value() == 0x1p63);
    Accumulation fresh(3, 2, {0, 0, 3, 2});
    const ExactSum below[3] = {ExactSum::of(0x1p62 - 1024), ExactSum::of(-0x1p62), {}};
    fresh.add(1, 1, below, 1);
    fresh.add(1, 1, below, 1);
    CHECK(!fresh.wide()); // 2^63 - 2048 and -2^63: both narrow
    CHECK(fresh.sum(1, 1, 0).value() == 0x1p63 - 2048);
    CHECK(fresh.sum(1, 1, 1).value() == -0x1p63);
    // Every pixel gets the largest float twice, and a negative wide one cancels in one.
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) {
            add(x, y, largest);
            add(x, y, largest);
        }
    add(2, 1, -double(largest));
    add(2, 1, -double(largest));
    const Film image = sums.image();
    CHECK(image.rejected() == 0);
    CHECK(image.at(1, 0).r == largest); // (largest + largest) / 2: the mean is a float
    CHECK(image.at(0, 0).r == float((2.0 * largest + 0x1p63) / 4));
    CHECK(image.at(2, 1).r == 0.0f);
    CHECK(image.at(2, 1).g == 1.0f);
    // A copy and a part added keep the upper bits.
    Accumulation copy = sums;
    CHECK(copy.wide());
    CHECK(copy.sums(1, 0) == sums.sums(1, 0));
    Accumulation whole(3, 2, {0, 0, 3, 2});
    whole += sums;
    whole += sums;
    CHECK(whole.sum(1, 0, 0).value() == 4.0 * largest);
}

TEST_CASE("an Accumulation stitches windows of one image and refuses what does not fit")
{
    // A 5 x 4 image whose pixel (x, y) is x + 10 y, made in two windows and whole.
    const auto make = [](PixelWindow w) {
        Accumulation a(5, 4, w);
        for (int y = w.y0; y < w.y1; ++y)
            for (int x = w.x0; x < w.x1; ++x) {
                const ExactSum v = ExactSum::of(3.0 * (x + 10 * y)); // three samples' sum
                const ExactSum s[3] = {v, v, ExactSum::of(0.5)};
                a.add(x, y, s, 3);
            }
        return a;
    };
    Accumulation whole(5, 4, PixelWindow::whole(5, 4));
    whole += make({0, 0, 5, 1});
    whole += make({0, 1, 5, 4});
    const Film image = whole.image();
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) {
            CHECK(image.at(x, y).x == float(x + 10 * y));
            CHECK(image.at(x, y).z == float(0.5 / 3.0));
        }
    const Film crop = make({1, 2, 3, 4}).image();
    CHECK(crop.width() == 2);
    CHECK(crop.height() == 2);
    CHECK(crop.at(0, 0) == image.at(1, 2));
    CHECK(crop.at(1, 1) == image.at(2, 3));

    Accumulation part(5, 4, {1, 1, 3, 3});
    CHECK_THROWS_WITH_AS(part += make({0, 0, 5, 1}), doctest::Contains("window [0, 5) x [0, 1) added to one of [1, 3) x [1, 3)"), std::invalid_argument);
    Accumulation other_size(6, 4, {0, 0, 5, 4});
    CHECK_THROWS_WITH_AS(other_size += make({0, 0, 5, 1}), doctest::Contains("5 x 4 image added to one of 6 x 4"), std::invalid_argument);
    Accumulation more(5, 4, {0, 0, 5, 4}, {"R", "G", "B", "depth"});
    CHECK_THROWS_WITH_AS(more += make({0, 0, 5, 1}), doctest::Contains("other channels"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Accumulation(5, 4, {0, 0, 6, 4}), doctest::Contains("window [0, 6) x [0, 4) must be a non-empty part of the 5 x 4 image"),
                         std::invalid_argument);
    CHECK_THROWS_AS(Accumulation(5, 4, {2, 0, 2, 4}), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Accumulation(5, 4, {0, 0, 5, 4}, {"G", "R", "B"}), doctest::Contains("must begin with R, G, B"), std::invalid_argument);
    // A pixel no part reached has weight 0 and reads 0.
    CHECK(part.image().at(0, 0) == Rgb<float>(0.0f));
}
