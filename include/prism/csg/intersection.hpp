// SPDX-License-Identifier: MIT
// Intersection: inside both solids.
#pragma once

#include <prism/csg/csg_node.hpp>

namespace prism {

/// The CSG operation A ∩ B: inside both.
struct IntersectionOp {
    /// The second solid's surface bounds the result from the same side as the first's.
    static constexpr bool flips_second = false;
    /// Inside the intersection: inside both.
    [[nodiscard]] static constexpr bool combine(bool a, bool b) noexcept { return a && b; }
    /// The intersection lies within both boxes' overlap.
    template <Scalar T>
    [[nodiscard]] static constexpr Aabb<T> bounds(const Aabb<T>& a, const Aabb<T>& b) noexcept { return detail::aabb_intersection(a, b); }
};

/// A & B & ...: the part common to all.
template <Shape A, Shape B, Shape... Rest>
using Intersection = typename detail::csg_fold<IntersectionOp, A, B, Rest...>::type;

/// The intersection of two or more shapes, its type deduced. Also the way to clip an
/// unbounded quadric to a box: intersection_of(cylinder, Box<float>{lo, hi}).
template <Shape A, Shape B, Shape... Rest>
[[nodiscard]] constexpr Intersection<A, B, Rest...> intersection_of(A a, B b, Rest... rest)
{
    return Intersection<A, B, Rest...>(std::move(a), std::move(b), std::move(rest)...);
}

} // namespace prism
