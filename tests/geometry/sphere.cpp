// SPDX-License-Identifier: MIT
#include <prism/geometry/sphere.hpp>

#include "../chi2.hpp"
#include "../support.hpp"
#include "../uv_checks.hpp"

#include <cmath>

using prism::Interval;
using prism::Ray;
using prism::Sphere;
using prism::Vec3;

#if PRISM_CONSTEXPR_VECTORS
// Ray-sphere crossings in a constant expression: the unit sphere from z = -5.
constexpr auto unit_hits = Sphere<double>({0, 0, 0}, 1).crossings({{0, 0, -5}, {0, 0, 1}}, Interval<double>::universe());
static_assert(unit_hits.size() == 2 && unit_hits[0].t == 4 && unit_hits[1].t == 6);
static_assert(unit_hits[0].entering && !unit_hits[1].entering);
#endif

TEST_CASE_TEMPLATE("ray-sphere crossings against hand-solved values", T, float, double)
{
    // Sphere at (1, 2, 3), radius 2; a ray along z with a direction of length 2.
    const Sphere<T> sphere({T(1), T(2), T(3)}, T(2));
    const auto c = sphere.crossings({{T(1), T(2), T(-10)}, {T(0), T(0), T(2)}}, Interval<T>::universe());
    REQUIRE(c.size() == 2);
    CHECK(c[0].t == doctest::Approx(5.5));
    CHECK(c[1].t == doctest::Approx(7.5));
    CHECK(c[0].entering);
    CHECK_FALSE(c[1].entering);
    CHECK(c[0].normal.z == doctest::Approx(-1));
    CHECK(c[1].normal.z == doctest::Approx(1));
    CHECK(c[0].point.z == doctest::Approx(1));

    // Off-axis: the ray x = 1 + 1 meets the sphere where (z - 3)^2 = 4 - 1, z = 3 -+ sqrt(3).
    const auto d = sphere.crossings({{T(2), T(2), T(0)}, {T(0), T(0), T(1)}}, Interval<T>::universe());
    REQUIRE(d.size() == 2);
    CHECK(d[0].t == doctest::Approx(3 - std::sqrt(3.0)));
    CHECK(d[1].t == doctest::Approx(3 + std::sqrt(3.0)));
    CHECK(d[0].normal.x == doctest::Approx(0.5));
}

TEST_CASE_TEMPLATE("ranges, inside starts, misses and tangents", T, float, double)
{
    const Sphere<T> sphere({T(0), T(0), T(0)}, T(1));
    const Ray<T> from_centre{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}};
    const auto inside = sphere.crossings(from_centre, {T(0), prism::infinity<T>});
    CHECK(inside.inside_at_start);
    REQUIRE(inside.size() == 1);
    CHECK(inside[0].t == doctest::Approx(1));
    CHECK_FALSE(inside[0].entering);

    const Ray<T> along_z{{T(0), T(0), T(-5)}, {T(0), T(0), T(1)}};
    CHECK(sphere.crossings(along_z, {T(0), T(4)}).empty());     // stops short
    CHECK(sphere.crossings(along_z, {T(4.5), T(5.5)}).empty()); // starts and ends inside
    CHECK(sphere.crossings(along_z, {T(4.5), T(5.5)}).inside_at_start);
    CHECK(sphere.crossings({{T(0), T(2), T(-5)}, {T(0), T(0), T(1)}}, Interval<T>::universe()).empty()); // miss
    // Exactly tangent: a double root is a touch, not a crossing.
    const auto tangent = sphere.crossings({{T(1), T(0), T(-5)}, {T(0), T(0), T(1)}}, Interval<T>::universe());
    CHECK(tangent.empty());
    CHECK_FALSE(tangent.inside_at_start);
}

TEST_CASE_TEMPLATE("grazing rays: both crossings found, in order, close to the exact roots", T, float, double)
{
    const Sphere<T> sphere({T(0), T(0), T(0)}, T(1));
    for (double miss : {1e-1, 1e-3, 1e-5}) {
        // A ray at distance 1 - miss from the centre: roots at -+ sqrt(1 - (1 - miss)^2) about z = 0.
        const T y = T(1 - miss);
        const auto c = sphere.crossings({{T(0), y, T(-10)}, {T(0), T(0), T(1)}}, Interval<T>::universe());
        const double half_chord = std::sqrt(1 - double(y) * double(y));
        if (half_chord < 1e-6) continue; // the chord is below float resolution at this y
        REQUIRE(c.size() == 2);
        CHECK(c[0].t < c[1].t);
        CHECK(std::abs(c[0].t - (10 - half_chord)) < 1e-5 * 10 + 1e-3 * half_chord);
    }
}

