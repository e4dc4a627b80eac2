// SPDX-License-Identifier: MIT
// Aabb: an axis-aligned bounding box and its robust slab test.
#pragma once

#include <prism/core/interval.hpp>
#include <prism/core/lanes.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/ray.hpp>

#include <limits>
#include <type_traits>

namespace prism {

/// A sphere that encloses a solid: what the photon tracer aims caustic photons at, and
/// where parallel light's photons start from.
template <Scalar T>
struct BoundingSphere {
    Vec3<T> center{}; ///< the sphere's centre
    T radius = T(0); ///< its radius
};

/// Axis-aligned box [lo, hi]; empty when lo > hi on any axis (the default).
template <Scalar T>
struct Aabb {
    Vec3<T> lo{infinity<T>}; ///< the least corner
    Vec3<T> hi{-infinity<T>}; ///< the greatest corner

    /// Whether the box holds no point (lo > hi on some axis, or NaN).
    [[nodiscard]] constexpr bool empty() const noexcept { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }

    /// Every point: the bounds of an unbounded shape such as a half-space.
    [[nodiscard]] static constexpr Aabb universe() noexcept { return {Vec3<T>(-infinity<T>), Vec3<T>(infinity<T>)}; }

    /// The smallest box holding this one and `other`.
    [[nodiscard]] constexpr Aabb merged(const Aabb& other) const noexcept
    {
        return {component_min(lo, other.lo), component_max(hi, other.hi)};
    }

    /// Whether p is in the box, faces included.
    [[nodiscard]] constexpr bool contains(const Vec3<T>& p) const noexcept
    {
        return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
    }

    /// Finite on every axis: the box of a bounded shape (false for an empty box too).
    [[nodiscard]] constexpr bool bounded() const noexcept { return !empty() && is_finite(lo) && is_finite(hi); }

    /// The sphere through the box's corners (for a bounded box).
    [[nodiscard]] constexpr BoundingSphere<T> bounding_sphere() const noexcept
    {
        return {T(0.5) * (lo + hi), T(0.5) * length(hi - lo)};
    }

    /// The box grown outward by one float step on every side: a box computed by rounding
    /// to nearest then holds every point of the exact one.
    [[nodiscard]] constexpr Aabb rounded_out() const noexcept
    {
        Aabb out;
        for (int axis = 0; axis < 3; ++axis) out.lo[axis] = next_float_down(lo[axis]), out.hi[axis] = next_float_up(hi[axis]);
        return out;
    }

    /// Whether the ray meets the box at some t >= t_min: the test with which a bounded
    /// shape skips its own work. It ignores where the ray's range ends, so asking a shape
    /// again over a shorter range (a scene's surface query) cannot cull what it found
    /// before; and, as clip(), it never reports a miss for a ray that touches the box.
    [[nodiscard]] constexpr bool reached_after(const Ray<T>& ray, T t_min) const noexcept
    {
        return crosses(ray, {t_min, infinity<T>});
    }

    /// Whether a shape inside this box may report a crossing within `range`: the test
    /// with which a scene skips objects. A shape's crossings are computed with rounding
    /// that grows with the ray origin's distance from it, so a ray that just misses the
    /// exact shape may still be reported to cross it, and the scene must then still ask
    /// it: the box is widened for each ray by gamma(16) of that distance (and of its own
    /// size).
    [[nodiscard]] constexpr bool may_cross(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        if (range.min <= T(0) && range.max >= T(0) && contains(ray.origin)) return true; // most secondary rays in a closed scene
        const Vec3<T> half = T(0.5) * (hi - lo);
        const T pad = gamma<T>(16) * (max_component(abs(ray.origin - (lo + half))) + max_component(half)) + std::numeric_limits<T>::min();
        const Aabb wide{lo - Vec3<T>(pad), hi + Vec3<T>(pad)};
        return wide.crosses(ray, range);
    }

