// SPDX-License-Identifier: MIT
#include <prism/medium/graded_index.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

using prism::CurvedRay;
using prism::Vec3;
using doctest::Approx;

namespace {

/// n(y) cos(theta) along the ray, theta its angle with the horizontal, with n taken at
/// the ray's position (so the product drifts if the optical direction's length does not
/// follow the field).
template <class F>
double invariant(const F& field, const CurvedRay<double>& ray)
{
    const double horizontal = std::hypot(ray.optical.x, ray.optical.z) / prism::length(ray.optical);
    return field.index(ray.position) * horizontal;
}

} // namespace

TEST_CASE("n^2 = a + b y: Sharma's step traces the exact parabola y = y0 + tan(theta0) x + b x^2 / (4 K^2)")
{
    const prism::LinearSquareIndex<double> field{.a = 1.0006, .b = 0.004};
    const double theta0 = 0.1, y0 = 2;
    CurvedRay<double> ray = prism::curved_ray(field, prism::Ray<double>{{0, y0, 0}, {std::cos(theta0), std::sin(theta0), 0}});
    const double k = field.index({0, y0, 0}) * std::cos(theta0);
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        ray = prism::sharma_step(field, ray, 0.05); // large steps: the method is exact for constant grad(n^2)
        const double x = ray.position.x;
        const double expected = y0 + std::tan(theta0) * x + field.b * x * x / (4 * k * k);
        worst = std::max(worst, std::abs(ray.position.y - expected) / (1 + std::abs(expected)));
    }
    CHECK(ray.position.x > 90);
    CHECK(worst < 1e-12);
}

TEST_CASE("a stratified field keeps n(y) cos(theta) = K along the ray to 1e-6, with adaptive steps")
{
    const prism::LinearIndex<double> field{.n0 = 1.0, .slope = 0.01};
    const prism::AdaptiveStepper stepper(field, {.tolerance = 1e-9});
    CurvedRay<double> ray = prism::curved_ray(field, prism::Ray<double>{{0, 1, 0}, {1, -0.3, 0.2}});
    const double k = invariant(field, ray);
    double dt = 0, travelled = 0, worst = 0;
    int steps = 0;
    while (travelled < 80) {
        travelled += stepper.step(ray, dt);
        worst = std::max(worst, std::abs(invariant(field, ray) - k));
        ++steps;
    }
    INFO(steps << " steps");
    CHECK(worst < 1e-6);
    CHECK(steps < 2000);
    // The ray bent up toward the higher index: it started downward and now climbs.
    CHECK(ray.optical.y > 0);
}

TEST_CASE("a ray turns back where the index falls to K = n(y0) cos(theta0)")
{
    // Index decreasing with height: a ray climbing at 0.2 rad levels off at the height
    // where n(y) = K, (K^2 - a) / b for n^2 = a + b y.
    const prism::LinearSquareIndex<double> field{.a = 1.2, .b = -0.01};
    const double theta0 = 0.2;
    CurvedRay<double> ray = prism::curved_ray(field, prism::Ray<double>{{0, 0, 0}, {std::cos(theta0), std::sin(theta0), 0}});
    const double k = field.index({0, 0, 0}) * std::cos(theta0);
    const double turn = (k * k - field.a) / field.b;
    double highest = 0;
    for (int i = 0; i < 40000 && !(ray.position.y < -1); ++i) {
        ray = prism::sharma_step(field, ray, 0.002);
        highest = std::max(highest, ray.position.y);
    }
    CHECK(highest == Approx(turn).epsilon(1e-6));
    CHECK(field.index({0, highest, 0}) == Approx(k).epsilon(1e-9));
    CHECK(ray.optical.y < 0); // and comes down again
}

TEST_CASE("a uniform field gives the straight ray, bit for bit")
{
    const prism::LinearIndex<double> water{.n0 = 1.333, .slope = 0};
    const CurvedRay<double> ray = prism::curved_ray(water, prism::Ray<double>{{0.1, 0.2, 0.3}, {0.3, -0.4, 1.2}});
    const double dt = 0.37;
    const CurvedRay<double> next = prism::sharma_step(water, ray, dt);
    CHECK(next.position == ray.position + dt * ray.optical);
    CHECK(next.optical == ray.optical);
    CHECK(prism::length(ray.optical) == Approx(1.333));
}

TEST_CASE("hot air over a road bends a ray looking down at 0.3 degrees back up at 0.235 m: the inferior mirage")
{
    // K = n_air cos(0.3 deg) = n_air - 1.37e-5 (to first order); n falls to K where
    // drop e^(-y/h) = n_air (1 - cos 0.3 deg), y = h ln(drop / (n_air (1 - cos 0.3 deg))).
    const prism::HeatedLayer<double> road{};
    const prism::AdaptiveStepper stepper(road, {.tolerance = 1e-9, .first_step = 1});
    const double down = 0.3 * prism::pi<double> / 180;
    CurvedRay<double> ray = prism::curved_ray(road, prism::Ray<double>{{0, 1.5, 0}, {std::cos(down), -std::sin(down), 0}});
    const double k = road.index({0, 1.5, 0}) * std::cos(down);
    const double turn = -road.thickness * std::log((road.n_air - k) / road.drop);
    double dt = 0, lowest = 1.5;
    while (ray.position.x < 1500 && ray.position.y > 0) {
        stepper.step(ray, dt);
        lowest = std::min(lowest, ray.position.y);
    }
    CHECK(lowest == Approx(turn).epsilon(1e-3));
    CHECK(lowest > 0.2);
    CHECK(ray.position.y > 1.5); // it came back up, above the eye: the sky seen on the road
}

