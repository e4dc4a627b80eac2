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

TEST_CASE("a glass lens made by intersection focuses at the thick-lens back focal distance")
{
    // Faces of radius 1.1 (R1 = 1.1, R2 = -1.1), thickness d = 1 on the axis, n = 1.5:
    // power (n - 1)(1/R1 - 1/R2 + (n - 1) d / (n R1 R2)) = 0.771349, f = 1.296430, and the
    // back focal distance f (1 - (n - 1) d / (n R1)) = 0.903573 from the back vertex at x = 0.5.
    const double n = 1.5, r = 1.1, d = 1.0;
    const double power = (n - 1) * (1 / r + 1 / r - (n - 1) * d / (n * r * r));
    const double focus = 0.5 + (1 / power) * (1 - (n - 1) * d / (n * r));
    const auto lens = intersection_of(Sphere<double>({-0.6, 0, 0}, 1.1), Sphere<double>({0.6, 0, 0}, 1.1));
    for (double height : {1e-3, 2e-3}) {
        Ray<double> ray{{-3, height, 0}, {1, 0, 0}};
        // Through the front face, then the back face: refraction at each, normals from the CSG node.
        for (double eta : {n, 1 / n}) {
            const auto c = lens.crossings(ray, {0, infinity<double>});
            REQUIRE(!c.empty());
            const Crossing<double>& x = c.front();
            const Vec3<double> facing = x.facing_normal();
            const auto bent = refract(ray.direction, facing, eta);
            REQUIRE(bent);
            ray = spawn_ray(x.point, x.error, x.normal, *bent);
        }
        // Where the emerging ray crosses the axis.
        const double axis_x = ray.origin.x - ray.origin.y * ray.direction.x / ray.direction.y;
        CHECK(axis_x == doctest::Approx(focus).epsilon(1e-5));
    }
    CHECK(focus == doctest::Approx(1.403573).epsilon(1e-6));
}
