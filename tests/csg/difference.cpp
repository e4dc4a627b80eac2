// SPDX-License-Identifier: MIT
#include <prism/csg/difference.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

using namespace prism;

static_assert(Difference<Sphere<float>, Box<float>>::max_crossings == 4); // A + B
static_assert(std::same_as<Difference<Sphere<float>, Box<float>, Plane<float>>,
                           CsgNode<DifferenceOp, Sphere<float>, CsgNode<UnionOp, Box<float>, Plane<float>>>>);

#if PRISM_CONSTEXPR_VECTORS
// A - A is empty (coincident faces cancel), in a constant expression.
constexpr auto nothing = difference_of(Sphere<double>({0, 0, 0}, 1), Sphere<double>({0, 0, 0}, 1));
static_assert(nothing.crossings({{-5, 0, 0}, {1, 0, 0}}, Interval<double>::universe()).empty());
// A box with a bite: [0, 2]^3 minus [1, 3] x [0, 2] x [0, 2], which shares three faces.
constexpr auto bitten_box = difference_of(Box<float>({0, 0, 0}, {2, 2, 2}), Box<float>({1, 0, 0}, {3, 2, 2}));
constexpr auto bitten_hits = bitten_box.crossings({{-1, 1, 1}, {1, 0, 0}}, Interval<float>::universe());
static_assert(bitten_hits.size() == 2 && bitten_hits[0].t == 1 && bitten_hits[1].t == 2 && bitten_hits[1].normal.x == 1);
#endif

TEST_CASE("the seed snippets' failing cases")
{
    const Sphere<double> a({0, 0, 0}, 1);
    // B wholly in front of A along the ray: the seed's code returns nothing; A - B is all of A.
    const auto front = difference_of(a, Sphere<double>({-3, 0, 0}, 0.5));
    const auto c = front.crossings({{-5, 0, 0}, {1, 0, 0}}, Interval<double>::universe());
    REQUIRE(c.size() == 2);
    CHECK(c[0].t == doctest::Approx(4));
    CHECK(c[1].t == doctest::Approx(6));
    // B behind A, and B overlapping A's far side.
    const auto bite = difference_of(a, Sphere<double>({1, 0, 0}, 0.5));
    const auto b = bite.crossings({{-5, 0, 0}, {1, 0, 0}}, Interval<double>::universe());
    REQUIRE(b.size() == 2);
    CHECK(b[1].t == doctest::Approx(5.5));
    CHECK(b[1].normal.x == doctest::Approx(1)); // B's near face, flipped: outward of the result
    CHECK_FALSE(b[1].entering);
    // A ray starting inside A, inside the bite.
    const auto inside_b = bite.crossings({{0.8, 0, 0}, {-1, 0, 0}}, {0, infinity<double>});
    CHECK_FALSE(inside_b.inside_at_start);
    REQUIRE(inside_b.size() == 2);
    CHECK(inside_b[0].t == doctest::Approx(0.3)); // out of B: into the result
    CHECK(inside_b[0].entering);
    CHECK(inside_b[0].normal.x == doctest::Approx(1));
    // CSG of CSG: (A - B) | C with C overlapping the bite.
    const auto nested = union_of(bite, Sphere<double>({1.5, 0, 0}, 0.2));
    const auto n = nested.crossings({{-5, 0, 0}, {1, 0, 0}}, Interval<double>::universe());
    REQUIRE(n.size() == 4);
    CHECK(n[2].t == doctest::Approx(6.3));
    CHECK(n[3].t == doctest::Approx(6.7));
}

TEST_CASE("coincident faces: A - A is empty, a box minus a box sharing faces leaves no film")
{
    const Box<double> block({0, 0, 0}, {2, 2, 2});
    const auto none = difference_of(block, block);
    const auto self_union = union_of(block, block);
    const auto bitten = difference_of(block, Box<double>({1, 0, 0}, {3, 2, 2}));
    const auto flush = difference_of(block, Box<double>({0, 0, 1}, {2, 2, 2})); // the top half, flush on five faces
    for (const Vec3<double> dir : {Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}, Vec3<double>{0, 0, 1}}) {
        const Ray<double> ray{Vec3<double>{1.0, 1.0, 0.5} - 5.0 * dir, dir};
        CHECK(none.crossings(ray, Interval<double>::universe()).empty());
        CHECK(self_union.crossings(ray, Interval<double>::universe()).size() == 2);
        // Along x and y at z = 0.5 the flush cut is not in the way; along z the slab ends at z = 1.
        const auto f = flush.crossings(ray, Interval<double>::universe());
        REQUIRE(f.size() == 2);
        CHECK(f[0].t == doctest::Approx(dir.z == 1 ? 4.5 : 4));
        CHECK(f[1].t == doctest::Approx(dir.z == 1 ? 5.5 : 6));
    }
    // Through the shared faces at z = 1.5 along x: the cut removes everything above z = 1.
    CHECK(flush.crossings({{-5, 1, 1.5}, {1, 0, 0}}, Interval<double>::universe()).empty());
    // The bite: along x only [0, 1] is left; along y at x = 1.5 nothing.
    CHECK(bitten.crossings({{1.5, -5, 1}, {0, 1, 0}}, Interval<double>::universe()).empty());
}
