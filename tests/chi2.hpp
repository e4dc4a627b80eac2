// SPDX-License-Identifier: MIT
// Pearson's chi-square test of a sampler against the density it claims, as Mitsuba 3's
// chi2 tests do: histogram many samples over bins, integrate the density over each bin
// (the expected counts), pool bins expecting fewer than 5, and ask how likely a
// statistic this large is under the hypothesis that the samples follow the density.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/random.hpp>
#include <prism/core/sampler.hpp>
#include <prism/core/sampling.hpp>

#include <array>
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
    double stray = 0;      ///< samples in bins where the finest integration found no density (a sliver of support it missed, or a wrong sample)
    double mass = 0;       ///< the density's integral over the bins, by the quadrature that gave the expected counts (where a test sets it)
    double share = 0;      ///< the share of draws that gave a sample (where a test sets it)
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

/// Sample k's two numbers: independent ones from rng, or point k of the Sobol sampler's
/// first pair (core/sampler.hpp). Under Sobol points the counts scatter far less than a
/// multinomial's, so a right density gives a small statistic (p near 1) and a wrong one
/// still a large one: the test keeps its power to fail.
inline std::array<double, 2> uv(prism::SamplerKind points, std::uint64_t seed, long k, prism::Random& rng)
{
    if (points == prism::SamplerKind::independent) return rng.uniform2<double>();
    return prism::Sampler(points, seed, 0, static_cast<std::uint32_t>(k)).pair<double>(0);
}

/// A sampler of directions against its solid-angle density: `sample(u, v)` returns a unit
/// direction (or the zero vector for no sample), `pdf(w)` the density it claims. The cone
/// of directions within acos(cos_max) of `axis` (the whole sphere for -1), which must hold
/// every sample, is cut into theta_bins x phi_bins bins of equal solid angle; the density
/// is integrated over each on a grid of sub x sub points (finer where it has an edge, or
/// where a bin holds samples and the coarse grid found no density). A sample outside the
/// cone fails the test.
inline Chi2 chi2_directions(const std::function<prism::Vec3<double>(double, double)>& sample, const std::function<double(const prism::Vec3<double>&)>& pdf,
                            const prism::Vec3<double>& axis, long samples, int theta_bins = 20, int phi_bins = 40, int sub = 12,
                            double cos_max = -1, std::uint64_t seed = 7, prism::SamplerKind points = prism::SamplerKind::independent)
{
    const double z_span = 1 - cos_max;
    const auto [s, t] = prism::orthonormal_frame(axis);
    const auto bin_of = [&](const prism::Vec3<double>& w) {
        const double z = std::clamp(prism::dot(w, axis), -1.0, 1.0);
        double phi = std::atan2(prism::dot(w, t), prism::dot(w, s));
        if (phi < 0) phi += 2 * prism::pi<double>;
        if (z < cos_max) return -1;
        const int i = std::min(theta_bins - 1, int((1 - z) / z_span * theta_bins));
        const int j = std::min(phi_bins - 1, int(phi / (2 * prism::pi<double>) * phi_bins));
        return i * phi_bins + j;
    };
    std::vector<double> observed(std::size_t(theta_bins * phi_bins), 0.0), expected(observed.size(), 0.0);
    prism::Random rng(seed, 3);
    long taken = 0;
    for (long k = 0; k < samples; ++k) {
        const auto [u, v] = uv(points, seed, k, rng);
        const prism::Vec3<double> w = sample(u, v);
        if (w == prism::Vec3<double>(0)) continue;
        ++taken;
        const int bin = bin_of(w);
        if (bin < 0) {
            Chi2 outside;
            outside.statistic = INFINITY;
            return outside;
        }
        observed[std::size_t(bin)] += 1;
    }
    // Each bin is a z range times a phi range: dA = dz dphi; the midpoint rule on sub x sub
    // points, and on 16 sub x 16 sub where the density's support ends inside the bin (a
    // light's edge), where the coarse rule's error would dominate the statistic.
    const auto mass_of = [&](int i, int j, int n, bool& edge) {
        double mass = 0;
        bool zero = false, positive = false;
        const double dz = z_span / theta_bins / n, dphi = 2 * prism::pi<double> / phi_bins / n;
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) {
                const double z = 1 - z_span * i / theta_bins - (a + 0.5) * dz;
                const double phi = 2 * prism::pi<double> * j / phi_bins + (b + 0.5) * dphi;
                const double r = std::sqrt(std::max(0.0, 1 - z * z));
                const prism::Vec3<double> w = r * std::cos(phi) * s + r * std::sin(phi) * t + z * axis;
                const double f = pdf(w);
                (f > 0 ? positive : zero) = true;
                mass += f * dz * dphi;
            }
        edge = zero && positive;
        return mass;
    };
    double total = 0, stray = 0;
    for (int i = 0; i < theta_bins; ++i)
        for (int j = 0; j < phi_bins; ++j) {
            bool edge = false;
            const std::size_t k = std::size_t(i * phi_bins + j);
            double mass = mass_of(i, j, sub, edge);
            if (edge || (mass == 0 && observed[k] > 0)) mass = mass_of(i, j, 16 * sub, edge);
            expected[k] = mass * double(samples);
            total += mass;
            // Samples where even the fine grid saw no density: counted apart (the caller
            // bounds them), and pooled with their neighbours as a bin expecting almost none.
            if (mass == 0 && observed[k] > 0) stray += observed[k], expected[k] = 1e-9;
        }
    Chi2 out = chi2_test(observed, expected);
    out.missing = double(samples) * (1 - total) - double(samples - taken);
    out.stray = stray;
    return out;
}

