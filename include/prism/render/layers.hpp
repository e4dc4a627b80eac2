// SPDX-License-Identifier: MIT
// The layers a render can write beside its image (EXR's arbitrary output variables):
// per sample, what the camera ray meets first (its albedo, shading normal and distance,
// and whether it meets anything at all: coverage), and, for an integrator that splits
// its light by where it came from, the parts (the photon mapper's direct light,
// caustics and indirect light). They are summed per pixel exactly as the image is
// (render/accumulation.hpp), so a crop or a range of passes of them adds up too.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/core/random.hpp>
#include <prism/transport/first_surface.hpp>

#include <concepts>
#include <optional>
#include <string>
#include <vector>

namespace prism {

/// Radiance split by the light's last stretch before the camera path's diffuse surface:
/// straight from a light (shadow rays) or the background, through specular surfaces
/// from a light (caustics), or off other diffuse surfaces (indirect).
template <Scalar T>
struct LightParts {
    Rgb<T> direct{T(0)}; ///< from the lights by shadow rays, and the background
    Rgb<T> caustic{T(0)}; ///< from the caustic map
    Rgb<T> indirect{T(0)}; ///< off other diffuse surfaces

    /// The radiance: the three parts summed.
    [[nodiscard]] constexpr Rgb<T> sum() const noexcept { return direct + caustic + indirect; }
    /// Adds another split's parts.
    constexpr LightParts& operator+=(const LightParts& o) noexcept
    {
        direct += o.direct;
        caustic += o.caustic;
        indirect += o.indirect;
        return *this;
    }
    /// Scales every part by k.
    constexpr LightParts& operator*=(const Rgb<T>& k) noexcept
    {
        direct *= k;
        caustic *= k;
        indirect *= k;
        return *this;
    }
    /// Every part scaled by k.
    [[nodiscard]] friend constexpr LightParts operator*(const Rgb<T>& k, LightParts p) noexcept { return p *= k; }
};

/// An integrator whose camera rays start in a scene's air (its scene() and air()), so
/// that what they meet first is first_surface's (transport/first_surface.hpp): the
/// surface layers of render_layers.
template <class I>
concept SeesSurfaces = requires(const I& integrator, const Ray<typename I::scalar_type>& ray) {
    { first_surface(integrator.scene(), integrator.air(), ray) } -> std::same_as<std::optional<SurfaceSample<typename I::scalar_type>>>;
};

/// An integrator that splits its radiance into LightParts (whose sum is its radiance).
template <class I>
concept SplitsLight = requires(const I& integrator, const Ray<typename I::scalar_type>& ray, Random& rng) {
    { integrator.radiance_parts(ray, rng) } -> std::same_as<LightParts<typename I::scalar_type>>;
};

/// The channels render_layers writes for an integrator: R, G, B; A (the fraction of
/// samples that met a surface); albedo, normal and Z (distance), each summed over the
/// samples that met one, so that albedo / A is the mean albedo of those; and the
/// light's parts where the integrator splits it.
template <class I>
[[nodiscard]] std::vector<std::string> layer_channels()
{
    std::vector<std::string> names{"R", "G", "B"};
    if constexpr (SeesSurfaces<I>) names.insert(names.end(), {"A", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z", "Z"});
    if constexpr (SplitsLight<I>)
        names.insert(names.end(), {"direct.R", "direct.G", "direct.B", "caustic.R", "caustic.G", "caustic.B", "indirect.R", "indirect.G", "indirect.B"});
    return names;
}

} // namespace prism
