// SPDX-License-Identifier: MIT
// Pearson's chi-square test of a sampler against the density it claims, as Mitsuba 3's
// chi2 tests do: histogram many samples over bins, integrate the density over each bin
// (the expected counts), pool bins expecting fewer than 5, and ask how likely a
// statistic this large is under the hypothesis that the samples follow the density.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/sampling.hpp>

#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace test {

/// The regularised upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a): the
/// probability that a chi-square variable of 2a degrees of freedom exceeds 2x. A series
/// below x = a + 1, Lentz's continued fraction above (Numerical Recipes, section 6.2).
inline double gamma_q(double a, double x)
{
    if (x <= 0) return 1;
    const double log_front = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1) {
        double term = 1 / a, sum = term;
        for (int n = 1; n < 100000 && std::abs(term) > std::abs(sum) * 1e-16; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1 - sum * std::exp(log_front);
    }
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        d = std::abs(d) < tiny ? tiny : d;
        c = b + an / c;
        c = std::abs(c) < tiny ? tiny : c;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-16) break;
    }
    return std::exp(log_front) * h;
}

/// The outcome of a chi-square test.
struct Chi2 {
    double statistic = 0;  ///< sum of (observed - expected)^2 / expected over the pooled bins
    int degrees = 0;       ///< pooled bins - 1
    double p_value = 0;    ///< the probability of a statistic at least this large if the sampler is right
    double missing = 0;    ///< expected count of samples the bins do not hold (the density's mass outside them, or where it is 0)
};

/// Pearson's test of `observed` counts against `expected` ones (the same bins, the same
/// total), bins expecting fewer than 5 pooled together in order.
inline Chi2 chi2_test(const std::vector<double>& observed, const std::vector<double>& expected)
{
    Chi2 out;
    double pooled_o = 0, pooled_e = 0;
    int bins = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] == 0 && observed[i] > 0) {
            // A sample where the density says there can be none: certain failure.
            out.statistic = INFINITY;
            out.p_value = 0;
            return out;
        }
        pooled_o += observed[i];
        pooled_e += expected[i];
        if (pooled_e >= 5) {
            out.statistic += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e;
            ++bins;
            pooled_o = pooled_e = 0;
        }
    }
    if (pooled_e > 0) {
        out.statistic += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e;
        ++bins;
    }
    out.degrees = bins - 1;
    out.p_value = out.degrees > 0 ? gamma_q(0.5 * out.degrees, 0.5 * out.statistic) : 1;
    return out;
}

/// A sampler of directions against its solid-angle density: `sample(u, v)` returns a unit
/// direction (or the zero vector for no sample), `pdf(w)` the density it claims. The sphere
/// is cut into theta_bins x phi_bins bins of equal area about `axis`; the density is
/// integrated over each on a grid of sub x sub points.
inline Chi2 chi2_directions(const std::function<prism::Vec3<double>(double, double)>& sample, const std::function<double(const prism::Vec3<double>&)>& pdf,
                            const prism::Vec3<double>& axis, long samples, int theta_bins = 20, int phi_bins = 40, int sub = 12,
                            std::uint64_t seed = 7)
{
    const auto [s, t] = prism::orthonormal_frame(axis);
    const auto bin_of = [&](const prism::Vec3<double>& w) {
        const double z = std::clamp(prism::dot(w, axis), -1.0, 1.0);
        double phi = std::atan2(prism::dot(w, t), prism::dot(w, s));
        if (phi < 0) phi += 2 * prism::pi<double>;
        const int i = std::min(theta_bins - 1, int((1 - z) / 2 * theta_bins));
        const int j = std::min(phi_bins - 1, int(phi / (2 * prism::pi<double>) * phi_bins));
        return i * phi_bins + j;
    };
    std::vector<double> observed(std::size_t(theta_bins * phi_bins), 0.0), expected(observed.size(), 0.0);
    prism::Pcg32 rng(seed, 3);
    long taken = 0;
    for (long k = 0; k < samples; ++k) {
        const double u = rng.uniform<double>(), v = rng.uniform<double>();
        const prism::Vec3<double> w = sample(u, v);
        if (w == prism::Vec3<double>(0)) continue;
        ++taken;
        observed[std::size_t(bin_of(w))] += 1;
    }
    // Each bin is a z range times a phi range: dA = dz dphi; the midpoint rule on sub x sub.
    double total = 0;
    for (int i = 0; i < theta_bins; ++i)
        for (int j = 0; j < phi_bins; ++j) {
            double mass = 0;
            const double dz = 2.0 / theta_bins / sub, dphi = 2 * prism::pi<double> / phi_bins / sub;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    const double z = 1 - 2.0 * i / theta_bins - (a + 0.5) * dz;
                    const double phi = 2 * prism::pi<double> * j / phi_bins + (b + 0.5) * dphi;
                    const double r = std::sqrt(std::max(0.0, 1 - z * z));
                    const prism::Vec3<double> w = r * std::cos(phi) * s + r * std::sin(phi) * t + z * axis;
                    mass += pdf(w) * dz * dphi;
                }
            expected[std::size_t(i * phi_bins + j)] = mass * double(samples);
            total += mass;
        }
    Chi2 out = chi2_test(observed, expected);
    out.missing = double(samples) * (1 - total) - double(samples - taken);
    return out;
}

} // namespace test
