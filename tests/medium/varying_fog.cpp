// SPDX-License-Identifier: MIT
#include <prism/medium/fog.hpp>
#include <prism/medium/varying_fog.hpp>

#include "../effort.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace prism;

namespace fog_test {

const Rgb<double> absorption{0.2, 0.05, 0.0}; // sigma_a at density 1
const Rgb<double> scattering{0.6, 0.45, 0.1}; // sigma_s at density 1 (a coloured fog: the channels' trackers weigh differently)

/// density = 0.2 + 0.9 x + 0.4 y + 0.3 z on a 9^3 lattice over [0, 2]^3: trilinear
/// interpolation reproduces it, so its integral along a segment inside the box is the
/// trapezoid rule's, exactly.
double linear(const Vec3<double>& p) { return 0.2 + 0.9 * p.x + 0.4 * p.y + 0.3 * p.z; }

DensityGrid<double> linear_grid()
{
    std::vector<float> values;
    for (int z = 0; z < 9; ++z)
        for (int y = 0; y < 9; ++y)
            for (int x = 0; x < 9; ++x) values.push_back(float(linear(Vec3<double>(x, y, z) / 4.0)));
    return DensityGrid<double>(9, 9, 9, {Vec3<double>(0), Vec3<double>(2)}, values);
}

/// The mean of n estimates, per channel, and its standard error.
struct Mean {
    Rgb<double> mean, error;
};

template <class F>
Mean mean_of(long n, F estimate)
{
    Rgb<double> sum{0}, squares{0};
    for (long i = 0; i < n; ++i) {
        const Rgb<double> x = estimate(i);
        sum += x;
        squares += x * x;
    }
    Mean m{sum / double(n), Rgb<double>(0)};
    for (int c = 0; c < 3; ++c) m.error[c] = std::sqrt(std::max(0.0, squares[c] / double(n) - m.mean[c] * m.mean[c]) / double(n));
    return m;
}

void check_against(const Mean& m, const Rgb<double>& expected, double tolerance)
{
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        CAPTURE(m.mean[c]);
        CAPTURE(m.error[c]);
        CAPTURE(expected[c]);
        CHECK(std::abs(m.mean[c] - expected[c]) <= tolerance * expected[c]);
        CHECK(m.error[c] < tolerance * expected[c] / 2); // enough estimates that the tolerance means something
    }
}

} // namespace fog_test

using fog_test::check_against;
using fog_test::linear;
using fog_test::linear_grid;
using fog_test::mean_of;

TEST_CASE("residual ratio tracking's transmittance is exp(-int sigma_t) on graded densities, unbiased to 0.1 %: a linear grid, ground fog, a ray leaving the box")
{
    // Optical depths 0.05 to 0.8. Residual ratio tracking's control (each cell's floor)
    // leaves it little to estimate: a million estimates pin the mean to 0.05 %.
    // (Plain ratio tracking against a tight majorant is nearly the indicator of no
    // collision, relative variance e^tau - 1: it needed twenty times as many.)
    const Rgb<double> absorption = fog_test::absorption * 0.5, scattering = fog_test::scattering * 0.5;
    const Rgb<double> sigma_t = absorption + scattering;
    const long n = test::samples(1000000); // (under a sanitizer an eighth, and 0.28 %: tests/effort.hpp)
    SUBCASE("a linear density, a segment inside the box")
    {
        const VaryingFog fog(linear_grid(), absorption, scattering);
        const Vec3<double> from{0.1, 0.3, 1.8}, to{1.2, 1.3, 0.6};
        const double length = prism::length(to - from);
        const double depth = length * (linear(from) + linear(to)) / 2;
        Random rng(1, 1);
        const Ray<double> ray{from, (to - from) / length};
        check_against(mean_of(n, [&](long) { return fog.transmittance(ray, length, rng); }),
                      {std::exp(-sigma_t.x * depth), std::exp(-sigma_t.y * depth), std::exp(-sigma_t.z * depth)}, test::resolved(1e-3));
    }
    SUBCASE("ground fog, thinning upward; each estimate seeded by its segment (the rays differ only across the fog's layers)")
    {
        const HeightFog<double> ground{.box = {{-1, 0, -1}, {3, 2, 1}}, .floor = 0, .base = 1.2, .scale_height = 0.4};
        const VaryingFog fog(ground, absorption, scattering, {}, 8);
        const Vec3<double> w = normalize(Vec3<double>(1, 0.6, 0));
        const double length = 1.8 / 0.6 * prism::length(Vec3<double>(1, 0.6, 0)); // from y = 0.1 to y = 1.9
        const double depth = ground.base * ground.scale_height / w.y * (std::exp(-0.1 / 0.4) - std::exp(-1.9 / 0.4));
        check_against(mean_of(n, [&](long i) { return fog.transmittance(Ray<double>{{-0.8, 0.1, -0.9 + 1.8 * double(i) / double(n)}, w}, length); }),
                      {std::exp(-sigma_t.x * depth), std::exp(-sigma_t.y * depth), std::exp(-sigma_t.z * depth)}, test::resolved(1e-3));
    }
    SUBCASE("an unbounded segment from outside: only the chord through the box counts")
    {
        std::vector<float> ones(8, 0.7f);
        const VaryingFog fog(DensityGrid<double>(2, 2, 2, {{0, 0, 0}, {1.5, 1, 1}}, ones), absorption, scattering, {}, 3);
        Random rng(2, 1);
        const Ray<double> ray{{-4, 0.5, 0.5}, {1, 0, 0}};
        const double depth = 0.7 * 1.5;
        check_against(mean_of(n, [&](long) { return fog.transmittance(ray, infinity<double>, rng); }),
                      {std::exp(-sigma_t.x * depth), std::exp(-sigma_t.y * depth), std::exp(-sigma_t.z * depth)}, test::resolved(1e-3));
    }
}

