// SPDX-License-Identifier: MIT
// KdTree: k-nearest and radius queries over a point set; pointer-free, constexpr-friendly.
//
// The point set is a policy (the PointSet concept, in the spirit of nanoflann's dataset
// adaptor). The tree is implicit: node n covers a range of points, its children are 2n
// and 2n + 1 and cover the two halves of the range, split at the median along the axis
// of largest extent (found with std::nth_element, O(n log n) overall). A node stores
// only its split value and axis; ranges, and whether a node is a leaf, follow from the
// point count. The points are copied in tree order, so a leaf is contiguous in memory.
// Points with a NaN coordinate are refused (std::invalid_argument): they have no place
// in the order. Queries allocate nothing; the capacity K is a compile-time constant. Neighbours are ordered by
// (squared distance, index), so ties are broken the same way as a brute-force search.
// Distances are squared throughout, radii are not.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/config.hpp>
#include <prism/core/math.hpp>
#include <prism/core/parallel.hpp>

#include <algorithm>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <thread>
#include <type_traits>
#include <vector>

namespace prism {

/// A set of points: their count, dimension and coordinates.
template <class P>
concept PointSet = requires(const P& points, std::size_t i, std::size_t axis) {
    requires Scalar<typename P::scalar_type>;
    { P::dimension } -> std::convertible_to<std::size_t>;
    { points.size() } -> std::convertible_to<std::size_t>;
    { points.coordinate(i, axis) } -> std::convertible_to<typename P::scalar_type>;
};

/// Points kept by the caller in a contiguous array of std::array<T, Dim>.
template <Scalar T, std::size_t Dim>
struct ArrayPoints {
    /// The coordinates' type.
    using scalar_type = T;
    /// The number of coordinates a point has.
    static constexpr std::size_t dimension = Dim;

    std::span<const std::array<T, Dim>> points; ///< the points, which the caller keeps alive

    /// The number of points.
    [[nodiscard]] constexpr std::size_t size() const noexcept { return points.size(); }
    /// Coordinate `axis` of point i.
    [[nodiscard]] constexpr T coordinate(std::size_t i, std::size_t axis) const noexcept { return points[i][axis]; }
};

/// One neighbour: its squared distance from the query and its index in the point set.
/// Trivially default-constructible, so a search's buffer costs nothing to set up.
template <Scalar T>
struct Neighbour {
    T distance2; ///< the squared distance from the query
    std::uint32_t index; ///< the point's index in the point set

    /// Nearer first; at equal distance, the lower index first.
    friend constexpr bool operator<(const Neighbour& a, const Neighbour& b) noexcept
    {
        return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
    }
    /// Neighbours are equal when distance and index are.
    friend constexpr bool operator==(const Neighbour&, const Neighbour&) = default;
};

/// What a search collects. `bound()` is the squared distance beyond which it takes
/// nothing more (the search prunes every cell farther than that); `add(distance2,
/// index)` offers it a point within the bound.
template <class R, class T>
concept ResultSet = requires(R& results, const R& const_results, T distance2, std::uint32_t index) {
    { const_results.bound() } -> std::same_as<T>;
    results.add(distance2, index);
};

/// The k nearest points within a maximum distance, in a buffer of at least k the caller
/// owns: a max-heap on (distance, index) while searching, so the farthest is first.
template <Scalar T>
class KNearest {
public:
    /// k is capped by the buffer's size; max_distance2 is the squared maximum distance.
    constexpr KNearest(std::span<Neighbour<T>> buffer, std::size_t k, T max_distance2) noexcept
        : heap_(buffer.data()), k_(k < buffer.size() ? k : buffer.size()), bound_(max_distance2)
    {
    }

    /// The maximum distance squared until k are found, then the k-th nearest's.
    [[nodiscard]] constexpr T bound() const noexcept { return bound_; }

    /// Keep the point while fewer than k are found, else when it is nearer (ties: lower
    /// index) than the farthest kept, which it replaces.
    constexpr void add(T distance2, std::uint32_t index) noexcept
    {
        const Neighbour<T> candidate{distance2, index};
        if (count_ < k_) {
            heap_[count_++] = candidate;
            std::push_heap(heap_, heap_ + count_);
            if (count_ == k_) bound_ = heap_[0].distance2;
        } else if (candidate < heap_[0]) {
            replace_top(candidate);
            bound_ = heap_[0].distance2;
        }
    }

