// SPDX-License-Identifier: MIT
#include <prism/photon/photon.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>

using prism::Rgb;
using prism::Vec3;
using prism::Pcg32;
using prism::Photon;
using prism::uniform_sphere;

TEST_CASE("the compact photon record: 24 bytes, power to 1/256 relative, direction to 1e-4 rad")
{
    Pcg32 rng(9u, 9u);
    double worst_power = 0, worst_angle = 0, sum_in = 0, sum_out = 0;
    for (int i = 0; i < 20000; ++i) {
        const float scale = std::ldexp(1.0f, int(rng.next_u32() % 60) - 40); // 2^-40 ... 2^19
        const Rgb<float> power{scale * rng.uniform<float>(), scale * rng.uniform<float>(), scale * rng.uniform<float>()};
        const Vec3<float> from = uniform_sphere<float>(rng);
        const Photon p({1, 2, 3}, power, from, Photon::caustic);
        const Rgb<float> back = p.power();
        const float largest = std::max({power.x, power.y, power.z});
        // Each channel is within half a step, 2^(e-9), of itself; the largest is at least 2^(e-1).
        for (int c = 0; c < 3; ++c) worst_power = std::max(worst_power, double(std::abs(back[c] - power[c]) / largest));
        sum_in += power.x / scale;
        sum_out += back.x / scale;
        const Vec3<double> a(p.toward_source()), b(from); // in double: acos of a float dot cannot resolve below 3e-4 rad
        worst_angle = std::max(worst_angle, std::atan2(prism::length(prism::cross(a, b)), prism::dot(a, b)));
        REQUIRE(p.flags == Photon::caustic);
        REQUIRE(p.position == Vec3<float>{1, 2, 3});
    }
    CHECK(sizeof(Photon) == 24);
    CHECK(worst_power <= 1.001 / 256); // and float rounding in the scaling
    CHECK(std::abs(sum_out / sum_in - 1) < 1e-4); // rounding to nearest: no bias in sums
    CHECK(worst_angle < 1e-4);                    // 16-bit octahedral: about 2 / 65535 of a radian at worst
    CHECK(Photon({0, 0, 0}, Rgb<float>(0), {0, 0, 1}, Photon::shadow).power() == Rgb<float>(0.0f));
    CHECK(Photon({0, 0, 0}, Rgb<float>(1), {0, 0, -1}, 0).toward_source().z == doctest::Approx(-1.0f)); // the octahedron's folded half
}
