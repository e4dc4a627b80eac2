// SPDX-License-Identifier: MIT
// The Shape concept: what every primitive, transformed shape and CSG node provides.
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/core/interval.hpp>
#include <prism/core/ray.hpp>
#include <prism/geometry/crossings.hpp>

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

namespace prism {

/// A solid with a boundary. `crossings(ray, range)` returns every boundary crossing
/// with t strictly inside `range`, sorted by t, plus whether `ray.at(range.min)` is
/// inside; `crossings<false>` the same without the surface (point, error, normal), for
/// queries that need only where and which way: shadow rays, and finding which object
/// is nearest before asking it for its surface. `max_crossings` bounds their number at
/// compile time; `bounds()` encloses the solid (Aabb::universe() for an unbounded one);
/// `contains(p)` says whether a point is strictly inside (the implicit function). A shape
/// may also offer `bounding_sphere()` (see HasBoundingSphere).
template <class S>
concept Shape = requires(const S& shape, const Ray<typename S::scalar_type>& ray,
                         Interval<typename S::scalar_type> range, const Vec3<typename S::scalar_type>& p) {
    requires Scalar<typename S::scalar_type>;
    { S::max_crossings } -> std::convertible_to<std::size_t>;
    { shape.crossings(ray, range) } -> std::same_as<Crossings<typename S::scalar_type, S::max_crossings>>;
    { shape.template crossings<false>(ray, range) } -> std::same_as<Crossings<typename S::scalar_type, S::max_crossings>>;
    { shape.bounds() } -> std::same_as<Aabb<typename S::scalar_type>>;
    { shape.contains(p) } -> std::same_as<bool>;
};

/// A shape that knows a sphere around itself tighter than the one around its box
/// (Sphere does). Optional: `bounding_sphere(shape)` falls back to the box's sphere.
template <class S>
concept HasBoundingSphere = Shape<S> && requires(const S& shape) {
    { shape.bounding_sphere() } -> std::same_as<BoundingSphere<typename S::scalar_type>>;
};

/// A sphere enclosing a bounded shape: its own, or the one through its box's corners.
template <Shape S>
[[nodiscard]] constexpr BoundingSphere<typename S::scalar_type> bounding_sphere(const S& shape) noexcept
{
    if constexpr (HasBoundingSphere<S>) return shape.bounding_sphere();
    else return shape.bounds().bounding_sphere();
}

/// Whether the shape is convex (its `convex()`, false for a shape that has none): a ray
/// that leaves its surface on the side the outward normal faces never crosses it again, so
/// a shadow ray leaving it there need not ask it. A sphere, a box, a plane's half-space, an
/// ellipsoid; an intersection of convex children; a convex shape transformed.
template <Shape S>
[[nodiscard]] constexpr bool convex(const S& shape) noexcept
{
    if constexpr (requires { { shape.convex() } -> std::convertible_to<bool>; }) return shape.convex();
    else return (void)shape, false;
}

namespace detail {

/// How many CSG nodes deep a shape is (0 for a primitive).
template <class S>
[[nodiscard]] constexpr std::size_t csg_depth() noexcept
{
    if constexpr (requires { S::csg_depth; }) return S::csg_depth;
    else return 0;
}

} // namespace detail

/// A shape with surface coordinates: coordinates(c) sets c.uv, c.dpdu and c.dpdv of a
/// crossing of its own (found with its surface) from c.point and c.normal (and, in a CSG
/// node, c.path). Kept out of crossings() so that a scene computes them only for the
/// materials that read them (Scene::closest_hit, reads_coordinates).
template <class S>
concept HasCoordinates = Shape<S> && requires(const S& shape, Crossing<typename S::scalar_type>& c) { shape.coordinates(c); };

/// Sets the surface coordinates of a crossing of `shape` (found with its surface), where
/// the shape has them (a mesh's came with the crossing; other shapes leave them zero).
template <Shape S>
constexpr void add_coordinates(const S& shape, Crossing<typename S::scalar_type>& c) noexcept
{
    if constexpr (HasCoordinates<S>) shape.coordinates(c);
    (void)shape, (void)c;
}

/// A shape with a lean closest-hit query: first_crossing(ray, range) gives the t of
/// crossings<false>(ray, range).front() (infinity when there is none) without building
/// the list, and any_crossing whether that list is non-empty.
template <class S>
concept HasFirstCrossing = Shape<S> && requires(const S& shape, const Ray<typename S::scalar_type>& ray, Interval<typename S::scalar_type> range) {
    { shape.first_crossing(ray, range) } -> std::same_as<typename S::scalar_type>;
    { shape.any_crossing(ray, range) } -> std::same_as<bool>;
};

/// The t of the shape's first crossing strictly inside `range`, or infinity.
template <Shape S>
[[nodiscard]] constexpr typename S::scalar_type first_crossing(const S& shape, const Ray<typename S::scalar_type>& ray, Interval<typename S::scalar_type> range) noexcept
{
    if constexpr (HasFirstCrossing<S>) {
        return shape.first_crossing(ray, range);
    } else {
        const auto crossings = shape.template crossings<false>(ray, range);
        return crossings.empty() ? infinity<typename S::scalar_type> : crossings.front().t;
    }
}

/// Whether the shape crosses the ray strictly inside `range`.
template <Shape S>
[[nodiscard]] constexpr bool any_crossing(const S& shape, const Ray<typename S::scalar_type>& ray, Interval<typename S::scalar_type> range) noexcept
{
    if constexpr (HasFirstCrossing<S>) return shape.any_crossing(ray, range);
    else return !shape.template crossings<false>(ray, range).empty();
}

/// What a shape's lean query found, kept for its surface: a mesh's triangle, and the t
/// and barycentric weights at which its ray met it (in the shape's own frame).
template <Scalar T>
struct SurfaceHint {
    std::uint32_t index = 0; ///< the triangle found (a mesh's leaf-order index)
    T t = 0; ///< where along the ray
    std::array<T, 3> b{}; ///< all zero: nothing found, search again
    bool entering = false; ///< whether the ray enters the solid there
};

/// A shape whose lean query names what it found (a mesh: the triangle, where it was
/// met), so that its surface there needs no second search: first_crossing(ray, range,
/// hint) is first_crossing(ray, range) and sets the hint; surface_crossing(ray, range,
/// hint), for the same ray over a range that ends just past that t, is
/// crossings(ray, range).front().
template <class S>
concept HasHintedSurface = HasFirstCrossing<S> && requires(const S& shape, const Ray<typename S::scalar_type>& ray, Interval<typename S::scalar_type> range,
                                                           SurfaceHint<typename S::scalar_type>& hint) {
    { shape.first_crossing(ray, range, hint) } -> std::same_as<typename S::scalar_type>;
    { shape.surface_crossing(ray, range, std::as_const(hint)) } -> std::same_as<std::optional<Crossing<typename S::scalar_type>>>;
};

/// first_crossing, setting `hint` for surface_crossing where the shape gives one.
template <Shape S>
[[nodiscard]] constexpr typename S::scalar_type first_crossing(const S& shape, const Ray<typename S::scalar_type>& ray, Interval<typename S::scalar_type> range,
                                                               SurfaceHint<typename S::scalar_type>& hint) noexcept
{
    if constexpr (HasHintedSurface<S>) return shape.first_crossing(ray, range, hint);
    else return first_crossing(shape, ray, range);
}

/// crossings(ray, range).front(), if any: found from the hint where the shape takes one.
template <Shape S>
[[nodiscard]] constexpr std::optional<Crossing<typename S::scalar_type>> surface_crossing(const S& shape, const Ray<typename S::scalar_type>& ray,
                                                                                          Interval<typename S::scalar_type> range,
                                                                                          const SurfaceHint<typename S::scalar_type>& hint) noexcept
{
    if constexpr (HasHintedSurface<S>) {
        return shape.surface_crossing(ray, range, hint);
    } else {
        const auto crossings = shape.crossings(ray, range);
        if (crossings.empty()) return std::nullopt;
        return crossings.front();
    }
}

} // namespace prism
