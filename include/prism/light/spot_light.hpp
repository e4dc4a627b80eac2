// SPDX-License-Identifier: MIT
// SpotLight: a point light that shines into a cone, fading smoothly toward its edge.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/sampling.hpp>
#include <prism/light/light.hpp>

#include <cmath>

namespace prism {

/// A point light of radiant intensity I (W/sr) along `direction`, at full intensity within
/// `inner_angle` of it and none beyond `outer_angle` (half-angles in degrees), between them
/// falling off as smoothstep of the cosine (pbrt-v4's SpotLight). Photons leave only into
/// its cone.
template <Scalar T = float>
struct SpotLight {
    /// The precision of the light.
    using scalar_type = T;
    /// A delta light: from one point, seen by shadow rays only.
    static constexpr bool delta = true;

    Vec3<T> position{};                  ///< where the light is
    Vec3<T> direction{T(0), T(-1), T(0)}; ///< the cone's axis (need not be unit length)
    Rgb<T> intensity{T(1)};              ///< radiant intensity on the axis, per channel (W/sr)
    T inner_angle = T(30);               ///< half-angle of full intensity, degrees
    T outer_angle = T(35);               ///< half-angle beyond which nothing is emitted, degrees, >= inner_angle

    /// The share of the intensity sent at cos(angle from the axis): 1 inside the inner
    /// cone, 0 outside the outer one, smoothstep between.
    [[nodiscard]] T falloff(T cos_angle) const noexcept
    {
        const T cos_outer = cosine(outer_angle), cos_inner = cosine(inner_angle);
        if (cos_angle >= cos_inner) return T(1);
        if (cos_angle <= cos_outer) return T(0);
        const T x = (cos_angle - cos_outer) / (cos_inner - cos_outer);
        return x * x * (T(3) - T(2) * x);
    }

    /// Radiant power: I times the falloff integrated over the sphere, 2 pi I ((1 - cos
    /// inner) + (cos inner - cos outer) / 2), smoothstep's mean over the band being 1/2.
    [[nodiscard]] Rgb<T> power() const noexcept
    {
        const T cos_outer = cosine(outer_angle), cos_inner = cosine(inner_angle);
        return T(2) * pi<T> * ((T(1) - cos_inner) + T(0.5) * (cos_inner - cos_outer)) * intensity;
    }

    /// The light arriving at p: I falloff / r^2 from the light's position.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p) const noexcept
    {
        const Vec3<T> to_light = position - p;
        const T r2 = length_squared(to_light);
        const T r = prism::sqrt(r2);
        const Vec3<T> wi = to_light / r;
        return {wi, r, intensity * (falloff(dot(-wi, axis())) / r2)};
    }
    /// The same: a delta light needs no random numbers.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p, const Vec2<T>&) const noexcept { return sample(p); }

    /// Everywhere: the whole power. Toward a target sphere: I times the solid angle of the
    /// cone holding it (an upper bound; each photon's weight is its falloff), or nothing
    /// where the two cones do not meet.
    [[nodiscard]] Rgb<T> photon_power(const PhotonAim<T>& aim) const noexcept
    {
        if (!aim.target) return power();
        const ConeToward<T> c = ConeToward<T>::of(position, *aim.target);
        if (c.cos_half_angle <= T(-1)) return power();
        // The cones miss each other when their axes are further apart than their half-angles together.
        const T apart = std::acos(clamp(dot(c.axis, axis()), T(-1), T(1)));
        if (apart > std::acos(c.cos_half_angle) + radians(outer_angle)) return Rgb<T>(T(0));
        return intensity * c.solid_angle();
    }

