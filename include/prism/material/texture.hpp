// SPDX-License-Identifier: MIT
// Textures: an albedo that may vary with the surface point.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>

#include <cmath>

namespace prism {

/// A texture maps a surface point to an albedo in [0, 1] per channel.
template <class X>
concept Texture = requires(const X& texture, const Vec3<typename X::scalar_type>& p) {
    { texture.albedo(p) } -> std::same_as<Rgb<typename X::scalar_type>>;
    texture.validate();
};

/// One colour everywhere.
template <Scalar T = float>
struct Solid {
    using scalar_type = T;
    Rgb<T> color{T(0.75)};

    [[nodiscard]] constexpr Rgb<T> albedo(const Vec3<T>&) const noexcept { return color; }
    constexpr void validate() const { detail::require_non_negative("Solid color", color); }
};

/// A 3D checkerboard of cubes of side `size` (POV-Ray's `checker`): `even` where
/// floor(x/size) + floor(y/size) + floor(z/size) is even.
template <Scalar T = float>
struct Checker {
    using scalar_type = T;
    Rgb<T> even{T(0.8)};
    Rgb<T> odd{T(0.35)};
    T size = T(1);

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

    constexpr void validate() const
    {
        detail::require_non_negative("Checker even", even);
        detail::require_non_negative("Checker odd", odd);
        detail::require_positive("Checker size", size);
    }
};

static_assert(Texture<Solid<float>> && Texture<Checker<double>>);

} // namespace prism
