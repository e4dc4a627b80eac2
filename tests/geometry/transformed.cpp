// SPDX-License-Identifier: MIT
#include <prism/geometry/transformed.hpp>
#include <prism/prism.hpp>

#include "../support.hpp"
#include "../uv_checks.hpp"

using doctest::Approx;
using namespace prism;

TEST_CASE_TEMPLATE("a sphere under non-uniform scale is the ellipsoid quadric", T, float, double)
{
    const auto to_world = Transform<T>::scale({T(2), T(1), T(0.5)}).then(Transform<T>::rotate_y(T(30))).then(Transform<T>::translate({T(1), T(2), T(3)}));
    const Transformed squashed(Sphere<T>({T(0), T(0), T(0)}, T(1)), to_world);
    // The unit sphere as a quadric, moved by the same transform.
    const auto ellipsoid = Quadric<T>({.a = 1, .e = 1, .h = 1, .j = -1}).transformed(to_world);
    Random rng(7u, 7u);
    int compared = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3<T> eye = Vec3<T>{T(1), T(2), T(3)} + test::random_direction<T>(rng) * T(6);
        const Ray<T> ray{eye, normalize(Vec3<T>{T(1), T(2), T(3)} + test::random_point<T>(rng, T(1)) - eye)};
        const auto a = squashed.crossings(ray, Interval<T>::universe());
        const auto b = ellipsoid.crossings(ray, Interval<T>::universe());
        if (a.size() != 2 || b.size() != 2) continue; // grazing rays may differ by a touch
        ++compared;
        for (int k = 0; k < 2; ++k) {
            CHECK(a[k].t == Approx(b[k].t).epsilon(1e-3));
            CHECK(a[k].entering == b[k].entering);
            CHECK(dot(a[k].normal, b[k].normal) == Approx(1).epsilon(1e-3));
            CHECK(length(a[k].point - b[k].point) < T(1e-3));
        }
        CHECK(squashed.contains(ray.at(T(0.5) * (a[0].t + a[1].t))));
    }
    CHECK(compared > 1000);
    CHECK(squashed.bounds().contains({T(1), T(2), T(3)}));
}

TEST_CASE_TEMPLATE("a ray leaving a transformed box or sphere never hits it again", T, float, double)
{
    Random rng(3u, 8u);
    for (double distance : {1.0, 1e3, 1e5}) {
        INFO("distance " << distance);
        CHECK(test::reintersections(rng, 3000, [&](Random& r) {
                  const Vec3<T> centre = test::random_point<T>(r, T(distance));
                  const auto place = Transform<T>::scale({T(0.5) + r.uniform<T>(), T(0.5) + r.uniform<T>(), T(0.5) + r.uniform<T>()})
                                         .then(Transform<T>::rotate(T(360) * r.uniform<T>(), test::random_direction<T>(r)))
                                         .then(Transform<T>::translate(centre));
                  return std::pair{Transformed(Box<T>({T(-1), T(-1), T(-1)}, {T(1), T(1), T(1)}), place), centre};
              }) == 0);
        CHECK(test::reintersections(rng, 3000, [&](Random& r) {
                  const Vec3<T> centre = test::random_point<T>(r, T(distance));
                  const auto place = Transform<T>::scale({T(0.5) + r.uniform<T>(), T(0.5) + r.uniform<T>(), T(2)}).then(Transform<T>::translate(centre));
                  return std::pair{Transformed(Sphere<T>({T(0), T(0), T(0)}, T(1)), place), centre};
              }) == 0);
    }
}

TEST_CASE("a transformed sphere keeps its surface coordinates, and carries dp/du and dp/dv into the world")
{
    const auto place = Transform<double>::scale({2, 1, 0.5}).then(Transform<double>::rotate_y(30)).then(Transform<double>::translate({1, 2, 3}));
    const Transformed<Sphere<double>> ellipsoid(Sphere<double>({0, 0, 0}, 1), place);
    const auto found = uv_checks::check_derivatives(ellipsoid, {1, 2, 3}, 1.5, 3000, [](const auto& c) {
        return c.uv.x < 0.02 || c.uv.x > 0.98 || c.uv.y < 0.05 || c.uv.y > 0.95;
    });
    CHECK(found.checked > 1000);
    CHECK(found.worst < 2e-3);
    CHECK(found.left_handed == 0);
}

TEST_CASE_TEMPLATE("a turned ball's world box is its own size, and a CSG node's is made of its children's", T, float, double)
{
    // A unit ball turned 45 degrees about (1, 1, 0): the box around its box's turned
    // corners is 3 wide on x; its own is 2 (bounds_under, from the ball's ellipsoid).
    const auto turn = Transform<T>::rotate(T(45), {T(1), T(1), T(0)}).then(Transform<T>::translate({T(3), T(-1), T(2)}));
    const Transformed ball(Sphere<T>({T(0), T(0), T(0)}, T(1)), turn);
    for (int axis = 0; axis < 3; ++axis) CHECK(ball.bounds().hi[axis] - ball.bounds().lo[axis] == Approx(2).epsilon(1e-5));
    // A lens (two balls' intersection) and a bored bead (a ball less a cylinder), turned:
    // each box lies within the box of its turned balls, and holds every crossing a ray finds.
    const auto lens = Transformed(intersection_of(Sphere<T>({T(-0.6), T(0), T(0)}, T(1.1)), Sphere<T>({T(0.6), T(0), T(0)}, T(1.1))), turn);
    const auto bead = Transformed(difference_of(Sphere<T>({T(0), T(0), T(0)}, T(1)), Quadric<T>::from_povray(1, 1, 0, 0, 0, 0, 0, 0, 0, T(-0.2025))), turn);
    const Aabb<T> left = Transformed(Sphere<T>({T(-0.6), T(0), T(0)}, T(1.1)), turn).bounds();
    const Aabb<T> right = Transformed(Sphere<T>({T(0.6), T(0), T(0)}, T(1.1)), turn).bounds();
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(lens.bounds().lo[axis] == std::max(left.lo[axis], right.lo[axis]));
        CHECK(lens.bounds().hi[axis] == std::min(left.hi[axis], right.hi[axis]));
        CHECK(bead.bounds().lo[axis] == ball.bounds().lo[axis]);
        CHECK(bead.bounds().hi[axis] == ball.bounds().hi[axis]);
    }
    // (A crossing's point is rounded: the boxes are grown by 10^-5 for it.)
    const auto holds = [](const Aabb<T>& box, const Vec3<T>& p) { return Aabb<T>{box.lo - Vec3<T>(T(1e-5)), box.hi + Vec3<T>(T(1e-5))}.contains(p); };
    Random rng(5u, 17u);
    int found = 0, outside = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3<T> centre{T(3), T(-1), T(2)};
        const Vec3<T> eye = centre + test::random_direction<T>(rng) * T(4);
        const Ray<T> ray{eye, normalize(centre + test::random_point<T>(rng, T(1.2)) - eye)};
        for (const auto& c : lens.crossings(ray, Interval<T>::universe())) ++found, outside += !holds(lens.bounds(), c.point);
        for (const auto& c : bead.crossings(ray, Interval<T>::universe())) ++found, outside += !holds(bead.bounds(), c.point);
    }
    CHECK(found > 20000);
    CHECK(outside == 0);
}
