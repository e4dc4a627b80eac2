// SPDX-License-Identifier: MIT
// Textures: an albedo that may vary with the surface point.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/geometry/crossings.hpp>

#include <cmath>

namespace prism {

/// Where a texture is read: the surface point, its surface coordinates (Crossing::uv),
/// and the width in uv units of the footprint the ray sees there (0: a point; an image
/// texture then reads its full picture).
template <Scalar T>
struct TexturePoint {
    Vec3<T> point{}; ///< the surface point
    Vec2<T> uv{};    ///< its surface coordinates
    T width = T(0);  ///< the footprint's width in uv units
};

/// A texture maps a surface point, `albedo(p)`, or a point and its surface coordinates,
/// `albedo(p, uv)` (Crossing::uv: (0, 0) on a shape without them), or a TexturePoint
/// with the footprint, `albedo(at)`, to an albedo (in [0, 1] per channel for a surface
/// that keeps energy).
template <class X>
concept Texture = requires(const X& texture) { texture.validate(); } &&
                  (requires(const X& texture, const Vec3<typename X::scalar_type>& p) {
                      { texture.albedo(p) } -> std::same_as<Rgb<typename X::scalar_type>>;
                  } || requires(const X& texture, const Vec3<typename X::scalar_type>& p, const Vec2<typename X::scalar_type>& uv) {
                      { texture.albedo(p, uv) } -> std::same_as<Rgb<typename X::scalar_type>>;
                  } || requires(const X& texture, const TexturePoint<typename X::scalar_type>& at) {
                      { texture.albedo(at) } -> std::same_as<Rgb<typename X::scalar_type>>;
                  });

/// A texture of one number (a roughness, a height): `value(at)`.
template <class X>
concept ScalarTexture = requires(const X& texture, const TexturePoint<typename X::scalar_type>& at) {
    { texture.value(at) } -> std::same_as<typename X::scalar_type>;
    texture.validate();
};

/// Whether a texture (or a one-number parameter: a plain number reads nothing) reads
/// surface coordinates: albedo(p, uv), albedo(at) or value(at).
template <class X>
inline constexpr bool texture_reads_coordinates = requires(const X& texture, const Vec3<typename X::scalar_type>& p, const Vec2<typename X::scalar_type>& uv) {
    texture.albedo(p, uv);
} || requires(const X& texture, const TexturePoint<typename X::scalar_type>& at) { texture.albedo(at); } || ScalarTexture<X>;

/// A texture's albedo at `at`, whichever form it reads.
template <Texture X>
[[nodiscard]] constexpr Rgb<typename X::scalar_type> albedo_at(const X& texture, const TexturePoint<typename X::scalar_type>& at) noexcept
{
    if constexpr (requires { texture.albedo(at); })
        return texture.albedo(at);
    else if constexpr (requires { texture.albedo(at.point, at.uv); })
        return texture.albedo(at.point, at.uv);
    else
        return texture.albedo(at.point);
}

/// A texture's albedo at point p with surface coordinates uv and no footprint.
template <Texture X>
[[nodiscard]] constexpr Rgb<typename X::scalar_type> albedo_at(const X& texture, const Vec3<typename X::scalar_type>& p,
                                                               const Vec2<typename X::scalar_type>& uv) noexcept
{
    return albedo_at(texture, TexturePoint<typename X::scalar_type>{p, uv, typename X::scalar_type(0)});
}

/// Where a crossing's textures are read: its point and uv, and the ray's footprint
/// there (Crossing::footprint) in uv units: its width over the square root of the area
/// a unit square of uv covers, |dp/du x dp/dv| (0 on a shape without coordinates).
template <Scalar T>
[[nodiscard]] inline TexturePoint<T> texture_point(const Crossing<T>& at) noexcept
{
    TexturePoint<T> out{at.point, at.uv, T(0)};
    if (at.footprint > T(0)) {
        const T area = length(cross(at.dpdu, at.dpdv));
        if (area > T(0)) out.width = at.footprint / prism::sqrt(area);
    }
    return out;
}

/// One colour everywhere.
template <Scalar T = float>
struct Solid {
    /// The precision of the colour.
    using scalar_type = T;
    Rgb<T> color{T(0.75)}; ///< the albedo everywhere

    /// The albedo at any point: color.
    [[nodiscard]] constexpr Rgb<T> albedo(const Vec3<T>&) const noexcept { return color; }
    /// Throws std::invalid_argument for a negative or non-finite colour.
    constexpr void validate() const { detail::require_non_negative("Solid color", color); }
};

/// A 3D checkerboard of cubes of side `size` (POV-Ray's `checker`): `even` where
/// floor(x/size) + floor(y/size) + floor(z/size) is even.
template <Scalar T = float>
struct Checker {
    /// The precision of the colours.
    using scalar_type = T;
    Rgb<T> even{T(0.8)}; ///< albedo of the even cells
    Rgb<T> odd{T(0.35)}; ///< albedo of the odd cells
    T size = T(1); ///< side of a cell

    /// The albedo at p: even or odd by the parity of p's cell.
    [[nodiscard]] Rgb<T> albedo(const Vec3<T>& p) const noexcept
    {
        // Cells are half-open, so a point on a cell face belongs to exactly one cell. A
        // floor at y = 0 stays in one layer because Plane refines its hit points onto
        // the plane exactly when the plane is axis-aligned. Parity is taken in floating
        // point, so far-away points cannot overflow an integer conversion.
        const T inv = T(1) / size;
        const T sum = std::floor(p.x * inv) + std::floor(p.y * inv) + std::floor(p.z * inv);
        return std::floor(sum * T(0.5)) * T(2) == sum ? even : odd;
    }

    /// Throws std::invalid_argument, naming the parameter, for a negative or non-finite colour or a size <= 0.
    constexpr void validate() const
    {
        detail::require_non_negative("Checker even", even);
        detail::require_non_negative("Checker odd", odd);
        detail::require_positive("Checker size", size);
    }
};

/// A checkerboard in surface coordinates: squares of side `size` in (u, v), `even`
/// where floor(u/size) + floor(v/size) is even (the square [0, size)^2 is even).
template <Scalar T = float>
struct UvChecker {
    /// The precision of the colours.
    using scalar_type = T;
    Rgb<T> even{T(0.8)}; ///< albedo of the even squares
    Rgb<T> odd{T(0.35)}; ///< albedo of the odd squares
    T size = T(0.125); ///< side of a square in (u, v)

    /// Checker's cells in the plane (u, v, 0).
    [[nodiscard]] Rgb<T> albedo(const Vec3<T>&, const Vec2<T>& uv) const noexcept { return Checker<T>{even, odd, size}.albedo({uv.x, uv.y, T(0)}); }

    /// Throws std::invalid_argument, naming the parameter, for a negative or non-finite colour or a size <= 0.
    constexpr void validate() const
    {
        detail::require_non_negative("UvChecker even", even);
        detail::require_non_negative("UvChecker odd", odd);
        detail::require_positive("UvChecker size", size);
    }
};

static_assert(Texture<Solid<float>> && Texture<Checker<double>> && Texture<UvChecker<float>>);

} // namespace prism
