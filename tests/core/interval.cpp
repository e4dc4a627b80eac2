// SPDX-License-Identifier: MIT
#include <prism/core/interval.hpp>

#include <doctest/doctest.h>

static_assert(prism::Interval<float>{}.empty(), "the default interval is empty");
static_assert(prism::Interval<float>{0, 1}.contains(1) && !prism::Interval<float>{0, 1}.surrounds(1));
static_assert(prism::Interval<double>::universe().surrounds(1e300));

TEST_CASE("Interval size")
{
    CHECK(prism::Interval<double>{2, 5}.size() == 3);
}
