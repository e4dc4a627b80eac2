// SPDX-License-Identifier: MIT
// How a Bvh (accel/bvh.hpp) is built: a binary tree by the surface area heuristic, top
// down (binned, or a sweep of every split), its subtrees on several threads with the same
// result for any number, the primitives put in leaf order in blocks, and the collapse of
// the binary tree into Width-wide nodes at the least SAH cost.
#pragma once

#include <prism/accel/bvh_node.hpp>
#include <prism/core/aabb.hpp>
#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/core/parallel.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace prism {

/// How the build chooses a node's split.
enum class BvhSplit {
    binned, ///< the best of `bins` - 1 planes per axis (Wald 2007): fast, near the sweep's quality
    sweep,  ///< the best between any two neighbours in centroid order: O(n log^2 n), the lowest SAH cost
};

/// How a Bvh is built: the split search, the leaf size, the threads.
struct BvhConfig {
    int max_leaf_size = 4;               ///< a leaf holds at most this many primitives (>= 1)
    int bins = 16;                       ///< SAH bins per axis (2 to 256), for BvhSplit::binned
    float traversal_cost = 1;            ///< C_trav, relative to one leaf test of leaf_block primitives
    int leaf_block = 1;                  ///< primitives a leaf tests at once (TriangleMesh: 4): n cost ceil(n / leaf_block) tests, and each leaf starts a block in leaf order
    BvhSplit split = BvhSplit::binned; ///< how splits are searched: binned SAH, or every split between neighbours (sweep)
    unsigned threads = 0;                ///< build threads (0: every hardware thread); the tree is the same for any number
};

namespace detail {

template <Scalar T>
constexpr T half_area(const Aabb<T>& b) noexcept
{
    const Vec3<T> d = b.hi - b.lo;
    return d.x * d.y + d.y * d.z + d.z * d.x;
}

/// The build of a Bvh<T>: build() makes the binary tree and fills `primitives` (leaf
/// order), `size` and `depth`; collapse<Width>() makes the wide nodes of it.
template <Scalar T>
class BvhBuilder {
public:
    /// A node of the binary tree the build makes: its box, its first child (the second is
    /// next to it, and both after their parent) or first primitive, and its primitive
    /// count (0 for an inner node).
    struct BinaryNode {
        Aabb<T> box;
        std::uint32_t first = 0;
        std::uint32_t count = 0;
    };