TEST_CASE("spectral tracking's flights are unbiased in every channel on a linear density: what passes, what scatters and where, within 4 standard errors of 0.3 % or less")
{
    // The chance-weighted expectations, per channel c, along [0, L] (T(s) = e^{-sigma_t,c tau(s)}):
    //   passing: T(L); scattering: int sigma_s,c d T ds = sigma_s,c / sigma_t,c (1 - T(L));
    //   the distance scattered at: int s sigma_s,c d(s) T(s) ds, by Simpson's rule in double.
    // (Optical depths 0.3 to 1.2 across.)
    const Rgb<double> absorption = fog_test::absorption * 0.3, scattering = fog_test::scattering * 0.3;
    const VaryingFog fog(linear_grid(), absorption, scattering);
    const Vec3<double> from{1.9, 0.1, 0.2}, to{0.2, 1.8, 1.7};
    const double length = prism::length(to - from);
    const Ray<double> ray{from, (to - from) / length};
    const auto tau = [&](double s) { return s * (linear(from) + linear(ray.at(s))) / 2; };
    for (const Rgb<double> power : {Rgb<double>(1), Rgb<double>(1, 0.2, 0.05)}) {
        CAPTURE(power.y);
        Random rng(7, 3);
        const long n = test::samples(1000000); // (under a sanitizer an eighth: the bound on the error widened by sqrt(8))
        long outside = 0;
        // Per channel: what passed, what scattered, and the distance where, each a mean with its standard error.
        Rgb<double> sums[3] = {Rgb<double>(0), Rgb<double>(0), Rgb<double>(0)}, squares[3] = {Rgb<double>(0), Rgb<double>(0), Rgb<double>(0)};
        for (long i = 0; i < n; ++i) {
            const FreeFlight<double> f = fog.sample_flight(ray, length, power, rng);
            outside += f.scattered && !(f.distance >= 0 && f.distance < length);
            const Rgb<double> x[3] = {f.scattered ? Rgb<double>(0) : f.weight, f.scattered ? f.weight : Rgb<double>(0), f.scattered ? f.weight * f.distance : Rgb<double>(0)};
            for (int k = 0; k < 3; ++k) sums[k] += x[k], squares[k] += x[k] * x[k];
        }
        CHECK(outside == 0);
        for (int c = 0; c < 3; ++c) {
            CAPTURE(c);
            const double st = absorption[c] + scattering[c];
            const int m = 2000;
            double moment = 0;
            for (int k = 0; k <= m; ++k) {
                const double s = length * k / m;
                moment += (k == 0 || k == m ? 1 : k % 2 ? 4 : 2) * s * scattering[c] * linear(ray.at(s)) * std::exp(-st * tau(s));
            }
            moment *= length / m / 3;
            const double expected[3] = {std::exp(-st * tau(length)), scattering[c] / st * (1 - std::exp(-st * tau(length))), moment};
            for (int k = 0; k < 3; ++k) {
                CAPTURE(k);
                const double mean = sums[k][c] / n, error = std::sqrt((squares[k][c] / n - mean * mean) / n);
                CAPTURE(mean);
                CAPTURE(error);
                CAPTURE(expected[k]);
                CHECK(std::abs(mean - expected[k]) < 4 * error);
                CHECK(error < test::resolved(3e-3) * expected[k]);
            }
        }
    }
}

