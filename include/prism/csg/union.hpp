// SPDX-License-Identifier: MIT
// Union: inside either solid.
#pragma once

#include <prism/csg/csg_node.hpp>

namespace prism {

/// The CSG operation A ∪ B: inside either.
struct UnionOp {
    /// The second solid's surface bounds the result from the same side as the first's.
    static constexpr bool flips_second = false;
    /// Inside the union: inside either.
    [[nodiscard]] static constexpr bool combine(bool a, bool b) noexcept { return a || b; }
    /// The union lies within the box around both boxes.
    template <Scalar T>
    [[nodiscard]] static constexpr Aabb<T> bounds(const Aabb<T>& a, const Aabb<T>& b) noexcept { return detail::aabb_union(a, b); }
};

/// A | B | ...: Union<Sphere<float>, Box<float>>, or of any number of shapes.
template <Shape A, Shape B, Shape... Rest>
using Union = typename detail::csg_fold<UnionOp, A, B, Rest...>::type;

/// The union of two or more shapes, its type deduced: union_of(sphere, box, quadric).
template <Shape A, Shape B, Shape... Rest>
[[nodiscard]] constexpr Union<A, B, Rest...> union_of(A a, B b, Rest... rest)
{
    return Union<A, B, Rest...>(std::move(a), std::move(b), std::move(rest)...);
}

} // namespace prism
