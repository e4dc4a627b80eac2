// SPDX-License-Identifier: MIT
// The airlight test scene every integrator's single scattering is held to: a point light
// of intensity 1 at (0, 1, 0), a ray from (-2, 0, 0) along +x through unbounded coloured
// fog, and what it sees by single scattering,
//   L = int_0^inf sigma_s e^(-sigma_t s) p(cos) I / d^2 e^(-sigma_t d) ds
// (d the distance from the ray's point at s to the light), by Simpson's rule on [0, 120]
// in double: an outside number, computed without prism's integrators. airlight_along
// gives the same for any ray and light position.
#pragma once

#include <prism/prism.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace test {

inline const prism::Rgb<double> airlight_absorption{0.1, 0.05, 0.2}; ///< sigma_a of the airlight fog
inline const prism::Rgb<double> airlight_scattering{0.3, 0.5, 0.1};  ///< sigma_s of the airlight fog
inline constexpr double airlight_g = 0.5;                             ///< its Henyey-Greenstein g

/// The scene: the light and one tiny object far off (a scene needs an object).
inline auto airlight_scene()
{
    using namespace prism;
    return Scene{Lights{PointLight<float>{.position = {0, 1, 0}, .intensity = Rgb<float>(1)}}, Object{Sphere<float>({0, -1000, 0}, 1e-3f), Diffuse<float>{}}};
}

/// The fog, filling the scene's air everywhere.
inline prism::FilledAir<prism::Fog<float>> airlight_fog()
{
    return {.medium = {.absorption = prism::Rgb<float>(airlight_absorption), .scattering = prism::Rgb<float>(airlight_scattering),
                       .phase = {.g = float(airlight_g)}}};
}

/// The fog filling GradedAir of a uniform index, which cuts every path into straight
/// pieces of at most 0.5 inside a box 50 about the light (straight beyond it): the same
/// fog, the same integral, summed piece by piece.
inline auto airlight_fog_in_pieces()
{
    using Graded = prism::GradedAir<prism::LinearSquareIndex<float>>;
    const Graded graded{.field = {.a = 1, .b = 0}, .region = {prism::Vec3<float>(-50), prism::Vec3<float>(50)},
                        .stepping = {.tolerance = 1e-5f, .first_step = 0.5f, .max_step = 0.5f}};
    return prism::FilledAir<prism::Fog<float>, Graded>{.medium = airlight_fog().medium, .base = graded};
}

/// The ray the test looks along.
inline prism::Ray<float> airlight_ray() { return {{-2, 0, 0}, {1, 0, 0}}; }

/// The single-scattered radiance of a point light of intensity 1 at `light` in the
/// airlight fog, in channel c, along the ray from `origin` in unit direction `w`, by
/// Simpson's rule over [from, length] with n (even) intervals: the fog lies on the ray
/// from `from` on (clear air before it), and all about the light.
inline double airlight_along(int c, const prism::Vec3<double>& origin, const prism::Vec3<double>& w, const prism::Vec3<double>& light,
                             double length = 120.0, int n = 400000, double from = 0.0)
{
    const double st = airlight_absorption[c] + airlight_scattering[c];
    const prism::HenyeyGreenstein<double> hg{airlight_g};
    const auto f = [&](double s) {
        const prism::Vec3<double> to_point = origin + s * w - light;
        const double d = prism::length(to_point);
        // The light travels from the light to the point, then back along the ray (-w).
        return airlight_scattering[c] * std::exp(-st * (s - from)) * hg.value(-prism::dot(to_point, w) / d) / (d * d) * std::exp(-st * d);
    };
    const double h = (length - from) / n;
    double sum = f(from) + f(length);
    for (int i = 1; i < n; ++i) sum += f(from + i * h) * (i % 2 ? 4 : 2);
    return sum * h / 3;
}

/// The single-scattered radiance along airlight_ray() in channel c, by quadrature.
inline double airlight(int c) { return airlight_along(c, {-2, 0, 0}, {1, 0, 0}, {0, 1, 0}); }

