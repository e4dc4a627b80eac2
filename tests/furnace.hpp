// SPDX-License-Identifier: MIT
// The furnace every integrator is tested in (pbrt-v4's): the inside of a unit sphere
// of diffuse albedo 0.5, lit by point lights of total intensity pi. With the light at
// the centre the wall receives E = pi directly, and each bounce gives back half:
// L = rho / pi * E / (1 - rho) = 1.0 with global illumination, 0.5 from direct light.
// Four lights of pi / 4 off the centre: direct light varies over the wall, but a
// sphere's wall lights itself evenly (every patch sees every other with a form factor
// of its area over 4 pi), so L(x) = rho / pi (E_direct(x) + pi rho / (1 - rho)).
#pragma once

#include <prism/prism.hpp>

#include <array>

namespace test {

inline constexpr std::array<prism::Vec3<float>, 4> furnace_lights{
    prism::Vec3<float>{0.3f, 0.1f, 0.0f}, prism::Vec3<float>{-0.2f, 0.4f, 0.1f}, prism::Vec3<float>{0.0f, -0.3f, -0.35f}, prism::Vec3<float>{0.1f, 0.0f, 0.5f}};

/// One light of intensity pi at the centre, or four of pi / 4 at furnace_lights.
inline auto furnace_scene(bool four)
{
    using namespace prism;
    const auto light = [&](int i) {
        return four ? PointLight<float>{.position = furnace_lights[std::size_t(i)], .intensity = Rgb<float>(pi<float> / 4)}
                    : PointLight<float>{.position = {0, 0, 0}, .intensity = Rgb<float>(i == 0 ? pi<float> : 0.0f)};
    };
    return Scene{Lights{light(0), light(1), light(2), light(3)},
                 Object{Sphere<float>({0, 0, 0}, 1), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}}};
}

/// What the closed form says the wall at unit point p reads, with global illumination
/// (gi) or direct light only, for furnace_scene(four).
inline double furnace_radiance(const prism::Vec3<double>& p, bool four, bool gi)
{
    const double rho = 0.5;
    double direct = 0;
    if (!four) direct = prism::pi<double>;
    else
        for (const auto& light : furnace_lights) {
            const prism::Vec3<double> v = prism::Vec3<double>(light) - p;
            direct += prism::pi<double> / 4 * prism::dot(v, -p) / std::pow(prism::length(v), 3.0);
        }
    return rho / prism::pi<double> * (direct + (gi ? prism::pi<double> * rho / (1 - rho) : 0.0));
}

/// The mean over `count` rays from near the centre in uniform directions of
/// radiance(ray, rng) divided by the closed form at the wall it reaches (so 1.0 when
/// right), for furnace_scene(four).
template <class Radiance>
double furnace_mean(bool four, Radiance&& radiance, int count, bool gi = true, std::uint64_t seed = 1)
{
    prism::Pcg32 rng(seed, 7u);
    double sum = 0;
    const prism::Vec3<float> eye{0.01f, 0.02f, 0.03f};
    for (int i = 0; i < count; ++i) {
        const prism::Vec3<float> d = prism::uniform_sphere<float>(rng);
        // Where the ray meets the unit sphere.
        const double b = prism::dot(prism::Vec3<double>(eye), prism::Vec3<double>(d));
        const double t = -b + std::sqrt(b * b - (prism::length_squared(prism::Vec3<double>(eye)) - 1));
        const prism::Vec3<double> p = prism::Vec3<double>(eye) + t * prism::Vec3<double>(d);
        sum += double(radiance({eye, d}, rng).x) / furnace_radiance(p, four, gi);
    }
    return sum / count;
}

} // namespace test
