// SPDX-License-Identifier: MIT
// Ray: an origin and a direction; points along it are origin + t * direction.
#pragma once

#include <prism/core/math.hpp>

namespace prism {

/// A ray. The direction need not be unit length: t is measured in multiples of it.
template <Scalar T>
struct Ray {
    Vec3<T> origin{}; ///< where the ray starts
    Vec3<T> direction{T(0), T(0), T(-1)}; ///< where it goes, of any non-zero length: t counts multiples of it
    /// The width of the footprint it stands for at its origin (a ray cone, Amanatides 1984):
    /// a camera ray covers a pixel, whose footprint grows as width + spread t; every other
    /// ray samples a point (0, 0). Textures filter over it.
    T width = T(0);
    T spread = T(0); ///< how fast the footprint widens per unit of t

    /// The footprint's width at t (0 for a ray that samples a point).
    [[nodiscard]] constexpr T footprint_at(T t) const noexcept { return width + spread * t; }

    /// The point origin + t * direction.
    [[nodiscard]] constexpr Vec3<T> at(T t) const noexcept { return origin + t * direction; }
};

} // namespace prism
