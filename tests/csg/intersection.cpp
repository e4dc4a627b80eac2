// SPDX-License-Identifier: MIT
#include <prism/csg/intersection.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>

using namespace prism;

#if PRISM_CONSTEXPR_VECTORS
// A lens: two spheres of radius 1.1 with centres 1.2 apart overlap on x in [-0.5, 0.5].
constexpr auto constant_lens = intersection_of(Sphere<double>({-0.6, 0, 0}, 1.1), Sphere<double>({0.6, 0, 0}, 1.1));
constexpr auto lens_hits = constant_lens.crossings({{-5, 0, 0}, {1, 0, 0}}, Interval<double>::universe());
static_assert(lens_hits.size() == 2 && lens_hits[0].t > 4.49 && lens_hits[0].t < 4.51 && lens_hits[1].t > 5.49 && lens_hits[1].t < 5.51);
#endif

TEST_CASE("a lens: each face comes from the other sphere, with that sphere's normal")
{
    const auto lens = intersection_of(Sphere<double>({-0.6, 0, 0}, 1.1), Sphere<double>({0.6, 0, 0}, 1.1));
    const auto c = lens.crossings({{-5, 0, 0}, {1, 0, 0}}, Interval<double>::universe());
    REQUIRE(c.size() == 2);
    CHECK(c[0].t == doctest::Approx(4.5));
    CHECK(c[0].normal.x == doctest::Approx(-1)); // the right sphere's near face
    CHECK(c[1].t == doctest::Approx(5.5));
    CHECK(c[1].normal.x == doctest::Approx(1));
    // The lens is bounded by the overlap of the two boxes.
    CHECK(lens.bounds().lo.x == doctest::Approx(-0.5));
    CHECK(lens.bounds().hi.x == doctest::Approx(0.5));
    // Off-centre, the rim: at height y the lens is 2 (sqrt(1.21 - y^2) - 0.6) thick.
    const auto rim = lens.crossings({{-5, 0.3, 0}, {1, 0, 0}}, Interval<double>::universe());
    REQUIRE(rim.size() == 2);
    CHECK(rim[1].t - rim[0].t == doctest::Approx(2 * (std::sqrt(1.21 - 0.09) - 0.6)));
}

TEST_CASE("clipping an unbounded quadric to a box caps it")
{
    const auto tube = intersection_of(Quadric<double>::cylinder({0, 0, 0}, {0, 1, 0}, 1), Box<double>({-2, -1, -2}, {2, 1, 2}));
    // Down the axis: enters through the top cap (the box), leaves through the bottom.
    const auto down = tube.crossings({{0, 5, 0}, {0, -1, 0}}, Interval<double>::universe());
    REQUIRE(down.size() == 2);
    CHECK(down[0].t == doctest::Approx(4));
    CHECK(down[0].normal.y == doctest::Approx(1));
    CHECK(down[1].t == doctest::Approx(6));
    // Across: the cylinder wall.
    const auto across = tube.crossings({{-5, 0, 0}, {1, 0, 0}}, Interval<double>::universe());
    REQUIRE(across.size() == 2);
    CHECK(across[0].t == doctest::Approx(4));
    CHECK(tube.bounds().hi.y == 1);
}