    /// How many are kept (at most k).
    [[nodiscard]] constexpr std::size_t size() const noexcept { return count_; }
    /// Whether k are kept: then the k-th nearest is farthest().
    [[nodiscard]] constexpr bool full() const noexcept { return count_ == k_; }
    /// The first neighbour kept (in heap order, not sorted).
    [[nodiscard]] constexpr const Neighbour<T>* begin() const noexcept { return heap_; }
    /// One past the last neighbour kept.
    [[nodiscard]] constexpr const Neighbour<T>* end() const noexcept { return heap_ + count_; }
    /// The farthest found (the heap's top); only when size() > 0.
    [[nodiscard]] constexpr const Neighbour<T>& farthest() const noexcept { return heap_[0]; }

    /// Nearest first, ties by lower index (ends the heap order).
    constexpr void sort() noexcept { std::sort_heap(heap_, heap_ + count_); }

private:
    /// Replace the largest of the full heap and sift the newcomer down: one pass of log k
    /// steps, where pop_heap then push_heap take two.
    constexpr void replace_top(const Neighbour<T>& item) noexcept
    {
        std::size_t at = 0;
        for (;;) {
            const std::size_t left = 2 * at + 1;
            if (left >= k_) break;
            const std::size_t right = left + 1;
            const std::size_t larger = right < k_ && heap_[left] < heap_[right] ? right : left;
            if (!(item < heap_[larger])) break;
            heap_[at] = heap_[larger];
            at = larger;
        }
        heap_[at] = item;
    }

    Neighbour<T>* heap_;
    std::size_t k_;
    std::size_t count_ = 0;
    T bound_; ///< the maximum distance until k are found, then the k-th nearest's
};

/// Every point within a radius, handed to visit(index, distance2) in tree order.
template <Scalar T, class Visitor>
class WithinRadius {
public:
    /// A search for every point within sqrt(radius2), each handed to `visit`, which must outlive the search.
    constexpr WithinRadius(T radius2, Visitor& visit) noexcept : radius2_(radius2), visit_(&visit) {}

    /// The radius squared, fixed.
    [[nodiscard]] constexpr T bound() const noexcept { return radius2_; }
    /// Hand the point to the visitor.
    constexpr void add(T distance2, std::uint32_t index) { (*visit_)(index, distance2); }

private:
    T radius2_;
    Visitor* visit_;
};

/// The k nearest neighbours found, nearest first (fewer when the set is smaller).
template <Scalar T, std::size_t K>
struct NearestNeighbours {
    std::array<Neighbour<T>, K> items; ///< the neighbours, nearest first; the first `count` are valid
    std::size_t count = 0; ///< how many were found

    /// How many were found.
    [[nodiscard]] constexpr std::size_t size() const noexcept { return count; }
    /// The i-th nearest.
    [[nodiscard]] constexpr const Neighbour<T>& operator[](std::size_t i) const noexcept { return items[i]; }
    /// The nearest.
    [[nodiscard]] constexpr const Neighbour<T>* begin() const noexcept { return items.data(); }
    /// One past the farthest found.
    [[nodiscard]] constexpr const Neighbour<T>* end() const noexcept { return items.data() + count; }
};

/// A pointer-free KD-tree over a PointSet: one search over a result-set policy
/// (KNearest, WithinRadius or the caller's own); constexpr.
template <PointSet Points, std::size_t LeafSize = 8>
class KdTree {
    static_assert(LeafSize >= 1, "a leaf holds at least one point");

public:
    /// The coordinates' type.
    using scalar_type = typename Points::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;
    /// The number of coordinates a point has.
    static constexpr std::size_t dimension = Points::dimension;
    /// The most points a leaf holds.
    static constexpr std::size_t leaf_size = LeafSize;
    /// A point, copied into tree order.
    using Point = std::array<T, dimension>;

    // KdTree Public Methods

