// SPDX-License-Identifier: MIT
// Conductor: a metal mirror, with a constant kr or the complex-index Fresnel equations.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/traits.hpp>
#include <prism/optics/fresnel.hpp>

#include <complex>

namespace prism {

/// Reflectance independent of angle (the lecture notes' approximation for metals).
template <Scalar T = float>
struct ConstantKr {
    Rgb<T> kr{T(1)};

    [[nodiscard]] constexpr Rgb<T> reflectance(T) const noexcept { return kr; }
    constexpr void validate() const { detail::require_non_negative("ConstantKr kr", kr); }
};

/// The Fresnel equations for a complex index n + i k per channel (seed errata 5).
template <Scalar T = float>
struct ComplexIor {
    Rgb<T> eta{T(1)}; ///< real part n
    Rgb<T> k{T(0)};   ///< extinction coefficient

    [[nodiscard]] Rgb<T> reflectance(T cos_i) const noexcept
    {
        return {fresnel_conductor(cos_i, std::complex<T>(eta.x, k.x)),
                fresnel_conductor(cos_i, std::complex<T>(eta.y, k.y)),
                fresnel_conductor(cos_i, std::complex<T>(eta.z, k.z))};
    }

    constexpr void validate() const
    {
        detail::require_finite("ComplexIor eta", eta);
        if (!(eta.x > T(0) && eta.y > T(0) && eta.z > T(0)))
            detail::throw_invalid("ComplexIor eta must be > 0 in every channel, got ", detail::describe(eta));
        detail::require_non_negative("ComplexIor k", k);
    }
};

/// A perfect specular conductor: mirror reflection weighted by Fresnel(cos_i), no diffuse.
template <Scalar T = float, class Fresnel = ConstantKr<T>>
struct Conductor {
    using scalar_type = T;
    static constexpr bool has_diffuse = false;
    static constexpr bool reflects = true;
    static constexpr bool transmits = false;

    Fresnel fresnel{};

    [[nodiscard]] Rgb<T> reflectance(T cos_i) const noexcept { return fresnel.reflectance(cos_i); }
    constexpr void validate() const { fresnel.validate(); }
};

/// A mirror with constant reflectance kr.
template <Scalar T = float>
using Mirror = Conductor<T, ConstantKr<T>>;

/// A metal with a measured complex index.
template <Scalar T = float>
using Metal = Conductor<T, ComplexIor<T>>;

static_assert(Material<Mirror<float>> && Material<Metal<double>>);

} // namespace prism
