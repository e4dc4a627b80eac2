// SPDX-License-Identifier: MIT
// Box: the solid axis-aligned box [lo, hi].
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/geometry/shape.hpp>

#include <algorithm>
#include <limits>

namespace prism {

/// The solid axis-aligned box [lo, hi]: a Shape with at most two crossings per ray.
template <Scalar T = float>
class Box {
public:
    /// The precision of the corners and the crossings.
    using scalar_type = T;
    /// At most two crossings: in and out.
    static constexpr std::size_t max_crossings = 2;

    // Box Public Methods

    /// The box between two opposite corners (in any order). Throws
    /// std::invalid_argument for a non-finite corner or zero extent on an axis.
    constexpr Box(const Vec3<T>& corner_a, const Vec3<T>& corner_b)
    {
        detail::require_finite("Box corner_a", corner_a);
        detail::require_finite("Box corner_b", corner_b);
        for (int axis = 0; axis < 3; ++axis) {
            lo_[axis] = corner_a[axis] < corner_b[axis] ? corner_a[axis] : corner_b[axis];
            hi_[axis] = corner_a[axis] < corner_b[axis] ? corner_b[axis] : corner_a[axis];
            if (!(lo_[axis] < hi_[axis]))
                detail::throw_invalid("Box extent must be > 0 on every axis, got corners ",
                                      detail::describe(corner_a), " and ", detail::describe(corner_b));
        }
    }

    /// The least corner.
    [[nodiscard]] constexpr const Vec3<T>& lo() const noexcept { return lo_; }
    /// The greatest corner.
    [[nodiscard]] constexpr const Vec3<T>& hi() const noexcept { return hi_; }
    /// The box itself, as an Aabb.
    [[nodiscard]] constexpr Aabb<T> bounds() const noexcept { return {lo_, hi_}; }
    /// A box is convex.
    [[nodiscard]] static constexpr bool convex() noexcept { return true; }

    /// Whether p is strictly inside (the faces are the surface).
    [[nodiscard]] constexpr bool contains(const Vec3<T>& p) const noexcept
    {
        return lo_.x < p.x && p.x < hi_.x && lo_.y < p.y && p.y < hi_.y && lo_.z < p.z && p.z < hi_.z;
    }

    /// Every crossing of `ray` within `range` (at most two), sorted, by the slab test, with each hit point snapped onto its face.
    template <bool Surface = true>
    [[nodiscard]] constexpr Crossings<T, 2> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        Crossings<T, 2> out;
        const Span span = span_of(ray);
        if (!span.hit) return out;
        out.inside_at_start = span.t_near < range.min && range.min < span.t_far;
        if (range.surrounds(span.t_near))
            out.push_back(Surface ? crossing_at(ray, span.t_near, span.axis_near(), true) : Crossing<T>::without_surface(span.t_near, true));
        if (range.surrounds(span.t_far))
            out.push_back(Surface ? crossing_at(ray, span.t_far, span.axis_far(), false) : Crossing<T>::without_surface(span.t_far, false));
        return out;
    }

    /// The t of crossings<false>(ray, range).front() (infinity for none), without the list.
    [[nodiscard]] constexpr T first_crossing(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        const Span span = span_of(ray);
        if (!span.hit) return infinity<T>;
        if (range.surrounds(span.t_near)) return span.t_near;
        return range.surrounds(span.t_far) ? span.t_far : infinity<T>;
    }

    /// Whether crossings<false>(ray, range) is non-empty.
    [[nodiscard]] constexpr bool any_crossing(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        return first_crossing(ray, range) < infinity<T>;
    }

    /// Surface coordinates of a crossing of this box: each face spans [0, 1]^2 along its
    /// axes (as a Plane's), or runs in the scene's units along an infinite side.
    void coordinates(Crossing<T>& c) const noexcept { c = c.with_uv(face_uv(c.point, c.normal), face_extent(c.normal, 0), face_extent(c.normal, 1)); }

private:
    // Box Private Methods