TEST_CASE_TEMPLATE("the refined point lies within its error bound of the true surface", T, float, double)
{
    prism::Random rng(11u, 2u);
    for (double distance : {1.0, 1e3, 1e5}) {
        const Sphere<T> sphere({T(distance), T(-distance / 2), T(distance / 3)}, T(1.5));
        for (int i = 0; i < 2000; ++i) {
            const Vec3<T> o = sphere.center() + test::random_direction<T>(rng) * T(4);
            const Vec3<T> target = sphere.center() + test::random_point<T>(rng, T(1));
            const auto c = sphere.crossings({o, prism::normalize(target - o)}, Interval<T>::universe());
            for (const auto& x : c) {
                // Distance from the surface, in long double.
                long double r2 = 0;
                for (int k = 0; k < 3; ++k) {
                    const long double q = (long double)x.point[k] - (long double)sphere.center()[k];
                    r2 += q * q;
                }
                const long double off = std::abs(std::sqrt(r2) - 1.5L);
                const long double bound = prism::dot(prism::abs(x.normal), x.error) + 1e-30L;
                CHECK(off <= bound * 1.0001L);
            }
        }
    }
}

TEST_CASE_TEMPLATE("a ray leaving a sphere never hits it again (TestReintersectConvex)", T, float, double)
{
    prism::Random rng(5u, 9u);
    for (double distance : {1.0, 1e3, 1e4, 1e5}) {
        INFO("distance from origin " << distance);
        CHECK(test::reintersections(rng, 4000, [&](prism::Random& r) {
                  const Vec3<T> centre = test::random_point<T>(r, T(distance));
                  const T radius = T(0.1) + T(2) * r.uniform<T>();
                  return std::pair{Sphere<T>(centre, radius), centre + test::random_point<T>(r, radius * T(0.5))};
              }) == 0);
    }
}

TEST_CASE("bad input names the parameter")
{
    CHECK_THROWS_WITH_AS(Sphere<float>({0, 0, 0}, -1.0f), doctest::Contains("Sphere radius"), std::invalid_argument);
    CHECK_THROWS_AS(Sphere<float>({0, 0, 0}, 0.0f), std::invalid_argument);
    CHECK_THROWS_AS(Sphere<double>({0, 0, 0}, std::nan("")), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Sphere<float>({0, std::numeric_limits<float>::infinity(), 0}, 1.0f),
                         doctest::Contains("Sphere center"), std::invalid_argument);
}

