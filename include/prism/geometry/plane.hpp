// SPDX-License-Identifier: MIT
// Plane: the half-space dot(normal, p) <= offset, a solid bounded by one plane.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/geometry/shape.hpp>

namespace prism {

namespace detail {

/// p moved along the unit normal n onto the plane dot(n, x) = offset (a crossing point
/// computed as o + t d, refined).
template <Scalar T>
[[nodiscard]] constexpr Vec3<T> onto_plane(const Vec3<T>& n, T offset, Vec3<T> p) noexcept
{
    p -= (dot(n, p) - offset) * n;
    return p;
}

/// The error bound of a point onto_plane gave: the residual is evaluated with error
/// gamma(3)(|n|.|p| + |offset|), and that is what is left along the normal; along the
/// plane the point carries its own rounding.
template <Scalar T>
[[nodiscard]] constexpr Vec3<T> plane_point_error(const Vec3<T>& n, T offset, const Vec3<T>& p) noexcept
{
    const Vec3<T> n_abs = abs(n);
    const T along = gamma<T>(4) * (dot(n_abs, abs(p)) + (offset < T(0) ? -offset : offset));
    return along * n_abs + gamma<T>(1) * abs(p);
}

} // namespace detail

/// The half-space below a plane: inside where dot(normal, p) < offset, so the normal
/// points out of the solid. A floor at y = 0 is Plane{{0, 1, 0}, 0}.
template <Scalar T = float>
class Plane {
public:
    /// The precision of the plane and the crossings.
    using scalar_type = T;
    /// At most one crossing.
    static constexpr std::size_t max_crossings = 1;

    // Plane Public Methods

    /// The half-space dot(normal, p) <= offset; normal need not be unit length.
    /// Throws std::invalid_argument for a zero or non-finite normal or offset.
    constexpr Plane(const Vec3<T>& normal, T offset)
    {
        detail::require_nonzero("Plane normal", normal);
        detail::require_finite("Plane offset", offset);
        // Scaled by its largest component before normalising: |normal|^2 of (1e-45, 0, 0)
        // underflows and of (3e38, 3e38, 0) overflows.
        const T largest = max_component(abs(normal));
        const Vec3<T> scaled = normal / largest;
        const T len = length(scaled);
        normal_ = scaled * (T(1) / len);
        offset_ = offset / largest / len;
        if (!is_finite(offset_))
            detail::throw_invalid("Plane offset / |normal| must be finite, got ", offset, " / |", detail::describe(normal), "|");
    }

    /// The half-space bounded by the plane through `point` with outward `normal`.
    [[nodiscard]] static constexpr Plane through(const Vec3<T>& point, const Vec3<T>& normal)
    {
        detail::require_finite("Plane point", point);
        detail::require_nonzero("Plane normal", normal);
        const Vec3<T> n = normal / max_component(abs(normal)); // as in the constructor: no overflow in the dot product
        return Plane(n, dot(n, point));
    }

    /// The outward unit normal.
    [[nodiscard]] constexpr const Vec3<T>& normal() const noexcept { return normal_; }
    /// The solid is dot(normal(), p) < offset().
    [[nodiscard]] constexpr T offset() const noexcept { return offset_; }
    /// Unbounded: every point.
    [[nodiscard]] constexpr Aabb<T> bounds() const noexcept { return Aabb<T>::universe(); }
    /// A half-space is convex: a ray leaving the plane on its outer side never meets it again.
    [[nodiscard]] static constexpr bool convex() noexcept { return true; }

    /// Whether p is inside: dot(normal, p) < offset.
    [[nodiscard]] constexpr bool contains(const Vec3<T>& p) const noexcept { return dot(normal_, p) < offset_; }

    /// The crossing of `ray` within `range`, if it meets the plane there, with its point refined onto the plane.
    template <bool Surface = true>
    [[nodiscard]] constexpr Crossings<T, 1> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        Crossings<T, 1> out;
        const T denom = dot(normal_, ray.direction);
        const T height = dot(normal_, ray.origin) - offset_;
        if (denom == T(0)) { // parallel: inside or outside all along
            out.inside_at_start = height < T(0);
            return out;
        }
        const T t = -height / denom;
        const bool entering = denom < T(0);
        out.inside_at_start = entering ? t < range.min : range.min < t;
        if (range.surrounds(t)) out.push_back(Surface ? crossing_at(ray, t, entering) : Crossing<T>::without_surface(t, entering));
        return out;
    }

    /// crossings<false>(ray, range).front().t, or infinity: without the list, and without
    /// the division where the ray starts on the plane's positive side and leaves it (or
    /// starts inside and goes deeper) over a range from 0 on, which its t, negative,
    /// could not be in: most shadow rays from a floor.
    [[nodiscard]] constexpr T first_crossing(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        const T denom = dot(normal_, ray.direction);
        const T height = dot(normal_, ray.origin) - offset_;
        if (denom == T(0)) return infinity<T>; // (and NaN compares false: on to the division)
        if (range.min >= T(0) && ((height > T(0) && denom > T(0)) || (height < T(0) && denom < T(0)))) return infinity<T>;
        const T t = -height / denom;
        return range.surrounds(t) ? t : infinity<T>;
    }

    /// Whether crossings<false>(ray, range) is not empty (a shadow ray's query).
    [[nodiscard]] constexpr bool any_crossing(const Ray<T>& ray, Interval<T> range) const noexcept { return first_crossing(ray, range) < infinity<T>; }

    /// Surface coordinates of a crossing of this plane: in the scene's units along the
    /// face's axes (u along +x and v along -z on a floor; u to the right and v up on a wall
    /// seen from the side the normal points to).
    void coordinates(Crossing<T>& c) const noexcept
    {
        const auto [u, v] = detail::face_axes(normal_);
        c = c.with_uv({dot(c.point, u), dot(c.point, v)}, u, v);
    }

private:
    // Plane Private Methods

    [[nodiscard]] constexpr Crossing<T> crossing_at(const Ray<T>& ray, T t, bool entering) const noexcept
    {
        // The hit point projected onto the plane, with its error bound.
        const Vec3<T> point = detail::onto_plane(normal_, offset_, ray.at(t));
        return Crossing<T>::flat(t, point, detail::plane_point_error(normal_, offset_, point), normal_, entering);
    }

    Vec3<T> normal_{T(0), T(1), T(0)};
    T offset_ = T(0);
};

static_assert(Shape<Plane<float>>);
static_assert(Shape<Plane<double>>);

} // namespace prism