    /// The wide nodes of a binary tree (its root first), the root's first: which binary
    /// nodes become wide nodes is chosen so that the wide tree's SAH cost, in
    /// config.traversal_cost a node and one test a leaf_block of primitives, is the least
    /// of any collapse of this binary tree (the dynamic programme of Ylitie, Karras &
    /// Laine 2017, without their regrouping of leaves). best(n, i) is the least cost of
    /// binary node n's subtree spread over at most i lanes of its wide parent: a leaf
    /// costs its area times its tests, in one lane; an inner node kept whole becomes a
    /// wide node, costing its area times traversal_cost plus its two children spread over
    /// Width lanes; or its two children take the lanes themselves. (Taking the largest
    /// child apart until a node is full, as Embree's builders do, filled an 8-wide node
    /// with 4.1 children on average, over 10^6 random spheres; this fills it with 5.3.)
    template <int Width>
    [[nodiscard]] static constexpr std::vector<BvhNode<T, Width>> collapse(std::span<const BinaryNode> binary, const BvhConfig& config)
    {
        // Children come after their parent, so one backward pass fills best.
        constexpr auto W = std::size_t(Width);
        std::vector<std::array<T, W>> best(binary.size());
        const auto spread = [&](const BinaryNode& b, std::size_t lanes, std::size_t& left_lanes) {
            // The cheapest split of `lanes` lanes between b's two children.
            T cost = infinity<T>;
            for (std::size_t k = 1; k < lanes; ++k) {
                const T c = best[b.first][k - 1] + best[b.first + 1][lanes - k - 1];
                if (c < cost) cost = c, left_lanes = k;
            }
            return cost;
        };
        const auto whole = [&](const BinaryNode& b) {
            std::size_t k = 0;
            return half_area(b.box) * T(config.traversal_cost) + spread(b, W, k);
        };
        for (std::size_t n = binary.size(); n-- > 0;) {
            const BinaryNode& b = binary[n];
            if (b.count != 0) {
                best[n].fill(half_area(b.box) * tests(b.count, config));
                continue;
            }
            best[n][0] = whole(b);
            for (std::size_t i = 2; i <= W; ++i) {
                std::size_t k = 0;
                best[n][i - 1] = std::min(best[n][i - 2], spread(b, i, k));
            }
        }
        // Lays binary node n out over at most `lanes` lanes of `children`, as best chose.
        // (A cost that overflowed to infinity keeps a node whole: a valid tree, if not the
        // cheapest.)
        const auto lay_out = [&](auto& self, std::uint32_t n, std::size_t lanes, std::array<std::uint32_t, W>& children, int& used) -> void {
            const BinaryNode& b = binary[n];
            std::size_t k = 0;
            if (b.count != 0 || lanes == 1 || !(spread(b, lanes, k) < whole(b))) {
                children[std::size_t(used++)] = n;
                return;
            }
            self(self, b.first, k, children, used);
            self(self, b.first + 1, lanes - k, children, used);
        };
        struct Job {
            std::uint32_t binary, node;
        };
        std::vector<BvhNode<T, Width>> nodes(1);
        nodes.reserve(binary.size() / 2 + 1);
        std::vector<Job> jobs{{0, 0}};
        while (!jobs.empty()) {
            const Job job = jobs.back();
            jobs.pop_back();
            std::array<std::uint32_t, W> children{job.binary};
            int n = 1;
            if (const BinaryNode& b = binary[job.binary]; b.count == 0) {
                std::size_t k = 0;
                (void)spread(b, W, k);
                n = 0;
                lay_out(lay_out, b.first, k, children, n);
                lay_out(lay_out, b.first + 1, W - k, children, n);
            }
            for (int c = 0; c < n; ++c) {
                const BinaryNode& b = binary[children[std::size_t(c)]];
                std::uint32_t first = b.first;
                if (b.count == 0) {
                    first = std::uint32_t(nodes.size());
                    nodes.emplace_back();
                    jobs.push_back({children[std::size_t(c)], first});
                }
                nodes[job.node].set(c, b.box, first, b.count);
            }
        }
        nodes.shrink_to_fit();
        return nodes;
    }


    /// Fewer primitives than this are built on one thread (starting one costs more).
    static constexpr std::uint32_t parallel_build_size = 1u << 14;

    /// A node of the build still to split, at its depth.
    struct Open {
        std::uint32_t node;
        int depth;
    };

    /// A primitive during the build: its box and its index.
    struct Ref {
        Aabb<T> box;
        std::uint32_t index;

        [[nodiscard]] constexpr Vec3<T> center() const noexcept { return T(0.5) * (box.lo + box.hi); }
        /// Ordered by the center's coordinate on `axis`, ties by index.
        [[nodiscard]] constexpr bool before(const Ref& other, int axis) const noexcept
        {
            const T a = center()[axis], b = other.center()[axis];
            return a < b || (a == b && index < other.index);
        }
    };