    /// Where the line of the ray is inside the box, and which faces bound that span.
    struct Span {
        bool hit = false; ///< false for a miss, or a touch along an edge or a face
        T t_near = -infinity<T>, t_far = infinity<T>;
        /// Each slab's entry and exit along the line (NaN for a slab the ray runs along).
        Vec3<T> enters{std::numeric_limits<T>::quiet_NaN()}, leaves{std::numeric_limits<T>::quiet_NaN()};

        /// The first axis whose face the span begins at; the same for where it ends.
        [[nodiscard]] constexpr int axis_near() const noexcept { return enters.x == t_near ? 0 : enters.y == t_near ? 1 : 2; }
        [[nodiscard]] constexpr int axis_far() const noexcept { return leaves.x == t_far ? 0 : leaves.y == t_far ? 1 : 2; }
    };

    [[nodiscard, gnu::always_inline]] constexpr Span span_of(const Ray<T>& ray) const noexcept
    {
        // Slab test over the whole line, without branching on the slabs' order (which a
        // ray's direction makes unpredictable); the faces are found afterwards, for a
        // crossing that needs them.
        Span span;
        for (int axis = 0; axis < 3; ++axis) {
            const T o = ray.origin[axis];
            const T d = ray.direction[axis];
            if (d == T(0)) { // parallel to this slab
                if (o <= lo_[axis] || o >= hi_[axis]) return span; // in or beside a face plane: a touch at most
                continue;
            }
            // Divided, not multiplied by 1 / d: a face's t is then the bits a Plane or a
            // Quad on it computes, so that surfaces made to meet there (a glass's bottom on
            // a table, water filling a glass) meet exactly, not by the luck of a rounding.
            const T t0 = (lo_[axis] - o) / d;
            const T t1 = (hi_[axis] - o) / d;
            span.enters[axis] = std::min(t0, t1);
            span.leaves[axis] = std::max(t0, t1);
            span.t_near = std::max(span.t_near, span.enters[axis]);
            span.t_far = std::min(span.t_far, span.leaves[axis]);
        }
        span.hit = span.t_near < span.t_far;
        return span;
    }

    [[nodiscard]] constexpr Crossing<T> crossing_at(const Ray<T>& ray, T t, int axis, bool entering) const noexcept
    {
        // The face coordinate is snapped to the face and so exact; the other two carry
        // the rounding of o + t d, with t itself from two rounded operations.
        Vec3<T> point = ray.at(t);
        Vec3<T> error = gamma<T>(3) * (abs(ray.origin) + abs(t * ray.direction));
        Vec3<T> normal{T(0)};
        const bool toward_positive = ray.direction[axis] > T(0);
        // Entering through the face the ray meets first; leaving through the other.
        const bool high_face = entering ? !toward_positive : toward_positive;
        point[axis] = high_face ? hi_[axis] : lo_[axis];
        error[axis] = T(0);
        normal[axis] = high_face ? T(1) : T(-1);
        return Crossing<T>::flat(t, point, error, normal, entering);
    }

    [[nodiscard]] constexpr Vec3<T> face_extent(const Vec3<T>& normal, int which) const noexcept
    {
        const auto axes = detail::face_axes(normal);
        const Vec3<T> axis = which == 0 ? axes.first : axes.second;
        const T side = std::abs(dot(hi_ - lo_, axis));
        return is_finite(side) ? side * axis : axis;
    }
    [[nodiscard]] constexpr Vec2<T> face_uv(const Vec3<T>& point, const Vec3<T>& normal) const noexcept
    {
        const auto [u, v] = detail::face_axes(normal);
        const auto coordinate = [&](const Vec3<T>& axis) {
            // From the face's corner where the coordinate is least.
            const T start = std::min(dot(lo_, axis), dot(hi_, axis)), side = std::abs(dot(hi_ - lo_, axis));
            return is_finite(side) ? (dot(point, axis) - start) / side : dot(point, axis);
        };
        return {coordinate(u), coordinate(v)};
    }

    Vec3<T> lo_{};
    Vec3<T> hi_{};
};

static_assert(Shape<Box<float>>);
static_assert(Shape<Box<double>>);
static_assert(HasFirstCrossing<Box<float>>);

} // namespace prism
