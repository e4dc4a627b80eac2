// SPDX-License-Identifier: MIT
// Material traits known at compile time, on which integrators branch with if constexpr.
//
// Every material states three facts as static constexpr members:
//   has_diffuse  it reflects light diffusely (Lambert, albedo / pi), lit by shadow rays
//   reflects     it has a mirror (delta) reflection lobe
//   transmits    it refracts light through its interior (a dielectric)
// A scene whose materials never transmit compiles no refraction code at all.
#pragma once

#include <prism/core/math.hpp>

#include <concepts>

namespace prism {

template <class M>
concept Material = requires(const M& material) {
    requires Scalar<typename M::scalar_type>;
    { M::has_diffuse } -> std::convertible_to<bool>;
    { M::reflects } -> std::convertible_to<bool>;
    { M::transmits } -> std::convertible_to<bool>;
    material.validate();
};

/// Purely specular: every scattered direction is a delta (no diffuse lobe).
template <Material M>
inline constexpr bool is_delta = !M::has_diffuse && (M::reflects || M::transmits);

template <Material M>
inline constexpr bool has_diffuse = M::has_diffuse;

template <Material M>
inline constexpr bool reflects = M::reflects;

template <Material M>
inline constexpr bool transmits = M::transmits;

} // namespace prism
