// SPDX-License-Identifier: MIT
#include <prism/photon/photon.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>

using prism::Rgb;
using prism::Vec3;
using prism::Random;
using prism::Photon;
using prism::uniform_sphere;

TEST_CASE("the compact photon record: 28 bytes, power to 2^-16 relative, direction and normal to 1e-4 rad")
{
    Random rng(9u, 9u);
    double worst_power = 0, worst_angle = 0, sum_in = 0, sum_out = 0;
    for (int i = 0; i < 20000; ++i) {
        const float scale = std::ldexp(1.0f, int(rng.next_u32() % 60) - 40); // 2^-40 ... 2^19
        const Rgb<float> power{scale * rng.uniform<float>(), scale * rng.uniform<float>(), scale * rng.uniform<float>()};
        const Vec3<float> from = uniform_sphere<float>(rng), normal = uniform_sphere<float>(rng);
        const Photon p({1, 2, 3}, power, from, normal, Photon::caustic);
        const Rgb<float> back = p.power();
        const float largest = std::max({power.x, power.y, power.z});
        // Each channel is within half a step, 2^(e-17), of itself; the largest is at least 2^(e-1).
        for (int c = 0; c < 3; ++c) worst_power = std::max(worst_power, double(std::abs(back[c] - power[c]) / largest));
        sum_in += power.x / scale;
        sum_out += back.x / scale;
        const Vec3<double> a(p.toward_source()), b(from); // in double: acos of a float dot cannot resolve below 3e-4 rad
        worst_angle = std::max(worst_angle, std::atan2(prism::length(prism::cross(a, b)), prism::dot(a, b)));
        const Vec3<double> m(p.normal()), o(normal);
        worst_angle = std::max(worst_angle, std::atan2(prism::length(prism::cross(m, o)), prism::dot(m, o)));
        REQUIRE(p.flags == Photon::caustic);
        REQUIRE(p.position == Vec3<float>{1, 2, 3});
    }
    CHECK(sizeof(Photon) == 28);
    CHECK(worst_power <= 1.001 / 65536); // and float rounding in the scaling
    CHECK(std::abs(sum_out / sum_in - 1) < 1e-6); // rounding to nearest: no bias in sums
    CHECK(worst_angle < 1e-4);                    // 16-bit octahedral: about 2 / 65535 of a radian at worst
    CHECK(Photon({0, 0, 0}, Rgb<float>(0), {0, 0, 1}, {0, 0, 1}, Photon::shadow).power() == Rgb<float>(0.0f));
    CHECK(Photon({0, 0, 0}, Rgb<float>(1), {0, 0, -1}, {0, 0, -1}, 0).toward_source().z == doctest::Approx(-1.0f)); // the octahedron's folded half
    CHECK(Photon({0, 0, 0}, Rgb<float>(1), {0, 0, -1}, {0, 0, -1}, 0).normal().z == doctest::Approx(-1.0f));
}

TEST_CASE("photons of one power sum to it: a constant power rounds with an error far below a furnace's 0.5 %")
{
    // A point light's million direct photons all carry 4 pi^2 / 10^6 = 3.948e-5. Rounded
    // to 8 bits of mantissa (Ward's RGBE) every one gained 0.25 %, and so did the furnace;
    // at 16 bits the worst for any power is 2^-16 (and the extremes of float still encode).
    for (const float power : {3.9478418e-5f, 1.0f / 3.0f, 0.7f, 1e-30f, 1e30f}) {
        const Photon p({0, 0, 0}, Rgb<float>(power), {0, 1, 0}, {0, 1, 0}, 0);
        CAPTURE(power);
        CHECK(std::abs(p.power().x / power - 1) < 1.6e-5);
    }
    CHECK(Photon({0, 0, 0}, Rgb<float>(1e-45f), {0, 1, 0}, {0, 1, 0}, 0).power().x < 1e-38f); // a denormal: nothing, not garbage
    CHECK(Photon({0, 0, 0}, Rgb<float>(std::nanf("")), {0, 1, 0}, {0, 1, 0}, 0).power() == Rgb<float>(0.0f));
}

TEST_CASE("a photon records the segments of its path from the light beside its flags, up to 15")
{
    for (const int segments : {0, 1, 7, 15, 16, 1000}) {
        CAPTURE(segments);
        const Photon p({0, 0, 0}, Rgb<float>(1), {0, 0, 1}, {0, 0, 1}, std::uint8_t(Photon::caustic | Photon::volume | Photon::segments_bits(segments)));
        CHECK(p.segments() == std::min(segments, Photon::max_segments));
        CHECK((p.flags & 15) == (Photon::caustic | Photon::volume)); // the flags untouched
    }
    CHECK(Photon::segments_bits(-3) == 0);
}
