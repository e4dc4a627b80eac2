// SPDX-License-Identifier: MIT
// Robust spawning of secondary rays: the one place self-intersection is handled.
//
// A shape reports each hit point together with a bound on its floating-point error.
// A new ray starts from the hit point pushed along the geometric normal just past
// that bound, to the side the ray leaves by, then rounded one more ulp away, so it
// can never start on the wrong side of the surface it leaves (Pharr, Jakob and
// Humphreys, "Physically Based Rendering", 4th ed., section 6.8.6; pbrt-v4
// OffsetRayOrigin). No other code in prism nudges rays by an epsilon.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace prism {

/// Higham's gamma(n) = n u / (1 - n u), u = machine epsilon / 2: the relative error
/// bound of n successive rounded operations.
template <Scalar T>
[[nodiscard]] constexpr T gamma(int n) noexcept
{
    constexpr T u = std::numeric_limits<T>::epsilon() * T(0.5);
    return T(n) * u / (T(1) - T(n) * u);
}

/// The next representable value above v (pbrt-v4 NextFloatUp), by stepping its bits:
/// std::nextafter is an out-of-line library call, and this is on every secondary ray.
template <Scalar T>
[[nodiscard]] constexpr T next_float_up(T v) noexcept
{
    using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    if (v == infinity<T> || v != v) return v;
    if (v == T(-0.0)) v = T(0.0); // skip -0 so that the step leaves 0
    Bits bits = std::bit_cast<Bits>(v);
    bits = v >= T(0) ? bits + 1 : bits - 1;
    return std::bit_cast<T>(bits);
}

/// The next representable value below v.
template <Scalar T>
[[nodiscard]] constexpr T next_float_down(T v) noexcept
{
    using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    if (v == -infinity<T> || v != v) return v;
    if (v == T(0.0)) v = T(-0.0);
    Bits bits = std::bit_cast<Bits>(v);
    bits = v > T(0) ? bits - 1 : bits + 1;
    return std::bit_cast<T>(bits);
}

/// The origin for a ray leaving point p (absolute error bound p_error per axis) of a
/// surface with geometric normal n, in direction w.
template <Scalar T>
[[nodiscard]] inline Vec3<T> offset_ray_origin(const Vec3<T>& p, const Vec3<T>& p_error, const Vec3<T>& n,
                                               const Vec3<T>& w) noexcept
{
    const T d = dot(abs(n), p_error);
    const T side = dot(w, n) < T(0) ? T(-1) : T(1);
    Vec3<T> po = p + (side * d) * n;
    // Round one ulp further away from the surface on every axis the normal has, so the
    // offset survives the addition's rounding, and so a point whose error bound is zero
    // (a box face's snapped coordinate) still leaves the surface: a ray starting exactly
    // on a face could not tell which side of it it is on.
    for (int i = 0; i < 3; ++i) {
        if (side * n[i] > T(0))
            po[i] = next_float_up(po[i]);
        else if (side * n[i] < T(0))
            po[i] = next_float_down(po[i]);
    }
    return po;
}

/// A ray leaving a surface point in direction w.
template <Scalar T>
[[nodiscard]] inline Ray<T> spawn_ray(const Vec3<T>& p, const Vec3<T>& p_error, const Vec3<T>& n,
                                      const Vec3<T>& w) noexcept
{
    return {offset_ray_origin(p, p_error, n, w), w};
}

} // namespace prism