    /// Whether clip(ray, range) is not empty: the same decision for every ray, NaN and
    /// infinities included, where only the decision is wanted (a shape's or a scene's
    /// cull). With vector extensions the three axes are one division and a few lane
    /// operations, not three divisions and their branches.
    [[nodiscard, gnu::always_inline]] constexpr bool crosses(const Ray<T>& ray, Interval<T> range) const noexcept
    {
#if PRISM_VECTOR_EXTENSIONS
        if (!std::is_constant_evaluated()) {
            typedef T V __attribute__((vector_size(4 * sizeof(T))));
            constexpr T largest = std::numeric_limits<T>::max();
            // (The fourth lane is never read.)
            const V d{ray.direction.x, ray.direction.y, ray.direction.z, T(1)}, o{ray.origin.x, ray.origin.y, ray.origin.z, T(0)};
            const V low{lo.x, lo.y, lo.z, T(0)}, high{hi.x, hi.y, hi.z, T(0)};
            const auto flat = d == T(0);
            if (detail::lane_bits(flat & ((o < low) | (o > high))) & 7u) return false;
            // (Constants as whole vectors: one load each.)
            constexpr T inf = infinity<T>, widen = T(1) + T(2) * gamma<T>(3);
            constexpr V most{largest, largest, largest, largest}, least{-largest, -largest, -largest, -largest};
            constexpr V below{-inf, -inf, -inf, -inf}, above{inf, inf, inf, inf}, widening{widen, widen, widen, widen};
            // clip's arithmetic lane by lane: its clamp as max then min (a NaN goes to
            // -largest, as there), and its swap as min and max (b < a is false for a NaN on
            // either side, as a > b is).
            const V r = T(1) / d;
            V inv, near, far;
            detail::lane_max(inv, r, least);
            detail::lane_min(inv, inv, most);
            const V a = (low - o) * inv, b = (high - o) * inv;
            detail::lane_min(near, b, a);
            detail::lane_max(far, a, b);
            // A flat axis with the origin in its slab limits nothing: -inf to inf.
            near = flat ? below : near;
            far = flat ? above : far * widening;
            // clip's updates, in turn: comparisons false for a NaN (maxss, minss).
            T t0 = range.min, t1 = range.max;
            t0 = near[0] > t0 ? near[0] : t0, t1 = far[0] < t1 ? far[0] : t1;
            t0 = near[1] > t0 ? near[1] : t0, t1 = far[1] < t1 ? far[1] : t1;
            t0 = near[2] > t0 ? near[2] : t0, t1 = far[2] < t1 ? far[2] : t1;
            return t0 <= t1;
        }
#endif
        return !clip(ray, range).empty();
    }

    /// The part of `range` in which the ray is inside the box (empty if none).
    /// Slab test with the far distance widened by 2*gamma(3), so that rounding never
    /// reports a miss for a ray that touches the box (pbrt-v4, Bounds3::IntersectP).
    [[nodiscard]] constexpr Interval<T> clip(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        for (int axis = 0; axis < 3; ++axis) {
            const T o = ray.origin[axis];
            const T d = ray.direction[axis];
            if (d == T(0)) {
                if (o < lo[axis] || o > hi[axis]) return {};
                continue;
            }
            // 1 / d is clamped to the finite range: for a denormal d it would be
            // infinite, and 0 * inf is NaN where 0 / d is 0 (a ray starting on a face).
            constexpr T largest = std::numeric_limits<T>::max();
            const T inv = clamp(T(1) / d, -largest, largest);
            T t_near = (lo[axis] - o) * inv;
            T t_far = (hi[axis] - o) * inv;
            if (t_near > t_far) std::swap(t_near, t_far);
            t_far *= T(1) + T(2) * gamma<T>(3);
            if (t_near > range.min) range.min = t_near;
            if (t_far < range.max) range.max = t_far;
            if (range.min > range.max) return {};
        }
        return range;
    }
};

/// A ray to test a far shape with: the caller's ray with its origin moved along it toward
/// the shape, and the caller's t where the moved ray starts (see brought_near).
template <Scalar T>
struct NearRay {
    Ray<T> ray;        ///< the same direction; the origin the caller's ray at `shift`
    double shift = 0;  ///< 0: the caller's ray as it is