    /// The binary tree, its root first; fills primitives, size and depth.
    [[nodiscard]] constexpr std::vector<BinaryNode> build(std::span<const Aabb<T>> boxes, const BvhConfig& config)
    {
        const auto n = std::uint32_t(boxes.size());
        // The primitives' boxes travel with their indices, partitioned in place: every
        // pass over a node's primitives reads memory in order (indices into `boxes`
        // would make each a random access: a build of 10^6 took four times as long).
        std::vector<Ref> refs(n);
        for (std::uint32_t i = 0; i < n; ++i) refs[i] = {boxes[i], i};
        std::vector<BinaryNode> nodes;
        nodes.reserve(2 * std::size_t(n) - 1);
        nodes.push_back({bounds_of(refs, 0, n), 0, n});
        // On several threads (for 2^14 primitives or more): the nodes of fewer than
        // `grain` primitives are left for later as whole subtrees, built side by side
        // (each splits its own range of refs into its own nodes) and then appended.
        // Every node is split as one thread would split it, so the tree is the same for
        // any thread count. (`threads` is no const initializer: that one would be
        // constant-evaluated, and say 1.)
        unsigned threads = 1;
        if (!std::is_constant_evaluated() && n >= parallel_build_size) threads = detail::worker_count(config.threads);
        const std::uint32_t grain = threads > 1 ? std::max<std::uint32_t>(n / (16 * threads), 1024) : std::numeric_limits<std::uint32_t>::max();
        std::vector<Open> subtrees;
        depth = split_nodes(refs, nodes, {0, 1}, config, [&](const Open& open) {
            if (threads > 1 && nodes[open.node].count <= grain) return subtrees.push_back(open), true;
            return false;
        });
        if (subtrees.empty()) return finish(refs, nodes, config);
        std::vector<std::vector<BinaryNode>> parts(subtrees.size());
        std::vector<int> depths(subtrees.size());
        detail::parallel_for(subtrees.size(), threads, [&](std::size_t i) {
            parts[i] = {nodes[subtrees[i].node]};
            depths[i] = split_nodes(refs, parts[i], {0, subtrees[i].depth}, config, [](const Open&) { return false; });
        }, 1); // a subtree at a time
        for (std::size_t i = 0; i < subtrees.size(); ++i) {
            // The part's node j > 0 goes to base + j - 1; its root replaces the node it grew from.
            const auto base = std::uint32_t(nodes.size());
            for (std::size_t j = 0; j < parts[i].size(); ++j) {
                BinaryNode node = parts[i][j];
                if (node.count == 0) node.first += base - 1;
                if (j == 0) nodes[subtrees[i].node] = node;
                else nodes.push_back(node);
            }
            depth = std::max(depth, depths[i]);
        }
        return finish(refs, nodes, config);
    }

    /// The primitives' order, from the refs the build partitioned, each leaf moved up to
    /// start a block of leaf_block (see primitives()); returns the nodes.
    [[nodiscard]] constexpr std::vector<BinaryNode> finish(const std::vector<Ref>& refs, std::vector<BinaryNode>& nodes, const BvhConfig& config)
    {
        const auto n = std::uint32_t(refs.size()), block = std::uint32_t(config.leaf_block);
        size = n;
        if (block == 1) {
            primitives.resize(n);
            for (std::uint32_t k = 0; k < n; ++k) primitives[k] = refs[k].index;
            return std::move(nodes);
        }
        // shift[k]: the padding of the leaves that end at or before position k, all of
        // which come before the leaf holding k (the leaves partition [0, n)).
        std::vector<std::uint64_t> shift(std::size_t(n) + 1, 0);
        for (const BinaryNode& node : nodes)
            if (node.count != 0) shift[node.first + node.count] = (block - node.count % block) % block;
        for (std::size_t k = 1; k <= n; ++k) shift[k] += shift[k - 1];
        if (std::uint64_t(n) + shift[n] >= std::numeric_limits<std::uint32_t>::max())
            detail::throw_invalid("Bvh's leaf order, padded to blocks of ", block, ", must hold fewer than 2^32 - 1 positions, got ", std::uint64_t(n) + shift[n]);
        primitives.assign(std::size_t(n + shift[n]), 0);
        for (std::uint32_t k = 0; k < n; ++k) primitives[std::size_t(k + shift[k])] = refs[k].index;
        for (BinaryNode& node : nodes) {
            if (node.count == 0) continue;
            node.first += std::uint32_t(shift[node.first]);
            const std::uint32_t last = primitives[node.first + node.count - 1];
            for (std::uint32_t k = node.count; k % block != 0; ++k) primitives[node.first + k] = last;
        }
        return std::move(nodes);
    }

