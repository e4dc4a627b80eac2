// SPDX-License-Identifier: MIT
#include <prism/geometry/crossings.hpp>
#include <prism/geometry/shape.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

// Capacities are part of the type.
static_assert(prism::Sphere<float>::max_crossings == 2 && prism::Plane<float>::max_crossings == 1);
static_assert(prism::Crossings<double, 4>::capacity == 4);
static_assert(!prism::Shape<int>);

TEST_CASE("Crossings keeps its items in order")
{
    prism::Crossings<float, 3> list;
    CHECK(list.empty());
    list.push_back(prism::Crossing<float>::without_surface(1.0f, true));
    list.push_back(prism::Crossing<float>::without_surface(2.5f, false));
    CHECK(list.size() == 2);
    CHECK(list.front().entering);
    float last = -1;
    for (const auto& c : list) {
        CHECK(c.t > last);
        last = c.t;
    }
}
