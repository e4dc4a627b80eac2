// SPDX-License-Identifier: MIT
// Light arriving from each light at a surface point, by shadow rays: shared by the integrators.
#pragma once

#include <prism/core/offset.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/light/light.hpp>
#include <prism/material/scattering.hpp>
#include <prism/scene/scene.hpp>

namespace prism {

/// Shadow rays stop this fraction short of a point light, so a light placed on a
/// surface is not shadowed by that surface (pbrt's ShadowEpsilon).
template <Scalar T>
inline constexpr T shadow_epsilon = T(1e-4);

/// For each light in front of the surface on the side the ray arrived from, call
/// f(sample, v, cos): the light's sample at the point, the shadow ray's transmittance v
/// (0 when occluded, Beer-Lambert through glass) and the cosine at the surface (the
/// shading normal's: shading_cosine). Lights behind the surface are not visited: they
/// count as occluded. How dielectrics shadow: see Scene::transmittance.
template <ShadowsThroughGlass Glass = ShadowsThroughGlass::attenuated, class SceneT, Scalar T, class F>
void for_each_light_arriving(const SceneT& scene, const Crossing<T>& hit, F&& f)
{
    const Vec3<T> n = hit.facing_normal(), n_shading = hit.facing_shading();
    scene.for_each_light([&](const auto& light) {
        const LightSample<T> s = light.sample(hit.point);
        const T cos = shading_cosine(n_shading, n, s.wi);
        if (!(cos > T(0))) return;
        const Ray<T> shadow = spawn_ray(hit.point, hit.error, hit.normal, s.wi);
        f(s, scene.template transmittance<Glass>(shadow, s.distance * (T(1) - shadow_epsilon<T>)), cos);
    });
}

} // namespace prism
