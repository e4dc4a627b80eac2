// SPDX-License-Identifier: MIT
// Emissive: a surface that gives off light (an area light), and reflects none.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/traits.hpp>

namespace prism {

/// A surface emitting `radiance` (W/(m^2 sr), per channel) from its front (the side its
/// outward normal points to; a Quad's or Disk's normal side), and from its back too when
/// `two_sided`: any bounded Sphere, Quad, Disk or TriangleMesh with this material is an
/// area light. It reflects nothing: a lamp's black body, seen where it is not lit.
template <Scalar T = float>
struct Emissive {
    /// The precision of the material.
    using scalar_type = T;
    /// No diffuse lobe.
    static constexpr bool has_diffuse = false;
    /// No mirror reflection.
    static constexpr bool reflects = false;
    /// No transmission.
    static constexpr bool transmits = false;
    /// An area light.
    static constexpr bool emits = true;

    Rgb<T> radiance{T(1)}; ///< the radiance leaving every point in every direction of the front (W/(m^2 sr))
    bool two_sided = false; ///< whether the back emits as well

    /// The emitted radiance.
    [[nodiscard]] constexpr Rgb<T> emitted_radiance() const noexcept { return radiance; }

    /// Throws std::invalid_argument, naming the parameter, for a negative or non-finite radiance.
    constexpr void validate() const { detail::require_non_negative("Emissive radiance", radiance); }
};

static_assert(Material<Emissive<float>>);

} // namespace prism
