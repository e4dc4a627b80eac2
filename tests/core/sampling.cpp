// SPDX-License-Identifier: MIT
#include <prism/core/sampling.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>

using prism::Rgb;
using prism::Vec3;
using prism::Random;
using prism::uniform_sphere;

TEST_CASE("emission directions are uniform on the sphere (errata 4)")
{
    prism::Random rng(1u, 1u);
    constexpr int n = 400000;
    Vec3<double> mean(0.0);
    std::array<int, 8> octants{};
    for (int i = 0; i < n; ++i) {
        const Vec3<double> d = prism::uniform_sphere<double>(rng);
        REQUIRE(std::abs(prism::length(d) - 1) < 1e-12);
        mean += d;
        ++octants[static_cast<std::size_t>((d.x > 0) + 2 * (d.y > 0) + 4 * (d.z > 0))];
    }
    mean /= double(n);
    // Each coordinate of a uniform direction has variance 1/3: the mean's standard error is sqrt(1/3n).
    const double se = std::sqrt(1.0 / 3 / n);
    CHECK(std::abs(mean.x) < 4 * se);
    CHECK(std::abs(mean.y) < 4 * se);
    CHECK(std::abs(mean.z) < 4 * se);
    // Octant counts are binomial(n, 1/8): within 4 standard deviations of n/8.
    const double sd = std::sqrt(n * (1.0 / 8) * (7.0 / 8));
    for (int count : octants) CHECK(std::abs(count - n / 8.0) < 4 * sd);
}

TEST_CASE("diffuse bounces are cosine-distributed: E[cos] = 2/3, never below the surface")
{
    prism::Random rng(2u, 2u);
    const Vec3<double> n = prism::normalize(Vec3<double>{0.3, -0.5, 0.8});
    constexpr int count = 200000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < count; ++i) {
        const Vec3<double> d = prism::cosine_hemisphere(n, rng);
        const double c = prism::dot(d, n);
        REQUIRE(c >= 0);
        REQUIRE(std::abs(prism::length(d) - 1) < 1e-9);
        sum += c;
        sum2 += c * c;
    }
    // For p(w) = cos / pi: E[cos] = 2/3, E[cos^2] = 1/2, so the variance is 1/18.
    CHECK(std::abs(sum / count - 2.0 / 3) < 4 * std::sqrt(1.0 / 18 / count));
    CHECK(std::abs(sum2 / count - 0.5) < 0.005);
}

TEST_CASE("Russian roulette keeps the expected power, channel by channel (errata 7)")
{
    prism::Random rng(3u, 3u);
    const Rgb<double> reflectance{0.8, 0.4, 0.1};
    const Rgb<double> start{1.0, 2.0, 3.0};
    constexpr int n = 400000;
    Rgb<double> total(0.0);
    int survived = 0;
    for (int i = 0; i < n; ++i) {
        Rgb<double> power = start;
        if (prism::russian_roulette(power, reflectance, rng)) {
            total += power;
            ++survived;
        }
    }
    // Survival with p = 0.8; a survivor carries power * reflectance / 0.8.
    CHECK(std::abs(double(survived) / n - 0.8) < 4 * std::sqrt(0.8 * 0.2 / n));
    const Rgb<double> mean = total / double(n);
    for (int c = 0; c < 3; ++c) {
        const double expected = start[c] * reflectance[c];
        const double sd = start[c] * reflectance[c] / 0.8 * std::sqrt(0.8 * 0.2 / n); // Bernoulli times the survivor's power
        CHECK(std::abs(mean[c] - expected) < 4 * sd);
    }
    // Nothing to reflect: always absorbed.
    Rgb<double> dark{1.0, 1.0, 1.0};
    CHECK_FALSE(prism::russian_roulette(dark, Rgb<double>(0.0), rng));
}

TEST_CASE("Russian roulette on a path's throughput keeps its expectation, and leaves a bright path alone")
{
    prism::Random rng(6u, 6u);
    // Survives with p = sqrt(0.3), then carries start / p.
    const Rgb<double> start{0.3, 0.12, 0.05};
    const double p = std::sqrt(0.3);
    constexpr int n = 400000;
    Rgb<double> total(0.0);
    int survived = 0;
    for (int i = 0; i < n; ++i) {
        Rgb<double> throughput = start;
        if (prism::path_roulette(throughput, rng)) {
            CHECK(prism::max_component(throughput) == doctest::Approx(0.3 / p).epsilon(1e-12));
            total += throughput;
            ++survived;
        }
    }
    CHECK(std::abs(double(survived) / n - p) < 4 * std::sqrt(p * (1 - p) / n));
    const Rgb<double> mean = total / double(n);
    for (int c = 0; c < 3; ++c) CHECK(std::abs(mean[c] - start[c]) < 4 * start[c] / p * std::sqrt(p * (1 - p) / n));
    // At or above 1 in some channel: always kept, unchanged.
    for (int i = 0; i < 1000; ++i) {
        Rgb<double> bright{1.0, 0.2, 0.0};
        CHECK(prism::path_roulette(bright, rng));
        CHECK(bright == Rgb<double>{1.0, 0.2, 0.0});
    }
    Rgb<double> dark(0.0);
    CHECK_FALSE(prism::path_roulette(dark, rng));
}

TEST_CASE("orthonormal frames, including at the poles")
{
    prism::Random rng(4u, 4u);
    for (int i = 0; i < 1000; ++i) {
        const Vec3<double> n = i == 0 ? Vec3<double>{0, 0, -1} : i == 1 ? Vec3<double>{0, 0, 1} : prism::uniform_sphere<double>(rng);
        const auto [s, t] = prism::orthonormal_frame(n);
        CHECK(std::abs(prism::dot(s, t)) < 1e-12);
        CHECK(std::abs(prism::dot(s, n)) < 1e-12);
        CHECK(std::abs(prism::length(s) - 1) < 1e-12);
        CHECK(prism::dot(prism::cross(s, t), n) == doctest::Approx(1)); // right-handed
    }
}

TEST_CASE("cones and disks: directions within the cone, uniform in cos; points within the disk, uniform in area")
{
    Random rng(8u, 8u);
    const Vec3<double> axis = prism::normalize(Vec3<double>{1, 2, -2});
    const double cos_half = 0.6;
    const int n = 200000;
    double mean_cos = 0, inner = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3<double> d = prism::uniform_cone(axis, cos_half, rng.uniform<double>(), rng.uniform<double>());
        const double c = prism::dot(d, axis);
        CHECK(c >= cos_half - 1e-12);
        mean_cos += c / n;
        const Vec3<double> p = prism::uniform_disk(Vec3<double>{1, 1, 1}, axis, 2.0, rng.uniform<double>(), rng.uniform<double>());
        CHECK(std::abs(prism::dot(p - Vec3<double>{1, 1, 1}, axis)) < 1e-12);
        inner += prism::length(p - Vec3<double>{1, 1, 1}) < 1.0 ? 1.0 / n : 0.0;
    }
    // Uniform in cos on [0.6, 1]: mean 0.8. The inner disk of half the radius: a quarter.
    CHECK(mean_cos == doctest::Approx(0.8).epsilon(2e-3));
    CHECK(inner == doctest::Approx(0.25).epsilon(0.02));
}
