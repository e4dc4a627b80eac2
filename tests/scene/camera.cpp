// SPDX-License-Identifier: MIT
#include <prism/scene/camera.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <utility>

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
    // Regression: both said "up is parallel to the view direction".
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

TEST_CASE("a thin lens: a point on the plane in focus images to a point, and elsewhere to the thin-lens formula's circle of confusion")
{
    // Lens radius 0.1, focused at 5 along the view direction (-z). A point P in focus: every
    // ray through P's image position, from any lens point, passes through P.
    const Camera<double> camera{.position = {0, 0, 0}, .look_at = {0, 0, -3}, .fov = 50, .aperture_radius = 0.1, .focus_distance = 5.0};
    const auto rays = camera.rays(400, 300);
    const Vec3<double> p{0.7, -0.4, -5};
    const auto centre = rays.project(p);
    REQUIRE(centre);
    for (const auto& [u, v] : {std::pair{0.1, 0.2}, std::pair{0.9, 0.5}, std::pair{0.5, 0.95}, std::pair{1.0, 0.0}}) {
        const prism::Ray<double> ray = rays.ray(centre->x, centre->y, u, v);
        CHECK(prism::length(ray.origin - rays.origin) == doctest::Approx(0.1 * std::sqrt(u)));
        const Vec3<double> to_p = p - ray.origin;
        CHECK(prism::length(prism::cross(to_p, ray.direction)) == doctest::Approx(0).epsilon(1e-12)); // on the ray
        // And a light path joined at that lens point finds the same image position.
        const auto seen = rays.project(p, ray.origin);
        REQUIRE(seen);
        CHECK(seen->x == doctest::Approx(centre->x));
        CHECK(seen->y == doctest::Approx(centre->y));
    }
    // At depth z the images from the lens's rim spread over a circle of diameter
    // 2 r |1 / f - 1 / z| on the image plane one unit ahead (the thin-lens formula,
    // A |z - f| / z scaled by the image distance over f), in pixels over |pixel_right|.
    for (const double z : {2.0, 3.5, 9.0, 40.0}) {
        const Vec3<double> q{0.2 * z / 5, 0.1 * z / 5, -z};
        const double expected = 2 * 0.1 * std::abs(1 / 5.0 - 1 / z) / prism::length(rays.pixel_right);
        double widest = 0;
        for (int k = 0; k < 360; ++k) {
            const auto a = rays.project(q, rays.lens_point(1.0, k / 360.0)), b = rays.project(q, rays.lens_point(1.0, k / 360.0 + 0.5));
            REQUIRE(a);
            REQUIRE(b);
            widest = std::max(widest, std::hypot(a->x - b->x, a->y - b->y));
        }
        CAPTURE(z);
        CHECK(widest == doctest::Approx(expected).epsilon(1e-6));
    }
    // Focused at look_at without a distance; a pinhole has no lens and draws none.
    const Camera<double> at_look{.position = {0, 0, 0}, .look_at = {0, 0, -3}, .aperture_radius = 0.1};
    CHECK(at_look.rays(8, 8).focus == doctest::Approx(3));
    CHECK_FALSE(Camera<double>{}.rays(8, 8).thin_lens());
    CHECK_THROWS_WITH_AS((Camera<float>{.aperture_radius = -1}.validate()), doctest::Contains("Camera aperture_radius"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((Camera<float>{.aperture_radius = 0.1f, .focus_distance = 0.0f}.validate()), doctest::Contains("Camera focus_distance"),
                         std::invalid_argument);
}
