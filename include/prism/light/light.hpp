// SPDX-License-Identifier: MIT
// What a light tells a shading point and the photon tracer, and the Light concept.
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>

#include <concepts>

namespace prism {

/// Light arriving at a point from one light, or from one point of it.
///
/// For a light at a single point or from a single direction (a delta light: point,
/// spot, directional) `irradiance` is what arrives. For a light with extent (an emitting
/// surface, the environment) the sample is one direction drawn with solid-angle density
/// `pdf`, and `irradiance` is the radiance from there over that density: an estimate
/// whose mean, over the light's samples, is the irradiance the light gives. Either way a
/// surface's reflected radiance is BRDF * irradiance * cos, unoccluded.
template <Scalar T>
struct LightSample {
    Vec3<T> wi{};        ///< unit direction from the point toward the light
    T distance = T(0);   ///< distance to the light (infinity for a directional or environment light)
    Rgb<T> irradiance{}; ///< irradiance on a surface facing the light (W/m^2), or its one-sample estimate
    T pdf = T(0);        ///< the solid-angle density wi was drawn with; 0 for a delta light

    /// Whether the light is a delta light (nothing else can find it: no MIS).
    [[nodiscard]] constexpr bool delta() const noexcept { return pdf == T(0); }
};

/// Where the photon tracer asks a light to send photons: toward `target` (a specular
/// object's bounding sphere, for the caustic map) or, when it is null, everywhere it
/// shines (the global map). `scene` encloses every bounded object (null when there is
/// none): a light from infinitely far away starts its photons just outside it.
template <Scalar T>
struct PhotonAim {
    const BoundingSphere<T>* target = nullptr; ///< a specular object's bounding sphere to aim at, or null: everywhere
    const BoundingSphere<T>* scene = nullptr; ///< the sphere around every bounded object, or null
    Rgb<T> power{T(0)}; ///< what photon_power(aim) said, once the tracer asked (0 while it asks)
};

/// One photon leaving a light: its ray, a weight on the power the tracer gives it (1
/// when the light's emission is uniform over what it aims at), and whether the light
/// does not fall off with distance (then the photon's power grows with the square of
/// the path it travelled when it is stored, as POV-Ray does for `fade_power 0`).
template <Scalar T>
struct EmittedPhoton {
    Ray<T> ray; ///< where the photon starts and where it goes
    Rgb<T> weight{T(1)}; ///< the weight on the power the tracer gives it
    bool without_falloff = false; ///< whether the light does not fall off with distance
};

/// A ray a light emits, drawn for the bidirectional estimators (integrator/bidirectional.hpp)
/// with the densities it was drawn with: what it carries over pdf_area pdf_direction is
/// one path's estimate of the light's power (times `cos` for a surface).
template <Scalar T>
struct EmissionSample {
    Ray<T> ray{};          ///< from the light (off an emitting surface), unit direction
    Rgb<T> radiance{T(0)}; ///< emitted along it: L for a light with extent, I for a point or spot light, E for a parallel one
    T pdf_area = T(0);     ///< the origin's density per unit area (1 for a point: a delta; 1 / (pi R^2) on the disk a light at infinity enters by)
    T pdf_direction = T(0); ///< the direction's density per steradian (1 for a parallel light: a delta)
    T cos = T(1);          ///< at an emitting surface, the cosine between its normal and the ray (1 for the others)
    bool from_infinity = false; ///< a light infinitely far away (parallel, environment): its origin is a disk's, in no measure the other strategies share
};

/// The densities with which a light's emission() draws a given ray (Emission's pdf_area
/// and pdf_direction): the other strategy a bidirectional estimator weighs a light
/// sample or a light a path met against.
template <Scalar T>
struct EmissionPdf {
    T area = T(0);      ///< per unit area of the origin
    T direction = T(0); ///< per steradian

    /// Their product: the density per unit area and steradian.
    [[nodiscard]] constexpr T both() const noexcept { return area * direction; }
};

/// Where a light infinitely far away (parallel, environment) emits from: the disk of the
/// scene's sphere's radius facing the unit direction `travel`, 2 R upstream of its centre.
/// Its point for u in the unit square, uniform by area.
template <Scalar T>
[[nodiscard]] Vec3<T> entry_point(const BoundingSphere<T>& scene, const Vec3<T>& travel, const Vec2<T>& u) noexcept
{
    return uniform_disk(scene.center - T(2) * scene.radius * travel, travel, scene.radius, u.x, u.y);
}

/// The density per unit area of entry_point's points, 1 / (pi R^2).
template <Scalar T>
[[nodiscard]] constexpr T entry_pdf(const BoundingSphere<T>& scene) noexcept
{
    return T(1) / (pi<T> * scene.radius * scene.radius);
}

/// Whether p is reached by rays travelling along -w (w unit, toward the light) from
/// entry_point's disk: within its radius of the axis, downstream of it. A point off it (an
/// unbounded floor far out) has no light path from the light: a bidirectional estimator's
/// light samples there share their paths with none.
template <Scalar T>
[[nodiscard]] constexpr bool reached_from_entry(const BoundingSphere<T>& scene, const Vec3<T>& w, const Vec3<T>& p) noexcept
{
    const Vec3<T> v = p - scene.center;
    const T along = dot(v, w);
    return along < T(2) * scene.radius && length_squared(v - along * w) <= scene.radius * scene.radius;
}

/// The cone of directions from a point that holds a sphere: its unit axis and the cosine
/// of its half-angle, -1 from inside the sphere (every direction).
template <Scalar T>
struct ConeToward {
    Vec3<T> axis;     ///< from the point toward the sphere's centre
    T cos_half_angle; ///< -1: every direction (the point is inside the sphere)

