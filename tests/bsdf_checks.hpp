// SPDX-License-Identifier: MIT
// What every BSDF lobe is held to, each against something outside the lobe's own
// sampling code: its albedo by quadrature over the sphere (on a grid that crowds toward
// the mirror direction, where glossy lobes peak), sampling by a chi-square test against
// the density it claims (Mitsuba 3's method) and the density's mass against the share of
// draws that land, each sample's weight against f cos / pdf, and reciprocity.
#pragma once

#include "chi2.hpp"
#include "effort.hpp"

#include <prism/material/bsdf.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace test {

/// The integral of g(w) over the unit sphere, in polar coordinates about `axis` with
/// the polar angle's steps crowding toward the axis (theta = pi t^3), on rings x sectors points.
inline double sphere_integral(const std::function<double(const prism::Vec3<double>&)>& g, const prism::Vec3<double>& axis, int rings = 1500,
                              int sectors = 360)
{
    const auto [s, t] = prism::orthonormal_frame(prism::normalize(axis));
    double sum = 0;
    for (int i = 0; i < rings; ++i) {
        const double u = (i + 0.5) / rings;
        const double theta = prism::pi<double> * u * u * u, dtheta = 3 * prism::pi<double> * u * u / rings;
        const double st = std::sin(theta), ct = std::cos(theta);
        for (int j = 0; j < sectors; ++j) {
            const double phi = 2 * prism::pi<double> * (j + 0.5) / sectors;
            const prism::Vec3<double> w = st * std::cos(phi) * s + st * std::sin(phi) * t + ct * prism::normalize(axis);
            sum += g(w) * st * dtheta * (2 * prism::pi<double> / sectors);
        }
    }
    return sum;
}

/// The mirror direction of wo about the local z axis, where glossy reflection peaks.
inline prism::Vec3<double> local_mirror(const prism::Vec3<double>& wo) { return {-wo.x, -wo.y, wo.z}; }

/// A lobe's directional albedo for wo, the integral of f(wo, wi) |wi.z| by quadrature.
template <class B>
double albedo_by_quadrature(const B& lobe, const prism::Vec3<double>& wo, int channel = 0,
                            prism::Transport mode = prism::Transport::radiance)
{
    using T = typename B::scalar_type;
    return sphere_integral([&](const prism::Vec3<double>& wi) { return double(lobe.f(prism::Vec3<T>(wo), prism::Vec3<T>(wi), mode)[channel]) * std::abs(wi.z); },
                           local_mirror(wo));
}

/// Where light from wo refracts through a smooth interface with eta = n(-z) / n(+z): the
/// direction on the other side that a rough one's refraction crowds about.
inline prism::Vec3<double> snell_direction(const prism::Vec3<double>& wo, double eta)
{
    const double e = wo.z > 0 ? eta : 1 / eta; // n beyond / n on wo's side
    const double sin2 = (1 - wo.z * wo.z) / (e * e);
    if (sin2 >= 1) return {0, 0, wo.z > 0 ? -1.0 : 1.0}; // (total internal reflection: any axis on the other side)
    const double cos_t = std::sqrt(1 - sin2);
    return prism::normalize(prism::Vec3<double>{-wo.x / e, -wo.y / e, wo.z > 0 ? -cos_t : cos_t});
}

/// What sampling a lobe for wo finds, over n samples: the mean weight (the albedo, by
/// Monte Carlo), the share of draws that gave a direction, and the worst relative gap
/// between a sample's weight and f cos / pdf evaluated at its direction.
struct LobeSampling {
    double albedo = 0;   ///< mean of the weights (channel 0), a failed draw counting 0
    double taken = 0;    ///< share of draws that gave a direction
    double worst_weight = 0; ///< largest |weight - f cos / pdf| / weight over non-delta samples
    double worst_pdf = 0;    ///< largest |pdf - pdf(wo, wi)| / pdf over non-delta samples
};

