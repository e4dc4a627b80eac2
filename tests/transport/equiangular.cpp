// SPDX-License-Identifier: MIT
#include <prism/transport/equiangular.hpp>
#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>

#include <doctest/doctest.h>

#include <cmath>

using namespace prism;

TEST_CASE("equiangular sampling: the density integrates to 1 over the stretch, and the samples follow it (a chi-square over 32 bins)")
{
    const Ray<double> ray{{-2, 0.3, 0}, {1, 0, 0}};
    const Vec3<double> light{0.5, 1.2, -0.4};
    const double t0 = 0.7, t1 = 5.5;
    const Equiangular<double> rule(ray, t0, t1, light);
    // The density by the midpoint rule.
    double integral = 0;
    const int steps = 200000;
    for (int i = 0; i < steps; ++i) integral += rule.pdf(t0 + (i + 0.5) * (t1 - t0) / steps) * (t1 - t0) / steps;
    CHECK(integral == doctest::Approx(1.0).epsilon(1e-6));
    // The samples against it, 32 bins.
    constexpr int bins = 32, n = 400000;
    double counts[bins] = {};
    Random rng(5, 1);
    for (int i = 0; i < n; ++i) {
        const double t = rule.sample(rng.uniform<double>());
        REQUIRE(t >= t0 - 1e-12);
        REQUIRE(t <= t1 + 1e-12);
        counts[std::min(bins - 1, int((t - t0) / (t1 - t0) * bins))] += 1;
    }
    double chi2 = 0;
    for (int b = 0; b < bins; ++b) {
        double expected = 0;
        for (int j = 0; j < 100; ++j) expected += rule.pdf(t0 + (b + (j + 0.5) / 100) * (t1 - t0) / bins) * (t1 - t0) / bins / 100;
        expected *= n;
        chi2 += (counts[b] - expected) * (counts[b] - expected) / expected;
    }
    // 31 degrees of freedom: the 99.9th percentile is 61.1.
    MESSAGE("chi-square ", chi2);
    CHECK(chi2 < 61.1);
}

TEST_CASE("within_cone holds every point of a stretch inside a spot light's cone, and little else: against a brute-force march of a thousand random rays at 2001 points each")
{
    // Random cones and rays, the stretch marched at 2000 points: every point inside the cone
    // lies in the interval, and the interval's ends are within a step of an inside point
    // (or at a crossing of the apex's plane, where the two nappes meet).
    Random rng(9, 4);
    int missed = 0, loose = 0, rays = 0, crossing = 0;
    for (int r = 0; r < 1000; ++r) {
        const Vec3<double> apex{rng.uniform<double>() * 4 - 2, rng.uniform<double>() * 4 - 2, rng.uniform<double>() * 4 - 2};
        const Vec3<double> axis = uniform_sphere<double>(rng);
        const double half_angle = 0.02 + 1.4 * rng.uniform<double>(); // radians, up to 80 degrees
        const Ray<double> ray{{rng.uniform<double>() * 6 - 3, rng.uniform<double>() * 6 - 3, rng.uniform<double>() * 6 - 3}, uniform_sphere<double>(rng)};
        // Aim about half the rays near the apex, where a narrow cone is found at all.
        const Ray<double> aimed = r % 2 ? ray : Ray<double>{ray.origin, normalize(apex + axis * (1 + 2 * rng.uniform<double>()) - ray.origin)};
        const double t0 = rng.uniform<double>(), t1 = t0 + 8 * rng.uniform<double>() + 0.1;
        const auto span = within_cone(aimed, t0, t1, apex, axis, std::cos(half_angle));
        const int steps = 2000;
        double first = t1, last = t0;
        for (int i = 0; i <= steps; ++i) {
            const double t = i == steps ? t1 : t0 + (t1 - t0) * i / steps; // (the last exactly t1)
            const Vec3<double> p = aimed.at(t) - apex;
            const bool in = dot(p, axis) >= length(p) * std::cos(half_angle);
            if (!in) continue;
            first = std::min(first, t);
            last = std::max(last, t);
            if (!span || !span->contains(t)) ++missed;
        }
        ++rays;
        if (span && first <= last) {
            const double step = (t1 - t0) / steps;
            if (span->min < first - 2 * step || span->max > last + 2 * step) ++loose;
        }
        if (span && first > last) ++crossing; // an interval where the march found no inside point: a sliver
    }
    MESSAGE(rays, " rays: ", missed, " inside points outside the interval, ", loose, " intervals wider than the inside points, ", crossing,
            " intervals with no marched point inside");
    CHECK(missed == 0);
    CHECK(loose == 0);
    CHECK(crossing <= rays / 100);
    // A cone of 90 degrees or more keeps the whole stretch; a stretch of no length nothing.
    const Ray<double> ray{{0, 0, 0}, {1, 0, 0}};
    CHECK(within_cone(ray, 0.0, 2.0, {0, 1, 0}, {0, 1, 0}, 0.0)->max == 2.0);
    CHECK(!within_cone(ray, 1.0, 1.0, {0, 1, 0}, {0, -1, 0}, 0.5));
    // A ray below a downward cone, crossing it: [-h tan, h tan] about the axis.
    const auto below = within_cone(Ray<double>{{-3, 0, 0}, {1, 0, 0}}, 0.0, 6.0, {0, 2, 0}, {0, -1, 0}, std::cos(0.3));
    REQUIRE(below);
    CHECK(below->min == doctest::Approx(3 - 2 * std::tan(0.3)).epsilon(1e-4));
    CHECK(below->max == doctest::Approx(3 + 2 * std::tan(0.3)).epsilon(1e-4));
    CHECK(!within_cone(Ray<double>{{-3, 3, 0}, {1, 0, 0}}, 0.0, 6.0, {0, 2, 0}, {0, -1, 0}, std::cos(0.3))); // above the apex
}
