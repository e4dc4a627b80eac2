// SPDX-License-Identifier: MIT
#include <prism/material/texture.hpp>

#include <doctest/doctest.h>

TEST_CASE("checker cells alternate across every axis, including negative coordinates")
{
    const prism::Checker<double> c{.even = {1, 1, 1}, .odd = {0, 0, 0}, .size = 2};
    CHECK(c.albedo({0.5, 0, 0.5}).x == 1);
    CHECK(c.albedo({2.5, 0, 0.5}).x == 0);
    CHECK(c.albedo({-0.5, 0, 0.5}).x == 0); // floor(-0.25) = -1
    CHECK(c.albedo({-2.5, 0, -2.5}).x == 1);
    CHECK(c.albedo({0.5, 2.5, 0.5}).x == 0);
    CHECK_THROWS_AS((prism::Checker<float>{.size = 0}.validate()), std::invalid_argument);
}

TEST_CASE("checker parity far from the origin, where integer conversion would overflow")
{
    const prism::Checker<double> c{.even = {1, 1, 1}, .odd = {0, 0, 0}, .size = 1};
    CHECK(c.albedo({1e30, 0.5, 0.5}).x == 1); // 1e30 is an even integer
    CHECK(c.albedo({1e15 + 1, 0.5, 0.5}).x == 0);
    CHECK(c.albedo({-1e15 - 1, 0.5, 0.5}).x == 0);
}
