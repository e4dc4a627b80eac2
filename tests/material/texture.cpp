// SPDX-License-Identifier: MIT
#include <prism/material/diffuse.hpp>
#include <prism/material/scattering.hpp>
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

TEST_CASE("a uv checker alternates in surface coordinates, whatever the point; a diffuse lobe reads the crossing's uv")
{
    const prism::UvChecker<double> c{.even = {1, 1, 1}, .odd = {0, 0, 0}, .size = 0.25};
    const prism::Vec3<double> anywhere{7, -3, 2};
    CHECK(c.albedo(anywhere, {0.1, 0.1}).x == 1);
    CHECK(c.albedo(anywhere, {0.3, 0.1}).x == 0);
    CHECK(c.albedo(anywhere, {0.3, 0.3}).x == 1);
    CHECK(c.albedo(anywhere, {-0.1, 0.1}).x == 0); // floor(-0.4) = -1
    CHECK(prism::albedo_at(c, anywhere, {0.6, 0.1}).x == 1);
    // A texture of the point alone ignores uv.
    const prism::Checker<double> solid_cells{.even = {1, 1, 1}, .odd = {0, 0, 0}, .size = 2};
    CHECK(prism::albedo_at(solid_cells, {0.5, 0.5, 0.5}, {0.3, 0.1}).x == 1);
    const prism::Diffuse<double, prism::UvChecker<double>> matte{.albedo = c};
    auto at = prism::Crossing<double>::flat(1, anywhere, {0, 0, 0}, {0, 1, 0}, true);
    at.uv = {0.3, 0.1};
    CHECK(prism::diffuse_response(matte, at).albedo.x == 0);
    at.uv = {0.3, 0.3};
    CHECK(prism::diffuse_response(matte, at).albedo.x == 1);
    CHECK_THROWS_AS((prism::UvChecker<float>{.size = -1}.validate()), std::invalid_argument);
}