    /// Split `nodes`' node `root` (a leaf holding its range of refs) and its children
    /// until they are leaves, appending the children to `nodes`; a node that
    /// `defer(open)` takes is left as it is. Returns the deepest depth reached.
    template <class Defer>
    [[nodiscard]] static constexpr int split_nodes(std::vector<Ref>& refs, std::vector<BinaryNode>& nodes, Open root, const BvhConfig& config, Defer&& defer)
    {
        std::vector<Open> pending{root};
        int deepest = root.depth;
        const std::size_t bins = std::size_t(config.bins);
        std::vector<T> swept(config.split == BvhSplit::sweep ? nodes[root.node].count : 0); // the sweep's right-hand costs
        // The binned split's scratch: per axis, each bin's box and count, and the box of
        // the bins from b on (only the first `bins` of each are used, and reset per node).
        std::array<std::array<Aabb<T>, 256>, 3> bin_box;
        std::array<std::array<std::uint32_t, 256>, 3> bin_count;
        std::array<Aabb<T>, 256> right_box;
        std::array<T, 256> right_cost;
        while (!pending.empty()) {
            const Open open = pending.back();
            const auto [index, depth] = open;
            pending.pop_back();
            deepest = std::max(deepest, depth);
            const std::uint32_t first = nodes[index].first, count = nodes[index].count;
            if (count <= 1 || defer(open)) continue;
            // The centroids' bounds: the bins span them.
            Aabb<T> middle;
            for (std::uint32_t k = first; k < first + count; ++k) {
                const Vec3<T> c = refs[k].center();
                middle = middle.merged({c, c});
            }
            const auto begin = refs.begin() + first, end = begin + count;
            std::uint32_t split = 0; // primitives [first, first + split) go left
            std::optional<std::array<Aabb<T>, 2>> children; // their boxes, where the split found them
            if (depth < 48 && !(middle.lo == middle.hi) && config.split == BvhSplit::sweep) {
                // Every split between neighbours in centroid order, on each axis.
                T best_cost = infinity<T>;
                int best_axis = -1;
                std::uint32_t best_split = 0;
                for (int axis = 0; axis < 3; ++axis) {
                    if (!(middle.hi[axis] - middle.lo[axis] > T(0))) continue;
                    sort_by_center(begin, end, axis);
                    Aabb<T> right;
                    for (std::uint32_t k = count - 1; k > 0; --k) {
                        right = right.merged(begin[k].box);
                        swept[k] = half_area(right) * tests(count - k, config);
                    }
                    Aabb<T> left;
                    for (std::uint32_t k = 1; k < count; ++k) {
                        left = left.merged(begin[k - 1].box);
                        const T cost = half_area(left) * tests(k, config) + swept[k];
                        if (cost < best_cost) best_cost = cost, best_axis = axis, best_split = k;
                    }
                }
                if (best_axis < 0 || prefer_leaf(best_cost, nodes[index].box, count, config)) continue;
                if (best_axis != 2) sort_by_center(begin, end, best_axis);
                split = best_split;
            } else if (depth < 48 && !(middle.lo == middle.hi)) {
                // Binned SAH over the three axes, binned in one pass.
                std::array<T, 3> scale{};
                for (int axis = 0; axis < 3; ++axis) {
                    const T extent = middle.hi[axis] - middle.lo[axis];
                    scale[std::size_t(axis)] = extent > T(0) ? T(bins) / extent : T(0);
                    std::fill_n(bin_box[std::size_t(axis)].begin(), bins, Aabb<T>{});
                    std::fill_n(bin_count[std::size_t(axis)].begin(), bins, std::uint32_t(0));
                }
                for (auto it = begin; it != end; ++it) {
                    const Vec3<T> c = it->center();
                    for (std::size_t axis = 0; axis < 3; ++axis) {
                        if (!(scale[axis] > T(0))) continue;
                        const std::size_t b = bin_of(c[int(axis)], middle.lo[int(axis)], scale[axis], bins);
                        bin_box[axis][b] = bin_box[axis][b].merged(it->box);
                        ++bin_count[axis][b];
                    }
                }
                T best_cost = infinity<T>;
                int best_axis = -1;
                std::size_t best_bin = 0;
                std::array<Aabb<T>, 2> best_boxes{};
                for (std::size_t axis = 0; axis < 3; ++axis) {
                    if (!(scale[axis] > T(0))) continue;
                    // Right-to-left sweep of areas and counts, then left to right.
                    Aabb<T> right;
                    std::uint32_t right_count = 0;
                    for (std::size_t b = bins - 1; b > 0; --b) {
                        right = right.merged(bin_box[axis][b]);
                        right_count += bin_count[axis][b];
                        right_box[b] = right;
                        right_cost[b] = right_count ? half_area(right) * tests(right_count, config) : T(0);
                    }
                    Aabb<T> left;
                    std::uint32_t left_count = 0;
                    for (std::size_t b = 1; b < bins; ++b) {
                        left = left.merged(bin_box[axis][b - 1]);
                        left_count += bin_count[axis][b - 1];
                        if (left_count == 0 || left_count == count) continue;
                        const T cost = half_area(left) * tests(left_count, config) + right_cost[b];
                        if (cost < best_cost) best_cost = cost, best_axis = int(axis), best_bin = b, best_boxes = {left, right_box[b]};
                    }
                }
                if (best_axis < 0 || prefer_leaf(best_cost, nodes[index].box, count, config)) continue;
                const T lo = middle.lo[best_axis], axis_scale = scale[std::size_t(best_axis)];
                split = std::uint32_t(std::partition(begin, end, [&](const Ref& r) { return bin_of(r.center()[best_axis], lo, axis_scale, bins) < best_bin; }) - begin);
                children = best_boxes;
            } else {
                if (count <= std::uint32_t(config.max_leaf_size)) continue; // coincident centroids: a leaf if it may be one
                // By count: the lower half along the widest centroid axis (all equal: any half).
                const int axis = index_of_max(middle.hi - middle.lo);
                split = count / 2;
                std::nth_element(begin, begin + split, end, [&](const Ref& a, const Ref& b) { return a.before(b, axis); });
            }
            if (!children) children = std::array<Aabb<T>, 2>{bounds_of(refs, first, split), bounds_of(refs, first + split, count - split)};
            const std::uint32_t child = std::uint32_t(nodes.size());
            nodes.push_back({(*children)[0], first, split});
            nodes.push_back({(*children)[1], first + split, count - split});
            nodes[index].first = child;
            nodes[index].count = 0;
            pending.push_back({child + 1, depth + 1});
            pending.push_back({child, depth + 1});
        }
        return deepest;
    }

