// SPDX-License-Identifier: MIT
#include <prism/core/random.hpp>
#include <prism/medium/density.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace prism;

namespace {

/// The points of an nx x ny x nz lattice_of over `box` set to f(point), x fastest.
template <class F>
std::vector<float> lattice_of(int nx, int ny, int nz, const Aabb<float>& box, F f)
{
    std::vector<float> values;
    for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                const Vec3<float> u(float(x) / float(nx - 1), float(y) / float(ny - 1), float(z) / float(nz - 1));
                values.push_back(f(box.lo + u * (box.hi - box.lo)));
            }
    return values;
}

Vec3<float> uniform_in_box(const Aabb<float>& box, Random& rng)
{
    return box.lo + Vec3<float>(rng.uniform<float>(), rng.uniform<float>(), rng.uniform<float>()) * (box.hi - box.lo);
}

} // namespace

TEST_CASE("a DensityGrid reproduces a linear field exactly (trilinear interpolation does), and is 0 outside its box")
{
    const Aabb<float> box{{-1, 0, 2}, {3, 1, 4}};
    const auto linear = [](const Vec3<float>& p) { return 2.0f + 0.5f * p.x - 0.7f * p.y + 0.25f * p.z; };
    const DensityGrid<float> grid(5, 3, 7, box, lattice_of(5, 3, 7, box, linear));
    Random rng(3, 4);
    double worst = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3<float> p = uniform_in_box(box, rng);
        worst = std::max(worst, double(std::abs(grid.density(p) - linear(p))));
    }
    CHECK(worst < 2e-6);
    CHECK(grid.density({-1.001f, 0.5f, 3}) == 0.0f);
    CHECK(grid.density({0, 1.001f, 3}) == 0.0f);
    CHECK(grid.density({0, 0.5f, 4.01f}) == 0.0f);
    CHECK(grid.density(box.hi) == doctest::Approx(linear(box.hi)));
    CHECK(grid.points(0) == 5);
    CHECK(grid.points(2) == 7);
}

TEST_CASE("a DensityGrid's max_over bounds the density at every point of any box, and is its greatest lattice_of value over the whole box")
{
    const Aabb<float> box{{0, 0, 0}, {1, 2, 1}};
    Random values_rng(8, 1);
    const DensityGrid<float> grid(6, 9, 4, box, lattice_of(6, 9, 4, box, [&](const Vec3<float>&) { return 3 * values_rng.uniform<float>(); }));
    float most = 0;
    for (float v : grid.values()) most = std::max(most, v);
    CHECK(grid.max_over(box) == most);
    CHECK(grid.max_over(Aabb<float>::universe()) == most);
    CHECK(grid.max_over({{2, 2, 2}, {3, 3, 3}}) == 0.0f); // outside
    Random rng(9, 9);
    int broken = 0;
    for (int b = 0; b < 2000; ++b) {
        const Vec3<float> a = uniform_in_box({{-0.2f, -0.2f, -0.2f}, {1.2f, 2.2f, 1.2f}}, rng), c = uniform_in_box({{-0.2f, -0.2f, -0.2f}, {1.2f, 2.2f, 1.2f}}, rng);
        const Aabb<float> region{component_min(a, c), component_max(a, c)};
        const float bound = grid.max_over(region);
        for (int i = 0; i < 50; ++i)
            if (grid.density(uniform_in_box(region, rng)) > bound) ++broken;
    }
    CHECK(broken == 0);
}

TEST_CASE("a DensityGrid refuses, naming it, too few points, the wrong number of values, a negative or non-finite value, and a bad box")
{
    const Aabb<float> box{{0, 0, 0}, {1, 1, 1}};
    const auto message = [&](int nx, int ny, int nz, const Aabb<float>& b, std::vector<float> v) {
        try {
            (void)DensityGrid<float>(nx, ny, nz, b, std::move(v));
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK(message(1, 2, 2, box, std::vector<float>(4, 1.0f)).find("at least 2 points") != std::string::npos);
    CHECK(message(2, 2, 2, box, std::vector<float>(7, 1.0f)).find("needs 8 values, got 7") != std::string::npos);
    std::vector<float> negative(8, 1.0f);
    negative[5] = -0.5f;
    CHECK(message(2, 2, 2, box, negative).find("value 5 (x 1, y 0, z 1)") != std::string::npos);
    std::vector<float> nan(8, 1.0f);
    nan[2] = std::nanf("");
    CHECK(message(2, 2, 2, box, nan).find("value 2") != std::string::npos);
    CHECK(message(2, 2, 2, {{0, 0, 0}, {1, 0, 1}}, std::vector<float>(8, 1.0f)).find("box") != std::string::npos);
    CHECK(message(2, 2, 2, Aabb<float>::universe(), std::vector<float>(8, 1.0f)).find("box") != std::string::npos);
    CHECK(message(2, 2, 2, box, std::vector<float>(8, 1.0f)) == "accepted");
    // Regression: a box so thin that its lattice's spacing is not a float (points per
    // unit length infinite) turned a NaN into an int at every lookup; one so wide that
    // hi - lo overflows put every point in the first cell.
    const std::string thin = message(3, 2, 2, {{0, 0, 0}, {1e-44f, 1, 1}}, std::vector<float>(12, 1.0f));
    CHECK(thin.find("DensityGrid box is too small or too large for its 3 x 2 x 2 points on axis 0") != std::string::npos);
    CHECK(message(2, 2, 2, {{0, -3e38f, 0}, {1, 3e38f, 1}}, std::vector<float>(8, 1.0f)).find("on axis 1") != std::string::npos);
    CHECK(message(2, 2, 2, {{0, 0, 0}, {1e-30f, 1e-30f, 1e-30f}}, std::vector<float>(8, 1.0f)) == "accepted");
}

TEST_CASE("HeightFog: base e^{-(y - floor) / H} in its box, 0 outside; max_over bounds it on any box; bad parameters refused")
{
    const HeightFog<double> fog{.box = {{-1, -1, -1}, {1, 3, 1}}, .floor = 0.5, .base = 2, .scale_height = 0.7};
    CHECK(fog.density({0, 0.5, 0}) == doctest::Approx(2));
    CHECK(fog.density({0.3, 1.9, -0.2}) == doctest::Approx(2 * std::exp(-1.4 / 0.7)));
    CHECK(fog.density({0, 3.1, 0}) == 0);
    CHECK(fog.max_over({{-5, 1, -5}, {5, 2, 5}}) >= fog.density({0, 1, 0}));
    CHECK(fog.max_over({{-5, -9, -5}, {5, 9, 5}}) >= fog.density({0, -1, 0}));
    CHECK(fog.max_over({{-5, 4, -5}, {5, 9, 5}}) == 0);
    CHECK_NOTHROW(fog.validate());
    auto bad = fog;
    bad.scale_height = 0;
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("HeightFog scale_height"), std::invalid_argument);
    bad = fog;
    bad.base = -1;
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("HeightFog base"), std::invalid_argument);
    bad = fog;
    bad.box = Aabb<double>::universe();
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("HeightFog box"), std::invalid_argument);
}
