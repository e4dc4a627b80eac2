// SPDX-License-Identifier: MIT
#include <prism/core/ray.hpp>

#include <doctest/doctest.h>

using prism::Ray;
using prism::Vec3;

TEST_CASE("a ray cone widens by its spread along t, and a mirror's ray carries it on at the same angle")
{
    const Ray<double> ray{.origin = {0, 0, 0}, .direction = {0, 0, -2}, .width = 0.01, .spread = 0.004};
    CHECK(ray.footprint_at(0) == 0.01);
    CHECK(ray.footprint_at(3) == doctest::Approx(0.022));
    CHECK(ray.at(3).z == -6);
    // Met at t = 3 (6 units away), sent on with a unit direction: width 0.022 there, and
    // 0.004 per t of a direction twice as long is 0.002 per unit length.
    const Ray<double> next = prism::carrying_cone(Ray<double>{.origin = {0, 0, -6}, .direction = {0, 1, 0}}, ray, 3.0);
    CHECK(next.width == doctest::Approx(0.022));
    CHECK(next.spread == doctest::Approx(0.002));
    // 6 units after the mirror, as 6 units before it would have been: 0.01 + 0.002 (6 + 6).
    CHECK(next.footprint_at(6) == doctest::Approx(0.034));
    // A ray that samples a point stays one.
    const Ray<double> point = prism::carrying_cone(Ray<double>{.direction = {1, 0, 0}}, Ray<double>{}, 5.0);
    CHECK(point.width == 0);
    CHECK(point.spread == 0);
}
