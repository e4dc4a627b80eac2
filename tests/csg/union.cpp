// SPDX-License-Identifier: MIT
#include <prism/csg/union.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

using namespace prism;

// Variadic forms fold to the right and add up their capacities.
static_assert(std::same_as<Union<Sphere<float>, Box<float>, Plane<float>>,
                           CsgNode<UnionOp, Sphere<float>, CsgNode<UnionOp, Box<float>, Plane<float>>>>);
static_assert(Union<Sphere<float>, Box<float>, Plane<float>>::max_crossings == 5);
static_assert(Shape<Union<Sphere<double>, Quadric<double>>>);

#if PRISM_CONSTEXPR_VECTORS
// Two overlapping spheres along x, in a constant expression: one span, -2 to 2.
constexpr auto pair = union_of(Sphere<double>({-0.5, 0, 0}, 1.5), Sphere<double>({0.5, 0, 0}, 1.5));
constexpr auto pair_hits = pair.crossings({{-5, 0, 0}, {1, 0, 0}}, Interval<double>::universe());
static_assert(pair_hits.size() == 2 && pair_hits[0].t == 3 && pair_hits[1].t == 7);
#endif

TEST_CASE("union of three spheres, apart and overlapping, with the ray starting inside one")
{
    const auto snowman = union_of(Sphere<double>({0, 0.8, 0}, 0.8), Sphere<double>({0, 1.9, 0}, 0.55), Sphere<double>({0, 2.6, 0}, 0.35));
    // Up the axis from below: enters at y = 0, leaves at the top y = 2.95 (the spheres overlap).
    const auto up = snowman.crossings({{0, -1, 0}, {0, 1, 0}}, Interval<double>::universe());
    REQUIRE(up.size() == 2);
    CHECK(up[0].t == doctest::Approx(1));
    CHECK(up[1].t == doctest::Approx(3.95));
    // From inside the middle sphere: inside at the start, one crossing out at the top.
    const auto from_inside = snowman.crossings({{0, 1.9, 0}, {0, 1, 0}}, {0, infinity<double>});
    CHECK(from_inside.inside_at_start);
    REQUIRE(from_inside.size() == 1);
    CHECK(from_inside[0].t == doctest::Approx(2.95 - 1.9));
    // Two disjoint spheres: two spans.
    const auto apart = union_of(Sphere<double>({0, 0, 0}, 1), Sphere<double>({5, 0, 0}, 1));
    const auto two = apart.crossings({{-5, 0, 0}, {1, 0, 0}}, Interval<double>::universe());
    REQUIRE(two.size() == 4);
    CHECK(two[2].t == doctest::Approx(9));
    CHECK(two[2].entering);
    CHECK(apart.contains({5, 0.5, 0}));
    CHECK_FALSE(apart.contains({2.5, 0, 0}));
}