TEST_CASE("a grey VaryingFog that does not absorb weighs every flight 1 (delta tracking); one of constant density scatters as Fog does")
{
    std::vector<float> values(27);
    Random values_rng(3, 3);
    for (float& v : values) v = 2 * values_rng.uniform<float>();
    const VaryingFog<DensityGrid<float>> grey(DensityGrid<float>(3, 3, 3, {Vec3<float>(-1), Vec3<float>(1)}, values), Rgb<float>(0), Rgb<float>(1.5f));
    Random rng(5, 5);
    int wrong = 0;
    for (int i = 0; i < 100000; ++i) {
        const FreeFlight<float> f = grey.sample_flight({{-2, 0.1f, 0.3f}, normalize(Vec3<float>(1, 0.2f, -0.1f))}, infinity<float>, Rgb<float>(0.2f, 1, 0.4f), rng);
        if (max_component(abs(f.weight - Rgb<float>(1))) > 1e-5f) ++wrong;
    }
    CHECK(wrong == 0);
    // Constant density 1 in a box against Fog across the same chord: the chance of passing.
    const VaryingFog<DensityGrid<float>> constant(DensityGrid<float>(2, 2, 2, {Vec3<float>(-1), Vec3<float>(1)}, std::vector<float>(8, 1.0f)),
                                                  Rgb<float>(0.1f), Rgb<float>(0.4f));
    const Fog<float> fog{.absorption = Rgb<float>(0.1f), .scattering = Rgb<float>(0.4f)};
    double a = 0, b = 0;
    Random r1(9, 1), r2(9, 2);
    const int n = 400000;
    for (int i = 0; i < n; ++i) {
        a += double(!constant.sample_flight({{-1, 0, 0}, {1, 0, 0}}, 2.0f, Rgb<float>(1), r1).scattered);
        b += double(!fog.sample_flight({{-1, 0, 0}, {1, 0, 0}}, 2.0f, Rgb<float>(1), r2).scattered);
    }
    CHECK(a / n == doctest::Approx(std::exp(-1.0)).epsilon(0.005));
    CHECK(b / n == doctest::Approx(std::exp(-1.0)).epsilon(0.005));
}

TEST_CASE("a VaryingFog's transmittance without a stream is the same for the same segment, and refuses bad coefficients by name")
{
    using fog_test::absorption;
    using fog_test::scattering;
    const VaryingFog fog(linear_grid(), absorption, scattering);
    const Ray<double> ray{{0.1, 0.1, 0.1}, normalize(Vec3<double>(1, 1, 1))};
    const Rgb<double> once = fog.transmittance(ray, 2.0), again = fog.transmittance(ray, 2.0);
    CHECK(once.x == again.x);
    CHECK(once.z == again.z);
    CHECK(max_component(abs(fog.scattering_at({1, 1, 1}) - scattering * linear({1, 1, 1}))) < 1e-6);
    CHECK(fog.bounds().hi.x == 2);
    CHECK_THROWS_WITH_AS(VaryingFog(linear_grid(), Rgb<double>(-1, 0, 0), scattering), doctest::Contains("VaryingFog absorption"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(VaryingFog(linear_grid(), absorption, Rgb<double>(0, std::nan(""), 0)), doctest::Contains("VaryingFog scattering"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(VaryingFog(linear_grid(), absorption, scattering, {.g = 1.5}), doctest::Contains("g"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(VaryingFog(linear_grid(), absorption, scattering, {}, 0), doctest::Contains("cells"), std::invalid_argument);
}

TEST_CASE("regression: a VaryingFog too dense for its precision is refused by name; a ray from far away is tracked to its end")
{
    // The fuzzer's grid of densities up to 1.5e28 in a unit box: the trackers' steps fell
    // below a float's precision there and never advanced (57 s on one input, unbounded).
    std::vector<float> values(8, 0.0f);
    values[5] = 1.5e28f;
    CHECK_THROWS_WITH_AS(VaryingFog(DensityGrid<float>(2, 2, 2, {Vec3<float>(0), Vec3<float>(1)}, values), Rgb<float>(0.1f), Rgb<float>(0.5f)),
                         doctest::Contains("VaryingFog is too dense for its precision"), std::invalid_argument);
    // Dense but allowed (optical depth about 1500 across the middle): from 10^5 away,
    // where a float's step is 1/128 (a mean free path 1/6000), the trackers count their
    // steps from each cell's entry, and end.
    values[5] = 1e4f;
    const VaryingFog fog(DensityGrid<float>(2, 2, 2, {Vec3<float>(0), Vec3<float>(1)}, values), Rgb<float>(0.1f), Rgb<float>(0.5f));
    Random rng(1, 1);
    const Ray<float> far{{-1e5f, 0.5f, 0.5f}, {1, 0, 0}};
    int outside = 0;
    double passed = 0;
    for (int i = 0; i < 1000; ++i) {
        const Rgb<float> tr = fog.transmittance(far, infinity<float>, rng);
        outside += !(tr.x >= 0 && tr.y >= 0 && tr.z >= 0 && max_component(tr) <= 1);
        passed += tr.x;
    }
    CHECK(outside == 0);
    CHECK(passed < 10); // (e^-150 through the middle)
    for (int i = 0; i < 1000; ++i) (void)fog.sample_flight(far, infinity<float>, Rgb<float>(1), rng);
}
