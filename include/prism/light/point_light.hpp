// SPDX-License-Identifier: MIT
// PointLight: an isotropic point source.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/sampling.hpp>
#include <prism/light/light.hpp>

namespace prism {

enum class Falloff {
    inverse_square, ///< physical: E = I / r^2
    none,           ///< E = I at any distance; only to mirror POV-Ray's `fade_power 0`
};

/// A point light of radiant intensity I (W/sr, per channel); its power is 4 pi I.
template <Scalar T = float>
struct PointLight {
    /// The precision of the light.
    using scalar_type = T;
    /// A delta light: from one point (one direction), seen by shadow rays only.
    static constexpr bool delta = true;

    Vec3<T> position{}; ///< where the light is
    Rgb<T> intensity{T(1)}; ///< radiant intensity per channel (W/sr)
    Falloff falloff = Falloff::inverse_square; ///< inverse-square (physical) or none (POV-Ray's `fade_power 0`)

    /// Radiant power Phi = 4 pi I.
    [[nodiscard]] constexpr Rgb<T> power() const noexcept { return T(4) * pi<T> * intensity; }

    /// The light arriving at p: its direction, distance and irradiance I / r^2 (I without falloff).
    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p) const noexcept
    {
        const Vec3<T> to_light = position - p;
        const T r2 = length_squared(to_light);
        const T r = prism::sqrt(r2);
        const Rgb<T> e = falloff == Falloff::inverse_square ? intensity / r2 : intensity;
        return {to_light / r, r, e};
    }
    /// The same: a delta light needs no random numbers.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p, const Vec2<T>&) const noexcept { return sample(p); }

    /// Everywhere: the whole power. Toward a target sphere: the power into the cone that
    /// holds it (Phi times the cone's solid angle / 4 pi), or the whole power when the
    /// light is inside it.
    [[nodiscard]] Rgb<T> photon_power(const PhotonAim<T>& aim) const noexcept
    {
        if (!aim.target) return power();
        const ConeToward<T> cone = ConeToward<T>::of(position, *aim.target);
        return cone.cos_half_angle <= T(-1) ? power() : power() * (T(0.5) * (T(1) - cone.cos_half_angle));
    }

    /// Uniform over the sphere of directions, or over the cone toward the target.
    [[nodiscard]] EmittedPhoton<T> emit_photon(const PhotonAim<T>& aim, T u, T v) const noexcept
    {
        const bool without_falloff = falloff == Falloff::none;
        if (!aim.target) return {{position, uniform_sphere(u, v)}, Rgb<T>(T(1)), without_falloff};
        const ConeToward<T> cone = ConeToward<T>::of(position, *aim.target);
        const Vec3<T> direction = cone.cos_half_angle <= T(-1) ? uniform_sphere(u, v) : uniform_cone(cone.axis, cone.cos_half_angle, u, v);
        return {{position, direction}, Rgb<T>(T(1)), without_falloff};
    }

    /// A ray uniform over the sphere of directions (u_direction), carrying I; the origin is
    /// the light's position (a delta in area: density 1).
    [[nodiscard]] EmissionSample<T> emission(const BoundingSphere<T>&, const Vec2<T>&, const Vec2<T>& u_direction) const noexcept
    {
        return {{position, uniform_sphere(u_direction.x, u_direction.y)}, intensity, T(1), T(1) / (T(4) * pi<T>)};
    }

    /// The densities emission() draws a ray leaving along `leaving` with.
    [[nodiscard]] EmissionPdf<T> emission_pdf(const Vec3<T>&, const BoundingSphere<T>&) const noexcept { return {T(1), T(1) / (T(4) * pi<T>)}; }

    /// Throws std::invalid_argument, naming the parameter, for a non-finite position or a negative intensity.
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
