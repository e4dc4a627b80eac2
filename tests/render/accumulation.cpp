// SPDX-License-Identifier: MIT
#include <prism/render/accumulation.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace prism;

TEST_CASE("ExactSum keeps every float sample from 2^-41 to 2^40 exactly, and rounds smaller ones to 2^-64")
{
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> exponent(-41, 40);
    for (int i = 0; i < 100000; ++i) {
        const float x = float(std::exp2(exponent(random)));
        REQUIRE(ExactSum::of(x).value() == double(x));
        REQUIRE(ExactSum::of(-x).value() == -double(x));
    }
    CHECK(ExactSum::of(0x1p-64).bits() == Int128::from_int64(1));
    CHECK(ExactSum::of(0x1p-66).bits() == Int128::from_int64(0));  // a quarter of the step: down
    CHECK(ExactSum::of(0x3p-66).bits() == Int128::from_int64(1));  // three quarters: up
    CHECK(ExactSum::of(0x1p-65).bits() == Int128::from_int64(1));  // a half: away from zero
    CHECK(ExactSum::of(-0x1p-65).bits() == Int128::from_int64(-1));
    CHECK(ExactSum::takes(0x1p40 - 1));
    CHECK(!ExactSum::takes(0x1p40));
    CHECK(!ExactSum::takes(std::numeric_limits<double>::quiet_NaN()));
    CHECK(!ExactSum::takes(std::numeric_limits<double>::infinity()));
}

// round(ldexp(x, 64)) as a 128-bit integer, from doubles alone: the integral double's
// two 64-bit halves (each exact), negated in two's complement when x < 0.
[[nodiscard]] static Int128 rounded_reference(double x)
{
    const double v = std::abs(std::round(std::ldexp(x, 64)));
    const double high = std::floor(std::ldexp(v, -64));
    const auto magnitude = Int128::from_words(std::uint64_t(v - std::ldexp(high, 64)), std::uint64_t(high));
    return std::signbit(x) && v != 0 ? -magnitude : magnitude;
}

TEST_CASE("ExactSum::of, done in integers, equals the library's round(ldexp(x, 64)) for doubles of every size")
{
    // The reference: the formula of() replaced (the library's calls), on doubles of
    // every exponent from denormals to the limit, both signs, with random mantissas and
    // with halves and their neighbours (the rounding's edge), and in constant evaluation.
    const auto reference = rounded_reference;
    std::mt19937_64 random(11);
    std::uniform_int_distribution<int> exponent(-1074, 39);
    std::uniform_int_distribution<std::uint64_t> mantissa(0, (std::uint64_t(1) << 53) - 1);
    for (int i = 0; i < 1000000; ++i) {
        const double x = std::ldexp(double(mantissa(random)), exponent(random) - 52);
        if (!(x < ExactSum::limit)) continue;
        REQUIRE(ExactSum::of(x).bits() == reference(x));
        REQUIRE(ExactSum::of(-x).bits() == reference(-x));
    }
    for (int k = -120; k <= 39; ++k)
        for (const double x : {std::ldexp(1.0, k), std::ldexp(3.0, k - 1), std::ldexp(5.0, k - 2)})
            for (const double y : {x, std::nextafter(x, 0.0), std::nextafter(x, 1e300), -x})
                if (std::abs(y) < ExactSum::limit) REQUIRE(ExactSum::of(y).bits() == reference(y));
    for (const double x : {0.0, -0.0, std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(), std::nextafter(ExactSum::limit, 0.0)})
        CHECK(ExactSum::of(x).bits() == reference(x));
    static_assert(ExactSum::of(0.75).bits() == Int128::from_words(std::uint64_t(3) << 62, 0) && ExactSum::of(-0x1p-65).bits() == Int128::from_int64(-1));
    // The portable words give the same sums.
    using Portable = BasicExactSum<detail::WordsInt128>;
    static_assert(Portable::of(0.75).bits() == detail::WordsInt128::from_words(std::uint64_t(3) << 62, 0));
    for (int i = 0; i < 100000; ++i) {
        const double x = std::ldexp(double(mantissa(random)), exponent(random) - 52);
        if (!(x < ExactSum::limit)) continue;
        for (const double y : {x, -x}) {
            const auto words = Portable::of(y).bits();
            REQUIRE(Int128::from_words(words.low(), words.high()) == reference(y));
            REQUIRE(Portable::of(y).value() == ExactSum::of(y).value());
        }
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

    // A pixel's samples from 1e-10 to 1e10, summed whole, in two parts, and shuffled.
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> exponent(-10, 10);
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
    const Int128 highest_but_5 = Int128::from_words(~std::uint64_t(0) - 5, ~std::uint64_t(0) >> 1); // 2^127 - 6
    ExactSum s = ExactSum::from_bits(highest_but_5);
    CHECK(!s.add(ExactSum::from_bits(Int128::from_int64(6))));
    CHECK(s.bits() == highest_but_5); // unchanged
    CHECK(s.add(ExactSum::from_bits(Int128::from_int64(5))));
    Accumulation sums(1, 1, {0, 0, 1, 1});
    const ExactSum near[3] = {ExactSum::from_bits(highest_but_5), {}, {}};
    sums.add(0, 0, near, 1);
    CHECK(!sums.overflowed());
    CHECK_NOTHROW((void)sums.image());
    sums.add(0, 0, near, 1);
    CHECK(sums.overflowed());
    CHECK_THROWS_WITH_AS((void)sums.image(), doctest::Contains("overflowed"), std::invalid_argument);
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
