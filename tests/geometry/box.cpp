// SPDX-License-Identifier: MIT
#include <prism/geometry/box.hpp>
#include <prism/geometry/plane.hpp>

#include "../support.hpp"
#include "../uv_checks.hpp"

using prism::Box;
using prism::Interval;
using prism::Vec3;

#if PRISM_CONSTEXPR_VECTORS
constexpr auto box_hits = Box<float>({-1, -1, -1}, {1, 1, 1}).crossings({{-3, 0.5f, 0}, {1, 0, 0}}, Interval<float>::universe());
static_assert(box_hits.size() == 2 && box_hits[0].t == 2 && box_hits[1].t == 4 && box_hits[0].normal.x == -1);
#endif

TEST_CASE_TEMPLATE("ray-box crossings and face normals", T, float, double)
{
    const Box<T> box({T(2), T(0), T(-1)}, {T(0), T(1), T(1)}); // corners in any order
    CHECK(box.lo() == Vec3<T>{0, 0, -1});
    const auto c = box.crossings({{T(1), T(3), T(0)}, {T(0), T(-1), T(0)}}, Interval<T>::universe());
    REQUIRE(c.size() == 2);
    CHECK(c[0].t == doctest::Approx(2));
    CHECK(c[0].normal == Vec3<T>{0, 1, 0});
    CHECK(c[0].point.y == T(1));
    CHECK(c[1].t == doctest::Approx(3));
    CHECK(c[1].normal == Vec3<T>{0, -1, 0});
    // Diagonal: enters through x = 0 at t = 1 (the last slab entered), leaves through z = 1.
    const auto d = box.crossings({{T(-1), T(0.5), T(0)}, {T(1), T(0), T(0.25)}}, Interval<T>::universe());
    REQUIRE(d.size() == 2);
    CHECK(d[0].t == doctest::Approx(1));
    CHECK(d[0].normal == Vec3<T>{-1, 0, 0});
    CHECK(d[1].t == doctest::Approx(3));
    CHECK(d[1].normal == Vec3<T>{1, 0, 0});
    // From inside.
    const auto in = box.crossings({{T(1), T(0.5), T(0)}, {T(0), T(0), T(1)}}, {T(0), prism::infinity<T>});
    CHECK(in.inside_at_start);
    REQUIRE(in.size() == 1);
    CHECK(in[0].normal == Vec3<T>{0, 0, 1});
    // Parallel to a face, outside it.
    CHECK(box.crossings({{T(1), T(2), T(-5)}, {T(0), T(0), T(1)}}, Interval<T>::universe()).empty());
}

TEST_CASE_TEMPLATE("a ray leaving a box never hits it again", T, float, double)
{
    prism::Random rng(4u, 4u);
    for (double distance : {1.0, 1e3, 1e4, 1e5}) {
        INFO("distance from origin " << distance);
        CHECK(test::reintersections(rng, 4000, [&](prism::Random& r) {
                  const Vec3<T> centre = test::random_point<T>(r, T(distance));
                  const Vec3<T> half_size{T(0.2) + r.uniform<T>(), T(0.2) + r.uniform<T>(), T(0.2) + r.uniform<T>()};
                  return std::pair{Box<T>(centre - half_size, centre + half_size), centre};
              }) == 0);
    }
}

