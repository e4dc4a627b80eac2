// SPDX-License-Identifier: MIT
#include <prism/scene/shadow.hpp>

#include <doctest/doctest.h>

TEST_CASE("a shadow ray's glass boundaries: sorted by t, and overlap found where two insides meet, not where they only touch")
{
    using Boundaries = prism::detail::ShadowBoundaries<double>;
    // Object 0 over [1, 3], object 1 over [2, 4]: they overlap on [2, 3].
    Boundaries overlapping;
    overlapping.add({3.0, 0, 0, false, false});
    overlapping.add({2.0, 0, 1, true, false});
    overlapping.add({1.0, 0, 0, true, false});
    overlapping.add({4.0, 0, 1, false, false});
    CHECK(overlapping.sort_and_find_overlap());
    for (std::size_t i = 1; i < overlapping.count; ++i) CHECK(overlapping.items[i - 1].t <= overlapping.items[i].t);
    // One after the other: no overlap. A ray starting inside counts as entering at 0.
    Boundaries apart;
    apart.add({0.0, 0, 0, true, true});
    apart.add({1.0, 0, 0, false, false});
    apart.add({2.0, 0, 1, true, false});
    apart.add({3.0, 0, 1, false, false});
    CHECK(!apart.sort_and_find_overlap());
    // More boundaries than it holds: flagged, and no overlap claimed (the caller falls back).
    Boundaries many;
    for (std::size_t i = 0; i <= Boundaries::capacity; ++i) many.add({double(i), 0, std::uint32_t(i), true, false});
    CHECK(many.overflow);
    CHECK(!many.sort_and_find_overlap());
}
