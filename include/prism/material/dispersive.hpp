// SPDX-License-Identifier: MIT
// A dispersive dielectric: glass or water whose index depends on the wavelength, so
// white light refracting through it fans out into colours (a prism's rainbow).
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/homogeneous.hpp>
#include <prism/optics/dispersion.hpp>
#include <prism/optics/fresnel.hpp>

namespace prism {

/// A dielectric whose index is `glass.index(lambda)` (a Dispersion policy: Sellmeier or
/// Cauchy; glass::bk7, glass::f2, glass::water). The integrators split white light into
/// wavelength bands where it refracts through it (Whitted::Config::dispersion_bands),
/// and each band, and each photon, then refracts at its own index; refractive_index()
/// without a wavelength is n_d (587.56 nm). Otherwise it is Dielectric: the Fresnel
/// policy, the interior medium and Whitted's kr and kt.
template <Scalar T = float, Dispersion Glass = Sellmeier<double>, class Fresnel = ExactFresnel, Medium Interior = Homogeneous<T>>
    requires FresnelPolicy<Fresnel, T> && std::same_as<typename Interior::scalar_type, T>
struct DispersiveDielectric {
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
    /// Splits white light into wavelength bands where it refracts.
    static constexpr bool disperses = true;

    Glass glass = glass::bk7<typename Glass::scalar_type>; ///< the glass's index against wavelength (Sellmeier or Cauchy)
    Interior interior{}; ///< the medium inside (Beer-Lambert absorption)
    T kr = T(1); ///< Whitted's scale on the reflected ray
    T kt = T(1); ///< Whitted's scale on the refracted ray
    int priority = 0; ///< where it overlaps another transmissive object, the higher priority's medium wins (medium/nesting.hpp)

    /// The index at a vacuum wavelength in nanometres.
    [[nodiscard]] T refractive_index(T wavelength_nm) const noexcept
    {
        return T(glass.index(typename Glass::scalar_type(wavelength_nm)));
    }
    /// The index for white light that is not split: n_d.
    [[nodiscard]] T refractive_index() const noexcept { return refractive_index(T(fraunhofer::d)); }
    /// The Fresnel reflectance at the interface (eta = n_t / n_i).
    [[nodiscard]] constexpr T fresnel(T cos_i, T cos_t, T eta) const noexcept { return Fresnel::reflectance(cos_i, cos_t, eta); }
    /// Grey: kr.
    [[nodiscard]] constexpr Rgb<T> reflection_tint() const noexcept { return Rgb<T>(kr); }
    /// Grey: kt.
    [[nodiscard]] constexpr Rgb<T> transmission_tint() const noexcept { return Rgb<T>(kt); }
    /// The medium inside.
    [[nodiscard]] constexpr const Interior& medium() const noexcept { return interior; }

    /// Throws std::invalid_argument, naming the parameter, for a bad glass, an index <= 0 anywhere from 380 to 780 nm, a bad interior or a negative kr or kt.
    constexpr void validate() const
    {
        glass.validate();
        // An index at or below 0 anywhere in the visible range is no glass.
        for (T lambda = T(380); lambda <= T(780); lambda += T(5))
            if (!(refractive_index(lambda) > T(0))) detail::throw_invalid("DispersiveDielectric glass index must be > 0 from 380 to 780 nm, got ", refractive_index(lambda), " at ", lambda, " nm");
        interior.validate();
        detail::require_non_negative("DispersiveDielectric kr", kr);
        detail::require_non_negative("DispersiveDielectric kt", kt);
    }
};

static_assert(Material<DispersiveDielectric<float>> && disperses<DispersiveDielectric<float>>);
static_assert(Material<DispersiveDielectric<double, Cauchy<double>>>);

} // namespace prism
