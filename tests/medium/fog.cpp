// SPDX-License-Identifier: MIT
#include <prism/medium/fog.hpp>

#include "../chi2.hpp"
#include "../effort.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace prism;

TEST_CASE("Fog's free flights are unbiased in every channel: what passes is exp(-sigma_t d), what scatters sigma_s / sigma_t (1 - exp(-sigma_t d)), within 4 standard errors of 0.2 % or less")
{
    // A coloured fog, so that the channel drawn and the weight differ (the balance
    // heuristic over channels), and one channel nearly clear; walkers carrying white, or
    // mostly red (the channel drawn by its share), or nothing yet known (all zero). Each
    // mean's standard error from its draws' own spread: 2 million draws put it at 0.16 %
    // at most (what scatters over a short way), 0.03 % to 0.11 % for what passes.
    const Fog<double> fog{.absorption = {0.2, 0.05, 0.0}, .scattering = {0.6, 0.3, 0.02}};
    const Rgb<double> sigma_t = fog.extinction(), sigma_s = fog.scattering;
    for (const auto& [d, power] : {std::pair{0.5, Rgb<double>(1)}, std::pair{2.0, Rgb<double>(1)}, std::pair{2.0, Rgb<double>(1, 0.2, 0.05)},
                                   std::pair{0.5, Rgb<double>(0)}}) {
        CAPTURE(d);
        CAPTURE(power.y);
        Random rng(7, 2);
        Rgb<double> passed{0}, scattered{0}, passed_squares{0}, scattered_squares{0};
        const long n = test::samples(2000000); // (under a sanitizer an eighth, and the bound 0.57 %: tests/effort.hpp)
        const Ray<double> ray{{0, 0, 0}, {1, 0, 0}};
        long outside = 0;
        for (long i = 0; i < n; ++i) {
            const FreeFlight<double> f = fog.sample_flight(ray, d, power, rng);
            if (f.scattered) {
                if (!(f.distance >= 0 && f.distance < d)) ++outside;
                scattered += f.weight;
                scattered_squares += f.weight * f.weight;
            } else {
                passed += f.weight;
                passed_squares += f.weight * f.weight;
            }
        }
        CHECK(outside == 0);
        const auto check_mean = [&](double sum, double squares, double expected) {
            const double mean = sum / double(n), error = std::sqrt(std::max(0.0, squares / double(n) - mean * mean) / double(n));
            CAPTURE(mean);
            CAPTURE(error);
            CHECK(error <= test::resolved(2e-3) * expected);
            CHECK(std::abs(mean - expected) <= 4 * error);
        };
        for (int c = 0; c < 3; ++c) {
            CAPTURE(c);
            check_mean(passed[c], passed_squares[c], std::exp(-sigma_t[c] * d));
            check_mean(scattered[c], scattered_squares[c], sigma_s[c] / sigma_t[c] * (1 - std::exp(-sigma_t[c] * d)));
        }
    }
}

TEST_CASE("Fog's flight_pdf is the density its flights are drawn with (chi-square over where they scatter, and the mass that passes)")
{
    // A coloured fog and a walker carrying mostly red: the draw is a mixture over
    // channels, and flight_pdf must be that mixture (the path tracer weighs equiangular
    // samples against it). 60 bins over [0, 3) and one for the flights that pass.
    const Fog<double> fog{.absorption = {0.2, 0.05, 0.0}, .scattering = {0.6, 0.3, 0.02}};
    const Rgb<double> power{1, 0.2, 0.05};
    const double t_max = 3;
    const int bins = 60;
    const long n = 400000;
    std::vector<double> observed(bins + 1, 0.0), expected(bins + 1, 0.0);
    Random rng(11, 5);
    for (long i = 0; i < n; ++i) {
        const FreeFlight<double> f = fog.sample_flight({{0, 0, 0}, {1, 0, 0}}, t_max, power, rng);
        observed[f.scattered ? std::size_t(std::min(bins - 1, int(f.distance / t_max * bins))) : std::size_t(bins)] += 1;
    }
    double inside = 0;
    for (int b = 0; b < bins; ++b) {
        // Simpson's rule over the bin, 32 panels (the density is smooth).
        const double a = t_max * b / bins, h = t_max / bins / 32;
        double sum = fog.flight_pdf(power, a) + fog.flight_pdf(power, a + 32 * h);
        for (int k = 1; k < 32; ++k) sum += (k % 2 ? 4 : 2) * fog.flight_pdf(power, a + k * h);
        expected[std::size_t(b)] = n * sum * h / 3;
        inside += sum * h / 3;
    }
    // What passes: each channel's share of the draws times its transmittance over t_max.
    const Rgb<double> chance = power / (power.x + power.y + power.z);
    const double passing = dot(chance, fog.transmittance(t_max));
    CHECK(inside + passing == doctest::Approx(1).epsilon(1e-9));
    expected[std::size_t(bins)] = n * passing;
    const test::Chi2 chi = test::chi2_test(observed, expected);
    CAPTURE(chi.statistic);
    CAPTURE(chi.degrees);
    CHECK(chi.p_value > 1e-3);
}

TEST_CASE("a grey fog's flights weigh exactly (to rounding): its albedo where they scatter, 1 where they pass; a clear channel never turns NaN")
{
    const Fog<float> grey{.absorption = Rgb<float>(0.25f), .scattering = Rgb<float>(0.75f)};
    Random rng(1, 1);
    int wrong = 0, scattered = 0;
    for (int i = 0; i < 10000; ++i) {
        const FreeFlight<float> f = grey.sample_flight({{0, 0, 0}, {0, 1, 0}}, 1.5f, Rgb<float>(0.3f, 1, 0.1f), rng);
        if (max_component(abs(f.weight - (f.scattered ? Rgb<float>(0.75f) : Rgb<float>(1)))) > 1e-6f) ++wrong;
        scattered += f.scattered;
    }
    CHECK(wrong == 0);
    CHECK(scattered > 7500); // 1 - exp(-1.5) = 78 % of them
    // One clear channel, an unbounded segment: the clear channel passes every time it is drawn.
    const Fog<float> half_fog{.scattering = {0.5f, 0.0f, 0.5f}};
    int bad = 0, passed = 0;
    for (int i = 0; i < 10000; ++i) {
        const FreeFlight<float> f = half_fog.sample_flight({{0, 0, 0}, {0, 1, 0}}, infinity<float>, Rgb<float>(1), rng);
        if (!std::isfinite(f.weight.x + f.weight.y + f.weight.z)) ++bad;
        // Only the clear channel reaches infinity, drawn 1 time in 3.
        if (!f.scattered && f.weight != Rgb<float>(0, 3, 0)) ++bad;
        passed += !f.scattered;
    }
    CHECK(bad == 0);
    CHECK(passed > 3000);
    CHECK(passed < 3700);
    CHECK(half_fog.transmittance(infinity<float>) == Rgb<float>(0, 1, 0));
}

TEST_CASE("Fog refuses a negative coefficient or a bad phase function, by name")
{
    CHECK_THROWS_WITH_AS((Fog<float>{.absorption = {0, -0.1f, 0}}.validate()), doctest::Contains("Fog absorption"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((Fog<float>{.scattering = {0, 0, std::nanf("")}}.validate()), doctest::Contains("Fog scattering"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((Fog<float>{.phase = {.g = 1}}.validate()), doctest::Contains("HenyeyGreenstein g"), std::invalid_argument);
}
