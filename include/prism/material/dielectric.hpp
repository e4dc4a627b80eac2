// SPDX-License-Identifier: MIT
// Dielectric: glass or water; Fresnel-weighted reflection and Snell refraction,
// Beer-Lambert absorption inside.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/traits.hpp>
#include <prism/optics/fresnel.hpp>

namespace prism {

/// A clear or tinted dielectric. The Fresnel policy (ExactFresnel or SchlickFresnel)
/// splits light between reflection and refraction; kr and kt are the seed's scale
/// factors on top; absorption is Beer-Lambert's coefficient per unit length, per channel.
/// The outside medium has index 1.
template <Scalar T = float, class Fresnel = ExactFresnel>
    requires FresnelPolicy<Fresnel, T>
struct Dielectric {
    using scalar_type = T;
    using fresnel_policy = Fresnel;
    static constexpr bool has_diffuse = false;
    static constexpr bool reflects = true;
    static constexpr bool transmits = true;

    T ior = T(1.5);
    Rgb<T> absorption{T(0)};
    T kr = T(1);
    T kt = T(1);

    /// Fresnel reflectance for incident cosine cos_i and eta = n_t / n_i.
    [[nodiscard]] constexpr T fresnel(T cos_i, T eta) const noexcept { return Fresnel::reflectance(cos_i, eta); }

    constexpr void validate() const
    {
        detail::require_positive("Dielectric ior", ior);
        detail::require_non_negative("Dielectric absorption", absorption);
        detail::require_non_negative("Dielectric kr", kr);
        detail::require_non_negative("Dielectric kt", kt);
    }
};

static_assert(Material<Dielectric<float>> && Material<Dielectric<double, SchlickFresnel>>);

} // namespace prism