template <class B>
LobeSampling sample_lobe(const B& lobe, const prism::Vec3<double>& wo_d, long n, prism::Transport mode = prism::Transport::radiance,
                         std::uint64_t seed = 3)
{
    using T = typename B::scalar_type;
    const prism::Vec3<T> wo(wo_d);
    prism::Random rng(seed, 9);
    LobeSampling out;
    double sum = 0;
    long taken = 0;
    for (long k = 0; k < n; ++k) {
        const T u0 = rng.uniform<T>(), u1 = rng.uniform<T>(), u2 = rng.uniform<T>();
        const auto s = lobe.sample(wo, u0, u1, u2, mode);
        if (!s) continue;
        ++taken;
        sum += double(s->weight.x);
        if (s->delta) continue;
        const double expected = double(lobe.f(wo, s->wi, mode).x) * std::abs(double(s->wi.z)) / double(lobe.pdf(wo, s->wi));
        if (s->weight.x > 0) out.worst_weight = std::max(out.worst_weight, std::abs(double(s->weight.x) - expected) / double(s->weight.x));
        out.worst_pdf = std::max(out.worst_pdf, std::abs(double(s->pdf) - double(lobe.pdf(wo, s->wi))) / double(s->pdf));
    }
    out.albedo = sum / double(n);
    out.taken = double(taken) / double(n);
    return out;
}

/// Pearson's test of a sampler of directions against its density, as chi2_directions but
/// with bins of equal polar angle about `axis` (Mitsuba 3's binning), which resolve a
/// narrow lobe about the axis where bins of equal solid angle put it all in one ring.
/// Each bin's mass is integrated adaptively: the midpoint rule on sub x sub points, then on
/// each quarter of the bin the same way; where the two differ by more than a twentieth of
/// the bin's expected count's standard error, each quarter again, up to `depth` times (a
/// narrow peak, the edge of the density's support). A bin where samples landed but no
/// point saw density is searched to the full depth.
inline Chi2 chi2_polar(const std::function<prism::Vec3<double>()>& sample, const std::function<double(const prism::Vec3<double>&)>& pdf,
                       const prism::Vec3<double>& axis, long samples, int theta_bins = 40, int phi_bins = 40, int sub = 8, int depth = 5)
{
    const auto [s, t] = prism::orthonormal_frame(axis);
    std::vector<double> observed(std::size_t(theta_bins * phi_bins), 0.0), expected(observed.size(), 0.0);
    long taken = 0;
    for (long k = 0; k < samples; ++k) {
        const prism::Vec3<double> w = sample();
        if (w == prism::Vec3<double>(0)) continue;
        ++taken;
        const double theta = std::acos(std::clamp(prism::dot(w, axis), -1.0, 1.0));
        double phi = std::atan2(prism::dot(w, t), prism::dot(w, s));
        if (phi < 0) phi += 2 * prism::pi<double>;
        const int i = std::min(theta_bins - 1, int(theta / prism::pi<double> * theta_bins));
        const int j = std::min(phi_bins - 1, int(phi / (2 * prism::pi<double>) * phi_bins));
        observed[std::size_t(i * phi_bins + j)] += 1;
    }
    // The midpoint rule over [theta0, theta0 + dtheta] x [phi0, phi0 + dphi]; `seen` says
    // whether any point found density.
    const auto midpoint = [&](double theta0, double dtheta, double phi0, double dphi, bool& seen) {
        double mass = 0;
        const double h_theta = dtheta / sub, h_phi = dphi / sub;
        for (int a = 0; a < sub; ++a)
            for (int b = 0; b < sub; ++b) {
                const double theta = theta0 + (a + 0.5) * h_theta, phi = phi0 + (b + 0.5) * h_phi;
                const prism::Vec3<double> w = std::sin(theta) * (std::cos(phi) * s + std::sin(phi) * t) + std::cos(theta) * axis;
                const double f = pdf(w);
                seen = seen || f > 0;
                mass += f * std::sin(theta) * h_theta * h_phi;
            }
        return mass;
    };
    const auto refine = [&](const auto& self, double theta0, double dtheta, double phi0, double dphi, double coarse, int levels, bool search) -> double {
        const double half_theta = dtheta / 2, half_phi = dphi / 2;
        std::array<double, 4> quarter{};
        bool seen = false;
        for (int q = 0; q < 4; ++q) quarter[std::size_t(q)] = midpoint(theta0 + (q & 1) * half_theta, half_theta, phi0 + (q >> 1) * half_phi, half_phi, seen);
        const double fine = quarter[0] + quarter[1] + quarter[2] + quarter[3];
        const double count_error = std::abs(fine - coarse) * double(samples), allowed = 0.05 * std::sqrt(fine * double(samples) + 1);
        if (levels == 0 || (count_error <= allowed && (seen || !search))) return fine;
        double sum = 0;
        for (int q = 0; q < 4; ++q)
            sum += self(self, theta0 + (q & 1) * half_theta, half_theta, phi0 + (q >> 1) * half_phi, half_phi, quarter[std::size_t(q)], levels - 1, search && !seen);
        return sum;
    };
    const double bin_theta = prism::pi<double> / theta_bins, bin_phi = 2 * prism::pi<double> / phi_bins;
    double total = 0, stray = 0;
    for (int i = 0; i < theta_bins; ++i)
        for (int j = 0; j < phi_bins; ++j) {
            const std::size_t k = std::size_t(i * phi_bins + j);
            bool seen = false;
            const double coarse = midpoint(i * bin_theta, bin_theta, j * bin_phi, bin_phi, seen);
            const double mass = refine(refine, i * bin_theta, bin_theta, j * bin_phi, bin_phi, coarse, depth - 1, observed[k] > 0 && !seen);
            expected[k] = mass * double(samples);
            total += mass;
            // Samples where even the finest grid saw no density (a sliver at the horizon):
            // counted apart, for the caller to bound.
            if (mass == 0 && observed[k] > 0) stray += observed[k], expected[k] = 1e-9;
        }
    Chi2 out = chi2_test(observed, expected);
    out.missing = double(samples) * (1 - total) - double(samples - taken);
    out.stray = stray;
    out.mass = total;
    out.share = double(taken) / double(samples);
    return out;
}

