// SPDX-License-Identifier: MIT
// Emissive: a surface that gives off light (an area light), and reflects none.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/texture.hpp>
#include <prism/material/traits.hpp>

#include <concepts>

namespace prism {

/// An Emissive's pattern when it has none: the same radiance everywhere.
struct Unpatterned {};

/// A surface emitting `radiance` (W/(m^2 sr), per channel) from its front (the side its
/// outward normal points to; a Quad's or Disk's normal side), and from its back too when
/// `two_sided`: any bounded Sphere, Quad, Disk or TriangleMesh with this material is an
/// area light. It reflects nothing: a lamp's black body, seen where it is not lit.
///
/// With a `pattern` (a Texture: an image, read by the surface's coordinates, or a solid
/// pattern of the point), the radiance at a point is `radiance` times the pattern's
/// colour there: a lit sign, a window seen from inside. A pattern read by surface
/// coordinates needs a Sphere, Quad or Disk (a mesh's coordinates come only with a ray's
/// crossing). The scene finds such a light's power from the mean of 64 x 64 points
/// stratified over its area; light samples and photons read the pattern where they leave.
template <Scalar T = float, class Pattern = Unpatterned>
struct Emissive {
    static_assert(std::same_as<Pattern, Unpatterned> || Texture<Pattern>, "an Emissive's pattern is a Texture (an ImageTexture, Checker, ...)");

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
    /// Whether its radiance changes over the surface (it has a pattern).
    static constexpr bool emission_varies = !std::same_as<Pattern, Unpatterned>;
    /// Whether its pattern reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates = emission_varies && texture_reads_coordinates<Pattern>;

    Rgb<T> radiance{T(1)}; ///< the radiance leaving every point in every direction of the front (W/(m^2 sr)), times the pattern
    bool two_sided = false; ///< whether the back emits as well
    [[no_unique_address]] Pattern pattern{}; ///< the colour the radiance is multiplied by over the surface (Unpatterned: 1)

    /// The emitted radiance at `at`: radiance, times the pattern there.
    [[nodiscard]] constexpr Rgb<T> emitted_radiance(const TexturePoint<T>& at) const noexcept
    {
        if constexpr (emission_varies) return radiance * albedo_at(pattern, at);
        else return (void)at, radiance;
    }

    /// Throws std::invalid_argument, naming the parameter, for a negative or non-finite
    /// radiance, or a bad pattern.
    constexpr void validate() const
    {
        detail::require_non_negative("Emissive radiance", radiance);
        if constexpr (emission_varies) pattern.validate();
    }
};

static_assert(Material<Emissive<float>>);

} // namespace prism
