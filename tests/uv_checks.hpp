// SPDX-License-Identifier: MIT
// Surface coordinates checked from outside a shape's own formulas: dp/du and dp/dv by
// finite differences (step along each, find the surface again by a ray, read its uv),
// and their orientation against the outward normal.
#pragma once

#include "support.hpp"

#include <prism/geometry/shape.hpp>

#include <doctest/doctest.h>

#include <cmath>

namespace uv_checks {

/// What check_derivatives found: how many crossings it checked, and the largest error of
/// a finite-difference derivative (in uv per uv step, relative to 1).
struct Found {
    int checked = 0;
    double worst = 0;
    int left_handed = 0;
};

/// For `rays` random rays aimed within `radius` of `centre` at `shape`: at its first
/// crossing with coordinates, step h along dp/du (then dp/dv) over |dp/du|^2, find the
/// surface again by a ray along the normal, and compare the change of uv with (1, 0)
/// (then (0, 1)). Crossings where `skip(crossing)` (a seam, a pole, an edge) are left out.
template <class S, class Skip>
Found check_derivatives(const S& shape, prism::Vec3<double> centre, double radius, int rays, Skip&& skip, double h = 1e-5)
{
    prism::Random rng(17, 5);
    Found found;
    for (int i = 0; i < rays; ++i) {
        const prism::Vec3<double> target = centre + radius * std::cbrt(rng.uniform<double>()) * test::random_direction<double>(rng);
        const prism::Vec3<double> origin = target + 4 * radius * test::random_direction<double>(rng);
        auto crossings = shape.crossings(prism::Ray<double>{origin, target - origin}, {1e-9, prism::infinity<double>});
        if (crossings.empty()) continue;
        prism::Crossing<double> c = crossings.front();
        prism::add_coordinates(shape, c);
        if (skip(c)) continue;
        if (!c.has_uv()) {
            found.worst = 1e9;
            continue;
        }
        if (dot(cross(c.dpdu, c.dpdv), c.normal) <= 0) ++found.left_handed;
        for (int axis = 0; axis < 2; ++axis) {
            const prism::Vec3<double> d = axis == 0 ? c.dpdu : c.dpdv;
            const double step = h * radius / length(d); // a step of h * radius in space
            const prism::Vec3<double> moved = c.point + step * d;
            const double lift = 1e-3 * radius;
            const auto again_list = shape.crossings(prism::Ray<double>{moved + lift * c.normal, -c.normal}, {0, 2 * lift});
            if (again_list.empty()) continue;
            prism::Crossing<double> again_c = again_list.front();
            prism::add_coordinates(shape, again_c);
            if (dot(again_c.normal, c.normal) < 0.99) continue; // off the face
            const prism::Vec2<double> change = (again_c.uv - c.uv) / step;
            const double error = std::max(std::abs(change.x - (axis == 0 ? 1 : 0)), std::abs(change.y - (axis == 0 ? 0 : 1)));
            found.worst = std::max(found.worst, error);
        }
        ++found.checked;
    }
    return found;
}

} // namespace uv_checks
