// SPDX-License-Identifier: MIT
// Diffuse: a Lambertian surface with the seed's kd (diffuse) and ka (ambient) factors.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/texture.hpp>
#include <prism/material/traits.hpp>

namespace prism {

/// Lambertian reflection, BRDF = albedo / pi, scaled by kd for light from the lights and
/// by ka for the scene's ambient term (seen only where every light is occluded).
///
/// `phong` adds POV-Ray's Phong highlight, phong (R . L)^phong_size E / pi per light,
/// with R the mirror direction of the viewing ray (Phong 1975, as POV-Ray's `phong`
/// finish computes it, so that scenes written for POV-Ray look the same). It is a
/// non-physical highlight and off by default.
template <Scalar T = float, Texture Albedo = Solid<T>>
struct Diffuse {
    using scalar_type = T;
    static constexpr bool has_diffuse = true;
    static constexpr bool reflects = false;
    static constexpr bool transmits = false;

    Albedo albedo{};
    T kd = T(1);
    T ka = T(1);
    T phong = T(0);
    T phong_size = T(40);

    constexpr void validate() const
    {
        albedo.validate();
        detail::require_non_negative("Diffuse kd", kd);
        detail::require_non_negative("Diffuse ka", ka);
        detail::require_non_negative("Diffuse phong", phong);
        detail::require_positive("Diffuse phong_size", phong_size);
    }
};

static_assert(Material<Diffuse<float>>);

} // namespace prism
