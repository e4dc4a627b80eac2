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

/// A point in 2D: surface (texture) coordinates.
template <Scalar T>
using Vec2 = glm::vec<2, T, glm::defaultp>;

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

/// |x|, the sign bit cleared (one andps; a comparison and a select where the compiler
/// has no builtin). -0 gives +0.
template <Scalar T>
[[nodiscard, gnu::always_inline]] constexpr T abs(T x) noexcept
{
#if defined(__GNUC__)
    if constexpr (std::is_same_v<T, float>) return __builtin_fabsf(x);
    else if constexpr (std::is_same_v<T, double>) return __builtin_fabs(x);
    else return __builtin_fabsl(x);
#else
    return x < T(0) || (x == T(0) && std::signbit(x)) ? -x : x;
#endif
}

template <Scalar T>
[[nodiscard]] constexpr Vec3<T> abs(const Vec3<T>& v) noexcept
{
    return {prism::abs(v.x), prism::abs(v.y), prism::abs(v.z)};
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

/// Whether x is finite: |x| at most the largest finite value (false for an infinity,
/// and for a NaN, which compares false). One mask and one comparison.
template <Scalar T>
[[nodiscard]] constexpr bool is_finite(T x) noexcept
{
    return prism::abs(x) <= std::numeric_limits<T>::max();
}

/// Whether every component is finite. (x - x is 0 for a finite x and NaN for an infinity
/// or a NaN, and a sum with a NaN is NaN: no branch, as a ray's test before every query
/// wants.)
template <Scalar T>
[[nodiscard]] constexpr bool is_finite(const Vec3<T>& v) noexcept
{
    const T zero = (v.x - v.x) + (v.y - v.y) + (v.z - v.z);
    return zero == T(0);
}

/// Clamp x into [lo, hi] (NaN maps to lo).
template <Scalar T>
[[nodiscard]] constexpr T clamp(T x, T lo, T hi) noexcept
{
    return x > lo ? (x < hi ? x : hi) : lo;
}

} // namespace prism

namespace prism {

namespace detail {

/// Leaves `x` (a product just computed, a scalar or a vector of the compiler's vector
/// extensions) as it is, but where the compiler can no longer fuse it into a later sum or
/// difference: floating-point contraction to an FMA, GCC's default wherever the target has
/// FMA (-march=native, -mfma, every aarch64) and clang's within one expression. An empty
/// asm that claims to change x: no instruction. (x86 without FMA cannot fuse, so it is
/// left alone there.)
template <class V>
[[gnu::always_inline]] constexpr void keep_rounded(V& x) noexcept
{
#if defined(__GNUC__) && (!(defined(__x86_64__) || defined(__i386__)) || defined(__FMA__) || defined(__FMA4__))
    if (!std::is_constant_evaluated()) {
#if defined(__x86_64__) || defined(__i386__)
        asm("" : "+x"(x)); // (FMA implies AVX: a 32-byte vector fits a register)
#elif defined(__aarch64__) || defined(__arm__)
        if constexpr (sizeof(V) <= 16) asm("" : "+w"(x));
        else asm("" : "+m"(x));
#else
        asm("" : "+m"(x));
#endif
    }
#else
    (void)x;
#endif
}

} // namespace detail

/// `x`, a product, rounded as computed (detail::keep_rounded): `rounded(a * b) -
/// rounded(c * d)` is exactly the negative of `rounded(c * d) - rounded(a * b)` in every
/// build, which the watertight triangle test needs; a fused difference rounds one product
/// and not the other.
template <Scalar T>
[[nodiscard, gnu::always_inline]] constexpr T rounded(T x) noexcept
{
    detail::keep_rounded(x);
    return x;
}

/// a*b - c*d without catastrophic cancellation (the discriminant of a quadratic).
///  float:  the products of two floats are exact in double, so computing in double
///          rounds once, at the end.
///  double: Kahan's algorithm with fused multiply-adds where the target has them
///          (pbrt-v4 DifferenceOfProducts); on targets without (baseline x86-64),
///          std::fma is a slow library call, so Dekker's exact product by splitting.
template <Scalar T>
[[nodiscard]] constexpr T difference_of_products(T a, T b, T c, T d) noexcept
{
    if constexpr (sizeof(T) < sizeof(double)) {
        return T(double(a) * double(b) - double(c) * double(d));
    } else {
        if (std::is_constant_evaluated()) return a * b - c * d;
#if defined(__FMA__) || defined(FP_FAST_FMA)
        const T cd = c * d;
        const T error = std::fma(-c, d, cd);
        return std::fma(a, b, -cd) + error;
#else
        // Dekker (1971): x*y = p + e exactly, with x and y split into halves of 26 bits.
        const auto two_product = [](T x, T y, T& e) {
            constexpr T split = T(134217729.0); // 2^27 + 1
            const T p = x * y;
            const T xs = split * x, ys = split * y;
            const T xh = xs - (xs - x), yh = ys - (ys - y);
            const T xl = x - xh, yl = y - yh;
            e = ((xh * yh - p) + xh * yl + xl * yh) + xl * yl;
            return p;
        };
        T e_ab = T(0), e_cd = T(0);
        const T ab = two_product(a, b, e_ab);
        const T cd = two_product(c, d, e_cd);
        return (ab - cd) + (e_ab - e_cd);
#endif
    }
}

} // namespace prism