    /// Everywhere: uniform over the outer cone, weighted by the falloff over its mean
    /// there. Toward a target: uniform over the cone holding it, weighted by the falloff.
    [[nodiscard]] EmittedPhoton<T> emit_photon(const PhotonAim<T>& aim, T u, T v) const noexcept
    {
        const Vec3<T> a = axis();
        if (aim.target) {
            const ConeToward<T> c = ConeToward<T>::of(position, *aim.target);
            if (c.cos_half_angle > T(-1)) {
                const Vec3<T> w = uniform_cone(c.axis, c.cos_half_angle, u, v);
                return {{position, w}, Rgb<T>(falloff(dot(w, a)))};
            }
            // The light is inside the target: everywhere, as photon_power says.
        }
        const Vec3<T> w = uniform_cone(a, cosine(outer_angle), u, v);
        return {{position, w}, Rgb<T>(falloff(dot(w, a)) * mean_falloff_inverse())};
    }

    /// A ray uniform over the outer cone (u_direction), carrying I times the falloff along
    /// it; the origin is the light's position (a delta in area: density 1).
    [[nodiscard]] EmissionSample<T> emission(const BoundingSphere<T>&, const Vec2<T>&, const Vec2<T>& u_direction) const noexcept
    {
        const Vec3<T> a = axis();
        const Vec3<T> w = uniform_cone(a, cosine(outer_angle), u_direction.x, u_direction.y);
        return {{position, w}, intensity * falloff(dot(w, a)), T(1), outer_cone_pdf()};
    }

    /// The densities emission() draws a ray leaving along `leaving` (unit) with: none
    /// outside the outer cone.
    [[nodiscard]] EmissionPdf<T> emission_pdf(const Vec3<T>& leaving, const BoundingSphere<T>&) const noexcept
    {
        return {T(1), dot(leaving, axis()) >= cosine(outer_angle) ? outer_cone_pdf() : T(0)};
    }

    /// The cone the light reaches (nothing beyond it): apex, unit axis and the cosine of
    /// its half-angle (transport/equiangular.hpp's within_cone keeps samples to it).
    struct Cone {
        Vec3<T> apex; ///< the light's position
        Vec3<T> axis; ///< unit, the way it points
        T cos_half;   ///< the cosine of the outer angle
    };
    /// See Cone.
    [[nodiscard]] Cone cone() const noexcept { return {position, axis(), cosine(outer_angle)}; }

    /// Throws std::invalid_argument, naming the parameter, for a non-finite position, a zero
    /// direction, a negative intensity, or angles outside 0 <= inner <= outer <= 180.
    constexpr void validate() const
    {
        detail::require_finite("SpotLight position", position);
        detail::require_nonzero("SpotLight direction", direction);
        detail::require_finite("SpotLight direction", direction);
        detail::require_non_negative("SpotLight intensity", intensity);
        if (!(inner_angle >= T(0) && inner_angle <= outer_angle))
            detail::throw_invalid("SpotLight inner_angle must be in [0, outer_angle = ", outer_angle, "], got ", inner_angle);
        if (!(outer_angle > T(0) && outer_angle <= T(180))) detail::throw_invalid("SpotLight outer_angle must be in (0, 180] degrees, got ", outer_angle);
        if (!is_finite(power())) detail::throw_invalid("SpotLight intensity ", detail::describe(intensity), " is too large: its power overflows");
    }

private:
    [[nodiscard]] static T radians(T degrees) noexcept { return degrees * (pi<T> / T(180)); }
    [[nodiscard]] static T cosine(T degrees) noexcept { return std::cos(radians(degrees)); }
    [[nodiscard]] Vec3<T> axis() const noexcept { return normalize(direction); }

    /// The density of a direction uniform over the outer cone, 1 / (2 pi (1 - cos outer)).
    [[nodiscard]] T outer_cone_pdf() const noexcept { return T(1) / (T(2) * pi<T> * (T(1) - cosine(outer_angle))); }

    /// 1 / (the falloff's mean over the outer cone): the solid angle of the outer cone
    /// over the falloff's integral.
    [[nodiscard]] T mean_falloff_inverse() const noexcept
    {
        const T cos_outer = cosine(outer_angle), cos_inner = cosine(inner_angle);
        const T integral = (T(1) - cos_inner) + T(0.5) * (cos_inner - cos_outer);
        return (T(1) - cos_outer) / integral;
    }
};

static_assert(Light<SpotLight<float>>);

} // namespace prism
