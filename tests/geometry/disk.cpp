// SPDX-License-Identifier: MIT
#include <prism/geometry/disk.hpp>

#include "../chi2.hpp"
#include "../support.hpp"
#include "../uv_checks.hpp"

using prism::Disk;
using prism::Vec3;

TEST_CASE_TEMPLATE("a disk is crossed inside its radius, entering on its normal's side", T, float, double)
{
    const Disk<T> d({T(1), T(2), T(3)}, {T(0), T(0), T(-2)}, T(0.5));
    CHECK(d.normal().z == T(-1));
    CHECK(d.area() == doctest::Approx(prism::pi<double> * 0.25));
    const auto front = d.crossings({{T(1.3), T(2), T(0)}, {T(0), T(0), T(1)}}, {T(0), prism::infinity<T>});
    REQUIRE(front.size() == 1);
    CHECK(front[0].t == doctest::Approx(3));
    CHECK(front[0].entering);
    prism::Crossing<T> at = front[0];
    CHECK_FALSE(at.has_uv()); // added where a material reads them
    d.coordinates(at);
    CHECK(at.uv.x == doctest::Approx(0.6));
    CHECK(d.crossings({{T(1.6), T(2), T(0)}, {T(0), T(0), T(1)}}, {T(0), prism::infinity<T>}).empty());
    const auto back = d.crossings({{T(1), T(2.4), T(5)}, {T(0), T(0), T(-1)}}, {T(0), prism::infinity<T>});
    REQUIRE(back.size() == 1);
    CHECK_FALSE(back[0].entering);
    // Its box holds its rim, tilted or not.
    const Disk<T> tilted({T(0), T(0), T(0)}, {T(1), T(1), T(0)}, T(2));
    prism::Random rng(1, 1);
    for (int i = 0; i < 1000; ++i) {
        const auto p = tilted.sample_area({T(1), rng.uniform<T>()}).point; // on the rim
        CHECK(tilted.bounds().contains(p));
    }
    CHECK_THROWS_WITH_AS(Disk<T>({T(0), T(0), T(0)}, {T(0), T(0), T(0)}, T(1)), doctest::Contains("Disk normal"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Disk<T>({T(0), T(0), T(0)}, {T(0), T(1), T(0)}, T(-1)), doctest::Contains("Disk radius"), std::invalid_argument);
}

TEST_CASE("a disk's points by area, seen from a point, follow the density they report (chi-square)")
{
    const Disk<double> d({0, 1, 0}, {0, -1, 0}, 0.4);
    for (const Vec3<double>& p : {Vec3<double>(0, 0, 0), Vec3<double>(1, 0.5, 0.3), Vec3<double>(0, 3, 0)}) {
        const test::Chi2 c = test::chi2_directions(
            [&](double u, double v) { return prism::normalize(prism::sample_toward(d, p, {u, v}).point - p); },
            [&](const Vec3<double>& w) {
                const auto x = d.crossings({p, w}, {0.0, prism::infinity<double>});
                return x.empty() ? 0.0 : prism::pdf_toward(d, p, x[0].point, x[0].normal);
            },
            prism::normalize(d.center() - p), 400000, 40, 40, 8, test::cone_around(p, d.center(), d.radius()));
        MESSAGE("from (", p.x, ", ", p.y, ", ", p.z, "): chi2 ", c.statistic, " with ", c.degrees, " degrees, p = ", c.p_value);
        CHECK(c.p_value > 1e-3);
        CHECK(std::abs(c.missing) < 4e-3 * 400000);
    }
}

TEST_CASE("a disk's surface coordinates are polar (distance over radius, angle over 2 pi): dp/du and dp/dv by finite differences")
{
    const Disk<double> disk({1, 0, 2}, normalize(Vec3<double>{0.2, 1, -0.3}), 1.5);
    const auto found = uv_checks::check_derivatives(disk, {1, 0, 2}, 1.5, 3000, [](const auto& c) { return c.uv.x < 0.05 || c.uv.y < 0.01 || c.uv.y > 0.99; });
    CHECK(found.checked > 500);
    CHECK(found.worst < 1e-3);
    CHECK(found.left_handed == 0);
}
