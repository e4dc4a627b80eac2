// SPDX-License-Identifier: MIT
// The airlight test scene every integrator's single scattering is held to: a point light
// of intensity 1 at (0, 1, 0), a ray from (-2, 0, 0) along +x through unbounded coloured
// fog, and what it sees by single scattering,
//   L = int_0^inf sigma_s e^(-sigma_t s) p(cos) I / d^2 e^(-sigma_t d) ds
// (d the distance from the ray's point at s to the light), by Simpson's rule on [0, 120]
// in double: an outside number, computed without prism's integrators.
#pragma once

#include <prism/prism.hpp>

#include <cmath>

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

/// The ray the test looks along.
inline prism::Ray<float> airlight_ray() { return {{-2, 0, 0}, {1, 0, 0}}; }

/// The single-scattered radiance along airlight_ray() in channel c, by quadrature.
inline double airlight(int c)
{
    const double st = airlight_absorption[c] + airlight_scattering[c];
    const prism::HenyeyGreenstein<double> hg{airlight_g};
    const auto f = [&](double s) {
        const double x = -2 + s, d = std::sqrt(x * x + 1);
        return airlight_scattering[c] * std::exp(-st * s) * hg.value(-x / d) / (d * d) * std::exp(-st * d);
    };
    const int n = 400000;
    const double h = 120.0 / n;
    double sum = f(0) + f(120);
    for (int i = 1; i < n; ++i) sum += f(i * h) * (i % 2 ? 4 : 2);
    return sum * h / 3;
}

} // namespace test
