// SPDX-License-Identifier: MIT
// EnvironmentLight: light arriving from infinitely far away in every direction (a sky).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/sampling.hpp>
#include <prism/light/light.hpp>

namespace prism {

/// Radiance L arriving from every direction, from infinitely far away: a uniform sky, or
/// the white furnace's enclosure. Rays that leave the scene see it (as well as the scene's
/// background); shading points sample it over the sphere of directions, and its photons
/// enter through the disk that covers the scene, from directions uniform over the sphere
/// (as pbrt-v4's UniformInfiniteLight).
template <Scalar T = float>
struct EnvironmentLight {
    /// The precision of the light.
    using scalar_type = T;
    /// Not a delta light: drawn direction by direction.
    static constexpr bool delta = false;
    /// Seen by the rays that leave the scene.
    static constexpr bool at_infinity = true;

    Rgb<T> radiance{T(1)}; ///< the radiance arriving from every direction (W/(m^2 sr))

    /// The radiance arriving along -direction (from `direction`'s side of the sky).
    [[nodiscard]] constexpr Rgb<T> arriving_from(const Vec3<T>&) const noexcept { return radiance; }

    /// A direction uniform over the sphere, density 1 / (4 pi); its estimate L 4 pi.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>&, const Vec2<T>& u) const noexcept
    {
        return {uniform_sphere(u.x, u.y), infinity<T>, radiance * (T(4) * pi<T>), T(1) / (T(4) * pi<T>)};
    }

    /// The density sample() draws `direction` with: 1 / (4 pi).
    [[nodiscard]] constexpr T pdf(const Vec3<T>&) const noexcept { return T(1) / (T(4) * pi<T>); }

    /// The power entering the disk of radius R that faces each direction and covers the
    /// scene (or the target): L 4 pi pi R^2, from directions uniform over the sphere and
    /// points uniform over the disk (nothing when nothing bounded is there to light).
    [[nodiscard]] Rgb<T> photon_power(const PhotonAim<T>& aim) const noexcept
    {
        if (!aim.scene) return Rgb<T>(T(0));
        const T r = aim.target ? aim.target->radius : aim.scene->radius;
        return radiance * (T(4) * pi<T> * pi<T> * r * r);
    }

    /// A photon from a direction uniform over the sphere (from `rng`), through the point
    /// (u, v) of the disk facing it, upstream of everything bounded.
    [[nodiscard]] EmittedPhoton<T> emit_photon(const PhotonAim<T>& aim, T u, T v, Random& rng) const noexcept
    {
        const BoundingSphere<T>& scene = *aim.scene;
        const BoundingSphere<T>& sphere = aim.target ? *aim.target : scene;
        const auto [a, b] = rng.uniform2<T>();
        const Vec3<T> travel = -uniform_sphere(a, b);
        const T upstream = length(sphere.center - scene.center) + scene.radius + sphere.radius;
        return {{uniform_disk(sphere.center - upstream * travel, travel, sphere.radius, u, v), travel}};
    }

    /// A ray from a direction drawn as sample() draws it (u_direction), through a point
    /// uniform (u_position) over the disk of the scene's sphere that faces it, upstream of
    /// the sphere, carrying the radiance from there.
    [[nodiscard]] EmissionSample<T> emission(const BoundingSphere<T>& scene, const Vec2<T>& u_position, const Vec2<T>& u_direction) const noexcept
    {
        const LightSample<T> from = sample(scene.center, u_direction);
        return {{entry_point(scene, -from.wi, u_position), -from.wi}, arriving_from(from.wi), entry_pdf(scene), from.pdf, T(1), true};
    }

    /// The densities emission() draws a ray travelling along `leaving` (unit) with.
    [[nodiscard]] EmissionPdf<T> emission_pdf(const Vec3<T>& leaving, const BoundingSphere<T>& scene) const noexcept
    {
        return {entry_pdf(scene), pdf(-leaving)};
    }

    /// Throws std::invalid_argument, naming the parameter, for a negative or non-finite radiance.
    constexpr void validate() const { detail::require_non_negative("EnvironmentLight radiance", radiance); }
};

static_assert(Light<EnvironmentLight<float>>);

} // namespace prism
