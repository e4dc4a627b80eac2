// SPDX-License-Identifier: MIT
// Difference: inside the first solid and outside the second.
#pragma once

#include <prism/csg/union.hpp>

namespace prism {

/// The CSG operation A - B: inside A and not inside B.
struct DifferenceOp {
    /// The subtracted solid's surface bounds the result from the other side.
    static constexpr bool flips_second = true;
    /// Inside the difference: inside a and not inside b.
    [[nodiscard]] static constexpr bool combine(bool a, bool b) noexcept { return a && !b; }
    /// The difference lies within a's box.
    template <Scalar T>
    [[nodiscard]] static constexpr Aabb<T> bounds(const Aabb<T>& a, const Aabb<T>&) noexcept { return a; }
};

/// A - B - ... = A - (B | ...): the first shape with all the others removed.
template <Shape A, Shape B, Shape... Rest>
using Difference = CsgNode<DifferenceOp, A, typename detail::csg_fold<UnionOp, B, Rest...>::type>;

/// The first shape minus all the others, its type deduced.
template <Shape A, Shape B, Shape... Rest>
[[nodiscard]] constexpr Difference<A, B, Rest...> difference_of(A a, B b, Rest... rest)
{
    if constexpr (sizeof...(Rest) == 0) return Difference<A, B>(std::move(a), std::move(b));
    else return Difference<A, B, Rest...>(std::move(a), union_of(std::move(b), std::move(rest)...));
}

} // namespace prism