TEST_CASE("radii whose square would underflow or overflow are refused by name")
{
    using prism::infinity;
    // Regression: radius 1e20 was not hit from inside (r^2 overflows float), 1e-30 not at all.
    CHECK_THROWS_WITH_AS(Sphere<float>({0, 0, 0}, 1e20f), doctest::Contains("Sphere radius"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Sphere<float>({0, 0, 0}, 1e-30f), doctest::Contains("Sphere radius"), std::invalid_argument);
    // The limits themselves work, from inside and from outside.
    for (const float r : {2e-18f, 1e18f}) {
        const Sphere<float> s({0, 0, 0}, r);
        const auto inside = s.crossings({{0, 0, 0}, {0, 0, 1}}, {0, infinity<float>});
        REQUIRE(inside.size() == 1);
        CHECK(inside[0].t == doctest::Approx(r));
        const auto outside = s.crossings({{0, 0, -3 * r}, {0, 0, 1}}, {0, infinity<float>});
        REQUIRE(outside.size() == 2);
        CHECK(outside[0].t == doctest::Approx(2 * r));
    }
    CHECK_NOTHROW(Sphere<double>({0, 0, 0}, 1e100));
}

TEST_CASE("a sphere's bounding sphere is its own (a hair larger); other shapes get their box's")
{
    const prism::Sphere<float> ball({1, 2, 3}, 2);
    const prism::BoundingSphere<float> own = prism::bounding_sphere(ball);
    CHECK(own.center == prism::Vec3<float>{1, 2, 3});
    CHECK(own.radius >= 2.0f);
    CHECK(own.radius < 2.0f * (1 + 1e-5f)); // the box's sphere would be sqrt(3) times larger
    const prism::Box<float> box({0, 0, 0}, {2, 2, 2});
    const prism::BoundingSphere<float> around = prism::bounding_sphere(box);
    CHECK(around.radius >= std::sqrt(3.0f));
    CHECK(prism::length(around.center - prism::Vec3<float>{1, 1, 1}) < 1e-5f);
}

// Regression: the float sphere took its closest approach at t = h / a in float, an ulp of
// the distance off the true one, which |l|^2 counts squared: rays within 10^-6 of its
// rim (in r^2 - |l|^2) were lost from 10^4.
TEST_CASE("a float sphere seen from 10^4 loses no hit and gains none against its double evaluation")
{
    prism::Random rng(33u, 11u);
    test::Disagreements total;
    for (const double where : {0.0, 1e3, 1e4})
        for (int shape = 0; shape < 100; ++shape) {
            const Vec3<double> c = where * test::random_direction<double>(rng);
            const Vec3<float> centre(c);
            const auto radius = float(0.4 + 0.6 * rng.uniform<double>());
            Sphere<float> sphere(centre, radius);
            test::through_memory(sphere); // the twin from the float sphere's own numbers (see test::through_memory)
            const Sphere<double> twin{Vec3<double>(sphere.center()), double(sphere.radius())};
            const test::Disagreements d = test::far_disagreements(sphere, twin, Vec3<double>(sphere.center()), 1.0, 1e4, 1000, rng);
            total.lost += d.lost, total.phantom += d.phantom, total.hits += d.hits;
        }
    MESSAGE(total.hits, " hits of 300000 rays: lost ", total.lost, ", phantom ", total.phantom);
    CHECK(total.hits > 100000);
    CHECK(total.lost == 0);
    CHECK(total.phantom == 0);
}

TEST_CASE("a sphere's points seen from a point follow the density they report (chi-square): its cone from outside, its area from inside")
{
    const prism::Sphere<double> s({0.2, 0.1, -0.3}, 0.5);
    for (const prism::Vec3<double>& p : {prism::Vec3<double>(0, 0, 3), prism::Vec3<double>(0.2, 0.1, 0.21), prism::Vec3<double>(0, 0, 0),
                                         prism::Vec3<double>(40, 0, 0)}) {
        const test::Chi2 c = test::chi2_directions(
            [&](double u, double v) { return prism::normalize(s.sample_from(p, {u, v}).point - p); },
            [&](const prism::Vec3<double>& w) {
                const auto x = s.crossings({p, w}, {0.0, prism::infinity<double>});
                return x.empty() ? 0.0 : s.pdf_from(p, x[0].point);
            },
            prism::normalize(s.center() - p), 400000, 40, 40, 8, test::cone_around(p, s.center(), s.radius()));
        MESSAGE("from (", p.x, ", ", p.y, ", ", p.z, "): chi2 ", c.statistic, " with ", c.degrees, " degrees, p = ", c.p_value, ", missing ",
                c.missing / 400000);
        CHECK(c.p_value > 1e-3);
        CHECK(std::abs(c.missing) < 4e-3 * 400000);
    }
    // Each point drawn is on the sphere and faces the point it was drawn for.
    prism::Random rng(3, 4);
    for (int i = 0; i < 100000; ++i) {
        const prism::Vec3<double> p = prism::Vec3<double>(0.2, 0.1, -0.3) + (0.6 + 100 * rng.uniform<double>()) * test::random_direction<double>(rng);
        const auto x = s.sample_from(p, {rng.uniform<double>(), rng.uniform<double>()});
        CHECK(std::abs(prism::length(x.point - s.center()) - 0.5) < 1e-12);
        CHECK(prism::dot(x.normal, p - x.point) >= -1e-9);
    }
}

TEST_CASE("a sphere's surface coordinates: u round the vertical from +z, v from the bottom; dp/du and dp/dv by finite differences")
{
    const Sphere<double> sphere({1, 2, 3}, 2);
    const auto uv_seen = [&](Vec3<double> toward) {
        const auto c = sphere.crossings({Vec3<double>{1, 2, 3} + 10.0 * toward, -toward}, {0, prism::infinity<double>});
        REQUIRE(c.size() == 2);
        prism::Crossing<double> first = c.front();
        sphere.coordinates(first);
        return first.uv;
    };
    // The definitions (docs/guide.md): u = 1/4 at +x, 1/2 at -z, 3/4 at -x; v = 1/2 on the equator.
    CHECK(uv_seen({1, 0, 0}).x == doctest::Approx(0.25));
    CHECK(uv_seen({0, 0, -1}).x == doctest::Approx(0.5));
    CHECK(uv_seen({-1, 0, 0}).x == doctest::Approx(0.75));
    CHECK(uv_seen({1, 0, 0}).y == doctest::Approx(0.5));
    CHECK(uv_seen(normalize(Vec3<double>{0, 1, -1})).y == doctest::Approx(0.75)); // 45 degrees above the equator
    CHECK(uv_seen({0, -1, 0}).y == doctest::Approx(0).epsilon(1e-12));
    CHECK(uv_seen({0, 1, 0}).y == doctest::Approx(1));
    // Away from the seam (+z, u = 0 | 1) and the poles.
    const auto found = uv_checks::check_derivatives(sphere, {1, 2, 3}, 2.0, 4000, [](const prism::Crossing<double>& c) {
        return c.uv.x < 0.01 || c.uv.x > 0.99 || c.uv.y < 0.02 || c.uv.y > 0.98;
    });
    CHECK(found.checked > 2000);
    CHECK(found.worst < 1e-3);
    CHECK(found.left_handed == 0);
}
