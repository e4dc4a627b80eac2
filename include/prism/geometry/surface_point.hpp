// SPDX-License-Identifier: MIT
// Points drawn on a surface, for lights with extent: by area, or by solid angle from a point.
//
// A shape that can emit light can be sampled. `area()` and `sample_area(u)` draw a point
// uniformly over it; `sample_from(p, u)` draws one as seen from p, with its density per
// steradian there, and `pdf_from(p, x)` gives that density back for a point x a ray from
// p found (what multiple importance sampling needs). A shape that has no better way
// converts its area density (sample_toward, pdf_toward).
#pragma once

#include <prism/core/math.hpp>

#include <cmath>
#include <concepts>

namespace prism {

/// A point drawn on a surface: where, its unit normal (the outward one), and the density
/// it was drawn with (per unit area, or per steradian as seen from a point: as the
/// function that drew it says).
template <Scalar T>
struct SurfacePoint {
    Vec3<T> point{};  ///< the point on the surface
    Vec3<T> normal{}; ///< the surface's unit outward normal there
    T pdf = T(0);     ///< the density it was drawn with
};

/// A density per unit area at x (normal n) seen from p, as a density per steradian:
/// pdf_area |x - p|^2 / |cos| (0 where the surface is seen edge-on).
template <Scalar T>
[[nodiscard]] inline T area_to_solid_angle(T pdf_area, const Vec3<T>& p, const Vec3<T>& x, const Vec3<T>& n) noexcept
{
    const Vec3<T> d = x - p;
    const T d2 = length_squared(d);
    const T cos = std::abs(dot(n, d)) / prism::sqrt(d2);
    return cos > T(0) ? pdf_area * d2 / cos : T(0);
}

/// The solid angle of the triangle abc seen from p (Van Oosterom and Strackee 1983).
template <Scalar T>
[[nodiscard]] inline T triangle_solid_angle(const Vec3<T>& p, const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) noexcept
{
    const Vec3<T> x = a - p, y = b - p, z = c - p;
    const T lx = length(x), ly = length(y), lz = length(z);
    const T numerator = std::abs(dot(x, cross(y, z)));
    const T denominator = lx * ly * lz + dot(x, y) * lz + dot(x, z) * ly + dot(y, z) * lx;
    T omega = T(2) * std::atan2(numerator, denominator);
    return omega < T(0) ? omega + T(2) * pi<T> : omega;
}

/// A surface points can be drawn on uniformly: area() and sample_area(u).
template <class S>
concept AreaSampled = requires(const S& shape, const Vec2<typename S::scalar_type>& u) {
    { shape.area() } -> std::same_as<typename S::scalar_type>;
    { shape.sample_area(u) } -> std::same_as<SurfacePoint<typename S::scalar_type>>;
};

/// A surface with its own way of drawing points as seen from p (by solid angle).
template <class S>
concept SolidAngleSampled = AreaSampled<S> && requires(const S& shape, const Vec3<typename S::scalar_type>& p, const Vec2<typename S::scalar_type>& u) {
    { shape.sample_from(p, u) } -> std::same_as<SurfacePoint<typename S::scalar_type>>;
    { shape.pdf_from(p, p) } -> std::same_as<typename S::scalar_type>;
};

/// What points are drawn on when `shape` emits: the shape itself (a mesh has its own,
/// MeshSurface, with a table of its triangles).
template <AreaSampled S>
[[nodiscard]] const S& surface_of(const S& shape) noexcept
{
    return shape;
}

/// A point of `shape` as seen from p for u in the unit square, its pdf per steradian:
/// the shape's own solid-angle sampling, or a point by area, converted.
template <AreaSampled S>
[[nodiscard]] SurfacePoint<typename S::scalar_type> sample_toward(const S& shape, const Vec3<typename S::scalar_type>& p,
                                                                   const Vec2<typename S::scalar_type>& u) noexcept
{
    if constexpr (SolidAngleSampled<S>) {
        return shape.sample_from(p, u);
    } else {
        SurfacePoint<typename S::scalar_type> s = shape.sample_area(u);
        s.pdf = area_to_solid_angle(s.pdf, p, s.point, s.normal);
        return s;
    }
}

/// The density per steradian sample_toward(shape, p, .) gives the point x (normal n) of `shape`.
template <AreaSampled S>
[[nodiscard]] typename S::scalar_type pdf_toward(const S& shape, const Vec3<typename S::scalar_type>& p, const Vec3<typename S::scalar_type>& x,
                                                 const Vec3<typename S::scalar_type>& n) noexcept
{
    using T = typename S::scalar_type;
    if constexpr (SolidAngleSampled<S>) return shape.pdf_from(p, x);
    else return area_to_solid_angle(T(1) / shape.area(), p, x, n);
}

} // namespace prism
