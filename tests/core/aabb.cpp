// SPDX-License-Identifier: MIT
#include <prism/core/aabb.hpp>

#include <prism/core/random.hpp>

#include "../effort.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <iterator>
#include <limits>

using prism::Vec3;

TEST_CASE_TEMPLATE("Aabb clips a ray to the span inside it", T, float, double)
{
    const prism::Aabb<T> box{Vec3<T>{-1, -1, -1}, Vec3<T>{1, 1, 1}};
    const auto span = box.clip({{T(-3), T(0), T(0)}, {T(1), T(0), T(0)}}, prism::Interval<T>::universe());
    CHECK(span.min == doctest::Approx(2));
    CHECK(span.max == doctest::Approx(4));
    CHECK(box.clip({{T(-3), T(2), T(0)}, {T(1), T(0), T(0)}}, prism::Interval<T>::universe()).empty());
    // A ray parallel to a slab with its origin exactly on the slab's plane (0 * inf).
    CHECK_FALSE(box.clip({{T(-3), T(1), T(0)}, {T(1), T(0), T(0)}}, prism::Interval<T>::universe()).empty());
    CHECK(box.contains({T(0.5), T(-1), T(1)}));
    CHECK(prism::Aabb<T>{}.empty());
    CHECK(prism::Aabb<T>::universe().contains({T(1e30), T(-1e30), T(0)}));
}

TEST_CASE("a denormal direction from a face is not a miss (0 * inf was NaN)")
{
    // Regression: a ray starting on a box's top face and going down at 7e-45 per unit came
    // out NaN on that axis and was culled; the box itself says it crosses.
    const prism::Aabb<float> box{Vec3<float>{8711.77051f, -46.0414314f, 4909.47168f}, Vec3<float>{8711.77246f, -46.0396309f, 4909.47314f}};
    const prism::Ray<float> ray{{8711.77148f, 9953.95996f, 4909.47314f}, {7.00649232e-45f, -0.770615876f, -7.00649232e-45f}};
    const auto span = box.clip(ray, {0, prism::infinity<float>});
    REQUIRE_FALSE(span.empty());
    CHECK(span.min == doctest::Approx(12976.6f).epsilon(1e-4));
    CHECK(box.reached_after(ray, 0));
}

TEST_CASE_TEMPLATE("reached_after ignores the range's end; rounded_out holds the exact box", T, float, double)
{
    const prism::Aabb<T> box{Vec3<T>{T(-1), T(-1), T(-1)}, Vec3<T>{T(1), T(1), T(1)}};
    const prism::Ray<T> ray{{T(-3), T(0), T(0)}, {T(1), T(0), T(0)}};
    CHECK(box.clip(ray, {T(0), T(1)}).empty()); // the range ends before the box
    CHECK(box.reached_after(ray, T(0)));       // but the shape's cull does not look at the end
    CHECK_FALSE(box.reached_after(ray, T(5))); // nor before the start
    // 0.1 is not a float: its sum with 1 rounds; the rounded-out box still holds the exact one.
    const prism::Aabb<T> tenth{Vec3<T>(T(1) + T(0.1)), Vec3<T>(T(3) + T(0.1))};
    const prism::Aabb<T> out = tenth.rounded_out();
    CHECK(out.lo.x < tenth.lo.x);
    CHECK(out.hi.x > tenth.hi.x);
    CHECK(double(out.lo.x) < 1.1);
    CHECK(double(out.hi.x) > 3.1);
}

TEST_CASE("may_cross widens the box per ray by the rounding of the ray's distance")
{
    // A unit box 10^4 away: a ray passing 10^-4 beside it may still be reported crossing
    // by a shape inside (its rounding there is about 10^-3), one passing 1 beside it not.
    const prism::Aabb<float> box{Vec3<float>{-0.5f, -0.5f, -0.5f}, Vec3<float>{0.5f, 0.5f, 0.5f}};
    const prism::Ray<float> close{{-1e4f, 0.5001f, 0}, {1, 0, 0}}, clear{{-1e4f, 1.5f, 0}, {1, 0, 0}};
    CHECK(box.clip(close, {0, prism::infinity<float>}).empty());
    CHECK(box.may_cross(close, {0, prism::infinity<float>}));
    CHECK_FALSE(box.may_cross(clear, {0, prism::infinity<float>}));
    CHECK_FALSE(box.may_cross(close, {0, 100})); // it uses the range's end
}

