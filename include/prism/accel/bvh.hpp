// SPDX-License-Identifier: MIT
// Bvh: a bounding volume hierarchy over boxes, for ray queries (after madmann91's bvh v2:
// a flat node array, a Config, the query a template of the traversal).
//
// Build: top-down, binned surface area heuristic (Wald 2007). At each node the
// primitives' centroids are binned along each axis, every bin boundary is costed as
//     C = C_trav + C_isect (A_left n_left + A_right n_right) / A_node
// and the cheapest split is taken, unless a leaf of n primitives (C_isect n) is cheaper
// and holds no more than max_leaf_size. For a caller that tests b primitives at once
// (BvhConfig::leaf_block; TriangleMesh tests four), every n above is ceil(n / b), as in
// Embree's builders. (BvhSplit::sweep costs instead every split
// between neighbours in centroid order, sorting on each axis: a build 2-3.5 times as
// long, for an SAH cost 0.1-0.6 % lower in bench/bvh_quality.cpp.) Primitives whose
// centroids coincide are split by
// count. Below depth 48 only count splits are made, so no binary tree is deeper than
// 48 + 32 levels and traversal needs a fixed stack. The binary tree is then collapsed
// into a wide one of up to Width children a node (4, or 8 in float where the target has
// AVX; Embree's BVH4 and BVH8), choosing the binary nodes to keep by the least SAH cost
// (Bvh::collapse), so a ray tests four or eight boxes at once, side by side in memory
// (128 or 256 bytes a node in float), with one SIMD instruction per step, and meets a
// half or a third as many levels.
//
// Traversal (its node and the node's box test: accel/bvh_node.hpp) visits children nearest first (an any-hit query's in any order) and never
// misses a primitive whose box the ray may cross (Aabb::may_cross: the box widened by
// gamma(16) of the ray origin's distance, the far slab by 2 gamma(3)). Every box is
// widened by one pad per ray that is at least as wide as that for any box of the tree
// (from the root box's largest coordinate), so a node's widened box holds each widened
// box inside it, and the test per node is a plain slab test (Ize 2013), the same
// arithmetic in each lane as in SlabRay::may_cross. So a scene that accelerates its
// linear scan with a Bvh tests every object that scan would have tested, and finds the
// same hit. The query is the caller's: visit(primitive, range) may shrink range.max
// (closest hit) or return true to stop (any hit). Queries allocate nothing.
#pragma once

#include <prism/accel/bvh_build.hpp>
#include <prism/accel/bvh_node.hpp>
#include <prism/core/aabb.hpp>
#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/core/parallel.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <span>
#include <type_traits>
#include <vector>

namespace prism {

/// A bounding volume hierarchy over boxes (binned SAH, collapsed to nodes of Width children),
/// walked nearest child first with the query as the caller's visitor; constexpr.
template <Scalar T, int Width = detail::default_bvh_width<T>>
class Bvh {
public:
    /// The precision of the boxes.
    using scalar_type = T;
    /// The tree's node type.
    using Node = BvhNode<T, Width>;
    /// The binary tree's depth bound; the wide tree is no deeper.
    static constexpr int max_depth = 48 + 32;
    /// Children per node: 4, or 8 for float where the compiler targets AVX.
    static constexpr int width = Width;

    constexpr Bvh() = default;

    /// The hierarchy over `boxes`; primitive i is boxes[i]. Every box must be bounded
    /// (finite, not empty): unbounded shapes are tested on their own, beside the tree.
    constexpr explicit Bvh(std::span<const Aabb<T>> boxes, BvhConfig config = {})
    {
        if (config.max_leaf_size < 1) detail::throw_invalid("BvhConfig max_leaf_size must be >= 1, got ", config.max_leaf_size);
        if (config.bins < 2 || config.bins > 256) detail::throw_invalid("BvhConfig bins must be in [2, 256], got ", config.bins);
        if (config.leaf_block < 1) detail::throw_invalid("BvhConfig leaf_block must be >= 1, got ", config.leaf_block);
        if (!(config.traversal_cost >= 0.0f)) detail::throw_invalid("BvhConfig traversal_cost must be >= 0, got ", config.traversal_cost);
        if (config.split != BvhSplit::binned && config.split != BvhSplit::sweep) detail::throw_invalid("BvhConfig split must be binned or sweep, got ", int(config.split));
        if (boxes.size() >= std::size_t(std::numeric_limits<std::uint32_t>::max()))
            detail::throw_invalid("Bvh takes fewer than 2^32 - 1 primitives, got ", boxes.size());
        for (std::size_t i = 0; i < boxes.size(); ++i)
            if (!boxes[i].bounded()) detail::throw_invalid("Bvh primitive ", i, " has no finite box: test unbounded shapes beside the tree");
        if (boxes.empty()) return;
        leaf_block_ = config.leaf_block;
        detail::BvhBuilder<T> builder;
        const std::vector<BinaryNode> binary = builder.build(boxes, config);
        primitives_ = std::move(builder.primitives);
        size_ = builder.size;
        depth_ = builder.depth;
        bounds_ = binary[0].box;
        magnitude_ = std::max(max_component(prism::abs(bounds_.lo)), max_component(prism::abs(bounds_.hi)));
        nodes_ = collapse(binary, config);
    }