    /// Build over the points (copied; the set may go away afterwards), the subtrees of
    /// large ranges on up to `threads` threads (0 = all hardware threads). The tree is
    /// the same for any thread count: the subtrees own disjoint ranges and nodes.
    constexpr explicit KdTree(const Points& points, unsigned threads = 1)
    {
        const std::size_t n = points.size();
        if (n >= std::numeric_limits<std::uint32_t>::max())
            detail::throw_invalid("KdTree holds at most ", std::numeric_limits<std::uint32_t>::max() - 1, " points (32-bit indices), got ", n);
        points_.resize(n);
        index_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            index_[i] = static_cast<std::uint32_t>(i);
            for (std::size_t a = 0; a < dimension; ++a) {
                points_[i][a] = static_cast<T>(points.coordinate(i, a));
                // A NaN is neither left nor right of any split: the median partition and
                // every query's pruning would go wrong for ordinary points too.
                if (points_[i][a] != points_[i][a]) detail::throw_invalid("KdTree point ", i, " has a NaN coordinate (axis ", a, ")");
            }
        }
        if (n > LeafSize) {
            // Heap-numbered nodes: enough for every split of halving ranges down to a leaf.
            std::size_t nodes = 2;
            for (std::size_t leaves = 1; (n + leaves - 1) / leaves > LeafSize; leaves *= 2) nodes *= 2;
            split_.resize(nodes);
            axis_.resize(nodes);
            if (std::is_constant_evaluated()) build(1, 0, n);
            else build_on_threads(1, 0, n, detail::worker_count(threads));
        }
        // Store the points in tree order.
        std::vector<Point> ordered(n);
        if (std::is_constant_evaluated()) {
            for (std::size_t i = 0; i < n; ++i) ordered[i] = points_[index_[i]];
        } else {
            detail::parallel_for(n, threads, [&](std::size_t i) { ordered[i] = points_[index_[i]]; });
        }
        points_ = std::move(ordered);
    }

    /// The number of points.
    [[nodiscard]] constexpr std::size_t size() const noexcept { return points_.size(); }

    /// The point set's index of each point in tree order: a leaf's points are
    /// consecutive, so data kept in this order is read with good locality.
    [[nodiscard]] constexpr std::span<const std::uint32_t> order() const noexcept { return index_; }

    /// For a caller that has put its own data in order(): from now on a point's index
    /// is its place in tree order (and ties are broken by that).
    constexpr void index_in_tree_order() noexcept
    {
        for (std::size_t i = 0; i < index_.size(); ++i) index_[i] = static_cast<std::uint32_t>(i);
    }

    /// Bytes held by the tree (points in tree order, their indices, the nodes).
    [[nodiscard]] constexpr std::size_t memory_bytes() const noexcept
    {
        return points_.capacity() * sizeof(Point) + index_.capacity() * sizeof(std::uint32_t) + split_.capacity() * sizeof(T) +
               axis_.capacity();
    }

    /// The one search: descend toward q, then visit the far side of each split whose
    /// cell is within results.bound(), handing results every point within it.
    template <ResultSet<T> Results>
    constexpr void search(const Point& q, Results& results) const
    {
        if (points_.empty() || !(results.bound() >= T(0))) return;
        Point offsets{};
        descend(q, 1, 0, points_.size(), offsets, results);
    }

    /// The K nearest points to q, nearest first, ties by lower index.
    template <std::size_t K>
    [[nodiscard]] constexpr NearestNeighbours<T, K> nearest(const Point& q) const noexcept
    {
        return nearest<K>(q, K, infinity<T>);
    }

    /// The k <= K nearest points to q within max_radius (distance <= max_radius), nearest
    /// first, ties by lower index: K is the capacity, fixed at compile time, k and the
    /// radius are chosen at run time (Jensen's k-nearest search with a maximum distance).
    /// Sorted = false leaves them in heap order (the same set, the farthest first), for
    /// callers that only sum over them.
    template <std::size_t K, bool Sorted = true>
    [[nodiscard]] constexpr NearestNeighbours<T, K> nearest(const Point& q, std::size_t k, T max_radius) const noexcept
    {
        static_assert(K >= 1);
        NearestNeighbours<T, K> found;
        if (std::is_constant_evaluated()) found.items = {};
        if (k == 0 || !(max_radius >= T(0))) return found;
        KNearest<T> results(found.items, k, max_radius * max_radius);
        search(q, results);
        if constexpr (Sorted) results.sort();
        found.count = results.size();
        return found;
    }

