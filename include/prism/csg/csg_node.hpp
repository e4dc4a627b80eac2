// SPDX-License-Identifier: MIT
// CsgNode: the boolean combination of two solids, by merging their crossing lists.
//
// Roth's method ("Ray Casting for Modeling Solids", 1982): walk the two sorted lists
// of crossings together, keep whether the ray is inside each child, and emit a
// crossing wherever the combination changes. It is right wherever the ray starts
// (inside either child), whatever order the children lie in along the ray, for
// unbounded children, and nests to any depth: a node is a Shape like any other, with
// a capacity known at compile time (the sum of its children's).
//
// Coincident faces: all crossings at exactly the same t, from either child, are
// applied together before the result is compared, so A - A is empty, A + A is A, and a
// box minus a box that shares a face leaves no film. Faces that coincide only up to
// rounding (computed by different arithmetic) are separate crossings and may leave a
// sliver no thicker than their error bounds.
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/geometry/shape.hpp>
#include <prism/geometry/transformed.hpp>

#include <algorithm>
#include <limits>
#include <type_traits>
#include <utility>

namespace prism {

/// A boolean operation: whether a point is inside the result, from whether it is
/// inside each child; and whether the second child's surface faces the other way.
template <class Op>
concept CsgOperation = requires(bool a, bool b) {
    { Op::combine(a, b) } -> std::same_as<bool>;
    { Op::flips_second } -> std::convertible_to<bool>;
};

/// A CSG node: the solid Op makes of A and B (Roth 1982, "Ray casting for modeling solids"),
/// found by merging the children's sorted crossings; itself a Shape, so nodes nest.
template <CsgOperation Op, Shape A, Shape B>
    requires std::same_as<typename A::scalar_type, typename B::scalar_type>
class CsgNode {
public:
    /// The children's precision.
    using scalar_type = typename A::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;
    /// The CSG operation (UnionOp, IntersectionOp, DifferenceOp).
    using operation = Op;
    /// The most crossings: the children's together.
    static constexpr std::size_t max_crossings = A::max_crossings + B::max_crossings;
    /// CSG nodes on the longest way down to a primitive (Crossing::path holds one bit each).
    static constexpr std::size_t csg_depth = 1 + std::max(detail::csg_depth<A>(), detail::csg_depth<B>());
    static_assert(csg_depth <= 32, "a CSG tree may be at most 32 nodes deep (Crossing::path)");

    // CsgNode Public Methods

    /// The node Op(a, b); its box is Op's of the children's boxes.
    constexpr CsgNode(A a, B b) : a_(std::move(a)), b_(std::move(b)), bounds_(Op::bounds(a_.bounds(), b_.bounds()))
    {
        bounded_ = bounds_.bounded();
        if (bounded_) {
            centre_ = T(0.5) * (bounds_.lo + bounds_.hi);
            far2_ = T(64) * length_squared(bounds_.hi - bounds_.lo);
        }
    }

    /// Nested construction for the variadic forms: CsgNode<Op, A, CsgNode<Op, B, C>>(a, b, c).
    template <class... Rest>
        requires(sizeof...(Rest) >= 2)
    constexpr CsgNode(A a, Rest&&... rest) : CsgNode(std::move(a), B(std::forward<Rest>(rest)...))
    {
    }

    /// The first child.
    [[nodiscard]] constexpr const A& first() const noexcept { return a_; }
    /// The second child.
    [[nodiscard]] constexpr const B& second() const noexcept { return b_; }
    /// The box around the result (conservative: Op of the children's boxes).
    [[nodiscard]] constexpr Aabb<T> bounds() const noexcept { return bounds_; }

    /// The box around the result carried by `transform`: Op of the children's own
    /// (bounds_under), tighter than the box around this box's corners.
    [[nodiscard]] Aabb<T> bounds_under(const Transform<T>& transform) const noexcept
    {
        return Op::bounds(prism::bounds_under(a_, transform), prism::bounds_under(b_, transform));
    }

    /// Convex where it is an intersection of convex children (a lens of two balls); any
    /// other node is not said to be.
    [[nodiscard]] constexpr bool convex() const noexcept
    {
        constexpr bool intersection = Op::combine(true, true) && !Op::combine(true, false) && !Op::combine(false, true) && !Op::combine(false, false) && !Op::flips_second;
        if constexpr (intersection) return prism::convex(a_) && prism::convex(b_);
        else return false;
    }

    /// Whether p is inside: Op of whether it is inside each child.
    [[nodiscard]] constexpr bool contains(const Vec3<T>& p) const noexcept { return Op::combine(a_.contains(p), b_.contains(p)); }

    /// Every crossing of `ray` within `range`, sorted: the children's crossings merged, each kept where it changes whether the ray is inside the result (Roth 1982).
    template <bool Surface = true>
    [[nodiscard]] constexpr Crossings<T, max_crossings> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        // A ray that cannot come near the bounds cannot cross the result.
        if (bounded_ && !bounds_.reached_after(ray, range.min)) return {};
        // A ray from far away meets the children at large t, where float's spacing may
        // exceed the gaps between their crossings (a shape of 10^-3 seen from 10^3 is 16
        // steps of t deep), so their order, and the result, would be lost: a sliver where
        // a ball's exit and a hole's fall within a step. So the children are asked along
        // the same line from a point near the node, t0 along it, and the crossings moved
        // back by t0; the range is applied to them afterwards, in the ray's own t.
        if (bounded_) {
            const Vec3<T> to_centre = centre_ - ray.origin;
            if (length_squared(to_centre) > far2_) {
                const T t0 = dot(to_centre, ray.direction) / dot(ray.direction, ray.direction);
                if (is_finite(t0)) return moved_back<Surface>(ray, range, t0);
            }
        }
        return merged<Surface>(ray, range);
    }

