// SPDX-License-Identifier: MIT
#include <prism/geometry/quad.hpp>

#include "../chi2.hpp"
#include "../support.hpp"
#include "../uv_checks.hpp"

#include <string>

using prism::Interval;
using prism::Quad;
using prism::Vec2;
using prism::Vec3;

TEST_CASE_TEMPLATE("a quad is crossed where its plane is, inside its edges, entering on its normal's side", T, float, double)
{
    // The unit square at y = 1 facing down (edge_u x edge_v = x x z = (0, -1, 0)).
    const Quad<T> q({T(0), T(1), T(0)}, {T(1), T(0), T(0)}, {T(0), T(0), T(1)});
    CHECK(q.normal().y == T(-1));
    CHECK(q.area() == doctest::Approx(1));
    CHECK(q.rectangle());
    const auto up = q.crossings({{T(0.25), T(0), T(0.5)}, {T(0), T(1), T(0)}}, {T(0), prism::infinity<T>});
    REQUIRE(up.size() == 1);
    CHECK(up[0].t == doctest::Approx(1));
    CHECK(up[0].entering); // from below, the normal's side
    CHECK(up[0].point.y == T(1));
    CHECK(up[0].uv.x == doctest::Approx(0.25)); // s along edge_u (x)
    CHECK(up[0].uv.y == doctest::Approx(0.5));
    CHECK_FALSE(up.inside_at_start);
    const auto down = q.crossings({{T(0.25), T(2), T(0.5)}, {T(0), T(-1), T(0)}}, {T(0), prism::infinity<T>});
    REQUIRE(down.size() == 1);
    CHECK_FALSE(down[0].entering);
    CHECK(q.crossings({{T(1.25), T(0), T(0.5)}, {T(0), T(1), T(0)}}, {T(0), prism::infinity<T>}).empty());   // beside it
    CHECK(q.crossings({{T(0.25), T(0), T(0.5)}, {T(1), T(0), T(0)}}, {T(0), prism::infinity<T>}).empty());   // parallel
    CHECK(q.crossings({{T(0.25), T(0), T(0.5)}, {T(0), T(1), T(0)}}, {T(0), T(0.5)}).empty());               // short of it
    CHECK_FALSE(q.contains({T(0.5), T(1), T(0.5)}));
    const prism::Aabb<T> box = q.bounds();
    CHECK((box.lo.y <= T(1) && box.hi.y >= T(1) && box.lo.x <= T(0) && box.hi.z >= T(1)));
}

TEST_CASE("a quad's crossings against solving the plane and the edges in long double, over random parallelograms")
{
    prism::Random rng(34u, 1u);
    long hits = 0, disagreements = 0;
    for (int shape = 0; shape < 1000; ++shape) {
        const Vec3<double> corner = test::random_point<double>(rng, 2.0);
        const Vec3<double> eu = test::random_point<double>(rng, 1.5), ev = test::random_point<double>(rng, 1.5);
        const Quad<double> q(corner, eu, ev);
        for (int i = 0; i < 500; ++i) {
            const Vec3<double> o = test::random_point<double>(rng, 4.0), d = test::random_direction<double>(rng);
            const auto c = q.crossings({o, d}, {0.0, prism::infinity<double>});
            // o + t d = corner + s eu + r ev, by Cramer's rule in long double.
            using L = long double;
            const L m[3][3] = {{L(d.x), -L(eu.x), -L(ev.x)}, {L(d.y), -L(eu.y), -L(ev.y)}, {L(d.z), -L(eu.z), -L(ev.z)}};
            const L b[3] = {L(corner.x) - L(o.x), L(corner.y) - L(o.y), L(corner.z) - L(o.z)};
            const auto det3 = [](const L a[3][3]) {
                return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
            };
            const L det = det3(m);
            L x[3];
            for (int k = 0; k < 3; ++k) {
                L mk[3][3];
                for (int r = 0; r < 3; ++r)
                    for (int col = 0; col < 3; ++col) mk[r][col] = col == k ? b[r] : m[r][col];
                x[k] = det3(mk) / det;
            }
            // Away from the edges by 1e-9, where rounding cannot decide.
            const bool inside = x[0] > 0 && x[1] > 1e-9L && x[1] < 1 - 1e-9L && x[2] > 1e-9L && x[2] < 1 - 1e-9L;
            const bool near_edge = std::min({std::abs(x[1]), std::abs(1 - x[1]), std::abs(x[2]), std::abs(1 - x[2])}) <= 1e-9L;
            if (near_edge) continue;
            hits += inside;
            if (inside != (c.size() == 1)) ++disagreements;
            else if (inside) {
                CHECK(std::abs(c[0].t - double(x[0])) <= 1e-9 * std::max(1.0, double(x[0])));
                CHECK(c[0].entering == (prism::dot(d, q.normal()) < 0));
                CHECK(c[0].uv.x == doctest::Approx(double(x[1])).epsilon(1e-9));
            }
        }
    }
    MESSAGE(hits, " hits of 500000 rays");
    CHECK(hits > 2000);
    CHECK(disagreements == 0);
}

