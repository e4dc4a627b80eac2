// SPDX-License-Identifier: MIT
// HashGrid: points found within one fixed radius, for vertex merging's pass of light
// vertices (integrator/bidirectional.hpp), built in linear time.
//
// Space is cut into cubes of side twice the radius, and each cube hashed to one of a
// power of two of buckets at least the number of points; a counting sort puts each
// bucket's points together, in their order. A query's ball of that radius meets at most
// the 2 x 2 x 2 cubes around it: their buckets (each once, though two cubes may share
// one) are read and every point within the radius handed over, in bucket order and, in
// a bucket, in the points' order. A KdTree (accel/kd_tree.hpp) answers any radius and
// nearest neighbours; this answers one radius, built about ten times faster (a pass of
// vertex merging rebuilds it for every pass).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace prism {

/// Points within a fixed radius of a query, by a hashed grid of cubes twice the radius.
template <Scalar T>
class HashGrid {
public:
    /// An empty grid: every query finds nothing.
    HashGrid() = default;

    /// The grid over `points` (copied in bucket order) for queries of `radius`; throws
    /// std::invalid_argument for a radius that is not finite and positive, more than 2^32 - 2
    /// points, or a point that is not finite (naming its index). Points may spread over any
    /// number of cubes (a floor to the horizon): far ones share cubes.
    HashGrid(std::span<const Vec3<T>> points, T radius) : radius_(radius)
    {
        if (!(radius > T(0) && radius < infinity<T>)) detail::throw_invalid("HashGrid radius must be finite and > 0, got ", radius);
        if (points.size() >= std::numeric_limits<std::uint32_t>::max()) detail::throw_invalid("HashGrid holds at most 2^32 - 2 points, got ", points.size());
        if (points.empty()) return;
        Vec3<T> low = points[0];
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (!is_finite(points[i])) detail::throw_invalid("HashGrid point ", i, " is not finite");
            low = component_min(low, points[i]);
        }
        low_ = low;
        inverse_cell_ = T(1) / (T(2) * radius);
        std::size_t buckets = 1;
        while (buckets < points.size()) buckets *= 2;
        mask_ = std::uint32_t(buckets - 1);
        starts_.assign(buckets + 1, 0);
        std::vector<std::uint32_t> bucket_of(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            bucket_of[i] = bucket(cell_of(points[i]));
            ++starts_[bucket_of[i] + 1];
        }
        for (std::size_t b = 0; b < buckets; ++b) starts_[b + 1] += starts_[b];
        std::vector<std::uint32_t> next(starts_.begin(), starts_.end() - 1);
        points_.resize(points.size());
        index_.resize(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            const std::uint32_t at = next[bucket_of[i]]++;
            points_[at] = points[i];
            index_[at] = std::uint32_t(i);
        }
    }

    /// The number of points.
    [[nodiscard]] std::size_t size() const noexcept { return points_.size(); }
    /// The radius queries are answered for.
    [[nodiscard]] T radius() const noexcept { return radius_; }

    /// Call visit(index, distance2) for every point within the radius of q (distance <= radius).
    template <class Visitor>
    void within(const Vec3<T>& q, Visitor&& visit) const
    {
        if (points_.empty() || !is_finite(q)) return;
        // The cube holding q and its neighbours toward q's nearer faces: the ball of
        // radius r about q lies in the 2 x 2 x 2 cubes from floor((q - r) / 2r).
        const std::array<std::int64_t, 3> base = cell_of(q - Vec3<T>(radius_));
        std::array<std::uint32_t, 8> seen{};
        int count = 0;
        const T r2 = radius_ * radius_;
        for (int k = 0; k < 8; ++k) {
            const std::uint32_t b = bucket({base[0] + (k & 1), base[1] + ((k >> 1) & 1), base[2] + ((k >> 2) & 1)});
            if (std::find(seen.begin(), seen.begin() + count, b) != seen.begin() + count) continue;
            seen[std::size_t(count++)] = b;
            for (std::uint32_t i = starts_[b]; i < starts_[b + 1]; ++i) {
                const T d2 = length_squared(points_[i] - q);
                if (d2 <= r2) visit(index_[i], d2);
            }
        }
    }

    /// The bytes the grid holds.
    [[nodiscard]] std::size_t memory_bytes() const noexcept
    {
        return points_.capacity() * sizeof(Vec3<T>) + index_.capacity() * sizeof(std::uint32_t) + starts_.capacity() * sizeof(std::uint32_t);
    }

private:
    /// The cube holding p, its coordinates counted from the lowest point's and held to
    /// +-2^62: cubes that far out share one, which only costs distance tests (every point
    /// found is tested), and no conversion overflows.
    [[nodiscard]] std::array<std::int64_t, 3> cell_of(const Vec3<T>& p) const noexcept
    {
        const Vec3<T> c = (p - low_) * inverse_cell_;
        std::array<std::int64_t, 3> cell{};
        for (int a = 0; a < 3; ++a) cell[std::size_t(a)] = std::int64_t(clamp(std::floor(c[a]), T(-4.6e18), T(4.6e18)));
        return cell;
    }

    /// A cell's bucket (Teschner et al. 2003's hash of its coordinates).
    [[nodiscard]] std::uint32_t bucket(const std::array<std::int64_t, 3>& c) const noexcept
    {
        const std::uint64_t h = (std::uint64_t(c[0]) * 73856093u) ^ (std::uint64_t(c[1]) * 19349663u) ^ (std::uint64_t(c[2]) * 83492791u);
        return std::uint32_t(h ^ (h >> 32)) & mask_;
    }

    T radius_ = T(0);
    T inverse_cell_ = T(0);
    Vec3<T> low_{};
    std::uint32_t mask_ = 0;
    std::vector<std::uint32_t> starts_; ///< bucket b's points are [starts_[b], starts_[b + 1])
    std::vector<Vec3<T>> points_;       ///< in bucket order
    std::vector<std::uint32_t> index_;  ///< each one's index in the points given
};

} // namespace prism
