// SPDX-License-Identifier: MIT
#include <prism/core/math.hpp>
#include <prism/core/random.hpp>

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <initializer_list>

using prism::Vec3;

#if PRISM_CONSTEXPR_VECTORS
// The helpers work in constant expressions, against hand-computed values.
static_assert(prism::dot(Vec3<float>{1, 2, 3}, Vec3<float>{4, -5, 6}) == 12.0f);
static_assert(prism::cross(Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}) == Vec3<double>{0, 0, 1});
static_assert(prism::length(Vec3<double>{2, 3, 6}) == 7.0);
static_assert(prism::sqrt(2.0) * prism::sqrt(2.0) - 2.0 < 1e-15);
static_assert(prism::max_component(Vec3<float>{-1, 5, 2}) == 5.0f);
#endif

TEST_CASE_TEMPLATE("constexpr sqrt agrees with std::sqrt to the last bit or one ulp", T, float, double)
{
    for (T x : {T(0), T(1e-30), T(0.25), T(2), T(3), T(1e6), T(123456.789), T(1e30)}) {
        // Evaluate the constexpr branch at run time through a constant-evaluated lambda is
        // not possible, so compare the run-time result and the defining property instead.
        const T y = prism::sqrt(x);
        CHECK(y == std::sqrt(x));
    }
    CHECK(std::isnan(prism::sqrt(T(-1))));
}

#if PRISM_CONSTEXPR_VECTORS
// The Newton branch, evaluated by the compiler, lands within one ulp of the true root.
constexpr double root2 = prism::sqrt(2.0);
constexpr double root1e6 = prism::sqrt(1e6);
constexpr float root3f = prism::sqrt(3.0f);
TEST_CASE("constant-evaluated sqrt is correctly rounded or within one ulp")
{
    CHECK(std::abs(root2 - std::sqrt(2.0)) <= std::nextafter(std::sqrt(2.0), 2.0) - std::sqrt(2.0));
    CHECK(root1e6 == 1000.0);
    CHECK(std::abs(root3f - std::sqrt(3.0f)) <= std::nextafter(std::sqrt(3.0f), 2.0f) - std::sqrt(3.0f));
}
#endif

TEST_CASE_TEMPLATE("vector helpers match GLM's own", T, float, double)
{
    const Vec3<T> a{T(0.3), T(-1.7), T(2.2)}, b{T(-4.1), T(0.5), T(1.25)};
    CHECK(prism::dot(a, b) == doctest::Approx(glm::dot(a, b)));
    const Vec3<T> c = prism::cross(a, b), g = glm::cross(a, b);
    for (int i = 0; i < 3; ++i) CHECK(c[i] == doctest::Approx(g[i]));
    CHECK(prism::length(a) == doctest::Approx(glm::length(a)));
    CHECK(prism::length(prism::normalize(b)) == doctest::Approx(1.0));
    CHECK_FALSE(prism::is_finite(Vec3<T>{T(0), prism::infinity<T>, T(0)}));
    CHECK_FALSE(prism::is_finite(std::numeric_limits<T>::quiet_NaN()));
    CHECK(prism::clamp(std::numeric_limits<T>::quiet_NaN(), T(0), T(1)) == T(0));
}

TEST_CASE_TEMPLATE("is_finite of a scalar and of a vector (both branch-free) agree with std::isfinite over every mix of hostile values", T, float, double)
{
    using L = std::numeric_limits<T>;
    const T values[] = {T(0), -T(0), T(1), -T(2.5), L::max(), -L::max(), L::min(), L::denorm_min(), L::infinity(), -L::infinity(), L::quiet_NaN(), -L::quiet_NaN()};
    int finite = 0;
    for (const T x : values)
        for (const T y : values)
            for (const T z : values) {
                const bool expected = std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
                CHECK(prism::is_finite(Vec3<T>{x, y, z}) == expected);
                CHECK((prism::is_finite(x) && prism::is_finite(y) && prism::is_finite(z)) == expected); // the scalar one (|x| <= max) too
                finite += expected;
            }
    CHECK(finite == 8 * 8 * 8);
}

TEST_CASE_TEMPLATE("difference_of_products keeps the digits that a*b - c*d cancels", T, float, double)
{
    // b^2 - a c for a nearly tangent quadratic: 1 + u against (1 + u/2)^2, whose exact
    // difference u^2/4 is far below the rounding of either product.
    const T u = std::numeric_limits<T>::epsilon() * T(64);
    const T b = T(1) + u / 2, a = T(1), c = T(1) + u;
    const long double exact = (long double)u * u / 4; // b^2 - a c = u^2 / 4 exactly (u is a power of 2)
    const T fast = prism::difference_of_products(b, b, a, c);
    CHECK(std::abs(fast - exact) <= std::abs(exact) * 1e-5L);
    // Random values: within a couple of roundings of the exact result.
    prism::Random rng(3u, 3u);
    for (int i = 0; i < 10000; ++i) {
        const T x = rng.uniform<T>(), y = rng.uniform<T>(), z = rng.uniform<T>(), w = rng.uniform<T>();
        const long double e = (long double)x * y - (long double)z * w;
        CHECK(std::abs(prism::difference_of_products(x, y, z, w) - e) <= 2 * std::numeric_limits<T>::epsilon() * (std::abs(e) + 1e-30L));
    }
}

TEST_CASE_TEMPLATE("abs clears the sign bit: -0 gives +0, NaN stays NaN, at run time and in constant evaluation, per component of a vector", T, float, double)
{
    static_assert(prism::abs(T(-2.5)) == T(2.5) && prism::abs(T(3)) == T(3));
    using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    static_assert(std::bit_cast<Bits>(prism::abs(-T(0))) == 0); // +0, every bit clear
    volatile T negative_zero = -T(0), nan = std::numeric_limits<T>::quiet_NaN(), minus_inf = -prism::infinity<T>;
    CHECK_FALSE(std::signbit(prism::abs(T(negative_zero))));
    CHECK(std::isnan(prism::abs(T(nan))));
    CHECK(prism::abs(T(minus_inf)) == prism::infinity<T>);
    CHECK(prism::abs(-std::numeric_limits<T>::denorm_min()) == std::numeric_limits<T>::denorm_min());
    const Vec3<T> v = prism::abs(Vec3<T>{-T(1), T(negative_zero), T(2)});
    CHECK(v == Vec3<T>{T(1), T(0), T(2)});
    CHECK_FALSE(std::signbit(v.y));
}