    /// Whether a leaf of `count` primitives costs no more than the best split (of summed
    /// area-count `best_cost`) and may be one.
    [[nodiscard]] static constexpr bool prefer_leaf(T best_cost, const Aabb<T>& box, std::uint32_t count, const BvhConfig& config) noexcept
    {
        const T area = half_area(box);
        const T leaf_cost = tests(count, config), split_cost = T(config.traversal_cost) + (area > T(0) ? best_cost / area : leaf_cost);
        return leaf_cost <= split_cost && count <= std::uint32_t(config.max_leaf_size);
    }

    /// The leaf tests `count` primitives take: one per leaf_block of them.
    [[nodiscard]] static constexpr T tests(std::uint32_t count, const BvhConfig& config) noexcept
    {
        const auto block = std::uint32_t(config.leaf_block);
        return T((count + block - 1) / block);
    }

    /// Sorts primitives by their centers' coordinate on `axis`, ties by index.
    template <class It>
    static constexpr void sort_by_center(It begin, It end, int axis)
    {
        std::sort(begin, end, [&](const Ref& a, const Ref& b) { return a.before(b, axis); });
    }

    [[nodiscard]] static constexpr std::size_t bin_of(T c, T lo, T scale, std::size_t bins) noexcept
    {
        const T b = (c - lo) * scale;
        return b >= T(bins) ? bins - 1 : (b > T(0) ? std::size_t(b) : 0);
    }

    [[nodiscard]] static constexpr int index_of_max(const Vec3<T>& v) noexcept { return v.x >= v.y ? (v.x >= v.z ? 0 : 2) : (v.y >= v.z ? 1 : 2); }

    [[nodiscard]] static constexpr Aabb<T> bounds_of(const std::vector<Ref>& refs, std::uint32_t first, std::uint32_t count) noexcept
    {
        Aabb<T> box;
        for (std::uint32_t k = first; k < first + count; ++k) box = box.merged(refs[k].box);
        return box;
    }


    std::vector<std::uint32_t> primitives;
    std::size_t size = 0; ///< primitives, without the padding of leaf blocks
    int depth = 0;
};

} // namespace detail

} // namespace prism
