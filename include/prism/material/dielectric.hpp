// SPDX-License-Identifier: MIT
// Dielectric: glass or water; Fresnel-weighted reflection and Snell refraction into an
// interior medium (Beer-Lambert absorption by default).
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/homogeneous.hpp>
#include <prism/optics/fresnel.hpp>

namespace prism {

/// A clear or tinted dielectric of index `ior` (the outside has index 1). The Fresnel
/// policy (ExactFresnel or SchlickFresnel) splits light between reflection and
/// refraction; kr and kt are Whitted's (1980) scale factors on top; `interior` is the medium
/// inside (Homogeneous: Beer-Lambert absorption per unit length, per channel).
template <Scalar T = float, class Fresnel = ExactFresnel, Medium Interior = Homogeneous<T>>
    requires FresnelPolicy<Fresnel, T> && std::same_as<typename Interior::scalar_type, T>
struct Dielectric {
    /// The precision of the material.
    using scalar_type = T;
    /// The Fresnel policy (ExactFresnel or SchlickFresnel).
    using fresnel_policy = Fresnel;
    /// No diffuse lobe.
    static constexpr bool has_diffuse = false;
    /// Reflects at the interface, by Fresnel.
    static constexpr bool reflects = true;
    /// Transmits at the interface, by Fresnel.
    static constexpr bool transmits = true;

    T ior = T(1.5);      ///< the index of refraction inside
    Interior interior{}; ///< the medium that fills it
    T kr = T(1); ///< Whitted's scale on the reflected ray
    T kt = T(1); ///< Whitted's scale on the refracted ray
    int priority = 0; ///< where it overlaps another transmissive object, the higher priority's medium wins (medium/nesting.hpp)

    // Dielectric capabilities (DeltaTransmission, InteriorMedium)

    /// The index of refraction inside.
    [[nodiscard]] constexpr T refractive_index() const noexcept { return ior; }
    /// Fresnel reflectance for the incident and refracted cosines and eta = n_t / n_i.
    [[nodiscard]] constexpr T fresnel(T cos_i, T cos_t, T eta) const noexcept { return Fresnel::reflectance(cos_i, cos_t, eta); }
    /// Whitted's kr on the reflected ray and kt on the refracted one, grey.
    [[nodiscard]] constexpr Rgb<T> reflection_tint() const noexcept { return Rgb<T>(kr); }
    /// Grey: kt.
    [[nodiscard]] constexpr Rgb<T> transmission_tint() const noexcept { return Rgb<T>(kt); }
    /// The medium inside.
    [[nodiscard]] constexpr const Interior& medium() const noexcept { return interior; }
    /// Whether the index outside equals the index inside, with exact Fresnel: the
    /// reflectance is then 0 at every angle and the boundary vanishes but for kt
    /// (may_match_index). Schlick's approximation still reflects (1 - cos)^5 there.
    [[nodiscard]] constexpr bool index_matched(T outside_index) const noexcept { return std::same_as<Fresnel, ExactFresnel> && ior == outside_index; }

    /// Throws std::invalid_argument, naming the parameter, for ior <= 0, a bad interior, or a negative kr or kt.
    constexpr void validate() const
    {
        detail::require_index("Dielectric ior", ior);
        interior.validate();
        detail::require_non_negative("Dielectric kr", kr);
        detail::require_non_negative("Dielectric kt", kt);
    }
};

static_assert(Material<Dielectric<float>> && Material<Dielectric<double, SchlickFresnel>>);

} // namespace prism