    /// A node of the binary tree the build makes (accel/bvh_build.hpp).
    using BinaryNode = typename detail::BvhBuilder<T>::BinaryNode;

    /// The wide nodes of a binary tree, at the least SAH cost (BvhBuilder::collapse).
    [[nodiscard]] static constexpr std::vector<Node> collapse(std::span<const BinaryNode> binary, const BvhConfig& config)
    {
        return detail::BvhBuilder<T>::template collapse<Width>(binary, config);
    }

    /// The wide nodes, the root first.
    [[nodiscard]] constexpr std::span<const Node> nodes() const noexcept { return nodes_; }
    /// The primitives in leaf order: a leaf holds primitives()[first, first + count).
    /// With BvhConfig::leaf_block b > 1, every leaf's first is a multiple of b, and the
    /// positions from its end to the next multiple hold its last primitive again: a
    /// caller that keeps its primitives in blocks of b in this order finds a leaf's first
    /// block at first / b, with no table to look it up in.
    [[nodiscard]] constexpr std::span<const std::uint32_t> primitives() const noexcept { return primitives_; }
    /// The number of primitives (primitives() also holds the padding of leaf blocks).
    [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
    /// The depth of the binary tree the build made (the wide one is a half or a third as deep).
    [[nodiscard]] constexpr int depth() const noexcept { return depth_; }
    /// The box around every primitive (empty for none).
    [[nodiscard]] constexpr const Aabb<T>& bounds() const noexcept { return bounds_; }

    /// The tree's expected cost for a ray through its box (the surface area heuristic,
    /// in leaf tests of BvhConfig::leaf_block primitives): each node's box area, times
    /// `node_cost` (a node's box test), and each leaf's, times its tests, over the root's
    /// area.
    [[nodiscard]] constexpr double sah_cost(double node_cost = 1) const noexcept
    {
        const double root = double(detail::half_area(bounds_));
        if (nodes_.empty() || !(root > 0)) return double(size());
        double cost = node_cost; // the root node
        for (const Node& node : nodes_)
            for (int c = 0; c < width; ++c)
                if (node.used(c))
                    cost += double(detail::half_area(node.box(c))) / root *
                            (node.leaf(c) ? double(detail::BvhBuilder<T>::tests(node.count[std::size_t(c)], {.leaf_block = leaf_block_})) : node_cost);
        return cost;
    }

    /// Visit, nearest node first, every primitive whose box the ray may cross within
    /// `range`: visit(primitive, range) tests it, may shrink range.max to a hit it found,
    /// and returns true to end the query (an any-hit query's first hit).
    /// Returns whether a visit ended it.
    template <class Visit>
    constexpr bool traverse(const Ray<T>& ray, Interval<T>& range, Visit&& visit) const
    {
        return walk<true>(ray, range, each_primitive([&](std::uint32_t k, Interval<T>& r) { return visit(primitives_[k], r); }));
    }

    /// traverse, with visit given a primitive's position k in leaf order (primitives()[k])
    /// instead: for callers that store their primitives in that order, as TriangleMesh does.
    template <class Visit>
    constexpr bool traverse_in_leaf_order(const Ray<T>& ray, Interval<T>& range, Visit&& visit) const
    {
        return walk<true>(ray, range, each_primitive(visit));
    }

    /// traverse_in_leaf_order for a query that takes any hit (a shadow ray's): the same
    /// primitives, in no particular order (children are not sorted by distance), until a
    /// visit returns true.
    template <class Visit>
    constexpr bool any_in_leaf_order(const Ray<T>& ray, Interval<T>& range, Visit&& visit) const
    {
        return walk<false>(ray, range, each_primitive(visit));
    }

    /// traverse_in_leaf_order a leaf at a time: visit(first, count, range) tests the
    /// primitives at leaf-order positions [first, first + count) (for callers that test
    /// several at once), may shrink range.max, and returns true to end the query.
    template <class Visit>
    constexpr bool traverse_leaves(const Ray<T>& ray, Interval<T>& range, Visit&& visit) const
    {
        return walk<true>(ray, range, visit);
    }

    /// any_in_leaf_order a leaf at a time (as traverse_leaves).
    template <class Visit>
    constexpr bool any_leaf(const Ray<T>& ray, Interval<T>& range, Visit&& visit) const
    {
        return walk<false>(ray, range, visit);
    }

private:

    /// A child met but not yet visited: a node (count 0) or a leaf, and where the ray's
    /// range within its box begins.
    struct Pending {
        std::uint32_t first, count;
        T near;
    };

    /// A leaf's visit from a primitive's: each in turn, until one ends the query.
    template <class Visit>
    [[nodiscard]] static constexpr auto each_primitive(Visit&& visit) noexcept
    {
        return [&visit](std::uint32_t first, std::uint32_t count, Interval<T>& range) {
            for (std::uint32_t k = first; k < first + count; ++k)
                if (visit(k, range)) return true;
            return false;
        };
    }

    /// The traversal, visit(first, count, range) for each leaf; `Nearest`: children
    /// nearest first (else in lane order).
    template <bool Nearest, class Visit>
    constexpr bool walk(const Ray<T>& ray, Interval<T>& range, Visit&& visit) const
    {
        // A ray with a NaN or an infinity in it meets nothing. (A NaN would pass every
        // box test, the padding lanes' empty boxes too, and those lanes' zeros would be
        // taken for the root: a walk without end.)
        if (nodes_.empty()) return false;
#if PRISM_VECTOR_EXTENSIONS
        if (!std::is_constant_evaluated()) return walk_in_lanes<Nearest>(ray, range, visit);
#endif
        if (!is_finite(ray.origin) || !is_finite(ray.direction)) return false;
        return walk_with<Nearest>(detail::SlabRay<T>(ray, magnitude_), range, visit);
    }

#if PRISM_VECTOR_EXTENSIONS
    /// walk at run time, with SlabLanes' node test (which tells a ray that is not finite
    /// in the same few instructions that make its numbers).
    template <bool Nearest, class Visit>
    [[gnu::always_inline]] bool walk_in_lanes(const Ray<T>& ray, Interval<T>& range, Visit&& visit) const
    {
        const detail::SlabLanes<T, Width> lanes(ray, magnitude_);
        return lanes.finite && walk_with<Nearest>(lanes, range, visit);
    }
#endif

    template <bool Nearest, class Slab, class Visit>
    constexpr bool walk_with(const Slab& slab, Interval<T>& range, Visit&& visit) const
    {
        // A node pushes all its children but one, on at most max_depth levels. (Left
        // uninitialized: clearing its 3 kB would cost more than a short query.)
        std::array<Pending, (width - 1) * max_depth + 1> stack;
        int top = 0;
        Pending at{0, 0, T(0)};
        for (;;) {
            if (at.count == 0) {
                // A node: its children the ray may cross, nearest first (or in lane
                // order); the first is taken next, the others wait on the stack, the
                // last deepest.
                const Node& node = nodes_[at.first];
                std::array<T, width> near{};
                unsigned hits = slab.may_cross(node, range, near);
                if (hits != 0) {
                    // One child or two (most nodes deep in the tree) take no sort: fewer
                    // branches for the processor to mispredict on incoherent rays.
                    const auto child = [&](unsigned mask) {
                        const auto lane = std::size_t(std::countr_zero(mask));
                        return Pending{node.first[lane], node.count[lane], near[lane]};
                    };
                    const unsigned rest = hits & (hits - 1);
                    if (rest == 0) {
                        at = child(hits);
                        continue;
                    }
                    if ((rest & (rest - 1)) == 0) {
                        Pending first = child(hits), second = child(rest);
                        if (Nearest && second.near < first.near) std::swap(first, second);
                        stack[std::size_t(top++)] = second;
                        at = first;
                        continue;
                    }
                    // Onto the stack, sorted as they go (the nearest on top), and the
                    // nearest taken off again.
                    const int base = top;
                    for (; hits != 0; hits &= hits - 1) {
                        const auto lane = std::size_t(std::countr_zero(hits));
                        const Pending p{node.first[lane], node.count[lane], near[lane]};
                        int k = top++;
                        if constexpr (Nearest)
                            for (; k > base && stack[std::size_t(k - 1)].near < p.near; --k) stack[std::size_t(k)] = stack[std::size_t(k - 1)];
                        stack[std::size_t(k)] = p;
                    }
                    at = stack[std::size_t(--top)];
                    continue;
                }
            } else {
                if (visit(at.first, at.count, range)) return true;
            }
            // Next on the stack, skipping children the shrunk range no longer reaches
            // (range.min stays, so the child's part of it is [near, range.max]).
            for (;;) {
                if (top == 0) return false;
                at = stack[std::size_t(--top)];
                if (at.near <= range.max) break;
            }
        }
    }

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> primitives_;
    Aabb<T> bounds_{};
    std::size_t size_ = 0; ///< primitives, without the padding of leaf blocks
    T magnitude_ = 0; ///< the largest coordinate magnitude of the root's box
    int depth_ = 0;
    int leaf_block_ = 1; ///< BvhConfig::leaf_block, for sah_cost
};

} // namespace prism
