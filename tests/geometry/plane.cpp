// SPDX-License-Identifier: MIT
#include <prism/geometry/plane.hpp>

#include "../support.hpp"

using prism::Interval;
using prism::Plane;
using prism::Vec3;

TEST_CASE_TEMPLATE("half-space crossings", T, float, double)
{
    // y <= 2, given with a non-unit normal: 3y <= 6.
    const Plane<T> floor({T(0), T(3), T(0)}, T(6));
    CHECK(floor.offset() == doctest::Approx(2));
    const auto down = floor.crossings({{T(1), T(5), T(1)}, {T(0), T(-1), T(0)}}, Interval<T>::universe());
    REQUIRE(down.size() == 1);
    CHECK(down[0].t == doctest::Approx(3));
    CHECK(down[0].entering);
    CHECK(down[0].point.y == T(2));
    CHECK_FALSE(down.inside_at_start);

    const auto up = floor.crossings({{T(1), T(0), T(1)}, {T(0), T(1), T(1)}}, {T(0), prism::infinity<T>});
    REQUIRE(up.size() == 1);
    CHECK(up[0].t == doctest::Approx(2));
    CHECK_FALSE(up[0].entering);
    CHECK(up.inside_at_start);

    // Parallel rays: inside or outside all along.
    CHECK(floor.crossings({{T(0), T(1), T(0)}, {T(1), T(0), T(0)}}, Interval<T>::universe()).inside_at_start);
    CHECK_FALSE(floor.crossings({{T(0), T(3), T(0)}, {T(1), T(0), T(0)}}, Interval<T>::universe()).inside_at_start);
    // Through a point, tilted.
    const auto tilted = Plane<T>::through({T(1), T(1), T(1)}, {T(1), T(1), T(1)});
    const auto hit = tilted.crossings({{T(0), T(0), T(0)}, {T(1), T(0), T(0)}}, Interval<T>::universe());
    REQUIRE(hit.size() == 1);
    CHECK(hit[0].t == doctest::Approx(3));
}

TEST_CASE_TEMPLATE("a ray leaving a plane never hits it again, near and far from the origin", T, float, double)
{
    prism::Pcg32 rng(8u, 1u);
    for (double distance : {1.0, 1e3, 1e4, 1e5}) {
        INFO("distance from origin " << distance);
        int i = 0;
        CHECK(test::reintersections(rng, 4000, [&](prism::Pcg32& r) {
                  const Vec3<T> point = test::random_point<T>(r, T(distance));
                  const Vec3<T> normal = ++i % 2 ? Vec3<T>{T(0), T(1), T(0)} : test::random_direction<T>(r);
                  return std::pair{Plane<T>::through(point, normal), point};
              }) == 0);
    }
}

TEST_CASE("bad input names the parameter")
{
    CHECK_THROWS_WITH_AS(Plane<float>({0, 0, 0}, 1.0f), doctest::Contains("Plane normal"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Plane<double>({0, 1, 0}, std::nan("")), doctest::Contains("Plane offset"), std::invalid_argument);
}
