// SPDX-License-Identifier: MIT
// PointLight: an isotropic point source.
#pragma once

#include <prism/core/check.hpp>
#include <prism/light/light.hpp>

namespace prism {

enum class Falloff {
    inverse_square, ///< physical: E = I / r^2
    none,           ///< E = I at any distance; only to mirror POV-Ray's `fade_power 0`
};

/// A point light of radiant intensity I (W/sr, per channel); its power is 4 pi I.
template <Scalar T = float>
struct PointLight {
    using scalar_type = T;

    Vec3<T> position{};
    Rgb<T> intensity{T(1)};
    Falloff falloff = Falloff::inverse_square;

    /// Radiant power Phi = 4 pi I.
    [[nodiscard]] constexpr Rgb<T> power() const noexcept { return T(4) * pi<T> * intensity; }

    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p) const noexcept
    {
        const Vec3<T> to_light = position - p;
        const T r2 = length_squared(to_light);
        const T r = prism::sqrt(r2);
        const Rgb<T> e = falloff == Falloff::inverse_square ? intensity / r2 : intensity;
        return {to_light / r, r, e};
    }

    constexpr void validate() const
    {
        detail::require_finite("PointLight position", position);
        detail::require_non_negative("PointLight intensity", intensity);
        // The photon tracer divides the power among the photons: it must be finite too.
        if (!is_finite(power()))
            detail::throw_invalid("PointLight intensity ", detail::describe(intensity), " is too large: its power 4 pi I overflows");
    }
};

static_assert(Light<PointLight<float>>);

} // namespace prism
