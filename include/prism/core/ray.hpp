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

/// `next`, the ray a mirror or an interface sends on where `ray` met it at t, carrying on
/// `ray`'s cone: its width there, widening at the same angle (a flat surface keeps it; the
/// change a curved mirror or a refraction makes to the angle is left out). A ray that
/// samples a point stays one.
template <Scalar T>
[[nodiscard]] inline Ray<T> carrying_cone(Ray<T> next, const Ray<T>& ray, T t) noexcept
{
    if (!(ray.width > T(0) || ray.spread > T(0))) return next;
    next.width = ray.footprint_at(t);
    next.spread = ray.spread * length(next.direction) / length(ray.direction); // per unit of t along next
    return next;
}

} // namespace prism