TEST_CASE("merged boxes and the sphere through a box's corners")
{
    const prism::Aabb<double> a{{0, 0, 0}, {1, 2, 2}}, b{{-1, 1, 1}, {0.5, 1.5, 4}};
    const auto m = a.merged(b);
    CHECK(m.lo == prism::Vec3<double>{-1, 0, 0});
    CHECK(m.hi == prism::Vec3<double>{1, 2, 4});
    CHECK(prism::Aabb<double>{}.merged(a).lo == a.lo); // the empty box is merging's identity
    const auto s = a.bounding_sphere();
    CHECK(s.center == prism::Vec3<double>{0.5, 1, 1});
    CHECK(s.radius == doctest::Approx(1.5)); // half the diagonal sqrt(1 + 4 + 4)
    CHECK(a.bounded());
    CHECK_FALSE(prism::Aabb<double>::universe().bounded());
}

namespace {

/// A hostile coordinate: mostly ordinary, sometimes 0, -0, a denormal, huge, infinite,
/// NaN, or (for an origin) one of the box's own faces.
template <class T>
T hostile_coordinate(prism::Random& rng, T face)
{
    const T specials[] = {T(0), -T(0), std::numeric_limits<T>::denorm_min(), -std::numeric_limits<T>::denorm_min(), std::numeric_limits<T>::max(),
                          prism::infinity<T>, -prism::infinity<T>, std::numeric_limits<T>::quiet_NaN(), face, T(1e-30), T(-1e30)};
    const double u = rng.uniform<double>();
    if (u < 0.25) return specials[std::size_t(rng.uniform<double>() * double(std::size(specials))) % std::size(specials)];
    return T(8 * rng.uniform<double>() - 4);
}

template <class T>
void crosses_agrees_with_clip(long rays)
{
    prism::Random rng(0xAABB5EEDu, 1);
    long differ = 0, met = 0;
    for (long i = 0; i < rays; ++i) {
        Vec3<T> lo, hi;
        for (int a = 0; a < 3; ++a) {
            const T x = T(4 * rng.uniform<double>() - 2), w = rng.uniform<double>() < 0.1 ? T(0) : T(2 * rng.uniform<double>());
            lo[a] = rng.uniform<double>() < 0.05 ? -prism::infinity<T> : x;
            hi[a] = rng.uniform<double>() < 0.05 ? prism::infinity<T> : x + w;
        }
        const prism::Aabb<T> box = rng.uniform<double>() < 0.02 ? prism::Aabb<T>{} : prism::Aabb<T>{lo, hi};
        Vec3<T> o, d;
        for (int a = 0; a < 3; ++a) {
            o[a] = hostile_coordinate<T>(rng, rng.uniform<double>() < 0.5 ? lo[a] : hi[a]);
            d[a] = hostile_coordinate<T>(rng, T(1));
        }
        if (rng.uniform<double>() < 0.5) // aimed at a point of the box, to meet it often
            for (int a = 0; a < 3; ++a)
                if (std::isfinite(lo[a]) && std::isfinite(hi[a]) && std::isfinite(o[a])) d[a] = lo[a] + T(rng.uniform<double>()) * (hi[a] - lo[a]) - o[a];
        const T t0 = rng.uniform<double>() < 0.1 ? hostile_coordinate<T>(rng, T(0)) : T(0);
        const T t1 = rng.uniform<double>() < 0.3 ? hostile_coordinate<T>(rng, T(1)) : prism::infinity<T>;
        const prism::Ray<T> ray{o, d};
        const bool slow = !box.clip(ray, {t0, t1}).empty(), fast = box.crosses(ray, {t0, t1});
        met += slow;
        if (slow != fast && ++differ <= 3)
            MESSAGE("box ", lo.x, " ", lo.y, " ", lo.z, " .. ", hi.x, " ", hi.y, " ", hi.z, " ray ", o.x, " ", o.y, " ", o.z, " -> ", d.x, " ", d.y, " ",
                    d.z, " range ", t0, " ", t1, ": clip ", slow, ", crosses ", fast);
    }
    CHECK(differ == 0);
    CHECK(met > rays / 20); // the rays are not all misses
    CHECK(met < rays - rays / 20);
}

} // namespace

TEST_CASE_TEMPLATE("crosses decides as clip does, over a million hostile rays", T, float, double)
{
    // The fast test is the slow one's twin: every ray, NaN, infinite, denormal, on a face
    // or parallel to it, against boxes flat, unbounded on a side, or empty.
    crosses_agrees_with_clip<T>(test::samples(1'000'000));
}