/// A sampler of points on a surface parametrised over the unit square, against the density
/// it claims there: `sample(u, v)` returns the point's parameters (s, t), `density(s, t)`
/// the density per unit of (s, t). The square is cut into bins x bins; the density is
/// integrated over each on sub x sub points. For a light seen from a point, binning on
/// the light itself has no edges inside the bins, which thin or grazing views give a
/// binning by direction.
inline Chi2 chi2_surface(const std::function<prism::Vec2<double>(double, double)>& sample, const std::function<double(double, double)>& density,
                         long samples, int bins = 40, int sub = 8, std::uint64_t seed = 11, prism::SamplerKind points = prism::SamplerKind::independent)
{
    std::vector<double> observed(std::size_t(bins * bins), 0.0), expected(observed.size(), 0.0);
    prism::Random rng(seed, 5);
    for (long k = 0; k < samples; ++k) {
        const auto [u, v] = uv(points, seed, k, rng);
        const prism::Vec2<double> st = sample(u, v);
        if (!(st.x >= -1e-9 && st.x <= 1 + 1e-9 && st.y >= -1e-9 && st.y <= 1 + 1e-9)) {
            Chi2 outside;
            outside.statistic = INFINITY;
            return outside;
        }
        const int i = std::clamp(int(st.x * bins), 0, bins - 1), j = std::clamp(int(st.y * bins), 0, bins - 1);
        observed[std::size_t(i * bins + j)] += 1;
    }
    double total = 0;
    const double cell = 1.0 / (double(bins) * sub);
    for (int i = 0; i < bins; ++i)
        for (int j = 0; j < bins; ++j) {
            double mass = 0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) mass += density((i * sub + a + 0.5) * cell, (j * sub + b + 0.5) * cell) * cell * cell;
            expected[std::size_t(i * bins + j)] = mass * double(samples);
            total += mass;
        }
    Chi2 out = chi2_test(observed, expected);
    out.missing = double(samples) * (1 - total);
    return out;
}

/// cos_max for chi2_directions: the cone from p holding a sphere (centre, radius), a
/// little wider; the whole sphere of directions from inside it.
inline double cone_around(const prism::Vec3<double>& p, const prism::Vec3<double>& centre, double radius)
{
    const double d = prism::length(centre - p);
    if (d <= radius * 1.01) return -1;
    return std::cos(std::min(prism::pi<double>, 1.05 * std::asin(radius / d)));
}

} // namespace test