    /// The cone from `from` holding `sphere`.
    [[nodiscard]] static ConeToward of(const Vec3<T>& from, const BoundingSphere<T>& sphere) noexcept
    {
        const Vec3<T> to = sphere.center - from;
        const T distance = length(to);
        if (!(distance > sphere.radius)) return {to / distance, T(-1)};
        const T sin_half = sphere.radius / distance;
        return {to / distance, prism::sqrt(T(1) - sin_half * sin_half)};
    }

    /// Its solid angle, 2 pi (1 - cos), 4 pi for every direction.
    [[nodiscard]] T solid_angle() const noexcept { return T(2) * pi<T> * (T(1) - cos_half_angle); }
};

/// A light: `sample(p, u)`, what arrives at a shading point (for a light with extent,
/// from the point of it that u in the unit square picks); `photon_power(aim)`, the power it
/// sends where it is aimed (0: it sends no photons there); `emit_photon(aim, u, v)`, the
/// photon for the point (u, v) of the unit square, so that uniform (u, v) give its
/// emission's distribution over the aim (the photons share photon_power(aim)). `L::delta`
/// says at compile time whether it is a delta light (one sample tells all about it).
template <class L>
concept Light = requires(const L& light, const Vec3<typename L::scalar_type>& p, const PhotonAim<typename L::scalar_type>& aim,
                         typename L::scalar_type u, const Vec2<typename L::scalar_type>& uv) {
    requires Scalar<typename L::scalar_type>;
    { L::delta } -> std::convertible_to<bool>;
    { light.sample(p, uv) } -> std::same_as<LightSample<typename L::scalar_type>>;
    { light.photon_power(aim) } -> std::same_as<Rgb<typename L::scalar_type>>;
    light.validate();
} && (requires(const L& light, const PhotonAim<typename L::scalar_type>& aim, typename L::scalar_type u) {
    { light.emit_photon(aim, u, u) } -> std::same_as<EmittedPhoton<typename L::scalar_type>>;
} || requires(const L& light, const PhotonAim<typename L::scalar_type>& aim, typename L::scalar_type u, Random& rng) {
    { light.emit_photon(aim, u, u, rng) } -> std::same_as<EmittedPhoton<typename L::scalar_type>>;
});

/// The photon `light` emits for (u, v) of the unit square aimed by `aim`; a light that
/// needs more random numbers than two (a point on an area and a direction) draws them
/// from `rng`.
template <Light L>
[[nodiscard]] EmittedPhoton<typename L::scalar_type> emit_photon(const L& light, const PhotonAim<typename L::scalar_type>& aim,
                                                                 typename L::scalar_type u, typename L::scalar_type v, Random& rng) noexcept
{
    if constexpr (requires { light.emit_photon(aim, u, v, rng); }) return light.emit_photon(aim, u, v, rng);
    else return light.emit_photon(aim, u, v);
}

/// Whether L is a delta light.
template <Light L>
inline constexpr bool is_delta_light = bool(L::delta);

/// Whether L is seen by the rays that leave the scene (an environment light, which says
/// so with `at_infinity = true` and gives `arriving_from(direction)` and `pdf(direction)`).
template <class L>
inline constexpr bool is_at_infinity = requires { requires bool(L::at_infinity); };

/// Whether L casts its own shadow: a delta light whose shading comes from one point but whose
/// shadow is the share of a shape it sees (POV-Ray's area_light, PointGridLight), given as
/// `shadow(through, colour, rng)`, where through(point) is what a shadow ray to a point of
/// the light lets through and colour the light's colour at the shading point.
template <class L>
inline constexpr bool has_own_shadow = requires(const L& light, const Rgb<typename L::scalar_type>& colour, Random* rng) {
    { light.shadow([](const Vec3<typename L::scalar_type>&) { return Rgb<typename L::scalar_type>(); }, colour, rng) }
        -> std::same_as<Rgb<typename L::scalar_type>>;
};

} // namespace prism
