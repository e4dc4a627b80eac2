// SPDX-License-Identifier: MIT
// DirectionalLight: parallel light from infinitely far away (the sun).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/sampling.hpp>
#include <prism/light/light.hpp>

namespace prism {

/// Parallel light travelling along `direction`, with irradiance E on a surface facing it.
template <Scalar T = float>
struct DirectionalLight {
    /// The precision of the light.
    using scalar_type = T;
    /// A delta light: from one point (one direction), seen by shadow rays only.
    static constexpr bool delta = true;

    Vec3<T> direction{T(0), T(-1), T(0)}; ///< the direction the light travels
    Rgb<T> irradiance{T(1)}; ///< the irradiance on a surface facing it (W/m^2)

    /// The light arriving at any point: from -direction, from infinitely far, with the irradiance.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>&) const noexcept
    {
        return {-normalize(direction), infinity<T>, irradiance};
    }
    /// The same: a delta light needs no random numbers.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p, const Vec2<T>&) const noexcept { return sample(p); }

    /// E pi r^2 onto the target sphere, or onto the sphere around the whole scene when
    /// aimed everywhere (nothing when the scene has nothing bounded to light).
    [[nodiscard]] Rgb<T> photon_power(const PhotonAim<T>& aim) const noexcept
    {
        if (!aim.scene) return Rgb<T>(T(0));
        const T radius = aim.target ? aim.target->radius : aim.scene->radius;
        return irradiance * (pi<T> * radius * radius);
    }

    /// Uniform over the disk of the sphere's radius facing the light, upstream of
    /// everything bounded (the projection disk), travelling along `direction`.
    [[nodiscard]] EmittedPhoton<T> emit_photon(const PhotonAim<T>& aim, T u, T v) const noexcept
    {
        const BoundingSphere<T>& scene = *aim.scene;
        const BoundingSphere<T>& sphere = aim.target ? *aim.target : scene;
        const Vec3<T> axis = normalize(direction);
        const T upstream = length(sphere.center - scene.center) + scene.radius + sphere.radius;
        return {{uniform_disk(sphere.center - upstream * axis, axis, sphere.radius, u, v), axis}};
    }

    /// A ray along `direction` from a point uniform (u_position) over the disk of the
    /// scene's sphere that faces the light, upstream of it, carrying E.
    [[nodiscard]] EmissionSample<T> emission(const BoundingSphere<T>& scene, const Vec2<T>& u_position, const Vec2<T>&) const noexcept
    {
        const Vec3<T> axis = normalize(direction);
        return {{entry_point(scene, axis, u_position), axis}, irradiance, entry_pdf(scene), T(1), T(1), true};
    }

    /// The densities emission() draws a ray along `direction` with (any other: none, but
    /// the estimators never ask, a delta direction being found by nothing else).
    [[nodiscard]] EmissionPdf<T> emission_pdf(const Vec3<T>&, const BoundingSphere<T>& scene) const noexcept
    {
        return {entry_pdf(scene), T(1)};
    }

    /// Throws std::invalid_argument, naming the parameter, for a zero or non-finite direction or a negative irradiance.
    constexpr void validate() const
    {
        detail::require_nonzero("DirectionalLight direction", direction);
        detail::require_non_negative("DirectionalLight irradiance", irradiance);
    }
};

static_assert(Light<DirectionalLight<float>>);

} // namespace prism
