// SPDX-License-Identifier: MIT
// Normal maps and bump maps: a material whose shading normal a texture tilts.
//
// NormalMapped<Base, Map> and BumpMapped<Base, Height> are the material Base (every
// capability, inherited) with a texture that sets the shading normal where a ray meets
// it. The scene applies it once, when it hands the crossing out (Scene::closest_hit: the
// material's shade(crossing)), so every integrator sees the tilted normal as it sees a
// mesh's interpolated one, with the same side test: light counts only from directions
// on the same side of the shading and the true normal (material/scattering.hpp). A tilt
// that would turn the normal past the surface is bent back to just above it, so no light
// leaks through.
//
// The tangent frame is the surface's: t along dp/du made perpendicular to the shading
// normal n, b = cross(n, t) turned as (dp/du, dp/dv) turn about the outward normal. A
// shape without surface coordinates (Crossing::has_uv false) keeps its normal.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/material/texture.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace prism {

namespace detail {

/// The shading normal n' kept at least a little above the true surface (normal n, both
/// outward): a component along n below 0.01 is raised to it.
template <Scalar T>
[[nodiscard]] Vec3<T> kept_above(const Vec3<T>& tilted, const Vec3<T>& n) noexcept
{
    const T along = dot(tilted, n);
    return along >= T(0.01) ? tilted : normalize(tilted + (T(0.01) - along) * n);
}

/// +1 where (dp/du, dp/dv, outward normal) is right-handed, -1 where it is mirrored (the
/// second solid of a Difference, a mirroring transform).
template <Scalar T>
[[nodiscard]] T handedness(const Crossing<T>& c) noexcept
{
    return dot(cross(c.dpdu, c.dpdv), c.normal) < T(0) ? T(-1) : T(1);
}

/// Tilts c's shading normal to the tangent-space normal 2 rgb - 1 (its tangent part
/// times `strength`), in the frame of t along dp/du and b = cross(n, t) turned as (dp/du,
/// dp/dv) turn.
template <Scalar T>
void apply_normal_map(Crossing<T>& c, const Rgb<T>& rgb, T strength) noexcept
{
    const Vec3<T> n = c.shading;
    const Vec3<T> along_u = c.dpdu - dot(c.dpdu, n) * n;
    if (!(length_squared(along_u) > T(0))) return;
    const Vec3<T> t = normalize(along_u);
    const Vec3<T> b = handedness(c) * cross(n, t);
    const Vec3<T> local{strength * (T(2) * rgb.x - T(1)), strength * (T(2) * rgb.y - T(1)), T(2) * rgb.z - T(1)};
    const Vec3<T> tilted = local.x * t + local.y * b + std::max(local.z, T(0)) * n;
    if (!(length_squared(tilted) > T(0))) return;
    c.shading = kept_above(normalize(tilted), c.normal);
}

/// Sets c's shading normal to that of the surface moved along it by scale x height(u, v),
/// the height's slope by central differences `du` apart.
template <Scalar T, class Height>
void apply_bump_map(Crossing<T>& c, const Height& height, T scale, T du) noexcept
{
    TexturePoint<T> at = texture_point(c);
    const Vec2<T> uv = at.uv;
    const auto h = [&](T u, T v) {
        at.uv = {u, v};
        return height.value(at);
    };
    const T h_u = scale * (h(uv.x + du, uv.y) - h(uv.x - du, uv.y)) / (T(2) * du);
    const T h_v = scale * (h(uv.x, uv.y + du) - h(uv.x, uv.y - du)) / (T(2) * du);
    // The moved surface p + h n has dp/du + h_u n and dp/dv + h_v n: their cross product,
    // with the shading normal for the unmoved surface's.
    const Vec3<T> n = c.shading;
    const Vec3<T> tilted = length(cross(c.dpdu, c.dpdv)) * n + handedness(c) * (h_v * cross(c.dpdu, n) + h_u * cross(n, c.dpdv));
    if (!(length_squared(tilted) > T(0)) || !is_finite(tilted)) return;
    c.shading = kept_above(normalize(tilted), c.normal);
}

/// The uv step of a bump map's differences: `delta` where given, else half a texel of a
/// texture that has texels, else 1/1000.
template <Scalar T, class Height>
[[nodiscard]] T bump_step(const Height& height, T delta) noexcept
{
    if (delta > T(0)) return delta;
    if constexpr (requires { height.width(); height.height(); }) {
        const int side = std::max(height.width(), height.height());
        if (side > 0) return T(0.5) / T(side);
    }
    return T(1e-3);
}

} // namespace detail

/// A tangent-space normal map over the material Base: the map's RGB in [0, 1] is the
/// normal (2 RGB - 1) in the frame (t, b, n) (OpenGL's and Blender's convention: green
/// along +v). Read it with TextureEncoding::linear and, for an image, Filter::bilinear or
/// trilinear. `strength` scales the tilt (0: none, 1: as the map says).
template <class Base, class Map>
struct NormalMapped : Base {
    using typename Base::scalar_type;
    /// Shorthand for scalar_type.
    using T = typename Base::scalar_type;

    /// It reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates = true;

    Map normal_map{};   ///< the normals, as RGB
    T strength = T(1);  ///< how much of the tilt to apply

    NormalMapped() = default;
    /// Base with the normal map `map`, applied with `strength`.
    NormalMapped(Base base, Map map, T tilt = T(1)) : Base(std::move(base)), normal_map(std::move(map)), strength(tilt) {}

    /// The crossing with its shading normal tilted by the map.
    void shade(Crossing<T>& c) const noexcept
    {
        if (c.has_uv()) detail::apply_normal_map(c, albedo_at(normal_map, texture_point(c)), strength);
    }

    /// Throws std::invalid_argument, naming the parameter, for a bad base, map or strength.
    void validate() const
    {
        Base::validate();
        normal_map.validate();
        detail::require_non_negative("NormalMapped strength", strength);
    }
};

/// A bump map over the material Base: the surface shades as if moved along its normal by
/// `scale` x height(u, v), the height a one-number texture (its slope taken by central
/// differences `delta` apart in uv: half a texel of an ImageTexture by default).
template <class Base, class Height>
struct BumpMapped : Base {
    using typename Base::scalar_type;
    /// Shorthand for scalar_type.
    using T = typename Base::scalar_type;

    /// It reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates = true;

    Height height{};  ///< the height over the surface, in units of `scale`
    T scale = T(1);   ///< scene units per unit of height
    T delta = T(0);   ///< the uv step of the slope's differences (0: half a texel, or 1/1000 for a texture without texels)

    BumpMapped() = default;
    /// Base with the bump map `bumps` at `height_scale` scene units per unit.
    BumpMapped(Base base, Height bumps, T height_scale) : Base(std::move(base)), height(std::move(bumps)), scale(height_scale) {}

    /// The crossing with its shading normal that of the moved surface.
    void shade(Crossing<T>& c) const noexcept
    {
        if (c.has_uv()) detail::apply_bump_map(c, height, scale, detail::bump_step(height, delta));
    }

    /// Throws std::invalid_argument, naming the parameter, for a bad base or height, or a
    /// scale or delta that is negative or not finite.
    void validate() const
    {
        Base::validate();
        height.validate();
        detail::require_non_negative("BumpMapped scale", scale);
        detail::require_non_negative("BumpMapped delta", delta);
    }

};

} // namespace prism
