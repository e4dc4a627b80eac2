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

#include "guide_material.hpp" // docs/guide.md's recipe for a material

#include <algorithm>
#include <array>
#include <cstdint>

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
    prism::Random rng(seed, 7u);
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

// The two-lobe furnace: the same sphere, its wall a Lambertian base of albedo rho_d
// under a clear coat that mirrors a constant rho_s (the user guide's recipe for a material,
// outside the library), lit by one light of intensity pi at the centre. Inside a sphere a mirror
// sends every chord to another chord, so the radiance leaving the wall is the same
// everywhere (but along the exact normals, a set of no measure): L = L_d / (1 - rho_s),
// with L_d = rho_d E / pi. The wall's irradiance E is the light's E0 = pi, plus the
// light mirrored back through the centre to the opposite wall any number of times
// (E0 rho_s^k: caustics, L S+ D), plus pi L from the wall around:
//     E = E0 / (1 - rho_s) + rho_d E / (1 - rho_s)  =>  E = E0 / (1 - rho_s - rho_d),
//     L = rho_d / ((1 - rho_s) (1 - rho_s - rho_d))                 (E0 = pi).
// Each estimator reads its own part of it:
//   Whitted (direct light and mirrors)    rho_d / (1 - rho_s)
//   path tracer (E (S|D)* D L)            L_D = rho_d / (1 - rho_s - rho_d)
//   light tracer (L S (S|D)* D E)         (1 - rho_s) (L - L_D): of the paths that leave
//                                         the light by the coat, those the camera sees
//                                         directly (none can find E S+ D ... S L: both
//                                         ends of it are delta, integrator/path_tracer.hpp)
//   photon mapping (every path)           L

/// The material is the user guide's recipe for a material (ClearCoat, compiled from docs/guide.md by
/// tools/snippets.py), at its defaults.
inline constexpr float coat_diffuse = ClearCoat{}.base.x, coat_mirror = ClearCoat{}.coat;

inline auto coated_furnace_scene()
{
    using namespace prism;
    return Scene{Lights{PointLight<float>{.position = {0, 0, 0}, .intensity = Rgb<float>(pi<float>)}}, Object{Sphere<float>({0, 0, 0}, 1), ClearCoat{}}};
}

/// The closed forms above, for each estimator's share of the paths.
struct CoatedFurnace {
    static constexpr double d = coat_diffuse, s = coat_mirror;
    static constexpr double whitted = d / (1 - s);
    static constexpr double path_tracer = d / (1 - s - d);
    static constexpr double all = d / ((1 - s) * (1 - s - d));
    static constexpr double light_tracer = (1 - s) * (all - path_tracer);
};

/// The mean and the largest of `count` samples radiance(ray, rng).x along rays from
/// near the centre in uniform directions.
struct SampleStats {
    double mean = 0;
    double largest = 0;
};

template <class Radiance>
SampleStats coated_furnace_samples(Radiance&& radiance, int count, std::uint64_t seed = 1)
{
    prism::Random rng(seed, 7u);
    const prism::Vec3<float> eye{0.01f, 0.02f, 0.03f};
    SampleStats stats;
    for (int i = 0; i < count; ++i) {
        const double value = double(radiance(prism::Ray<float>{eye, prism::uniform_sphere<float>(rng)}, rng).x);
        stats.mean += value / count;
        stats.largest = std::max(stats.largest, value);
    }
    return stats;
}

/// The mean over an image's pixels (the camera inside the coated furnace).
inline double image_mean(const prism::Film& image)
{
    double sum = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) sum += image.at(x, y).x;
    return sum / (double(image.width()) * image.height());
}

} // namespace test
