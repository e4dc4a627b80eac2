// SPDX-License-Identifier: MIT
#include <prism/core/random.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

using namespace prism;

TEST_CASE("an independent Random draws PCG's numbers, whatever bounce it is told")
{
    Random random(42u, 54u);
    Pcg32 pcg(42u, 54u);
    for (int i = 0; i < 100; ++i) {
        random.bounce(i % 5);
        CHECK(random.uniform<float>() == pcg.uniform<float>());
        CHECK(random.uniform<double>() == pcg.uniform<double>());
        const auto drawn = random.uniform2<double>();
        CHECK(drawn[0] == pcg.uniform<double>());
        CHECK(drawn[1] == pcg.uniform<double>());
        CHECK(random.next_u32() == pcg.next_u32());
    }
    // So does one built on an independent sampler: its numbers are the stream's.
    Random from_sampler(Sampler(SamplerKind::independent, 1, 2, 3), Pcg32(9u, 8u));
    Pcg32 stream(9u, 8u);
    for (int i = 0; i < 20; ++i) CHECK(from_sampler.uniform<float>() == stream.uniform<float>());
}

TEST_CASE("a camera sample's Random reads its sampler's pairs by name: the camera's, then each bounce's block, then PCG")
{
    const Sampler sampler(SamplerKind::sobol, 5, 77, 3);
    const Pcg32 pcg(1u, 2u);
    Random random(sampler, pcg);
    // The camera's pairs: the footprint, the lens.
    CHECK(random.uniform2<double>() == sampler.pair<double>(0));
    CHECK(random.uniform2<double>() == sampler.pair<double>(1));
    // Past the camera's pairs and before a bounce is named: the stream.
    Pcg32 stream = pcg;
    CHECK(random.uniform<double>() == stream.uniform<double>());
    // Bounce b starts at pair camera_pairs + b pairs_per_bounce; two single numbers are
    // the two coordinates of one pair; a pair after an odd single number is the next pair.
    for (int b : {0, 3, 1, 250}) {
        random.bounce(b);
        const std::uint32_t first = Random::camera_pairs + std::uint32_t(b) * Random::pairs_per_bounce;
        CHECK(random.uniform<double>() == sampler.pair<double>(first)[0]);
        CHECK(random.uniform<double>() == sampler.pair<double>(first)[1]);
        CHECK(random.uniform<double>() == sampler.pair<double>(first + 1)[0]);
        CHECK(random.uniform2<double>() == sampler.pair<double>(first + 2));
        // The block's last pairs, then the stream: a bounce that draws much cannot take
        // the next bounce's dimensions.
        for (std::uint32_t k = first + 3; k < first + Random::pairs_per_bounce; ++k) CHECK(random.uniform2<float>() == sampler.pair<float>(k));
        const auto past = random.uniform2<double>();
        CHECK(past[0] == stream.uniform<double>());
        CHECK(past[1] == stream.uniform<double>());
        CHECK(random.next_u32() == stream.next_u32());
    }
}

TEST_CASE("Random's numbers lie from 0 up to but not at 1, in float and double")
{
    for (std::uint32_t s = 0; s < 2000; ++s) {
        Random random(Sampler(SamplerKind::sobol, 3, s % 7, s), Pcg32(s, 1u));
        for (int b = 0; b < 3; ++b) {
            random.bounce(b);
            for (int i = 0; i < 14; ++i) {
                const float f = random.uniform<float>();
                const double d = random.uniform<double>();
                REQUIRE(f >= 0.0f);
                REQUIRE(f < 1.0f);
                REQUIRE(d >= 0.0);
                REQUIRE(d < 1.0);
            }
        }
    }
}
