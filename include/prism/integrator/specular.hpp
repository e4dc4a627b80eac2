// SPDX-License-Identifier: MIT
// How a mirror or a dielectric splits the light arriving at it: shared by the integrators.
#pragma once

#include <prism/material/traits.hpp>
#include <prism/optics/refract.hpp>

#include <optional>

namespace prism {

/// The weights of the reflected and transmitted rays at a specular surface, and the
/// transmitted direction (none under total internal reflection or for a conductor).
template <Scalar T>
struct SpecularSplit {
    Rgb<T> kr{T(0)};
    Rgb<T> kt{T(0)};
    std::optional<Vec3<T>> refracted;
};

/// d: the unit incident direction; n: the unit normal facing it; entering: whether d
/// goes into the material. A dielectric splits by Fresnel (all to reflection under total
/// internal reflection) times its kr and kt; a conductor reflects by its reflectance.
template <Material M, Scalar T>
[[nodiscard]] SpecularSplit<T> specular_split(const M& material, const Vec3<T>& d, const Vec3<T>& n, bool entering) noexcept
{
    const T cos_i = clamp(-dot(d, n), T(0), T(1));
    SpecularSplit<T> split;
    if constexpr (transmits<M>) {
        const T eta = entering ? material.ior : T(1) / material.ior;
        split.refracted = refract(d, n, eta);
        const T fresnel = split.refracted ? material.fresnel(cos_i, eta) : T(1);
        split.kr = Rgb<T>(material.kr * fresnel);
        split.kt = Rgb<T>(material.kt * (T(1) - fresnel));
    } else {
        split.kr = material.reflectance(cos_i);
    }
    return split;
}

} // namespace prism
