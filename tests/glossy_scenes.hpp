// SPDX-License-Identifier: MIT
// Scenes every integrator is held to on glossy surfaces, with what they must read from
// outside the integrators:
// - the glossy furnace: a convex glossy sphere under a uniform sky of radiance 1, where
//   every reflected ray escapes, so the sphere reads its lobe's directional albedo
//   toward the camera, found by quadrature of the lobe (bsdf_checks.hpp);
// - the glossy floor lit through a mirror: a point light beside a vertical mirror over
//   a glossy floor, whose light by way of the mirror (L S G) is the light of the
//   light's mirror image shining through the mirror's frame, which a second scene holds
//   with no mirror and Whitted lights exactly (the floor the camera sees is lit through
//   the frame everywhere).
#pragma once

#include <prism/prism.hpp>

#include "bsdf_checks.hpp"

#include <cmath>

namespace test {

/// A unit sphere at the origin of `material` under a uniform sky of radiance 1.
template <class M>
auto glossy_furnace(const M& material)
{
    using namespace prism;
    using T = typename M::scalar_type;
    return Scene{Lights{EnvironmentLight<T>{.radiance = Rgb<T>(T(1))}}, Object{Sphere<T>({0, 0, 0}, 1), material}};
}

/// A ray that meets glossy_furnace's sphere where its normal is theta (degrees) from the ray's reverse.
template <prism::Scalar T>
prism::Ray<T> furnace_ray(double theta_deg)
{
    const double s = std::sin(theta_deg * prism::pi<double> / 180);
    return {{T(s), T(0), T(5)}, {T(0), T(0), T(-1)}};
}

/// What glossy_furnace's sphere reads along furnace_ray(theta): the lobe's albedo, by
/// quadrature of its density part and, for a lobe with a delta part (a smooth coat's
/// mirror), by 4 million draws of the lobe in double (its mean weight).
template <class M>
double furnace_albedo(const M& material, double theta_deg)
{
    const auto lobe = material.glossy({});
    prism::Random rng(5, 5);
    bool delta = false;
    for (int i = 0; i < 64 && !delta; ++i) {
        using T = typename M::scalar_type;
        const auto s = lobe.sample(prism::Vec3<T>(polar(theta_deg, 0)), rng.uniform<T>(), rng.uniform<T>(), rng.uniform<T>(), prism::Transport::radiance);
        delta = s && s->delta;
    }
    return delta ? sample_lobe(lobe, polar(theta_deg, 0), 4000000).albedo : albedo_by_quadrature(lobe, polar(theta_deg, 0));
}

inline constexpr prism::Vec3<float> mirror_light{0.0f, 1.0f, 0.0f};  ///< the light beside the mirror
inline constexpr prism::Vec3<float> mirror_image{2.0f, 1.0f, 0.0f};  ///< its image in the mirror x = 1

/// A glossy floor (y = 0) of `floor`, a point light of intensity 4 at mirror_light and
/// a mirror of reflectance 1 in the plane x = 1 (y in [0, 3], z in [-3, 3]).
template <class M>
auto floor_by_mirror(const M& floor)
{
    using namespace prism;
    return Scene{Lights{PointLight<float>{.position = mirror_light, .intensity = Rgb<float>(4)}}, Object{Plane<float>({0, 1, 0}, 0), floor},
                 Object{Quad<float>({1, 0, -3}, {0, 3, 0}, {0, 0, 6}), Mirror<float>{{.kr = Rgb<float>(1)}}}};
}

/// The same floor lit by the light's image alone (no mirror): what floor_by_mirror's
/// floor receives by way of the mirror, wherever the camera below sees it.
template <class M>
auto floor_by_image(const M& floor)
{
    using namespace prism;
    return Scene{Lights{PointLight<float>{.position = mirror_image, .intensity = Rgb<float>(4)}}, Object{Plane<float>({0, 1, 0}, 0), floor}};
}

/// A camera looking down at floor_by_mirror's floor between x = -1 and 0.6.
inline prism::Camera<float> floor_camera() { return {.position = {-0.2f, 2.5f, 0.2f}, .look_at = {-0.2f, 0, 0}, .up = {0, 0, -1}, .fov = 35}; }

} // namespace test
