// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include "../support.hpp"

using prism::Interval;
using prism::Pcg32;
using prism::Ray;
using prism::Vec3;

namespace {

/// first_crossing and any_crossing (a shape's lean query or the fallback) against the
/// full list's first crossing, on random rays and ranges.
template <class S>
int disagreements(const S& shape, Pcg32& rng, int rays)
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
    }
    return wrong;
}

} // namespace

TEST_CASE_TEMPLATE("the lean first-crossing query gives the full list's first t, for every kind of shape", T, float, double)
{
    Pcg32 rng(8u, 1u);
    const prism::Sphere<T> ball({T(0.3), T(-0.2), T(0.1)}, T(1.2));
    static_assert(prism::HasFirstCrossing<prism::Sphere<T>>);
    CHECK(disagreements(ball, rng, 200000) == 0);
    // Transformed forwards to the sphere's lean query; CSG and quadrics use the fallback.
    const prism::Transformed<prism::Sphere<T>> moved(ball, prism::Transform<T>::rotate_x(T(30)).then(prism::Transform<T>::scale({T(1), T(0.5), T(2)})));
    CHECK(disagreements(moved, rng, 200000) == 0);
    const prism::Difference<prism::Sphere<T>, prism::Box<T>> cut(ball, prism::Box<T>({T(-2), T(-0.1), T(-2)}, {T(2), T(0.1), T(2)}));
    static_assert(!prism::HasFirstCrossing<decltype(cut)>);
    CHECK(disagreements(cut, rng, 100000) == 0);
    const auto b = prism::icosphere<T>({T(0), T(0), T(0)}, T(1), 2);
    const prism::TriangleMesh<T> mesh(b.positions, b.triangles);
    CHECK(disagreements(mesh, rng, 100000) == 0);
    CHECK(disagreements(prism::Transformed<prism::TriangleMesh<T>>(mesh, prism::Transform<T>::translate({T(0.5), T(0), T(0)})), rng, 100000) == 0);
}
