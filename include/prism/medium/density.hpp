// SPDX-License-Identifier: MIT
// Density fields: how thick a medium of varying density (VaryingFog) is at each point,
// zero outside a bounded box, with a conservative bound of the density over any box
// (what the majorant grid, medium/majorant.hpp, is built from).
//
// DensityGrid holds values at the points of a regular lattice spanning its box and
// interpolates them trilinearly (a voxel grid from a simulation or a file:
// io/density.hpp reads and writes its raw format); HeightFog is a procedural field,
// density falling exponentially with height, whose optical depth along any ray has a
// closed form. A field of one's own is any type with density(p), bounds() and
// max_over(box).
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/core/check.hpp>
#include <prism/core/math.hpp>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

namespace prism {

/// A field of density: `density(p)` >= 0 at a point (0 outside `bounds()`, a bounded
/// box), and `max_over(box)`, at least the density at every point of the box (a bound a
/// majorant may trust: too low a bound would bias every estimator). A field may also
/// give `min_over(box)`, at most the density at every point of the box inside the
/// field's: the control of residual ratio tracking (medium/varying_fog.hpp), which then
/// is exact where the field is constant.
template <class X>
concept DensityField = requires(const X& field, const Vec3<typename X::scalar_type>& p, const Aabb<typename X::scalar_type>& box) {
    requires Scalar<typename X::scalar_type>;
    { field.density(p) } -> std::same_as<typename X::scalar_type>;
    { field.bounds() } -> std::same_as<Aabb<typename X::scalar_type>>;
    { field.max_over(box) } -> std::same_as<typename X::scalar_type>;
    field.validate();
};

/// Densities at the nx x ny x nz points of a lattice spanning `box` (its corners lattice
/// points; x varying fastest in `values`), trilinear between them, 0 outside the box.
/// Copies share the values.
template <Scalar T = float>
class DensityGrid {
public:
    /// The precision of positions and densities.
    using scalar_type = T;

    /// The grid of `values` (nx ny nz of them, x fastest) over `box`. Throws
    /// std::invalid_argument, naming what is wrong, for fewer than 2 points on an axis, a
    /// count of values that is not nx ny nz, a value that is negative or not finite, or a
    /// box that is not bounded with lo < hi on every axis.
    DensityGrid(int nx, int ny, int nz, const Aabb<T>& box, std::vector<float> values)
        : n_{nx, ny, nz}, box_(box)
    {
        if (nx < 2 || ny < 2 || nz < 2) detail::throw_invalid("DensityGrid needs at least 2 points on every axis, got ", nx, " x ", ny, " x ", nz);
        if (!box.bounded() || !(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z))
            detail::throw_invalid("DensityGrid box must be bounded with lo < hi on every axis, got ", detail::describe(box.lo), " to ", detail::describe(box.hi));
        const std::size_t count = std::size_t(nx) * std::size_t(ny) * std::size_t(nz);
        if (values.size() != count) detail::throw_invalid("DensityGrid of ", nx, " x ", ny, " x ", nz, " points needs ", count, " values, got ", values.size());
        for (std::size_t i = 0; i < count; ++i)
            if (!(std::isfinite(values[i]) && values[i] >= 0.0f))
                detail::throw_invalid("DensityGrid value ", i, " (x ", i % std::size_t(nx), ", y ", i / std::size_t(nx) % std::size_t(ny), ", z ",
                                      i / (std::size_t(nx) * std::size_t(ny)), ") must be finite and >= 0, got ", values[i]);
        for (int a = 0; a < 3; ++a) {
            // Lattice cells per unit length, finite and normal, and the box's width a finite
            // number: a lookup turns (p - lo) times it into a cell index.
            const T width = box_.hi[a] - box_.lo[a];
            scale_[a] = T(n_[a] - 1) / width;
            if (!(is_finite(width) && is_finite(scale_[a]) && scale_[a] >= std::numeric_limits<T>::min()))
                detail::throw_invalid("DensityGrid box is too small or too large for its ", nx, " x ", ny, " x ", nz, " points on axis ", a, ": ",
                                      box_.lo[a], " to ", box_.hi[a]);
        }
        values_ = std::make_shared<const std::vector<float>>(std::move(values));
    }

    /// The density at p: trilinear between the lattice's points, 0 outside the box.
    [[nodiscard]] T density(const Vec3<T>& p) const noexcept
    {
        if (!box_.contains(p)) return T(0);
        int i[3];
        T f[3];
        for (int a = 0; a < 3; ++a) {
            const T u = (p[a] - box_.lo[a]) * scale_[a];
            i[a] = std::clamp(int(u), 0, n_[a] - 2);
            f[a] = std::clamp(u - T(i[a]), T(0), T(1));
        }
        const auto at = [&](int x, int y, int z) { return T((*values_)[index(x, y, z)]); };
        const auto line = [&](int y, int z) { return at(i[0], y, z) + f[0] * (at(i[0] + 1, y, z) - at(i[0], y, z)); };
        const auto plane = [&](int z) { return line(i[1], z) + f[1] * (line(i[1] + 1, z) - line(i[1], z)); };
        return std::max(T(0), plane(i[2]) + f[2] * (plane(i[2] + 1) - plane(i[2])));
    }

    /// The box the lattice spans.
    [[nodiscard]] Aabb<T> bounds() const noexcept { return box_; }