TEST_CASE("bad input names the parameter")
{
    CHECK_THROWS_WITH_AS(Box<float>({0, 0, 0}, {1, 0, 1}), doctest::Contains("Box extent"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Box<float>({0, 0, std::nanf("")}, {1, 1, 1}), doctest::Contains("Box corner_a"), std::invalid_argument);
}

TEST_CASE_TEMPLATE("a box's lean first_crossing and any_crossing give what its crossing list gives, bit for bit", T, float, double)
{
    // The slow, obvious twin: crossings<false>(ray, range).front(). Rays from anywhere,
    // many along an axis or in a face's plane, over ranges starting before, inside and
    // past the box.
    prism::Random rng(51u, 3u);
    const auto coordinate = [&](T scale) {
        const std::uint32_t pick = rng.next_u32() % 8;
        if (pick == 0) return T(-1);
        if (pick == 1) return T(2);
        return scale * (T(2) * rng.uniform<T>() - T(1));
    };
    const Box<T> box({T(-1), T(0.5), T(-2)}, {T(2), T(3), T(1)});
    int differences = 0, hits = 0;
    for (int i = 0; i < 400000; ++i) {
        const Vec3<T> origin{coordinate(T(5)), coordinate(T(5)), coordinate(T(5))};
        Vec3<T> direction{coordinate(T(1)), coordinate(T(1)), coordinate(T(1))};
        if (i % 5 == 0) direction[i % 3] = T(0);
        if (direction == Vec3<T>(T(0))) continue;
        const prism::Ray<T> ray{origin, direction};
        const T start = i % 3 == 0 ? T(0) : T(4) * (rng.uniform<T>() - T(0.25));
        const Interval<T> range{start, i % 4 == 0 ? prism::infinity<T> : start + T(6) * rng.uniform<T>()};
        const auto list = box.template crossings<false>(ray, range);
        const T expected = list.empty() ? prism::infinity<T> : list.front().t;
        hits += !list.empty();
        differences += !(box.first_crossing(ray, range) == expected) + (box.any_crossing(ray, range) != !list.empty());
    }
    CHECK(differences == 0);
    CHECK(hits > 20000);
}

TEST_CASE("a box's faces each span [0, 1]^2 of surface coordinates, right-handed from outside")
{
    const Box<double> box({-1, 0, 2}, {3, 1, 4});
    // The front face (-z, toward a camera at -z): u from the right edge seen from there (x = 3) to x = -1.
    const auto c = box.crossings({{2, 0.25, -10}, {0, 0, 1}}, Interval<double>::universe());
    REQUIRE(c.size() == 2);
    prism::Crossing<double> front = c.front();
    box.coordinates(front);
    CHECK(front.uv.x == doctest::Approx(0.25));
    CHECK(front.uv.y == doctest::Approx(0.25));
    const auto found = uv_checks::check_derivatives(box, {1, 0.5, 3}, 2.0, 3000, [](const auto& x) {
        return std::min({x.uv.x, x.uv.y, 1 - x.uv.x, 1 - x.uv.y}) < 0.01; // near an edge
    });
    CHECK(found.checked > 1000);
    CHECK(found.worst < 1e-6);
    CHECK(found.left_handed == 0);
}

TEST_CASE_TEMPLATE("a box's face and a Plane on it cross a ray at the same t, bit for bit, so that surfaces made to meet do", T, float, double)
{
    // A glass's bottom stands on a table (a Box face on a Plane) and water fills the glass
    // to its inner bottom: where two surfaces meet, the nearer of two equal crossings must
    // be decided the same way for every ray. With t = (lo - o) * (1 / d), one rounding more
    // than the plane's -(o - lo) / d, half the rays saw the table first and half the glass:
    // the glass of water's bottom turned to salt and pepper.
    prism::Random rng(23u, 5u);
    const Box<T> box({T(-1), T(0.15), T(-0.7)}, {T(1.3), T(2.6), T(0.9)});
    int mismatches = 0, crossings = 0;
    for (int i = 0; i < 200000; ++i) {
        const int axis = i % 3;
        const bool high = (i / 3) % 2 == 1;
        Vec3<T> normal{T(0)};
        normal[axis] = T(1);
        const T at = high ? box.hi()[axis] : box.lo()[axis];
        const prism::Plane<T> plane(normal, at);
        Vec3<T> origin{T(6) * rng.uniform<T>() - T(3), T(6) * rng.uniform<T>() - T(3), T(6) * rng.uniform<T>() - T(3)};
        origin[axis] = at + (high ? T(1) : T(-1)) * (T(0.01) + T(3) * rng.uniform<T>()); // outside, facing the face
        const Vec3<T> target{box.lo().x + (box.hi().x - box.lo().x) * rng.uniform<T>(), box.lo().y + (box.hi().y - box.lo().y) * rng.uniform<T>(),
                             box.lo().z + (box.hi().z - box.lo().z) * rng.uniform<T>()};
        Vec3<T> aim = target;
        aim[axis] = at;
        const prism::Ray<T> ray{origin, aim - origin};
        const auto on_box = box.crossings(ray, Interval<T>::universe());
        const auto on_plane = plane.crossings(ray, Interval<T>::universe());
        if (on_box.empty() || on_plane.empty()) continue;
        ++crossings;
        mismatches += on_box.front().t != on_plane.front().t;
    }
    CHECK(crossings > 150000);
    CHECK(mismatches == 0);
}
