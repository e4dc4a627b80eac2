// SPDX-License-Identifier: MIT
// The Medium concept: how light fares while it travels through the inside of an object
// or through the scene's air.
//
// A transmissive material names the medium that fills it (Dielectric's `interior`), and
// the integrators ask that medium, through `attenuate_inside` (material/scattering.hpp)
// and transport/media.hpp, what a path of a given length inside it lets through. A medium
// that also scatters (ScatteringMedium: Fog) tells a walker where it next scatters and by
// which phase function; the walk (transport/random_walk.hpp) asks it.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/core/rng.hpp>

#include <concepts>

namespace prism {

/// A medium in which light travels in straight lines and is attenuated along the way:
/// `transmittance(distance)` is the fraction of light, per channel, left after that
/// distance.
template <class X>
concept Medium = requires(const X& medium, typename X::scalar_type distance) {
    requires Scalar<typename X::scalar_type>;
    { medium.transmittance(distance) } -> std::same_as<Rgb<typename X::scalar_type>>;
    medium.validate();
};

/// Where a walker crossing a scattering medium next scatters, or that it reached the end
/// of its segment, and the weight its power takes (the medium's transmittance to there,
/// times its scattering coefficient where it scatters, over the density of the draw).
template <Scalar T>
struct FreeFlight {
    T distance;     ///< along the segment: where it scatters, or the segment's end
    Rgb<T> weight;  ///< multiplies the walker's power
    bool scattered; ///< whether it scattered before the segment's end
};

/// A medium that also scatters light: `sample_flight(ray, t_max, power, rng)`, where a
/// walker along ray (unit direction) carrying power next scatters before t_max;
/// `scattering_at(point)`, its scattering coefficient sigma_s there; and `phase`, the
/// phase function it scatters by.
template <class X>
concept ScatteringMedium = Medium<X> && requires(const X& medium, const Ray<typename X::scalar_type>& ray, typename X::scalar_type t,
                                                 const Rgb<typename X::scalar_type>& power, Pcg32& rng) {
    requires X::scatters;
    { medium.sample_flight(ray, t, power, rng) } -> std::same_as<FreeFlight<typename X::scalar_type>>;
    { medium.scattering_at(ray.origin) } -> std::same_as<Rgb<typename X::scalar_type>>;
    medium.phase;
};

/// Whether medium type X scatters light (a ScatteringMedium) rather than only absorbing it.
template <class X>
inline constexpr bool scatters_light = ScatteringMedium<X>;

} // namespace prism
