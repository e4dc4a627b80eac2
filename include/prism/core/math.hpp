// SPDX-License-Identifier: MIT
// Scalar concept, GLM aliases and the constexpr vector helpers GLM does not provide.
//
// glm::dot, glm::cross and glm::length are never constexpr in GLM 0.9.9.8, so prism
// keeps its own. They take prism's Vec3 exactly, so overload resolution prefers them
// to GLM's generic templates found by argument-dependent lookup.
#pragma once

#include <prism/core/config.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <concepts>
#include <limits>
#include <numbers>
#include <type_traits>

namespace prism {

/// The floating-point type a scene computes in: float (default) or double.
template <class T>
concept Scalar = std::floating_point<T>;

/// A point or direction in 3D.
template <Scalar T>
using Vec3 = glm::vec<3, T, glm::defaultp>;

/// Linear RGB: radiance, irradiance, albedo or a per-channel factor.
template <Scalar T>
using Rgb = glm::vec<3, T, glm::defaultp>;

template <Scalar T>
inline constexpr T infinity = std::numeric_limits<T>::infinity();

template <Scalar T>
inline constexpr T pi = std::numbers::pi_v<T>;

// Vector helpers (constexpr)

template <Scalar T>
[[nodiscard]] constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) noexcept
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <Scalar T>
[[nodiscard]] constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) noexcept
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <Scalar T>
[[nodiscard]] constexpr T length_squared(const Vec3<T>& v) noexcept
{
    return dot(v, v);
}

/// Square root usable in constant expressions (Newton's iteration there, std::sqrt at run time).
template <Scalar T>
[[nodiscard]] constexpr T sqrt(T x) noexcept
{
    if (std::is_constant_evaluated()) {
        if (x == T(0) || x == infinity<T>) return x;
        if (!(x > T(0))) return std::numeric_limits<T>::quiet_NaN();
        // Newton's iteration from above decreases monotonically until it stalls.
        for (T y = x > T(1) ? x : T(1);;) {
            const T next = T(0.5) * (y + x / y);
            if (next >= y) return y;
            y = next;
        }
    }
    return std::sqrt(x);
}

template <Scalar T>
[[nodiscard]] constexpr T length(const Vec3<T>& v) noexcept
{
    return prism::sqrt(length_squared(v));
}

template <Scalar T>
[[nodiscard]] constexpr Vec3<T> normalize(const Vec3<T>& v) noexcept
{
    return v * (T(1) / length(v));
}

template <Scalar T>
[[nodiscard]] constexpr Vec3<T> abs(const Vec3<T>& v) noexcept
{
    return {v.x < T(0) ? -v.x : v.x, v.y < T(0) ? -v.y : v.y, v.z < T(0) ? -v.z : v.z};
}

/// Component-wise minimum and maximum (glm::min and glm::max are not constexpr).
template <Scalar T>
[[nodiscard]] constexpr Vec3<T> component_min(const Vec3<T>& a, const Vec3<T>& b) noexcept
{
    return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}

template <Scalar T>
[[nodiscard]] constexpr Vec3<T> component_max(const Vec3<T>& a, const Vec3<T>& b) noexcept
{
    return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}

template <Scalar T>
[[nodiscard]] constexpr T max_component(const Vec3<T>& v) noexcept
{
    T m = v.x > v.y ? v.x : v.y;
    return m > v.z ? m : v.z;
}

template <Scalar T>
[[nodiscard]] constexpr bool is_finite(T x) noexcept
{
    return x == x && x != infinity<T> && x != -infinity<T>;
}

template <Scalar T>
[[nodiscard]] constexpr bool is_finite(const Vec3<T>& v) noexcept
{
    return is_finite(v.x) && is_finite(v.y) && is_finite(v.z);
}

/// Clamp x into [lo, hi] (NaN maps to lo).
template <Scalar T>
[[nodiscard]] constexpr T clamp(T x, T lo, T hi) noexcept
{
    return x > lo ? (x < hi ? x : hi) : lo;
}

} // namespace prism

namespace prism {

/// a*b - c*d with one rounding error instead of a catastrophic cancellation (Kahan's
/// algorithm with fused multiply-adds; pbrt-v4 DifferenceOfProducts).
template <Scalar T>
[[nodiscard]] constexpr T difference_of_products(T a, T b, T c, T d) noexcept
{
    if (std::is_constant_evaluated()) return a * b - c * d;
    const T cd = c * d;
    const T error = std::fma(-c, d, cd);
    return std::fma(a, b, -cd) + error;
}

} // namespace prism
