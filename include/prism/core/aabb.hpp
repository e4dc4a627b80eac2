// SPDX-License-Identifier: MIT
// Aabb: an axis-aligned bounding box and its robust slab test.
#pragma once

#include <prism/core/interval.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/ray.hpp>

namespace prism {

/// Axis-aligned box [lo, hi]; empty when lo > hi on any axis (the default).
template <Scalar T>
struct Aabb {
    Vec3<T> lo{infinity<T>};
    Vec3<T> hi{-infinity<T>};

    [[nodiscard]] constexpr bool empty() const noexcept { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }

    /// Every point: the bounds of an unbounded shape such as a half-space.
    [[nodiscard]] static constexpr Aabb universe() noexcept { return {Vec3<T>(-infinity<T>), Vec3<T>(infinity<T>)}; }

    [[nodiscard]] constexpr bool contains(const Vec3<T>& p) const noexcept
    {
        return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
    }

    /// The part of `range` in which the ray is inside the box (empty if none).
    /// Slab test with the far distance widened by 2*gamma(3), so that rounding never
    /// reports a miss for a ray that touches the box (pbrt-v4, Bounds3::IntersectP).
    [[nodiscard]] constexpr Interval<T> clip(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        for (int axis = 0; axis < 3; ++axis) {
            const T o = ray.origin[axis];
            const T d = ray.direction[axis];
            if (d == T(0)) {
                if (o < lo[axis] || o > hi[axis]) return {};
                continue;
            }
            const T inv = T(1) / d;
            T t_near = (lo[axis] - o) * inv;
            T t_far = (hi[axis] - o) * inv;
            if (t_near > t_far) std::swap(t_near, t_far);
            t_far *= T(1) + T(2) * gamma<T>(3);
            if (t_near > range.min) range.min = t_near;
            if (t_far < range.max) range.max = t_far;
            if (range.min > range.max) return {};
        }
        return range;
    }
};

} // namespace prism