    /// The greatest value at the lattice points of every lattice cell `region` touches:
    /// trilinear interpolation never exceeds its corners, so no point of the region is
    /// denser.
    [[nodiscard]] T max_over(const Aabb<T>& region) const noexcept
    {
        int from[3], to[3];
        if (!points_about(region, from, to)) return T(0);
        float most = 0.0f;
        for (int z = from[2]; z <= to[2]; ++z)
            for (int y = from[1]; y <= to[1]; ++y)
                for (int x = from[0]; x <= to[0]; ++x) most = std::max(most, (*values_)[index(x, y, z)]);
        return T(most);
    }

    /// The least value at the lattice points of every lattice cell the part of `region`
    /// inside the box touches (0 if none): no point of the region inside the box is thinner.
    [[nodiscard]] T min_over(const Aabb<T>& region) const noexcept
    {
        int from[3], to[3];
        if (!points_about(region, from, to)) return T(0);
        float least = (*values_)[index(from[0], from[1], from[2])];
        for (int z = from[2]; z <= to[2]; ++z)
            for (int y = from[1]; y <= to[1]; ++y)
                for (int x = from[0]; x <= to[0]; ++x) least = std::min(least, (*values_)[index(x, y, z)]);
        return T(least);
    }

    /// The number of lattice points along axis a (0, 1, 2).
    [[nodiscard]] int points(int axis) const noexcept { return n_[axis]; }
    /// The values, x fastest.
    [[nodiscard]] const std::vector<float>& values() const noexcept { return *values_; }

    /// Nothing to check: the constructor did.
    constexpr void validate() const noexcept {}

private:
    [[nodiscard]] std::size_t index(int x, int y, int z) const noexcept
    {
        return (std::size_t(z) * std::size_t(n_[1]) + std::size_t(y)) * std::size_t(n_[0]) + std::size_t(x);
    }

    /// The lattice points [from, to] on each axis of every lattice cell the part of
    /// `region` inside the box touches; false if it lies outside the box.
    bool points_about(const Aabb<T>& region, int (&from)[3], int (&to)[3]) const noexcept
    {
        for (int a = 0; a < 3; ++a) {
            const T lo = std::max(region.lo[a], box_.lo[a]), hi = std::min(region.hi[a], box_.hi[a]);
            if (!(lo <= hi)) return false;
            from[a] = std::clamp(int(std::floor((lo - box_.lo[a]) * scale_[a])), 0, n_[a] - 1);
            to[a] = std::clamp(int(std::ceil((hi - box_.lo[a]) * scale_[a])), 0, n_[a] - 1);
        }
        return true;
    }

    int n_[3];
    Aabb<T> box_;
    Vec3<T> scale_{};
    std::shared_ptr<const std::vector<float>> values_;
};

/// Ground fog: density base exp(-(y - floor) / scale_height) within `box` (0 outside):
/// `base` at height `floor`, thinning by e every scale_height above it.
/// Along a ray of unit direction its optical depth per unit density is
/// scale_height (e^{-h0} - e^{-h1}) / |d_y| in closed form (the tests' reference).
template <Scalar T = float>
struct HeightFog {
    /// The precision of positions and densities.
    using scalar_type = T;

    Aabb<T> box{};          ///< where the fog is
    T floor = T(0);         ///< the height of density `base`
    T base = T(1);          ///< the density at `floor`
    T scale_height = T(1);  ///< the height over which the density falls by e

    /// base exp(-(p.y - floor) / scale_height) in the box, 0 outside.
    [[nodiscard]] T density(const Vec3<T>& p) const noexcept { return box.contains(p) ? at_height(p.y) : T(0); }

    /// The box.
    [[nodiscard]] Aabb<T> bounds() const noexcept { return box; }

    /// The density at the region's lowest height inside the box (the field falls with height).
    [[nodiscard]] T max_over(const Aabb<T>& region) const noexcept
    {
        const T lo = std::max(region.lo.y, box.lo.y), hi = std::min(region.hi.y, box.hi.y);
        if (!(lo <= hi)) return T(0);
        return at_height(lo) * (T(1) + T(8) * std::numeric_limits<T>::epsilon()); // exp's rounding
    }

    /// The density at the greatest height of the region's part inside the box (0 if none).
    [[nodiscard]] T min_over(const Aabb<T>& region) const noexcept
    {
        const Aabb<T> inside{component_max(region.lo, box.lo), component_min(region.hi, box.hi)};
        if (inside.empty()) return T(0);
        return at_height(inside.hi.y) * (T(1) - T(8) * std::numeric_limits<T>::epsilon());
    }

    /// Throws std::invalid_argument, naming the parameter, for a box that is not bounded, a
    /// negative or non-finite base, or a scale height that is not positive.
    void validate() const
    {
        if (!box.bounded()) detail::throw_invalid("HeightFog box must be bounded and non-empty, got ", detail::describe(box.lo), " to ", detail::describe(box.hi));
        detail::require_finite("HeightFog floor", floor);
        detail::require_non_negative("HeightFog base", base);
        detail::require_positive("HeightFog scale_height", scale_height);
    }

private:
    [[nodiscard]] T at_height(T y) const noexcept { return base * std::exp(-(y - floor) / scale_height); }
};

static_assert(DensityField<DensityGrid<float>> && DensityField<HeightFog<float>> && DensityField<HeightFog<double>>);

} // namespace prism
