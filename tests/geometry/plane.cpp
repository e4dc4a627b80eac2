// SPDX-License-Identifier: MIT
#include <prism/geometry/plane.hpp>

#include "../support.hpp"
#include "../uv_checks.hpp"

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
    prism::Random rng(8u, 1u);
    for (double distance : {1.0, 1e3, 1e4, 1e5}) {
        INFO("distance from origin " << distance);
        int i = 0;
        CHECK(test::reintersections(rng, 4000, [&](prism::Random& r) {
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

TEST_CASE("normals as small as a denormal or as large as 3e38 give the same plane")
{
    // Regression: (1e-45, 0, 0) and (3e38, 3e38, 0) made |normal| underflow or overflow and
    // the plane vanished.
    for (const prism::Vec3<float> n : {prism::Vec3<float>{1e-45f, 0, 0}, prism::Vec3<float>{3e38f, 3e38f, 0}, prism::Vec3<float>{1, 1, 0}}) {
        const auto plane = prism::Plane<float>::through({1, 0, 0}, n);
        const auto c = plane.crossings({{5, 0.5f, 0}, {-1, 0, 0}}, prism::Interval<float>::universe());
        INFO(n.x);
        REQUIRE(c.size() == 1);
        CHECK(c[0].entering);
        CHECK(c[0].point.x == doctest::Approx(n.y == 0 ? 1.0f : 0.5f));
        CHECK(prism::length(c[0].normal) == doctest::Approx(1));
    }
    // x = 1 / 1e-45 is beyond float: said, not wrapped.
    CHECK_THROWS_WITH_AS(prism::Plane<float>({1e-45f, 0, 0}, 1.0f), doctest::Contains("Plane offset"), std::invalid_argument);
}

TEST_CASE("a plane's surface coordinates run in the scene's units: u along +x and v along -z on a floor, u right and v up on a wall")
{
    const Plane<double> floor({0, 1, 0}, 0.5);
    const auto c = floor.crossings({{3, 4, -2}, {0, -1, 0}}, Interval<double>::universe());
    REQUIRE(c.size() == 1);
    prism::Crossing<double> at = c.front();
    CHECK_FALSE(at.has_uv()); // added only where a material reads them
    floor.coordinates(at);
    CHECK(at.uv.x == doctest::Approx(3));
    CHECK(at.uv.y == doctest::Approx(2));
    // A wall facing a camera at -z looking +z: its right is -x.
    const Plane<double> wall({0, 0, -1}, -4);
    const auto w = wall.crossings({{1, 2, 0}, {0, 0, 1}}, Interval<double>::universe());
    REQUIRE(w.size() == 1);
    prism::Crossing<double> on_wall = w.front();
    wall.coordinates(on_wall);
    CHECK(on_wall.dpdu.x == doctest::Approx(-1));
    CHECK(on_wall.dpdv.y == doctest::Approx(1));
    for (const Vec3<double>& n : {Vec3<double>{0, 1, 0}, Vec3<double>{0, -1, 0}, normalize(Vec3<double>{1, 2, 3}), normalize(Vec3<double>{-3, 0.1, 1})}) {
        const auto found = uv_checks::check_derivatives(Plane<double>(n, 0.3), {0, 0, 0}, 2.0, 500, [](const auto&) { return false; });
        CHECK(found.checked > 100);
        CHECK(found.worst < 1e-6);
        CHECK(found.left_handed == 0);
    }
}

TEST_CASE_TEMPLATE("a plane's lean first_crossing and any_crossing give what its crossing list gives, bit for bit", T, float, double)
{
    // The slow, obvious twin: crossings<false>(ray, range).front(). Origins on the plane
    // and off it, directions along it, toward it and away, zeros of both signs, NaN and
    // infinities; ranges from 0, from below 0, and ending anywhere.
    prism::Random rng(52u, 9u);
    const T specials[] = {T(0), -T(0), T(1), T(-1), prism::infinity<T>, std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::denorm_min()};
    const auto coordinate = [&](T scale) {
        const std::uint32_t pick = rng.next_u32() % 10;
        if (pick < 2) return specials[rng.next_u32() % std::size(specials)];
        return scale * (T(2) * rng.uniform<T>() - T(1));
    };
    const Plane<T> floor({T(0), T(1), T(0)}, T(0)), slanted(prism::normalize(Vec3<T>{T(1), T(2), T(-0.5)}), T(0.7));
    int differences = 0, hits = 0, skipped = 0;
    for (const Plane<T>* plane : {&floor, &slanted})
        for (int i = 0; i < 200000; ++i) {
            const prism::Ray<T> ray{{coordinate(T(3)), coordinate(T(3)), coordinate(T(3))}, {coordinate(T(1)), coordinate(T(1)), coordinate(T(1))}};
            const T start = i % 3 == 0 ? T(0) : T(4) * (rng.uniform<T>() - T(0.25));
            const Interval<T> range{start, i % 4 == 0 ? prism::infinity<T> : start + T(6) * rng.uniform<T>()};
            const auto list = plane->template crossings<false>(ray, range);
            const T expected = list.empty() ? prism::infinity<T> : list.front().t;
            hits += !list.empty();
            const T height = dot(plane->normal(), ray.origin) - plane->offset(), denom = dot(plane->normal(), ray.direction);
            skipped += range.min >= T(0) && height * denom > T(0); // the division skipped
            differences += !(plane->first_crossing(ray, range) == expected) + (plane->any_crossing(ray, range) != !list.empty());
        }
    CHECK(differences == 0);
    CHECK(hits > 40000);
    CHECK(skipped > 40000);
}
