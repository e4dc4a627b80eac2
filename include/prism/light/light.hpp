// SPDX-License-Identifier: MIT
// What a light tells a shading point and the photon tracer, and the Light concept.
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>

#include <concepts>

namespace prism {

/// Light arriving at a point from one light.
template <Scalar T>
struct LightSample {
    Vec3<T> wi{};        ///< unit direction from the point toward the light
    T distance = T(0);   ///< distance to the light (infinity for a directional light)
    Rgb<T> irradiance{}; ///< irradiance on a surface facing the light (W/m^2)
};

/// Where the photon tracer asks a light to send photons: toward `target` (a specular
/// object's bounding sphere, for the caustic map) or, when it is null, everywhere it
/// shines (the global map). `scene` encloses every bounded object (null when there is
/// none): a light from infinitely far away starts its photons just outside it.
template <Scalar T>
struct PhotonAim {
    const BoundingSphere<T>* target = nullptr; ///< a specular object's bounding sphere to aim at, or null: everywhere
    const BoundingSphere<T>* scene = nullptr; ///< the sphere around every bounded object, or null
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

/// A light: `sample(p)`, what arrives at a shading point; `photon_power(aim)`, the power
/// it sends where it is aimed (0: it sends no photons there); `emit_photon(aim, u, v)`,
/// the photon for the point (u, v) of the unit square, so that uniform (u, v) give its
/// emission's distribution over the aim (the photons share photon_power(aim)).
template <class L>
concept Light = requires(const L& light, const Vec3<typename L::scalar_type>& p, const PhotonAim<typename L::scalar_type>& aim,
                         typename L::scalar_type u) {
    requires Scalar<typename L::scalar_type>;
    { light.sample(p) } -> std::same_as<LightSample<typename L::scalar_type>>;
    { light.photon_power(aim) } -> std::same_as<Rgb<typename L::scalar_type>>;
    { light.emit_photon(aim, u, u) } -> std::same_as<EmittedPhoton<typename L::scalar_type>>;
    light.validate();
};

} // namespace prism
