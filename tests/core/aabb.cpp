// SPDX-License-Identifier: MIT
#include <prism/core/aabb.hpp>

#include <doctest/doctest.h>

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
