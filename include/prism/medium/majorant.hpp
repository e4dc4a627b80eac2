// SPDX-License-Identifier: MIT
// The majorant grid: a coarse grid over a density field's box, each cell holding a bound
// of the density anywhere in it (slightly more than the cell: a point the traversal's
// rounding puts in the wrong cell is still bounded), and, where the field gives one, a
// floor of the density in the cell (residual ratio tracking's control). Delta and ratio tracking
// (medium/varying_fog.hpp) draw their tentative collisions cell by cell with each cell's
// own majorant, so a thin region costs few draws and a dense corner does not make the
// whole box expensive (the same scheme as pbrt-v4's majorant grid and Mitsuba's).
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/medium/density.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace prism {

/// Bounds of a density field over the cells of a grid on its box.
template <Scalar T>
class MajorantGrid {
public:
    /// The most cells along an axis.
    static constexpr int max_cells = 256;

    /// An empty grid (no box: every segment is clear).
    MajorantGrid() = default;

    /// `cells` cells along each axis over `field`'s box, each bounded by field.max_over
    /// of the cell grown by a thousandth of a cell on every side (and floored by its
    /// min_over, where the field has one; 0 otherwise). Throws
    /// std::invalid_argument for cells outside [1, max_cells].
    template <DensityField F>
    MajorantGrid(const F& field, int cells) : box_(field.bounds()), n_(cells)
    {
        if (cells < 1 || cells > max_cells) detail::throw_invalid("majorant grid cells must be in [1, ", max_cells, "], got ", cells);
        const Vec3<T> size = (box_.hi - box_.lo) / T(cells);
        std::vector<Range> bounds(std::size_t(cells) * std::size_t(cells) * std::size_t(cells));
        for (int z = 0; z < cells; ++z)
            for (int y = 0; y < cells; ++y)
                for (int x = 0; x < cells; ++x) {
                    const Vec3<T> lo = box_.lo + Vec3<T>(T(x), T(y), T(z)) * size;
                    const Aabb<T> cell{lo - T(1e-3) * size, lo + size + T(1e-3) * size};
                    T floor = T(0);
                    if constexpr (requires { field.min_over(cell); }) floor = std::min(field.min_over(cell), field.max_over(cell));
                    bounds[index(x, y, z)] = {floor, field.max_over(cell)};
                }
        bounds_ = std::make_shared<const std::vector<Range>>(std::move(bounds));
        for (int a = 0; a < 3; ++a) inverse_cell_[a] = T(cells) / (box_.hi[a] - box_.lo[a]);
    }

    /// The box the cells cover.
    [[nodiscard]] const Aabb<T>& box() const noexcept { return box_; }
    /// A cell's floor and bound of the density.
    struct Range {
        T floor; ///< at most the density anywhere in the cell
        T bound; ///< at least the density anywhere in the cell
    };

    /// The floor and bound of cell (x, y, z).
    [[nodiscard]] const Range& range(int x, int y, int z) const noexcept { return (*bounds_)[index(x, y, z)]; }
    /// The bound of cell (x, y, z).
    [[nodiscard]] T bound(int x, int y, int z) const noexcept { return range(x, y, z).bound; }
    /// The cells along each axis.
    [[nodiscard]] int cells() const noexcept { return n_; }

    /// f(a, b, range) for each stretch [a, b] of `ray` within [t0, t1] (t1 may be infinite)
    /// that crosses one cell, in order along the ray, with that cell's Range, until f
    /// returns false. A ray that misses the box calls nothing: the density is 0 there.
    template <class F>
    void traverse(const Ray<T>& ray, T t0, T t1, F&& f) const
    {
        if (!bounds_) return;
        const Interval<T> span = box_.clip(ray, {t0, t1});
        if (span.empty()) return;
        int cell[3], step[3];
        T next[3], delta[3];
        const Vec3<T> p = ray.at(span.min);
        for (int a = 0; a < 3; ++a) {
            const T u = (p[a] - box_.lo[a]) * inverse_cell_[a];
            cell[a] = std::clamp(int(std::floor(u)), 0, n_ - 1);
            const T d = ray.direction[a];
            if (d > T(0)) {
                step[a] = 1;
                next[a] = (box_.lo[a] + T(cell[a] + 1) / inverse_cell_[a] - ray.origin[a]) / d;
                delta[a] = T(1) / (inverse_cell_[a] * d);
            } else if (d < T(0)) {
                step[a] = -1;
                next[a] = (box_.lo[a] + T(cell[a]) / inverse_cell_[a] - ray.origin[a]) / d;
                delta[a] = T(-1) / (inverse_cell_[a] * d);
            } else {
                step[a] = 0;
                next[a] = infinity<T>;
                delta[a] = infinity<T>;
            }
        }
        for (T a = span.min;;) {
            const int axis = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
            const T b = std::min(std::max(next[axis], a), span.max);
            if (!f(a, b, range(cell[0], cell[1], cell[2])) || b >= span.max) return;
            cell[axis] += step[axis];
            if (cell[axis] < 0 || cell[axis] >= n_) return;
            next[axis] += delta[axis];
            a = b;
        }
    }

private:
    [[nodiscard]] std::size_t index(int x, int y, int z) const noexcept
    {
        return (std::size_t(z) * std::size_t(n_) + std::size_t(y)) * std::size_t(n_) + std::size_t(x);
    }

    Aabb<T> box_{};
    int n_ = 0;
    Vec3<T> inverse_cell_{};
    std::shared_ptr<const std::vector<Range>> bounds_;
};

} // namespace prism