/// The same fog filling only a ball of `radius` about the origin, clear air outside (a
/// ball of smoke: the fog inside an index-1 object): the single-scattered radiance of a
/// point light of intensity 1 at `light` (inside or outside the ball) along the ray from
/// `origin` in unit direction `w`, in channel c, by Simpson's rule over the ray's chord of
/// the ball with n (even) intervals; the light's way to each point is attenuated over
/// the part of it inside the ball only.
inline double smoke_ball_airlight(int c, const prism::Vec3<double>& origin, const prism::Vec3<double>& w, const prism::Vec3<double>& light, double radius,
                                  int n = 20000)
{
    using prism::dot;
    // Where a line from p along unit u leaves the ball (p inside it).
    const auto exit_along = [&](const prism::Vec3<double>& p, const prism::Vec3<double>& u) {
        const double b = dot(p, u);
        return -b + std::sqrt(std::max(b * b - (dot(p, p) - radius * radius), 0.0));
    };
    const double b = dot(origin, w), disc = b * b - (dot(origin, origin) - radius * radius);
    if (disc <= 0) return 0.0;
    const double s0 = std::max(0.0, -b - std::sqrt(disc)), s1 = -b + std::sqrt(disc);
    if (s1 <= s0) return 0.0;
    const double st = airlight_absorption[c] + airlight_scattering[c];
    const prism::HenyeyGreenstein<double> hg{airlight_g};
    const auto f = [&](double s) {
        const prism::Vec3<double> p = origin + s * w, to_point = p - light;
        const double d = prism::length(to_point);
        const double inside = std::min(d, exit_along(p, -to_point / d));
        return airlight_scattering[c] * std::exp(-st * (s - s0)) * hg.value(-dot(to_point, w) / d) / (d * d) * std::exp(-st * inside);
    };
    const double h = (s1 - s0) / n;
    double sum = f(s0) + f(s1);
    for (int i = 1; i < n; ++i) sum += f(s0 + i * h) * (i % 2 ? 4 : 2);
    return sum * h / 3;
}

/// A ball of smoke in foggy air: the airlight fog times `ball_scale` inside a ball of
/// `radius` about the origin, the airlight fog itself filling the air everywhere else.
/// The single-scattered radiance of a point light of intensity 1 at `light` along the
/// ray from `origin` in unit direction `w` over [0, length], in channel c, by Simpson's
/// rule on each stretch of the ray in one fog (n intervals in all); the light's way to
/// each point, and the ray's, attenuated by each fog over the part of it inside that fog.
inline double smoke_ball_in_fog_airlight(int c, const prism::Vec3<double>& origin, const prism::Vec3<double>& w, const prism::Vec3<double>& light,
                                         double radius, double ball_scale, double length = 120.0, int n = 400000)
{
    using prism::dot;
    const double st_air = airlight_absorption[c] + airlight_scattering[c], st_ball = ball_scale * st_air;
    // The part of the segment from a, `d` long along unit u, inside the ball.
    const auto chord = [&](const prism::Vec3<double>& a, const prism::Vec3<double>& u, double d) {
        const double b = dot(a, u), disc = b * b - (dot(a, a) - radius * radius);
        if (disc <= 0) return 0.0;
        const double t0 = -b - std::sqrt(disc), t1 = -b + std::sqrt(disc);
        return std::max(0.0, std::min(d, t1) - std::max(0.0, t0));
    };
    const auto optical = [&](const prism::Vec3<double>& a, const prism::Vec3<double>& u, double d) {
        const double inside = chord(a, u, d);
        return st_ball * inside + st_air * (d - inside);
    };
    const prism::HenyeyGreenstein<double> hg{airlight_g};
    const auto f = [&](double s) {
        const prism::Vec3<double> p = origin + s * w, to_point = p - light;
        const double d = prism::length(to_point);
        const bool in_ball = dot(p, p) < radius * radius;
        const double sigma_s = (in_ball ? ball_scale : 1.0) * airlight_scattering[c];
        return sigma_s * std::exp(-optical(origin, w, s)) * hg.value(-dot(to_point, w) / d) / (d * d) * std::exp(-optical(light, to_point / d, d));
    };
    // The stretches: split where the ray enters and leaves the ball.
    std::vector<double> cuts{0.0};
    const double b = dot(origin, w), disc = b * b - (dot(origin, origin) - radius * radius);
    if (disc > 0)
        for (const double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)})
            if (t > 0 && t < length) cuts.push_back(t);
    cuts.push_back(length);
    double total = 0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double from = cuts[k], to = cuts[k + 1];
        const int m = std::max(2, 2 * int(double(n) * (to - from) / length / 2));
        const double h = (to - from) / m;
        double sum = f(from) + f(to);
        for (int i = 1; i < m; ++i) sum += f(from + i * h) * (i % 2 ? 4 : 2);
        total += sum * h / 3;
    }
    return total;
}

} // namespace test