/// Pearson's test of a lobe's sampling for wo against its pdf (chi2_polar about the
/// mirror direction), its three numbers drawn from one stream; or, with Sobol `points`,
/// draw k's from sample k of a render's sampler as a path's first bounce draws them (the
/// lobe's choice one number, its direction the next pair: BsdfAt::sample), whose counts
/// scatter less than a multinomial's (the statistic falls far below its degrees of
/// freedom, and a wrong density still raises it).
template <class B>
Chi2 chi2_lobe(const B& lobe, const prism::Vec3<double>& wo, long samples = 1000000, prism::Transport mode = prism::Transport::radiance, int sub = 8,
               prism::SamplerKind points = prism::SamplerKind::independent)
{
    prism::Random rng(17, 5);
    long k = 0;
    return chi2_polar(
        [&] {
            prism::Random sobol(prism::Sampler(points, 17, 0, static_cast<std::uint32_t>(k)), prism::Pcg32(17, std::uint64_t(k)));
            ++k;
            sobol.bounce(0);
            prism::Random& draw = points == prism::SamplerKind::independent ? rng : sobol;
            const double u0 = draw.uniform<double>();
            const auto [u1, u2] = draw.uniform2<double>();
            const auto s = lobe.sample(wo, u0, u1, u2, mode);
            return s && !s->delta ? s->wi : prism::Vec3<double>(0);
        },
        [&](const prism::Vec3<double>& wi) { return lobe.pdf(wo, wi); }, local_mirror(wo), samples, 40, 40, sub);
}

/// A unit direction at polar angle theta (degrees) and azimuth phi (degrees) about local z.
inline prism::Vec3<double> polar(double theta_deg, double phi_deg)
{
    const double t = theta_deg * prism::pi<double> / 180, p = phi_deg * prism::pi<double> / 180;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

/// What every lobe's sampling is held to for wo: the chi-square test on 500 000 draws; the
/// pdf's mass (the test's bins integrated) against the share of those draws that gave a
/// direction, to `mass_epsilon` (the share's standard error is at most 0.5 / sqrt(500 000)
/// = 7e-4, and 2e-4 where nine draws in ten land); and each of `draws` more draws' weight
/// and density against f cos / pdf and the pdf at its direction. Returns what those draws
/// found, for the caller's own checks (their mean weight's standard error is the caller's
/// to size by `draws`). Under a sanitizer, an eighth of the draws (tests/effort.hpp).
template <class B>
LobeSampling check_lobe_sampling(const B& lobe, const prism::Vec3<double>& wo, double mass_epsilon = 5e-3, long draws = 200000)
{
    const Chi2 chi2 = chi2_lobe(lobe, wo, samples(500000));
    CAPTURE(chi2.statistic);
    CHECK(chi2.p_value > 1e-3);
    const Chi2 sobol = chi2_lobe(lobe, wo, samples(500000), prism::Transport::radiance, 8, prism::SamplerKind::sobol);
    CAPTURE(sobol.statistic);
    CHECK(sobol.p_value > 1e-3);
    CHECK(chi2.stray < 10);
    CHECK(chi2.mass == doctest::Approx(chi2.share).epsilon(resolved(mass_epsilon)));
    const LobeSampling s = sample_lobe(lobe, wo, samples(draws));
    CHECK(s.worst_weight < 1e-9);
    CHECK(s.worst_pdf < 1e-9);
    return s;
}

} // namespace test
