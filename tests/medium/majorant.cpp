// SPDX-License-Identifier: MIT
#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>
#include <prism/medium/majorant.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace prism;

TEST_CASE("the majorant grid's traversal covers a ray's part in the box once, in order, and every cell's bound and floor hold at every point of its stretch inside the box")
{
    // A field that varies fast (random values on an 11^3 lattice), 7 majorant cells a
    // side so that cells and lattice do not line up; rays from inside and outside, some
    // along the axes and on the box's faces; 1000 points checked on each stretch.
    const Aabb<float> box{{-1, -2, 0}, {2, 1, 1}};
    Random values_rng(4, 4);
    std::vector<float> values(11 * 11 * 11);
    for (float& v : values) v = values_rng.uniform<float>() < 0.3f ? 0.0f : 5 * values_rng.uniform<float>();
    const DensityGrid<float> field(11, 11, 11, box, values);
    const MajorantGrid<float> grid(field, 7);
    CHECK(grid.cells() == 7);
    Random rng(1, 2);
    int gaps = 0, backwards = 0, broken = 0, rays_inside = 0;
    for (int r = 0; r < 3000; ++r) {
        Ray<float> ray{Vec3<float>(-3 + 7 * rng.uniform<float>(), -4 + 7 * rng.uniform<float>(), -1 + 3 * rng.uniform<float>()), uniform_sphere<float>(rng)};
        if (r % 10 == 0) ray.direction = Vec3<float>(0, 0, 0), ray.direction[r / 10 % 3] = r % 20 == 0 ? 1.0f : -1.0f;
        if (r % 50 == 0) ray.origin.x = box.lo.x; // on a face
        const Interval<float> span = box.clip(ray, {0, infinity<float>});
        float last = span.empty() ? 0.0f : span.min;
        bool any = false;
        grid.traverse(ray, 0.0f, infinity<float>, [&](float a, float b, const MajorantGrid<float>::Range& range) {
            any = true;
            if (a != last) ++gaps;
            if (b < a) ++backwards;
            for (int i = 0; i < 1000; ++i)
                {
                const float d = field.density(ray.at(a + (b - a) * (float(i) + 0.5f) / 1000));
                if (d > range.bound || (d < range.floor && d > 0)) ++broken;
            }
            last = b;
            return true;
        });
        if (!span.empty()) {
            CHECK(any);
            CHECK(last == doctest::Approx(span.max).epsilon(1e-5)); // (the last cell's far side by the traversal's rounding)
            rays_inside += 1;
        }
    }
    CHECK(gaps == 0);
    CHECK(backwards == 0);
    CHECK(broken == 0);
    CHECK(rays_inside > 300);
}

TEST_CASE("the majorant grid stops when asked, keeps to [t0, t1], and refuses a cell count outside [1, 256]")
{
    const Aabb<double> box{{0, 0, 0}, {1, 1, 1}};
    const HeightFog<double> fog{.box = box, .scale_height = 0.25};
    const MajorantGrid<double> one(fog, 1);
    int calls = 0;
    one.traverse(Ray<double>{{-1, 0.5, 0.5}, {1, 0, 0}}, 0.0, 10.0, [&](double a, double b, const MajorantGrid<double>::Range& range) {
        ++calls;
        CHECK(a == doctest::Approx(1));
        CHECK(b == doctest::Approx(2));
        CHECK(range.bound >= 1);
        CHECK(range.floor == doctest::Approx(std::exp(-4.0)));
        return true;
    });
    CHECK(calls == 1);
    const MajorantGrid<double> many(fog, 16);
    calls = 0;
    many.traverse(Ray<double>{{0.5, -1, 0.5}, {0, 1, 0}}, 1.2, 1.7, [&](double a, double b, const MajorantGrid<double>::Range& range) {
        ++calls;
        CHECK(a >= 1.2);
        CHECK(b <= 1.7);
        CHECK(range.bound >= fog.density({0.5, a - 1, 0.5}));
        CHECK(range.floor <= fog.density({0.5, b - 1, 0.5}));
        return calls < 3;
    });
    CHECK(calls == 3);
    int none = 0;
    many.traverse(Ray<double>{{0.5, -1, 0.5}, {0, -1, 0}}, 0.0, infinity<double>, [&](double, double, const MajorantGrid<double>::Range&) { return ++none, true; });
    CHECK(none == 0);
    CHECK_THROWS_WITH_AS(MajorantGrid<double>(fog, 0), doctest::Contains("cells must be in [1, 256], got 0"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(MajorantGrid<double>(fog, 257), doctest::Contains("got 257"), std::invalid_argument);
}