    /// Surface coordinates: the child's the crossing came from (its path's lowest bit).
    void coordinates(Crossing<T>& c) const noexcept
    {
        const bool second = (c.path & 1u) != 0;
        c.path >>= 1;
        if (!second) {
            add_coordinates(a_, c);
        } else {
            // The second child's own normal, where the result turned it round.
            if constexpr (Op::flips_second) c.normal = -c.normal;
            add_coordinates(b_, c);
            if constexpr (Op::flips_second) c.normal = -c.normal;
        }
    }

private:
    /// The children's crossings merged (Roth 1982), along `ray` within `range`.
    template <bool Surface>
    [[nodiscard]] constexpr Crossings<T, max_crossings> merged(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        Crossings<T, max_crossings> out;
        const auto ca = a_.template crossings<Surface>(ray, range);
        // A result inside the first child only (an intersection, a difference): a ray
        // that stays outside it crosses nothing, whatever the second child does.
        if constexpr (!Op::combine(false, false) && !Op::combine(false, true)) {
            if (ca.empty() && !ca.inside_at_start) return out;
        }
        const auto cb = b_.template crossings<Surface>(ray, range);
        bool in_a = ca.inside_at_start, in_b = cb.inside_at_start;
        bool inside = Op::combine(in_a, in_b);
        out.inside_at_start = inside;

        std::size_t i = 0, j = 0;
        while (i < ca.size() || j < cb.size()) {
            const T t = j == cb.size() || (i < ca.size() && ca[i].t <= cb[j].t) ? ca[i].t : cb[j].t;
            // Apply every crossing at this t, from both children.
            const Crossing<T>* from_a = nullptr;
            const Crossing<T>* from_b = nullptr;
            for (; i < ca.size() && ca[i].t == t; ++i) in_a = ca[i].entering, from_a = &ca[i];
            for (; j < cb.size() && cb[j].t == t; ++j) in_b = cb[j].entering, from_b = &cb[j];
            const bool now = Op::combine(in_a, in_b);
            if (now == inside) continue;
            inside = now;
            // The result's surface here is the first child's where it has one.
            Crossing<T> c = from_a != nullptr ? *from_a : *from_b;
            if (from_a == nullptr && Op::flips_second) c.normal = -c.normal, c.shading = -c.shading;
            if constexpr (Surface) c.path = c.path << 1 | (from_a == nullptr ? 1u : 0u);
            c.entering = now;
            out.push_back(c);
        }
        return out;
    }

    /// merged() along the same line from o + t0 d (each coordinate rounded once), its
    /// crossings' t moved back by t0 and only those inside `range` kept.
    template <bool Surface>
    [[nodiscard]] constexpr Crossings<T, max_crossings> moved_back(const Ray<T>& ray, Interval<T> range, T t0) const noexcept
    {
        using W = std::conditional_t<(sizeof(T) < sizeof(double)), double, T>;
        Ray<T> near = ray;
        for (int i = 0; i < 3; ++i) near.origin[i] = T(W(ray.origin[i]) + W(t0) * W(ray.direction[i]));
        // Every crossing whose t, moved back and rounded, can lie in `range`: t - t0
        // rounds by half a step of the larger of the two, so a margin of two.
        const auto widened = [t0](T end, T sign) {
            const T margin = T(2) * std::numeric_limits<T>::epsilon() * ((end < T(0) ? -end : end) + (t0 < T(0) ? -t0 : t0));
            return (end - t0) + sign * margin;
        };
        const auto inner = merged<Surface>(near, {widened(range.min, T(-1)), widened(range.max, T(1))});
        Crossings<T, max_crossings> out;
        out.inside_at_start = inner.inside_at_start;
        for (Crossing<T> c : inner) {
            c.t = c.t + t0;
            if (c.t <= range.min) out.inside_at_start = c.entering;
            else if (c.t < range.max) out.push_back(c);
        }
        return out;
    }

    A a_;
    B b_;
    Aabb<T> bounds_;
    Vec3<T> centre_{T(0)}; ///< the box's centre (bounded only)
    T far2_ = T(0);        ///< 64 times the box's squared diagonal: a ray from farther off is asked from near the node
    bool bounded_ = false;
};

namespace detail {

/// Op applied left to right over a list of shapes: A op (B op (C ...)).
template <class Op, class... S>
struct csg_fold;

template <class Op, class A>
struct csg_fold<Op, A> {
    using type = A;
};

template <class Op, class A, class B, class... Rest>
struct csg_fold<Op, A, B, Rest...> {
    using type = CsgNode<Op, A, typename csg_fold<Op, B, Rest...>::type>;
};

template <Scalar T>
constexpr Aabb<T> aabb_union(const Aabb<T>& a, const Aabb<T>& b) noexcept
{
    return {component_min(a.lo, b.lo), component_max(a.hi, b.hi)};
}

template <Scalar T>
constexpr Aabb<T> aabb_intersection(const Aabb<T>& a, const Aabb<T>& b) noexcept
{
    return {component_max(a.lo, b.lo), component_min(a.hi, b.hi)};
}

} // namespace detail

} // namespace prism
