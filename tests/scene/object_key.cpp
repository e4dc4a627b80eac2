// SPDX-License-Identifier: MIT
#include <prism/scene/object_key.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

TEST_CASE("object keys order as a scan of the slots in turn; a shadow ray's keys come out sorted, and too many are flagged")
{
    using prism::detail::ObjectKey;
    CHECK(ObjectKey{0, 9}.before(ObjectKey{1, 0}));
    CHECK(ObjectKey{2, 3}.before(ObjectKey{2, 4}));
    CHECK(!ObjectKey{2, 4}.before(ObjectKey{2, 4}));
    CHECK(!ObjectKey{3, 0}.before(ObjectKey{2, 7}));
    prism::detail::ShadowKeys keys;
    const std::vector<ObjectKey> met{{3, 1}, {0, 5}, {3, 0}, {1, 2}, {0, 4}};
    for (const ObjectKey& k : met) keys.add(k);
    const auto sorted = keys.sorted();
    REQUIRE(sorted.size() == met.size());
    CHECK(std::is_sorted(sorted.begin(), sorted.end(), [](const ObjectKey& a, const ObjectKey& b) { return a.before(b); }));
    CHECK(!keys.overflow);
    prism::detail::ShadowKeys full;
    for (std::uint32_t i = 0; i <= prism::detail::ShadowKeys::capacity; ++i) full.add({0, i});
    CHECK(full.overflow);
    CHECK(full.count == prism::detail::ShadowKeys::capacity);
}
