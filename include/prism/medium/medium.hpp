// SPDX-License-Identifier: MIT
// The Medium concept: how light fares while it travels through the inside of an object.
//
// A transmissive material names the medium that fills it (Dielectric's `interior`), and
// the integrators ask that medium, through `attenuate_inside` (material/scattering.hpp),
// what a path of a given length inside it lets through. Today's media keep rays
// straight; a medium that bends them (a graded index) or that nests inside another
// (priorities) is one more header here, and extends this interface rather than the
// integrators.
#pragma once

#include <prism/core/math.hpp>

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

} // namespace prism
