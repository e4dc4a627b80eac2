// SPDX-License-Identifier: MIT
#include <prism/scene/camera.hpp>

#include <doctest/doctest.h>

#include <cmath>

using prism::Camera;
using prism::Vec3;

TEST_CASE("camera rays: centre toward look_at, edges at half the horizontal field of view")
{
    const Camera<double> camera{.position = {1, 2, 3}, .look_at = {1, 2, -7}, .up = {0, 1, 0}, .fov = 60};
    const auto rays = camera.rays(200, 100);
    const auto centre = rays.ray(100, 50);
    CHECK(centre.origin == Vec3<double>{1, 2, 3});
    CHECK(centre.direction.z == doctest::Approx(-1));
    const auto right_edge = rays.ray(200, 50);
    CHECK(std::atan2(right_edge.direction.x, -right_edge.direction.z) == doctest::Approx(std::acos(-1.0) / 6)); // 30 deg
    const auto top = rays.ray(100, 0);
    CHECK(top.direction.y > 0); // image rows go down
    CHECK(std::tan(std::atan2(top.direction.y, -top.direction.z)) == doctest::Approx(std::tan(std::acos(-1.0) / 6) / 2));
}

TEST_CASE("degenerate cameras are rejected with the parameter named")
{
    CHECK_THROWS_WITH_AS((Camera<float>{.position = {0, 0, 0}, .look_at = {0, 0, 0}}.validate()), doctest::Contains("look_at"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS((Camera<float>{.up = {0, 0, 1}}.validate()), doctest::Contains("Camera up"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((Camera<float>{.fov = 180}.validate()), doctest::Contains("Camera fov"), std::invalid_argument);
    CHECK_THROWS_AS((Camera<float>{.fov = std::nanf("")}.validate()), std::invalid_argument);
    CHECK_THROWS_AS((Camera<float>{.position = {0, 0, INFINITY}}.validate()), std::invalid_argument);
    CHECK_THROWS_WITH_AS((void)Camera<float>{}.rays(0, 10), doctest::Contains("image size"), std::invalid_argument);
}

TEST_CASE("a camera whose look_at is 3e38 or 1e-44 away still looks there")
{
    // Issue 10: both said "up is parallel to the view direction".
    const prism::Camera<float> far{.position = {-1.5e38f, 0, 0}, .look_at = {1.5e38f, 0, 0}};
    CHECK_NOTHROW(far.validate());
    CHECK(far.forward().x == doctest::Approx(1));
    const prism::Camera<float> near{.position = {0, 0, 0}, .look_at = {0, 0, -1e-44f}};
    CHECK_NOTHROW(near.validate());
    CHECK(near.forward().z == doctest::Approx(-1));
    const auto rays = near.rays(4, 4);
    CHECK(prism::is_finite(rays.ray(2, 2).direction));
    // The reason given for a truly parallel up is still that one.
    const prism::Camera<float> parallel{.position = {0, 0, 0}, .look_at = {0, 5, 0}};
    CHECK_THROWS_WITH_AS(parallel.validate(), doctest::Contains("parallel"), std::invalid_argument);
}