    /// The caller's range on the moved ray.
    [[nodiscard]] Interval<T> range(const Interval<T>& r) const noexcept
    {
        if (shift == 0) return r;
        return {T(double(r.min) - shift), T(double(r.max) - shift)};
    }
    /// A t on the moved ray as a t on the caller's.
    [[nodiscard]] T back(T t) const noexcept { return shift == 0 ? t : T(shift + double(t)); }
    /// The ray to test: `far` itself (the caller's ray, `far`, kept) or the moved one.
    /// (Read from where it is: a copy read back at once, by loads that straddle its stores,
    /// stalls.)
    [[nodiscard]] const Ray<T>& ray_for(const Ray<T>& far) const noexcept { return shift == 0 ? far : ray; }
};

/// What brought_near asks of a box, worked out once for the many rays a shape is asked
/// about: the box, its centre, and the squared distance from the centre within which a
/// ray is near already (64 half diagonals).
template <Scalar T>
struct NearBox {
    Aabb<T> box;    ///< the box
    Vec3<T> centre{T(0)}; ///< its centre
    T near2 = T(0); ///< 16384 |half diagonal|^2: a ray from nearer is near already

    constexpr NearBox() = default;
    /// The box `b`, worked out.
    constexpr explicit NearBox(const Aabb<T>& b) noexcept : box(b), centre((b.lo + b.hi) * T(0.5))
    {
        const Vec3<T> half = (b.hi - b.lo) * T(0.5);
        near2 = T(16384) * dot(half, half);
    }
};

/// A float ray from more than 64 times `box`'s diagonal away (and the box ahead), its
/// origin moved along it, in double, to twice the diagonal before the box's centre: the same line, rounded once
/// near the box. A shape's test subtracts the origin from its points, and from 10^6
/// times a float shape's size the far origin's rounding alone is as large as the shape:
/// a ray aimed across it could be found to cross it where the ray does not, or miss it.
/// A ray near already, one the box lies behind or beside, a ray that is not finite, and a
/// double ray are kept as they are (shift 0).
namespace detail {

/// brought_near's far case (out of line: rarely taken, and kept out of every query's set-up).
template <Scalar T>
[[nodiscard, gnu::noinline]] NearRay<T> brought_near_far(const Ray<T>& ray, const NearBox<T>& near) noexcept
{
    const Vec3<double> o(ray.origin), d(ray.direction), lo(near.box.lo), hi(near.box.hi);
    const double speed = length(d), size = length(hi - lo);
    const double shift = (dot((lo + hi) * 0.5 - o, d) / speed - 2 * size) / speed;
    if (!(shift * speed > 32 * size) || !(shift < double(std::numeric_limits<T>::max()))) return {ray};
    return {Ray<T>{Vec3<T>(o + shift * d), ray.direction}, shift};
}

} // namespace detail

template <Scalar T>
[[nodiscard, gnu::always_inline]] inline NearRay<T> brought_near(const Ray<T>& ray, const NearBox<T>& near) noexcept
{
    if constexpr (!std::is_same_v<T, float>) {
        (void)near;
        return {ray};
    } else {
        // Most rays start near what they test: a test in float first (the origin within 64
        // diagonals of the centre, or a NaN anywhere, keeps the ray).
        const Vec3<T> away = ray.origin - near.centre;
        if (!(dot(away, away) > near.near2)) return {ray};
        return detail::brought_near_far(ray, near);
    }
}

/// brought_near for a box asked about once.
template <Scalar T>
[[nodiscard]] NearRay<T> brought_near(const Ray<T>& ray, const Aabb<T>& box) noexcept
{
    return brought_near(ray, NearBox<T>(box));
}

} // namespace prism
