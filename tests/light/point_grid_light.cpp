// SPDX-License-Identifier: MIT
#include <prism/light/point_grid_light.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace prism;

namespace {

/// A 3 x 3 grid, 2 x 2 wide, around (0, 4, 0): points at x and z in {-1, 0, 1}.
PointGridLight<double> grid_light(int adaptive)
{
    return {.light = {.position = {0, 4, 0}, .intensity = Rgb<double>(pi<double>), .falloff = Falloff::none},
            .axis1 = {2, 0, 0}, .axis2 = {0, 0, 2}, .size1 = 3, .size2 = 3, .adaptive = adaptive};
}

} // namespace

TEST_CASE("POV-Ray's area_light: the grid's shadow is its recursive mean of corners, each point traced once")
{
    // The points with x = -1 (u = 0) are blocked. POV-Ray splits the 3 x 3 grid into four
    // cells, each the mean of its corners: (0 + 1 + 0 + 1) / 4, 1, 1/2, 1, so 3/4 (not the
    // plain mean over the points, 6/9).
    std::vector<Vec3<double>> traced;
    const auto through = [&](const Vec3<double>& p) {
        traced.push_back(p);
        return Rgb<double>(p.x < -0.5 ? 0.0 : 1.0);
    };
    const PointGridLight<double> full = grid_light(100);
    CHECK(full.shadow(through, Rgb<double>(1), nullptr).x == doctest::Approx(0.75).epsilon(1e-15));
    REQUIRE(traced.size() == 9);
    std::set<std::pair<double, double>> points;
    for (const Vec3<double>& p : traced) {
        CHECK(p.y == 4);
        points.insert({p.x, p.z});
    }
    CHECK(points.size() == 9); // each of the grid's points, once, the corners on the rectangle's corners
    CHECK(points.count({-1.0, -1.0}) == 1);
    CHECK(points.count({1.0, 1.0}) == 1);
    // adaptive 0: corners that agree end the recursion (4 rays) ...
    traced.clear();
    const auto open = [&](const Vec3<double>& p) {
        traced.push_back(p);
        return Rgb<double>(1);
    };
    CHECK(grid_light(0).shadow(open, Rgb<double>(1), nullptr).x == 1);
    CHECK(traced.size() == 4);
    // ... corners that differ by more than 0.1 in the light's colour split it ...
    traced.clear();
    CHECK(grid_light(0).shadow(through, Rgb<double>(1), nullptr).x == doctest::Approx(0.75).epsilon(1e-15));
    CHECK(traced.size() == 9);
    // ... and by less do not: a dim light's difference of 0.09 is below POV-Ray's 0.1.
    traced.clear();
    CHECK(grid_light(0).shadow(through, Rgb<double>(0.03), nullptr).x == doctest::Approx(0.5).epsilon(1e-15));
    CHECK(traced.size() == 4);
    // A 5 x 1 grid: the middle point is shared by both halves (floor and ceil of the
    // midpoint 2), as POV-Ray splits; blocked at u = 4 only: ((1 + 1) / 2 + ((1 + 1) / 2 + (1 + 0) / 2) / 2) / 2 = 0.875.
    const PointGridLight<double> row{.light = grid_light(100).light, .axis1 = {4, 0, 0}, .axis2 = {0, 0, 1}, .size1 = 5, .size2 = 1};
    CHECK(row.shadow([](const Vec3<double>& p) { return Rgb<double>(p.x > 1.5 ? 0.0 : 1.0); }, Rgb<double>(1), nullptr).x ==
          doctest::Approx(0.875).epsilon(1e-15));
}

TEST_CASE("POV-Ray's area_light with jitter moves each point by at most half a cell, at random")
{
    PointGridLight<double> light = grid_light(100);
    light.jitter = true;
    Random rng(3, 4);
    double largest = 0, sum = 0;
    int count = 0;
    for (int k = 0; k < 2000; ++k)
        (void)light.shadow(
            [&](const Vec3<double>& p) {
                // Each point lies within half a cell (0.5 of the 1-unit spacing) of a grid point.
                const double dx = p.x - std::round(p.x), dz = p.z - std::round(p.z);
                largest = std::max({largest, std::abs(dx), std::abs(dz)});
                sum += dx;
                ++count;
                return Rgb<double>(1);
            },
            Rgb<double>(1), &rng);
    CHECK(largest <= 0.5);
    CHECK(largest > 0.49);
    CHECK(std::abs(sum / count) < 0.01);
}

TEST_CASE("a floor under POV-Ray's area_light is shaded from its centre and shadowed by the share of its grid it sees")
{
    // A plate at height 2 over x in [-1, -0.25] hides from the floor's origin the grid
    // points at x = -1 (the ray to x_l crosses height 2 at x_l / 2), so the shadow is 3/4;
    // the light, colour 1 and no falloff (pi c, POV-Ray's kind), straight above.
    const PointGridLight<float> light{.light = {.position = {0, 4, 0}, .intensity = Rgb<float>(pi<float>), .falloff = Falloff::none},
                                      .axis1 = {2, 0, 0}, .axis2 = {0, 0, 2}, .size1 = 3, .size2 = 3};
    const Scene scene{Lights{light}, Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                      Object{Box<float>({-1, 1.95f, -3}, {-0.25f, 2.05f, 3}), Diffuse<float>{}}};
    Random rng(1, 1);
    const Ray<float> down{{0, 1, 0}, {0, -1, 0}};
    CHECK(Whitted(scene).radiance(down, rng).x == doctest::Approx(0.5 * 0.75).epsilon(1e-5));
    // Moved right, the floor sees every point: 1/2.
    const Ray<float> right{{2, 1, 0}, {0, -1, 0}};
    const double cos = 4 / std::sqrt(4.0 * 4.0 + 2.0 * 2.0);
    CHECK(Whitted(scene).radiance(right, rng).x == doctest::Approx(0.5 * cos).epsilon(1e-5));
}

TEST_CASE("POV-Ray's area_light refuses a grid it cannot trace, naming the parameter")
{
    const auto message = [](PointGridLight<float> light) {
        try {
            light.validate();
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK(message({}) == "accepted");
    CHECK(message({.size1 = 0}) == "prism: PointGridLight size1 and size2 must be >= 1, got 0 x 2");
    CHECK(message({.size1 = 33, .size2 = 32}) == "prism: PointGridLight grid of 33 x 32 has more than 1024 points");
    CHECK(message({.adaptive = -1}) == "prism: PointGridLight adaptive must be >= 0, got -1");
    CHECK(message({.axis1 = {NAN, 0, 0}}).find("PointGridLight axis1 must be finite") != std::string::npos);
    CHECK(message({.light = {.intensity = Rgb<float>(-1)}}).find("PointLight intensity") != std::string::npos);
}
