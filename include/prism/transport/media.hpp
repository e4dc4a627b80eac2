// SPDX-License-Identifier: MIT
// What the media a path is in (medium/nesting.hpp's MediumStack) do to light on its way:
// the index on an interface's far side, the attenuation along a segment, the parts of a
// path that lie in a medium that scatters (an object's interior, or the scene's air when it
// is FilledAir, straight or curved), and what such air lets through along a shadow ray.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/air.hpp>
#include <prism/medium/medium.hpp>
#include <prism/medium/nesting.hpp>
#include <prism/scene/hit.hpp>
#include <prism/scene/shadow.hpp>
#include <prism/transport/travel.hpp>

#include <optional>

namespace prism {

/// The refractive index of the medium of `object` for light of one wavelength (0: white):
/// 1 for none (the scene's air) or for an object that does not transmit.
template <class SceneT>
[[nodiscard]] typename SceneT::scalar_type index_of(const SceneT& scene, const Inside* object, typename SceneT::scalar_type wavelength_nm) noexcept
{
    using T = typename SceneT::scalar_type;
    if (object == nullptr) return T(1);
    return scene.visit_material(object->slot, object->index, [&]<class M>(const M& material) -> T {
        if constexpr (M::transmits)
            return index_at(material, wavelength_nm);
        else
            return T(1);
    });
}

/// Light that reached `hit` along `ray` travelled in the medium the ray is in: multiply
/// by what it lets through over that length. A ray known to be in no object leaving a
/// dielectric travelled inside it (the camera started there, or no nesting is tracked).
template <class SceneT, Material M>
void attenuate_segment(const SceneT& scene, const MediumStack& media, const M& material, const Crossing<typename M::scalar_type>& hit,
                       const Ray<typename M::scalar_type>& ray, Rgb<typename M::scalar_type>& light) noexcept
{
    if (const Inside* in = media.top()) {
        scene.visit_material(in->slot, in->index, [&]<class N>(const N& medium_material) {
            // (A medium that scatters was crossed by fly_through_medium, its weight taken.)
            if constexpr (N::transmits && !has_scattering_interior<N>) light *= transmittance_along(medium_material.medium(), ray, typename M::scalar_type(0), hit.t);
        });
    } else {
        attenuate_inside(material, hit, ray, light);
    }
}

/// f(medium, t0, t1) for the part [t0, t1] of `segment` (unit direction, up to t_max: the
/// surface it meets there, or infinity) that lies in a medium that scatters: all of it in
/// an object whose interior scatters, the part inside its region in FilledAir; nothing in
/// a medium that only absorbs (attenuate_segment's) or in clear air.
template <class SceneT, class Air, Scalar T, class F>
void for_scattering_medium_along(const SceneT& scene, const Air& air, const MediumStack& media, const Ray<T>& segment, T t_max, F&& f)
{
    if (const Inside* in = media.top()) {
        if constexpr (SceneT::has_scattering_media) {
            scene.visit_material(in->slot, in->index, [&]<class N>(const N& material) {
                if constexpr (has_scattering_interior<N>) f(material.medium(), T(0), t_max);
            });
        }
    } else if constexpr (air_scatters<Air>) {
        const Interval<T> inside = air.bounds().clip(segment, {T(0), t_max});
        if (!inside.empty()) f(air.medium, inside.min, inside.max);
    }
}

/// The first surface a path from `ray` meets in the media it is in (`media`: inside an
/// object straight, in the air along the air's curve), with `segment` and `path` as
/// first_hit_in_air's, and f(medium, piece, t0, t1, before) shown, in order along the
/// way, each part [t0, t1] of a straight piece (unit direction) that lies in a medium
/// that scatters (for_scattering_medium_along), `before` the path's length up to the
/// piece's origin. f returns false to stop the path there (a walker that scattered or was
/// absorbed; then nothing is met); true to go on.
template <class SceneT, class Air, class F>
[[nodiscard]] std::optional<Hit<typename SceneT::scalar_type>> first_hit_through_media(const SceneT& scene, const Air& air, const MediumStack& media,
                                                                                      const Ray<typename SceneT::scalar_type>& ray,
                                                                                      Ray<typename SceneT::scalar_type>& segment,
                                                                                      typename SceneT::scalar_type* path, F&& f)
{
    using T = typename SceneT::scalar_type;
    bool stopped = false;
    const auto on_piece = [&](const Ray<T>& piece, T length, T before) {
        for_scattering_medium_along(scene, air, media, piece, length, [&](const auto& medium, T t0, T t1) { stopped = !f(medium, piece, t0, t1, before); });
        return !stopped;
    };
    auto hit = media.empty() ? first_hit_in_air(scene, air, ray, segment, path, on_piece) : first_hit_in_air(scene, StraightAir{}, ray, segment, path, on_piece);
    if (stopped) return std::nullopt;
    return hit;
}

/// What the scene's air lets through along `ray` (unit direction) over `distance` (may be
/// infinite): its medium's transmittance over the part inside its region where it is
/// FilledAir, 1 in clear air. (Glass and the media inside objects are the scene's
/// transmittance.)
template <class Air, Scalar T>
[[nodiscard]] Rgb<T> air_transmittance(const Air& air, const Ray<T>& ray, T distance) noexcept
{
    if constexpr (air_scatters<Air>) {
        const Interval<T> inside = air.bounds().clip(ray, {T(0), distance});
        if (inside.empty()) return Rgb<T>(T(1));
        return transmittance_along(air.medium, ray, inside.min, inside.max);
    } else {
        (void)air, (void)ray, (void)distance;
        return Rgb<T>(T(1));
    }
}

/// What the scene's air lets through along a shadow ray from `ray.origin` over `distance`,
/// which the scene's transmittance<Glass> passes: air_transmittance over the stretches
/// outside the objects it passes through (Scene::for_each_stretch_outside), whose insides
/// hold their own media and no air. From inside a ball of smoke, the air beyond it counts;
/// through one, the air inside it does not.
template <ShadowsThroughGlass Glass, class SceneT, class Air, Scalar T>
[[nodiscard]] Rgb<T> air_transmittance(const SceneT& scene, const Air& air, const Ray<T>& ray, T distance) noexcept
{
    if constexpr (air_scatters<Air>) {
        Rgb<T> tr{T(1)};
        scene.template for_each_stretch_outside<Glass>(ray, distance, [&](T t0, T t1) {
            const Interval<T> inside = air.bounds().clip(ray, {t0, t1});
            if (!inside.empty()) tr *= transmittance_along(air.medium, ray, inside.min, inside.max);
        });
        return tr;
    } else {
        (void)scene, (void)air, (void)ray, (void)distance;
        return Rgb<T>(T(1));
    }
}

} // namespace prism