    /// Call visit(index, distance2) for every point within `radius` of q (distance <=
    /// radius), in tree order.
    template <class Visitor>
    constexpr void within(const Point& q, T radius, Visitor&& visit) const
    {
        if (!(radius >= T(0))) return;
        WithinRadius<T, std::remove_reference_t<Visitor>> results(radius * radius, visit);
        search(q, results);
    }

    /// Call visit(index, t, distance2) for every point within `radius` of the segment
    /// {origin + t direction : t_min <= t <= t_max} (direction a unit vector; three
    /// dimensions) whose projection t onto the line lies in [t_min, t_max], distance2 its
    /// squared distance from the line: the photons a beam radiance estimate gathers
    /// (Jarosz et al. 2008). The line is clipped, cell by cell, to the part within
    /// `radius` of each side of a split, so only cells the cylinder reaches are visited.
    template <class Visitor>
    constexpr void along(const Point& origin, const Point& direction, T t_min, T t_max, T radius, Visitor&& visit) const
    {
        static_assert(dimension == 3, "a segment query is in three dimensions");
        if (points_.empty() || !(radius >= T(0)) || !(t_min <= t_max)) return;
        // The cells are clipped with a radius padded by rounding; each point is then
        // tested exactly against the radius asked for.
        const T pad = radius * (T(1) + T(64) * std::numeric_limits<T>::epsilon()) + T(64) * std::numeric_limits<T>::min();
        along_cells(origin, direction, t_min, t_max, pad, 1, 0, points_.size(), t_min, t_max, radius * radius, visit);
    }

    /// Squared Euclidean distance, as every query computes it.
    [[nodiscard]] static constexpr T distance2(const Point& a, const Point& b) noexcept
    {
        T sum = T(0);
        for (std::size_t i = 0; i < dimension; ++i) {
            const T d = a[i] - b[i];
            sum += d * d;
        }
        return sum;
    }

private:
    // KdTree Private Methods

    [[nodiscard]] static constexpr std::size_t middle(std::size_t begin, std::size_t end) noexcept { return begin + (end - begin) / 2; }

    /// Ranges smaller than this are not worth a thread of their own.
    static constexpr std::size_t parallel_range = std::size_t(1) << 15;

    /// build(), with the two halves of a large range on threads of their own (not in a
    /// constant expression).
    void build_on_threads(std::size_t node, std::size_t begin, std::size_t end, unsigned threads)
    {
        if (threads <= 1 || end - begin < parallel_range) return build(node, begin, end);
        const std::size_t mid = split(node, begin, end);
        std::thread left([&] { build_on_threads(2 * node, begin, mid, threads / 2); });
        build_on_threads(2 * node + 1, mid, end, threads - threads / 2);
        left.join();
    }

    constexpr void build(std::size_t node, std::size_t begin, std::size_t end)
    {
        if (end - begin <= LeafSize) return;
        const std::size_t mid = split(node, begin, end);
        build(2 * node, begin, mid);
        build(2 * node + 1, mid, end);
    }

    /// Split node's range along the axis of largest extent at the median; returns the
    /// middle.
    constexpr std::size_t split(std::size_t node, std::size_t begin, std::size_t end)
    {
        Point lo, hi;
        lo.fill(infinity<T>);
        hi.fill(-infinity<T>);
        for (std::size_t i = begin; i < end; ++i)
            for (std::size_t a = 0; a < dimension; ++a) {
                const T x = points_[index_[i]][a];
                lo[a] = x < lo[a] ? x : lo[a];
                hi[a] = x > hi[a] ? x : hi[a];
            }
        std::size_t axis = 0;
        for (std::size_t a = 1; a < dimension; ++a)
            if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
        const std::size_t mid = middle(begin, end);
        std::nth_element(index_.begin() + static_cast<std::ptrdiff_t>(begin), index_.begin() + static_cast<std::ptrdiff_t>(mid),
                         index_.begin() + static_cast<std::ptrdiff_t>(end),
                         [this, axis](std::uint32_t x, std::uint32_t y) { return points_[x][axis] < points_[y][axis]; });
        split_[node] = points_[index_[mid]][axis];
        axis_[node] = static_cast<std::uint8_t>(axis);
        return mid;
    }

