// SPDX-License-Identifier: MIT
#include <prism/core/transform.hpp>

#include "../support.hpp"

#include <cstring>

using doctest::Approx;
using prism::Transform;
using prism::Vec3;

TEST_CASE_TEMPLATE("transforms compose in the order written and invert", T, float, double)
{
    // Rotate 90 deg about z (x -> y), then move by (1, 0, 0).
    const auto t = Transform<T>::rotate_z(T(90)).then(Transform<T>::translate({T(1), T(0), T(0)}));
    const Vec3<T> p = t.point({T(1), T(0), T(0)});
    CHECK(p.x == Approx(1));
    CHECK(p.y == Approx(1));
    const Vec3<T> back = t.inverse().point(p);
    CHECK(back.x == Approx(1));
    CHECK(back.y == Approx(0).epsilon(1e-6));
    CHECK(t.vector({T(1), T(0), T(0)}).x == Approx(0).epsilon(1e-6)); // directions ignore translation
}

TEST_CASE_TEMPLATE("normals stay perpendicular under non-uniform scale", T, float, double)
{
    const auto squash = Transform<T>::scale({T(4), T(1), T(0.5)}).then(Transform<T>::rotate(T(33), {T(1), T(2), T(3)}));
    prism::Random rng(2u, 2u);
    for (int i = 0; i < 1000; ++i) {
        const Vec3<T> n = test::random_direction<T>(rng);
        // A tangent vector of the plane with normal n, mapped as a direction.
        const Vec3<T> tangent = prism::cross(n, test::random_direction<T>(rng));
        CHECK(std::abs(prism::dot(squash.normal(n), squash.vector(tangent))) <= T(1e-4) * prism::length(squash.normal(n)) * T(4));
    }
}

TEST_CASE_TEMPLATE("the error bound of a transformed point covers the true value", T, float, double)
{
    const auto t = Transform<T>::rotate(T(17), {T(1), T(1), T(0)}).then(Transform<T>::translate({T(1000), T(-3), T(7)}));
    prism::Random rng(9u, 1u);
    for (int i = 0; i < 1000; ++i) {
        const Vec3<T> p = test::random_point<T>(rng, T(100));
        const Vec3<T> w = t.point(p);
        const Vec3<T> bound = t.point_error(p, Vec3<T>(T(0)));
        const auto& m = t.matrix();
        for (int r = 0; r < 3; ++r) {
            long double exact = m[3][r];
            for (int c = 0; c < 3; ++c) exact += (long double)m[c][r] * p[c];
            CHECK(std::abs(exact - w[r]) <= bound[r] + 1e-300L);
        }
    }
}

TEST_CASE("singular and malformed transforms are rejected")
{
    CHECK_THROWS_WITH_AS((void)Transform<float>::scale({1, 0, 1}), doctest::Contains("singular"), std::invalid_argument);
    CHECK_THROWS_AS((void)Transform<double>::translate({0, std::nan(""), 0}), std::invalid_argument);
    prism::Mat4<double> projective(1.0);
    projective[0][3] = 0.5;
    CHECK_THROWS_WITH_AS(Transform<double>{projective}, doctest::Contains("affine"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((void)Transform<float>::rotate(10, {0, 0, 0}), doctest::Contains("rotate axis"), std::invalid_argument);
}

TEST_CASE("then() checks its product, and singular means ill-conditioned, not a small determinant")
{
    // Regression: then() re-checked nothing, so four scale(1e12) gave an infinite matrix
    // and translate(3e38) twice gave inf; and scale({1e-6, 1, 1}) was called singular.
    const auto big = Transform<float>::scale(Vec3<float>(1e12f));
    CHECK_THROWS_WITH_AS((void)big.then(big).then(big).then(big), doctest::Contains("Transform::then"), std::invalid_argument);
    const auto far = Transform<float>::translate({3e38f, 0, 0});
    CHECK_THROWS_WITH_AS((void)far.then(far), doctest::Contains("overflows"), std::invalid_argument);
    // A legitimate flattening, and a uniformly tiny or huge scale, are well conditioned.
    const auto flat = Transform<float>::scale({1e-6f, 1, 1});
    CHECK(flat.inverse_point({1e-6f, 2, 3}).x == doctest::Approx(1));
    const auto tiny = Transform<float>::scale(Vec3<float>(1e-20f));
    CHECK(tiny.inverse_point({1e-20f, 0, 0}).x == doctest::Approx(1));
    CHECK(Transform<double>::scale({1e-12, 1, 1}).inverse_point({1e-12, 0, 0}).x == doctest::Approx(1));
    // Ill-conditioned for float, fine for double.
    CHECK_THROWS_WITH_AS((void)Transform<float>::scale({1e-8f, 1, 1}), doctest::Contains("condition number"), std::invalid_argument);
    // Its inverse would overflow float.
    CHECK_THROWS_WITH_AS((void)Transform<float>::scale(Vec3<float>(1e-40f)), doctest::Contains("not representable"), std::invalid_argument);
    // The inverse is still the inverse.
    const auto t = Transform<double>::rotate(33, {1, 2, 3}).then(Transform<double>::scale({2, 0.5, 3})).then(Transform<double>::translate({4, -5, 6}));
    const Vec3<double> p{0.3, -0.7, 1.9};
    CHECK(length(t.inverse_point(t.point(p)) - p) < 1e-14);
}

TEST_CASE_TEMPLATE("point and vector give the scalar sums' bits: each component in the order written, then the translation", T, float, double)
{
    // The slow, obvious twin of the column-by-column (SIMD) product, component by component.
    prism::Random rng(77u, 5u);
    const auto transform = prism::Transform<T>::rotate_x(T(37)).then(prism::Transform<T>::scale({T(1.5), T(-0.25), T(3)}))
                               .then(prism::Transform<T>::rotate_y(T(-71)))
                               .then(prism::Transform<T>::translate({T(0.1), T(-7), T(1e3)}));
    const prism::Mat4<T> m = transform.matrix();
    const auto slow = [&](const Vec3<T>& v, bool point) {
        Vec3<T> r{m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z, m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z, m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
        return point ? r + Vec3<T>(m[3]) : r;
    };
    const auto same = [](const Vec3<T>& a, const Vec3<T>& b) {
        for (int i = 0; i < 3; ++i)
            if (!(std::memcmp(&a[i], &b[i], sizeof(T)) == 0)) return false;
        return true;
    };
    int differ = 0;
    for (int i = 0; i < 100000; ++i) {
        Vec3<T> v{T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1)};
        v *= std::pow(T(10), T(int(rng.next_u32() % 13) - 6));
        if (i % 7 == 0) v[i % 3] = -T(0);
        differ += !same(transform.point(v), slow(v, true)) + !same(transform.vector(v), slow(v, false));
    }
    CHECK(differ == 0);
}
