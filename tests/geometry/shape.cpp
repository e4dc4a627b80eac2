// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include "../support.hpp"

using prism::Interval;
using prism::Random;
using prism::Ray;
using prism::Vec3;

namespace {

/// first_crossing and any_crossing (a shape's lean query or the fallback) against the
/// full list's first crossing, on random rays and ranges.
template <class S>
int disagreements(const S& shape, Random& rng, int rays)
{
    using T = typename S::scalar_type;
    int wrong = 0;
    for (int i = 0; i < rays; ++i) {
        const Ray<T> ray{test::random_point<T>(rng, T(3)), test::random_direction<T>(rng) * (T(0.5) + rng.uniform<T>())};
        const T a = T(4) * rng.uniform<T>() - T(2), b = T(8) * rng.uniform<T>();
        const Interval<T> range = i % 4 == 0 ? Interval<T>{T(0), prism::infinity<T>} : Interval<T>{std::min(a, b), std::max(a, b)};
        const auto list = shape.template crossings<false>(ray, range);
        const T first = prism::first_crossing(shape, ray, range);
        wrong += list.empty() ? first != prism::infinity<T> : first != list.front().t;
        wrong += prism::any_crossing(shape, ray, range) == list.empty();
        // The surface from the hint: the full list's first crossing over the range that
        // ends just past it (the scene's surface pass), bit for bit.
        prism::SurfaceHint<T> hint;
        const T t = prism::first_crossing(shape, ray, range, hint);
        if (!(t < prism::infinity<T>)) continue;
        const Interval<T> to_it{range.min, prism::next_float_up(t)};
        const auto surface = prism::surface_crossing(shape, ray, to_it, hint);
        const auto full = shape.crossings(ray, to_it);
        if (!surface || full.empty()) {
            ++wrong;
            continue;
        }
        const prism::Crossing<T>& lean = *surface;
        const prism::Crossing<T>& slow = full.front();
        wrong += lean.t != slow.t || lean.entering != slow.entering || lean.point != slow.point || lean.normal != slow.normal || lean.error != slow.error;
    }
    return wrong;
}

} // namespace

TEST_CASE_TEMPLATE("the lean first-crossing query gives the full list's first t, and its hinted surface the full list's, for every kind of shape", T, float, double)
{
    Random rng(8u, 1u);
    const prism::Sphere<T> ball({T(0.3), T(-0.2), T(0.1)}, T(1.2));
    static_assert(prism::HasFirstCrossing<prism::Sphere<T>>);
    CHECK(disagreements(ball, rng, 200000) == 0);
    // Transformed forwards to the sphere's lean query; CSG and quadrics use the fallback.
    const prism::Transformed<prism::Sphere<T>> moved(ball, prism::Transform<T>::rotate_x(T(30)).then(prism::Transform<T>::scale({T(1), T(0.5), T(2)})));
    CHECK(disagreements(moved, rng, 200000) == 0);
    // A plane's lean query skips the division where its t would be negative.
    static_assert(prism::HasFirstCrossing<prism::Plane<T>>);
    CHECK(disagreements(prism::Plane<T>(prism::normalize(Vec3<T>{T(0.2), T(1), T(-0.4)}), T(0.3)), rng, 200000) == 0);
    CHECK(disagreements(prism::Plane<T>({T(0), T(1), T(0)}, T(0)), rng, 200000) == 0);
    const prism::Difference<prism::Sphere<T>, prism::Box<T>> cut(ball, prism::Box<T>({T(-2), T(-0.1), T(-2)}, {T(2), T(0.1), T(2)}));
    static_assert(!prism::HasFirstCrossing<decltype(cut)>);
    CHECK(disagreements(cut, rng, 100000) == 0);
    const auto b = prism::icosphere<T>({T(0), T(0), T(0)}, T(1), 2);
    const prism::TriangleMesh<T> mesh(b.positions, b.triangles);
    static_assert(prism::HasHintedSurface<prism::TriangleMesh<T>> && prism::HasHintedSurface<prism::Transformed<prism::TriangleMesh<T>>>);
    CHECK(disagreements(mesh, rng, 100000) == 0);
    CHECK(disagreements(prism::Transformed<prism::TriangleMesh<T>>(mesh, prism::Transform<T>::translate({T(0.5), T(0), T(0)})), rng, 100000) == 0);
}

TEST_CASE_TEMPLATE("a shape that says it is convex is: a ray leaving it on its outer side never crosses it again", T, float, double)
{
    using namespace prism;
    // What each says (an unbounded quadric, a union, a difference and a mesh are not said to be).
    const auto lens = intersection_of(Sphere<T>({T(-0.6), T(0), T(0)}, T(1.1)), Sphere<T>({T(0.6), T(0), T(0)}, T(1.1)));
    const auto ellipsoid = Quadric<T>::ellipsoid({T(0), T(0), T(0)}, {T(1), T(0.5), T(2)});
    static_assert(Sphere<T>::convex() && Box<T>::convex() && Plane<T>::convex());
    CHECK(convex(lens));
    CHECK(convex(ellipsoid));
    CHECK(convex(Transformed(lens, Transform<T>::rotate_x(T(30)))));
    CHECK_FALSE(convex(Quadric<T>::cylinder({T(0), T(0), T(0)}, {T(0), T(0), T(1)}, T(1))));
    CHECK_FALSE(convex(union_of(Sphere<T>({T(0), T(0), T(0)}, T(1)), Sphere<T>({T(1), T(0), T(0)}, T(1)))));
    CHECK_FALSE(convex(difference_of(Sphere<T>({T(0), T(0), T(0)}, T(1)), Sphere<T>({T(1), T(0), T(0)}, T(0.5)))));
    CHECK_FALSE(convex(intersection_of(Sphere<T>({T(0), T(0), T(0)}, T(1)), Quadric<T>::cylinder({T(0), T(0), T(0)}, {T(0), T(0), T(1)}, T(0.5)))));
    // pbrt-v4's TestReintersectConvex on each, randomly placed, near and far from the origin.
    Random rng(13u, 21u);
    for (const double far : {1.0, 1e3}) {
        INFO("distance " << far);
        const auto place = [far](Random& r) {
            return Transform<T>::scale({T(0.5) + r.uniform<T>(), T(0.5) + r.uniform<T>(), T(0.5) + r.uniform<T>()})
                .then(Transform<T>::rotate(T(360) * r.uniform<T>(), test::random_direction<T>(r)))
                .then(Transform<T>::translate(test::random_point<T>(r, T(far))));
        };
        CHECK(test::reintersections(rng, 3000, [&](Random& r) {
                  const auto m = place(r);
                  return std::pair{Transformed(lens, m), m.point({T(0), T(0), T(0)})};
              }) == 0);
        CHECK(test::reintersections(rng, 3000, [&](Random& r) {
                  const Vec3<T> centre = test::random_point<T>(r, T(far));
                  return std::pair{Quadric<T>::ellipsoid(centre, {T(0.3) + r.uniform<T>(), T(0.3) + r.uniform<T>(), T(0.3) + r.uniform<T>()}), centre};
              }) == 0);
        CHECK(test::reintersections(rng, 3000, [&](Random& r) {
                  const Vec3<T> on = test::random_point<T>(r, T(far)), n = test::random_direction<T>(r);
                  return std::pair{Plane<T>::through(on, n), on - n};
              }) == 0);
    }
}
