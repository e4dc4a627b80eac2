// SPDX-License-Identifier: MIT
// Equiangular sampling (Kulla and Fajardo 2012): a distance along a stretch of medium drawn
// uniformly in the angle the stretch subtends at a point light, so that its density falls as
// 1 / d^2 from the light, as the light's own does: thin haze in a narrow beam is found by it
// where free flights pass the beam by. And the part of a ray a spot light's cone holds, to
// which such samples of a spot light are kept (a camera ray that crosses a narrow beam
// subtends a small share of its angles inside the cone).
#pragma once

#include <prism/core/interval.hpp>
#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/light/light.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace prism {

/// Equiangular sampling of the stretch [t0, t1] of a ray (unit direction; t1 may be
/// infinite) toward a point c: in the angle theta seen from c, uniform, so that the
/// density in t is h / ((theta1 - theta0) (h^2 + (t - along)^2)), h the point's distance
/// from the ray's line.
template <Scalar T>
struct Equiangular {
    T along;  ///< where the stretch's line passes nearest the point, along the ray
    T h;      ///< the point's distance from the line
    T theta0; ///< the angle of the stretch's start seen from the point, from the nearest pass
    T theta1; ///< the same of its end

    /// The stretch from the ray's origin to `extent` along it.
    Equiangular(const Ray<T>& stretch, T extent, const Vec3<T>& c) noexcept : Equiangular(stretch, T(0), extent, c) {}

    /// The stretch [t0, t1] of the ray.
    Equiangular(const Ray<T>& ray, T t0, T t1, const Vec3<T>& c) noexcept
    {
        const Vec3<T> to = c - ray.origin;
        along = dot(to, ray.direction);
        // (A light on the stretch's line: kept off it, as the airlight does.)
        h = std::max(length(to - along * ray.direction), T(1e-6) * (T(1) + std::abs(along)));
        theta0 = std::atan((t0 - along) / h);
        theta1 = t1 < infinity<T> ? std::atan((t1 - along) / h) : pi<T> / T(2);
    }
    /// The point at u in [0, 1).
    [[nodiscard]] T sample(T u) const noexcept { return along + h * std::tan(theta0 + u * (theta1 - theta0)); }
    /// The density of t.
    [[nodiscard]] T pdf(T t) const noexcept { return theta1 > theta0 ? h / ((theta1 - theta0) * (h * h + (t - along) * (t - along))) : T(0); }
};

/// The smallest interval of [t0, t1] along a ray (unit direction; t1 may be infinite) that
/// holds every point of it inside the cone from `apex` about the unit `axis` of half-angle
/// acos(cos_half), nothing where the ray misses the cone there. The cone's one nappe, where
/// dot(p - apex, axis) >= |p - apex| cos_half: the roots of the quadratic its boundary gives
/// split the stretch, and each piece is inside or out by its middle. Where the ray enters
/// the cone twice, the interval spans the gap between (a light is 0 there: the samples stay
/// unbiased). A cone of half-angle 90 degrees or more keeps the whole stretch.
template <Scalar T>
[[nodiscard]] std::optional<Interval<T>> within_cone(const Ray<T>& ray, T t0, T t1, const Vec3<T>& apex, const Vec3<T>& axis, T cos_half) noexcept
{
    if (!(t0 < t1)) return std::nullopt;
    if (!(cos_half > T(0))) return Interval<T>{t0, t1};
    const Vec3<T> v = ray.origin - apex;
    const T k2 = cos_half * cos_half;
    const T da = dot(ray.direction, axis), va = dot(v, axis);
    const auto inside = [&](T t) {
        const Vec3<T> p = v + t * ray.direction;
        const T along = dot(p, axis);
        return along >= T(0) && along * along >= k2 * length_squared(p);
    };
    // The breakpoints: the stretch's ends, the boundary's roots, where the ray crosses the apex's plane.
    std::array<T, 5> cuts{t0, t1, t0, t0, t0};
    int n = 2;
    const T a = da * da - k2, b = T(2) * (va * da - k2 * dot(v, ray.direction)), c = va * va - k2 * length_squared(v);
    if (std::abs(a) > T(1e-12)) {
        const T disc = b * b - T(4) * a * c;
        if (disc >= T(0)) {
            const T root = std::sqrt(disc);
            const T q = b >= T(0) ? T(-0.5) * (b + root) : T(-0.5) * (b - root); // (no cancellation)
            cuts[std::size_t(n++)] = q / a;
            if (q != T(0)) cuts[std::size_t(n++)] = c / q;
        }
    } else if (b != T(0)) {
        cuts[std::size_t(n++)] = -c / b;
    }
    if (da != T(0)) cuts[std::size_t(n++)] = -va / da;
    for (int i = 2; i < n; ++i) cuts[std::size_t(i)] = std::clamp(cuts[std::size_t(i)], t0, t1);
    std::sort(cuts.begin(), cuts.begin() + n);
    Interval<T> kept;
    for (int i = 0; i + 1 < n; ++i) {
        const T lo = cuts[std::size_t(i)], hi = cuts[std::size_t(i + 1)];
        if (!(lo < hi)) continue;
        const T middle = hi < infinity<T> ? lo + (hi - lo) / T(2) : T(2) * std::abs(lo) + T(1);
        if (!inside(middle)) continue;
        kept.min = std::min(kept.min, lo);
        kept.max = std::max(kept.max, hi);
    }
    if (kept.empty()) return std::nullopt;
    // A little wider at each end than the roots say (clamped to the stretch): a root's
    // rounding must not cut off a sliver inside the cone.
    const T pad = T(1e-5) * (T(1) + std::abs(kept.min) + (kept.max < infinity<T> ? std::abs(kept.max) : T(0)));
    return Interval<T>{std::max(t0, kept.min - pad), std::min(t1, kept.max + pad)};
}

/// Whether equiangular sampling aims at light L: a delta light at a point (a point or spot
/// light), whose own density falls as 1 / d^2 from its position.
template <class L>
inline constexpr bool aimed_equiangularly = is_delta_light<L> && requires(const L& light) { light.position; };

/// The part of [t0, t1] along a ray where `light` can send light (aimed_equiangularly): all of
/// it for a point light, a spot light's cone (SpotLight::cone) clipped by within_cone;
/// nothing where the ray misses the cone.
template <class L, Scalar T>
[[nodiscard]] std::optional<Interval<T>> lit_span(const L& light, const Ray<T>& ray, T t0, T t1) noexcept
{
    if constexpr (requires { light.cone(); }) {
        const auto cone = light.cone();
        return within_cone(ray, t0, t1, cone.apex, cone.axis, cone.cos_half);
    } else {
        return Interval<T>{t0, t1};
    }
}

} // namespace prism
