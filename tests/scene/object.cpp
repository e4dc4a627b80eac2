// SPDX-License-Identifier: MIT
#include <prism/scene/object.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

static_assert(prism::Slot<prism::Object<prism::Box<float>, prism::Mirror<float>>>);
static_assert(prism::Slot<prism::ObjectArray<prism::Box<float>, prism::Mirror<float>>>);
static_assert(!prism::Slot<prism::Box<float>>);

TEST_CASE("objects_of views a single object and an array alike")
{
    const prism::Object one{prism::Sphere<float>({0, 0, 0}, 1), prism::Diffuse<float>{}};
    CHECK(prism::objects_of(one).size() == 1);
    prism::ObjectArray<prism::Sphere<float>, prism::Diffuse<float>> many{{one, one, one}};
    CHECK(prism::objects_of(many).size() == 3);
    CHECK_THROWS_AS(prism::Object(prism::Sphere<float>({0, 0, 0}, 1), prism::Diffuse<float>{.ka = -2}), std::invalid_argument);
}
