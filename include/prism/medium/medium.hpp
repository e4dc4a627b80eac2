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
#include <prism/core/random.hpp>

#include <concepts>

namespace prism {

/// A medium in which light travels in straight lines and is attenuated along the way:
/// either the same everywhere, `transmittance(distance)` the fraction of light per
/// channel left after that distance, or varying from point to point,
/// `transmittance(ray, t_max)` an unbiased estimate of it along ray (unit direction) from
/// its origin to t_max. transmittance_along asks either.
template <class X>
concept Medium = requires(const X& medium, const Ray<typename X::scalar_type>& ray, typename X::scalar_type distance) {
    requires Scalar<typename X::scalar_type>;
    requires requires { { medium.transmittance(distance) } -> std::same_as<Rgb<typename X::scalar_type>>; } ||
                 requires { { medium.transmittance(ray, distance) } -> std::same_as<Rgb<typename X::scalar_type>>; };
    medium.validate();
};

/// Whether medium type X is the same everywhere (its transmittance a function of distance alone).
template <class X>
inline constexpr bool uniform_medium = requires(const X& medium, typename X::scalar_type distance) { medium.transmittance(distance); };

/// What `medium` lets through along [t0, t1] of `ray` (any direction length; t1 may be
/// infinite, t0 not): exp(-sigma_t length) in a uniform medium, the medium's own estimate
/// along the stretch in one that varies.
template <Medium M, Scalar T>
[[nodiscard]] Rgb<T> transmittance_along(const M& medium, const Ray<T>& ray, T t0, T t1) noexcept
{
    const T speed = length(ray.direction);
    if constexpr (uniform_medium<M>)
        return medium.transmittance((t1 - t0) * speed);
    else
        return medium.transmittance(Ray<T>{ray.at(t0), ray.direction / speed}, (t1 - t0) * speed);
}

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
                                                 const Rgb<typename X::scalar_type>& power, Random& rng) {
    requires X::scatters;
    { medium.sample_flight(ray, t, power, rng) } -> std::same_as<FreeFlight<typename X::scalar_type>>;
    { medium.scattering_at(ray.origin) } -> std::same_as<Rgb<typename X::scalar_type>>;
    medium.phase;
};

/// Whether medium type X scatters light (a ScatteringMedium) rather than only absorbing it.
template <class X>
inline constexpr bool scatters_light = ScatteringMedium<X>;

} // namespace prism
