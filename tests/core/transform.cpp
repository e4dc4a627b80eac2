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

TEST_CASE_TEMPLATE("box() holds the images of a box's points, and sphere_box() those of a ball's, touching it on every side", T, float, double)
{
    // Random transforms (rotations, shears by non-uniform scale between rotations, far
    // translations); the image of every point sampled on the box or ball lies in the
    // box computed for it, and the ball's box is tight: on each side, the farthest image,
    // worked out in double from the matrix, is within 10^-5 of the box's face.
    prism::Random rng(41u, 3u);
    int outside = 0, loose = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const T far = std::pow(T(10), T(int(rng.next_u32() % 7) - 3));
        const auto m = Transform<T>::rotate(T(360) * rng.uniform<T>(), test::random_direction<T>(rng))
                           .then(Transform<T>::scale({T(0.2) + T(3) * rng.uniform<T>(), T(0.2) + T(3) * rng.uniform<T>(), T(0.2) + T(3) * rng.uniform<T>()}))
                           .then(Transform<T>::rotate(T(360) * rng.uniform<T>(), test::random_direction<T>(rng)))
                           .then(Transform<T>::translate(test::random_point<T>(rng, far)));
        const Vec3<T> centre = test::random_point<T>(rng, T(2));
        const T radius = T(0.1) + T(2) * rng.uniform<T>();
        const prism::Aabb<T> cube{centre - Vec3<T>(radius), centre + Vec3<T>(radius)};
        const prism::Aabb<T> of_box = m.box(cube), of_ball = m.sphere_box(centre, radius);
        // (Points and images in double: the boxes hold the exact images.)
        const prism::Mat4<T> q = m.matrix();
        const auto image = [&q](const Vec3<double>& p) {
            Vec3<double> w;
            for (int i = 0; i < 3; ++i) w[i] = double(q[3][i]) + double(q[0][i]) * p.x + double(q[1][i]) * p.y + double(q[2][i]) * p.z;
            return w;
        };
        const auto holds = [](const prism::Aabb<T>& box, const Vec3<double>& p) {
            return double(box.lo.x) <= p.x && p.x <= double(box.hi.x) && double(box.lo.y) <= p.y && p.y <= double(box.hi.y) && double(box.lo.z) <= p.z &&
                   p.z <= double(box.hi.z);
        };
        for (int i = 0; i < 200; ++i) {
            const Vec3<double> u(test::random_direction<double>(rng));
            const Vec3<double> on_ball = Vec3<double>(centre) + double(radius) * u / prism::length(u);
            const Vec3<double> on_box = Vec3<double>(centre) + double(radius) * u / prism::max_component(prism::abs(u));
            outside += !holds(of_ball, image(on_ball)) + !holds(of_box, image(on_box));
        }
        // The ball's farthest image along axis i: the centre's, plus the radius times the
        // length of row i of the linear part.
        for (int i = 0; i < 3; ++i) {
            double c = double(q[3][i]), row2 = 0;
            for (int j = 0; j < 3; ++j) c += double(q[j][i]) * double(centre[j]), row2 += double(q[j][i]) * double(q[j][i]);
            const double reach = double(radius) * std::sqrt(row2), slack = 1e-5 * (std::abs(c) + reach);
            loose += !(double(of_ball.hi[i]) - (c + reach) <= slack && (c - reach) - double(of_ball.lo[i]) <= slack);
        }
        // Tighter than (or as tight as) the box around the ball's box.
        CHECK(of_ball.hi.x - of_ball.lo.x <= of_box.hi.x - of_box.lo.x);
    }
    CHECK(outside == 0);
    CHECK(loose == 0);
    // Empty stays empty; unbounded gives every point.
    const auto turn = Transform<T>::rotate_y(T(30));
    CHECK(turn.box(prism::Aabb<T>{}).empty());
    CHECK(turn.box(prism::Aabb<T>{{T(0), T(0), -prism::infinity<T>}, {T(1), T(1), T(1)}}).lo.x == -prism::infinity<T>);
}