TEST_CASE("the lecture notes' layers: Snell keeps n cos(theta) exactly and converges to the curved ray as layers are added")
{
    const prism::LinearSquareIndex<double> field{.a = 1.0, .b = 0.02};
    const double theta0 = 0.3, y_end = 4;
    // The exact parabola reaches y_end at x = x_end.
    const double k = std::cos(theta0), tan0 = std::tan(theta0), c = field.b / (4 * k * k);
    const double x_end = (-tan0 + std::sqrt(tan0 * tan0 + 4 * c * y_end)) / (2 * c);
    double previous_error = 1e9;
    for (const int layers : {25, 100, 400}) {
        const prism::LayeredMedium medium(field, 0.0, y_end, layers);
        Vec3<double> origin{0, 0, 0}, direction{std::cos(theta0), std::sin(theta0), 0};
        int layer = medium.layer_of(0.0);
        const double invariant0 = medium.index_of(layer) * direction.x;
        double worst = 0;
        while (medium.step(origin, direction, layer)) worst = std::max(worst, std::abs(medium.index_of(layer) * direction.x - invariant0));
        CHECK(worst < 1e-12);
        CHECK(origin.y == y_end);
        const double error = std::abs(origin.x - x_end);
        INFO(layers << " layers: x at the top " << origin.x << ", exact " << x_end);
        CHECK(error < previous_error / 3); // first order in the layer height
        previous_error = error;
    }
}

TEST_CASE("fields agree with their formulas; a callable's gradient by central differences; bad input named")
{
    const prism::ExponentialAtmosphere<double> air{};
    CHECK(air.index({0, 0, 0}) == Approx(1.000293));
    CHECK(air.index({0, 8500, 0}) - 1 == Approx(2.93e-4 / std::exp(1.0)));
    const prism::LinearSquareIndex<double> square{.a = 1.5, .b = 0.3};
    const prism::IndexFunction<double, double (*)(const Vec3<double>&)> callable{
        [](const Vec3<double>& p) { return std::sqrt(1.5 + 0.3 * p.y); }};
    for (const double y : {-1.0, 0.0, 2.0}) {
        CHECK(callable.gradient({0, y, 0}).y == Approx(square.gradient({0, y, 0}).y).epsilon(1e-7));
        CHECK(callable.gradient({0, y, 0}).x == 0);
        const double h = 1e-5, numeric = (air.index({0, 100 + h, 0}) - air.index({0, 100 - h, 0})) / (2 * h);
        CHECK(air.gradient({0, 100, 0}).y == Approx(numeric).epsilon(1e-5));
    }
    CHECK_THROWS_WITH_AS((prism::ExponentialAtmosphere<double>{.scale_height = 0}.validate()), doctest::Contains("scale_height"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS((prism::HeatedLayer<double>{.drop = 2}.validate()), doctest::Contains("drop"), std::invalid_argument);
    const prism::LinearIndex<double> flat{};
    const prism::LayeredMedium four(flat, 0.0, 1.0, 4);
    CHECK(four.layer_of(0.6) == 2);
    CHECK(four.layer_of(1e300) == 3); // clamped before the conversion to int, not after
    CHECK(four.layer_of(-1e300) == 0);
    CHECK(four.layer_of(std::nan("")) == 0);
    CHECK_THROWS_WITH_AS(prism::LayeredMedium(flat, 1.0, 0.0, 4), doctest::Contains("top"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(prism::LayeredMedium(flat, 0.0, 1.0, 0), doctest::Contains("layers"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(prism::AdaptiveStepper(flat, {.tolerance = -1}), doctest::Contains("tolerance"), std::invalid_argument);
}

TEST_CASE("n = 1 + g y, where grad(n^2) is not constant: adaptive steps reach x = (K/g)(acosh(n/K) - acosh(n0/K)) to their tolerance")
{
    // The stratified invariant n cos(theta) = K integrated: dx/dy = K / sqrt(n^2 - K^2).
    const double g = 0.05, theta0 = 0.3;
    const prism::LinearIndex<double> field{.n0 = 1, .slope = g};
    const double k = std::cos(theta0);
    for (const double tolerance : {1e-6, 1e-9}) {
        const prism::AdaptiveStepper stepper(field, {.tolerance = tolerance});
        CurvedRay<double> ray = prism::curved_ray(field, prism::Ray<double>{{0, 0, 0}, {std::cos(theta0), std::sin(theta0), 0}});
        double dt = 0, worst = 0;
        for (int i = 0; i < 200; ++i) {
            stepper.step(ray, dt);
            const double expected = k / g * (std::acosh(field.index(ray.position) / k) - std::acosh(1.0 / k));
            worst = std::max(worst, std::abs(ray.position.x - expected));
        }
        INFO("tolerance " << tolerance << ": reached y = " << ray.position.y);
        CHECK(ray.position.y > 10);
        CHECK(worst < 200 * tolerance); // at most the per-step tolerance times the steps taken
    }
}
