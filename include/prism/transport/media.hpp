// SPDX-License-Identifier: MIT
// What the media a path is in (medium/nesting.hpp's MediumStack) do to light on its way:
// the index on an interface's far side, and the attenuation along a segment.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/nesting.hpp>

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
            if constexpr (N::transmits) light *= medium_material.medium().transmittance(hit.t * length(ray.direction));
        });
    } else {
        attenuate_inside(material, hit, ray, light);
    }
}

} // namespace prism