    // The search keeps `offsets`, the squared distance from q to the current cell along
    // each axis (as nanoflann does); their sum bounds the distance to any point in the
    // cell from below. Points left of a split are <= its value, right ones >=. The sum is
    // taken afresh in axis order rather than updated by subtraction: each offset is at
    // most the matching term of any point's distance2, and rounded sums in the same order
    // keep that, so a point exactly on a cell's corner is never pruned, and ties at equal
    // distance resolve by index exactly as in a brute-force search (equal distances are
    // searched too).

    [[nodiscard]] static constexpr T sum(const Point& offsets) noexcept
    {
        T total = T(0);
        for (std::size_t i = 0; i < dimension; ++i) total += offsets[i];
        return total;
    }

    template <class Results>
    constexpr void descend(const Point& q, std::size_t node, std::size_t begin, std::size_t end, Point& offsets, Results& results) const
    {
        if (end - begin <= LeafSize) {
            for (std::size_t i = begin; i < end; ++i) {
                const T d2 = distance2(q, points_[i]);
                if (d2 <= results.bound()) results.add(d2, index_[i]);
            }
            return;
        }
        const std::size_t axis = axis_[node];
        const std::size_t mid = middle(begin, end);
        const T diff = q[axis] - split_[node];
        const bool left_first = diff < T(0);
        if (left_first) descend(q, 2 * node, begin, mid, offsets, results);
        else descend(q, 2 * node + 1, mid, end, offsets, results);
        // The far side: its cell is diff^2 away along this axis.
        const T saved = offsets[axis];
        offsets[axis] = diff * diff;
        if (sum(offsets) <= results.bound()) {
            if (left_first) descend(q, 2 * node + 1, mid, end, offsets, results);
            else descend(q, 2 * node, begin, mid, offsets, results);
        }
        offsets[axis] = saved;
    }

    /// along()'s descent: [t0, t1] is the part of the line that may come within the
    /// padded radius of the node's cell.
    template <class Visitor>
    constexpr void along_cells(const Point& o, const Point& d, T t_min, T t_max, T pad, std::size_t node, std::size_t begin, std::size_t end, T t0, T t1,
                               T radius2, Visitor& visit) const
    {
        if (end - begin <= LeafSize) {
            for (std::size_t i = begin; i < end; ++i) {
                const Point& p = points_[i];
                const T t = (p[0] - o[0]) * d[0] + (p[1] - o[1]) * d[1] + (p[2] - o[2]) * d[2];
                if (!(t >= t_min && t <= t_max)) continue;
                const T x = p[0] - o[0] - t * d[0], y = p[1] - o[1] - t * d[1], z = p[2] - o[2] - t * d[2];
                const T d2 = x * x + y * y + z * z;
                if (d2 <= radius2) visit(index_[i], t, d2);
            }
            return;
        }
        const std::size_t axis = axis_[node];
        const std::size_t mid = middle(begin, end);
        const T split = split_[node], oa = o[axis], da = d[axis];
        // Left points have coordinate <= split: the line may come near them where its own
        // coordinate is <= split + pad; right points where it is >= split - pad.
        T left0 = t0, left1 = t1, right0 = t0, right1 = t1;
        if (da == T(0)) {
            if (oa > split + pad) left1 = left0 - T(1);
            if (oa < split - pad) right1 = right0 - T(1);
        } else {
            const T to_left = (split + pad - oa) / da, to_right = (split - pad - oa) / da;
            if (da > T(0)) {
                left1 = std::min(left1, to_left);
                right0 = std::max(right0, to_right);
            } else {
                left0 = std::max(left0, to_left);
                right1 = std::min(right1, to_right);
            }
        }
        if (left0 <= left1) along_cells(o, d, t_min, t_max, pad, 2 * node, begin, mid, left0, left1, radius2, visit);
        if (right0 <= right1) along_cells(o, d, t_min, t_max, pad, 2 * node + 1, mid, end, right0, right1, radius2, visit);
    }

    std::vector<Point> points_;        ///< in tree order (the input order while building)
    std::vector<std::uint32_t> index_; ///< the point set's index of each point in tree order
    std::vector<T> split_;             ///< split value of each inner node (heap numbering from 1)
    std::vector<std::uint8_t> axis_;   ///< split axis of each inner node
};

} // namespace prism
