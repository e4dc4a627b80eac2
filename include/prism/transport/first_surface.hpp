// SPDX-License-Identifier: MIT
// What a camera ray meets first (its albedo, shading normal and distance): the surface
// layers a render writes beside its image (render/layers.hpp), the same for every
// integrator.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/traits.hpp>
#include <prism/transport/travel.hpp>

#include <optional>

namespace prism {

/// The first surface a camera ray meets.
template <Scalar T>
struct SurfaceSample {
    Rgb<T> albedo;  ///< a diffuse lobe's reflectance there, a glossy one's albedo toward the camera (GlossyAt::albedo); 1 for a surface with delta lobes only (glass, mirrors)
    Vec3<T> normal; ///< the shading normal, facing the ray
    T distance;     ///< the path's length from the camera's pinhole (along a curved ray in graded air)
};

/// What `ray` meets first in `scene` through `air` (straight or graded), as an
/// integrator that starts its camera rays in that air sees it.
template <class SceneT, class Air>
[[nodiscard]] std::optional<SurfaceSample<typename SceneT::scalar_type>> first_surface(const SceneT& scene, const Air& air,
                                                                                      const Ray<typename SceneT::scalar_type>& ray) noexcept
{
    using T = typename SceneT::scalar_type;
    Ray<T> segment = ray;
    T path = 0;
    const auto hit = first_hit_in_air(scene, air, ray, segment, &path);
    if (!hit) return std::nullopt;
    const Rgb<T> albedo = scene.visit_material(*hit, [&]<class M>(const M& material) {
        if constexpr (has_diffuse<M>) return diffuse_response(material, hit->crossing).albedo;
        else if constexpr (has_glossy<M>) return glossy_at(material, hit->crossing, normalize(segment.direction)).albedo();
        else return Rgb<T>(T(1));
    });
    return SurfaceSample<T>{albedo, hit->crossing.facing_shading(), path};
}

} // namespace prism