TEST_CASE("a quad refuses a degenerate or non-finite parallelogram, naming it")
{
    CHECK_THROWS_WITH_AS(Quad<float>({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), doctest::Contains("Quad edges"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Quad<float>({0, 0, 0}, {0, 0, 0}, {2, 0, 0}), doctest::Contains("Quad edge_u"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Quad<float>({NAN, 0, 0}, {1, 0, 0}, {0, 1, 0}), doctest::Contains("Quad corner"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Quad<float>({0, 0, 0}, {3e38f, 0, 0}, {0, 3e38f, 0}), doctest::Contains("finite, non-zero area"), std::invalid_argument);
}

namespace {

/// The solid angle of a quad from p by the midpoint rule over its area, cos / d^2 dA.
double solid_angle_by_area(const Quad<double>& q, const Vec3<double>& p, int n)
{
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3<double> x = q.corner() + (i + 0.5) / n * q.edge_u() + (j + 0.5) / n * q.edge_v();
            const Vec3<double> d = x - p;
            const double d2 = prism::length_squared(d);
            sum += std::abs(prism::dot(d, q.normal())) / (d2 * std::sqrt(d2));
        }
    return sum * q.area() / (double(n) * n);
}

/// The chi-square test of quad sampling from p, binned over the quad's own (s, t): the
/// points it draws against the density pdf_from reports, turned from per steradian to per
/// unit area (|cos| / d^2) and per unit of (s, t) (times the area).
test::Chi2 quad_chi2(const Quad<double>& q, const Vec3<double>& p, long samples)
{
    const auto st_of = [&](const Vec3<double>& x) {
        const auto c = q.crossings({p, x - p}, {0.5, 2.0});
        return c.empty() ? prism::Vec2<double>(-1) : c[0].uv;
    };
    return test::chi2_surface([&](double u, double v) { return st_of(q.sample_from(p, {u, v}).point); },
                              [&](double s, double t) {
                                  const Vec3<double> x = q.corner() + s * q.edge_u() + t * q.edge_v();
                                  const Vec3<double> d = x - p;
                                  const double d2 = prism::length_squared(d);
                                  return q.pdf_from(p, x) * std::abs(prism::dot(d, q.normal())) / (d2 * std::sqrt(d2)) * q.area();
                              },
                              samples);
}

} // namespace

TEST_CASE("a rectangle's solid angle, exact (Urena et al.) against the area integral, near and far")
{
    const Quad<double> r({-0.5, 1, -0.25}, {1, 0, 0}, {0, 0, 0.5});
    for (const Vec3<double>& p : {Vec3<double>(0, 0, 0), Vec3<double>(2, -1, 3), Vec3<double>(0.3, 0.9, 0.1), Vec3<double>(0, 30, 0)}) {
        const double exact = r.solid_angle(p), integral = solid_angle_by_area(r, p, 1000);
        CHECK_MESSAGE(exact == doctest::Approx(integral).epsilon(1e-4), "from ", p.x, " ", p.y, " ", p.z);
    }
    // A parallelogram: its two triangles' solid angles.
    const Quad<double> slanted({-0.5, 1, -0.25}, {1, 0, 0}, {0.5, 0.2, 0.5});
    CHECK_FALSE(slanted.rectangle());
    CHECK(slanted.solid_angle({0.1, -0.5, 0.3}) == doctest::Approx(solid_angle_by_area(slanted, {0.1, -0.5, 0.3}, 1000)).epsilon(1e-4));
}

TEST_CASE("a rectangle's solid angle in float, from nearly on it (2 pi) to far away: within 4e-6 sr (8 ulps of 2 pi) of the exact value")
{
    // On the axis through its centre, at height h, an a x b rectangle subtends
    // 4 asin(a b / sqrt((a^2 + 4 h^2) (b^2 + 4 h^2))).
    const double a = 1.3, b = 1.05;
    const Quad<float> r({-0.65f, 0, -0.525f}, {1.3f, 0, 0}, {0, 0, 1.05f});
    for (const double h : {1e-5, 1e-3, 0.1, 1.0, 10.0, 30.0}) {
        const double exact = 4 * std::asin(a * b / std::sqrt((a * a + 4 * h * h) * (b * b + 4 * h * h)));
        CHECK_MESSAGE(std::abs(double(r.solid_angle({0, float(-h), 0})) - exact) < 2e-6, "at height ", h, ": ", r.solid_angle({0, float(-h), 0}), " against ", exact);
    }
    // Anywhere, against the same rectangle in double (checked against the area integral
    // above). The worst is next to an edge, nearly in the plane: 2.95e-6 sr, as it was with
    // four normalised plane normals and four asin.
    const Quad<double> twin({-0.65, 0, -0.525}, {1.3, 0, 0}, {0, 0, 1.05});
    prism::Pcg32 rng(7, 1);
    double worst = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3<float> p(rng.uniform<float>() * 8 - 4, rng.uniform<float>() * 8 - 4, rng.uniform<float>() * 8 - 4);
        worst = std::max(worst, std::abs(double(r.solid_angle(p)) - twin.solid_angle(Vec3<double>(p))));
    }
    MESSAGE("largest difference from the double twin over 1e5 points: ", worst, " sr");
    CHECK(worst < 4e-6);
}

TEST_CASE("sampling a quad from a point follows the density it reports (chi-square): by spherical rectangle and by area")
{
    const Quad<double> r({-0.5, 1, -0.25}, {1, 0, 0}, {0, 0, 0.5});
    // Close under it (a wide rectangle), off to the side, nearly edge-on, from behind, and
    // far enough that it is sampled by area.
    for (const Vec3<double>& p : {Vec3<double>(0, 0.7, 0), Vec3<double>(2, -1, 3), Vec3<double>(0, 0.9, 1.5), Vec3<double>(0.1, 0.999, 0.5), Vec3<double>(0.2, 1.5, 0.1),
                                  Vec3<double>(0, 60, 0)}) {
        const bool by_area = r.solid_angle(p) <= Quad<double>::min_solid_angle;
        const test::Chi2 c = quad_chi2(r, p, 400000);
        MESSAGE("from (", p.x, ", ", p.y, ", ", p.z, ")", std::string(by_area ? " by area" : ""), ": chi2 ", c.statistic, " with ", c.degrees,
                " degrees, p = ", c.p_value, ", missing mass ", c.missing / 400000);
        CHECK(c.p_value > 1e-3);
        CHECK(std::abs(c.missing) < 1e-3 * 400000);
    }
    const Quad<double> slanted({-0.5, 1, -0.25}, {1, 0, 0}, {0.5, 0.2, 0.5});
    CHECK_FALSE(slanted.rectangle());
    const test::Chi2 c = quad_chi2(slanted, {0.1, -0.5, 0.3}, 400000);
    MESSAGE("a parallelogram, by area: chi2 ", c.statistic, ", p = ", c.p_value);
    CHECK(c.p_value > 1e-3);
    // A grazing view (3.8 degrees), where binning by direction fails on the light's edges.
    const test::Chi2 grazing = quad_chi2(r, {0, 0.98, 3}, 400000);
    MESSAGE("seen at a grazing 0.4 degrees: chi2 ", grazing.statistic, ", p = ", grazing.p_value);
    CHECK(grazing.p_value > 1e-3);
}

TEST_CASE("a rectangle's points by solid angle stay on it, with its normal")
{
    const Quad<float> r({-0.5f, 1, -0.25f}, {1, 0, 0}, {0, 0, 0.5f});
    prism::Random rng(2, 3);
    for (int i = 0; i < 100000; ++i) {
        const Vec3<float> p = test::random_point<float>(rng, 3.0f);
        const auto s = r.sample_from(p, {rng.uniform<float>(), rng.uniform<float>()});
        REQUIRE(prism::is_finite(s.point));
        CHECK(std::abs(s.point.y - 1) < 1e-5f);
        CHECK((s.point.x >= -0.5f - 1e-5f && s.point.x <= 0.5f + 1e-5f && s.point.z >= -0.25f - 1e-5f && s.point.z <= 0.25f + 1e-5f));
        CHECK(s.pdf > 0);
    }
}

TEST_CASE("a quad's surface coordinates (s, t) move with its edges: dp/du = edge u, dp/dv = edge v")
{
    const Quad<double> quad({0, 1, 0}, {2, 0, 0.5}, {0.3, 0, -1});
    const auto found = uv_checks::check_derivatives(quad, {1, 1, 0}, 1.0, 3000, [](const auto&) { return false; });
    CHECK(found.checked > 500);
    CHECK(found.worst < 1e-6);
}
