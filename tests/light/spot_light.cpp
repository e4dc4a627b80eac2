// SPDX-License-Identifier: MIT
#include <prism/light/spot_light.hpp>
#include <prism/prism.hpp>

#include "../support.hpp"
#include "../effort.hpp"
#include "../emission_checks.hpp"

#include <cmath>

using prism::Rgb;
using prism::Vec3;

namespace {

const prism::SpotLight<double> spot_20_35{.position = {0, 2, 0}, .direction = {0, -2, 0}, .intensity = Rgb<double>(10), .inner_angle = 20, .outer_angle = 35};

} // namespace

TEST_CASE("a spot light's falloff: full inside, none outside, pbrt-v4's smoothstep between")
{
    CHECK(spot_20_35.falloff(std::cos(0.0)) == 1);
    CHECK(spot_20_35.falloff(std::cos(19.9 * prism::pi<double> / 180)) == 1);
    CHECK(spot_20_35.falloff(std::cos(35.1 * prism::pi<double> / 180)) == 0);
    // Halfway in cosine: smoothstep(1/2) = 1/2.
    const double ci = std::cos(20 * prism::pi<double> / 180), co = std::cos(35 * prism::pi<double> / 180);
    CHECK(spot_20_35.falloff(0.5 * (ci + co)) == doctest::Approx(0.5));
    CHECK(spot_20_35.falloff(co + 0.25 * (ci - co)) == doctest::Approx(0.15625)); // 3/16 - 2/64
    // What arrives: I falloff / r^2 from the light.
    const auto s = spot_20_35.sample({1, 0, 0});
    const double cos_angle = 2 / std::sqrt(5.0);
    CHECK(s.irradiance.x == doctest::Approx(10 * spot_20_35.falloff(cos_angle) / 5));
    CHECK(s.delta());
}

TEST_CASE("a spot light's power is its falloff integrated over the sphere, and its photons carry it into its cone only")
{
    // The power by the midpoint rule over the polar angle.
    double integral = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double theta = (i + 0.5) / n * prism::pi<double>;
        integral += 10 * spot_20_35.falloff(std::cos(theta)) * 2 * prism::pi<double> * std::sin(theta) * prism::pi<double> / n;
    }
    CHECK(spot_20_35.power().x == doctest::Approx(integral).epsilon(1e-6));
    // Photons everywhere: their weights average 1 (the power is shared), none outside the outer cone.
    prism::Random rng(3, 1);
    double weight = 0;
    const int photons = 400000;
    for (int i = 0; i < photons; ++i) {
        const auto p = spot_20_35.emit_photon({}, rng.uniform<double>(), rng.uniform<double>());
        CHECK(prism::dot(p.ray.direction, Vec3<double>(0, -1, 0)) >= std::cos(35.0001 * prism::pi<double> / 180));
        weight += p.weight.x;
    }
    CHECK(weight / photons == doctest::Approx(1).epsilon(0.005));
    // Aimed at a sphere off the axis: photon_power times the mean weight is the power into
    // the sphere's cone, found by the midpoint rule over that cone.
    const prism::BoundingSphere<double> target{{0.9, 0, 0}, 0.3};
    const prism::PhotonAim<double> aim{&target, nullptr};
    double aimed = 0;
    for (int i = 0; i < photons; ++i) aimed += spot_20_35.emit_photon(aim, rng.uniform<double>(), rng.uniform<double>()).weight.x;
    aimed *= spot_20_35.photon_power(aim).x / photons;
    const Vec3<double> axis = prism::normalize(target.center - spot_20_35.position);
    const double cos_max = std::sqrt(1 - 0.09 / prism::length_squared(target.center - spot_20_35.position));
    const auto [s, t] = prism::orthonormal_frame(axis);
    double exact = 0;
    const int m = 1000;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            const double z = 1 - (i + 0.5) / m * (1 - cos_max), phi = 2 * prism::pi<double> * (j + 0.5) / m, r = std::sqrt(1 - z * z);
            const Vec3<double> w = r * std::cos(phi) * s + r * std::sin(phi) * t + z * axis;
            exact += 10 * spot_20_35.falloff(prism::dot(w, Vec3<double>(0, -1, 0))) * (1 - cos_max) / m * 2 * prism::pi<double> / m;
        }
    CHECK(aimed == doctest::Approx(exact).epsilon(0.01));
    // A target beyond the cone gets nothing.
    const prism::BoundingSphere<double> behind{{0, 5, 0}, 0.5};
    CHECK(spot_20_35.photon_power({&behind, nullptr}).x == 0);
}

TEST_CASE("a spot light lights a floor as its falloff says, by Whitted and by its photons")
{
    const prism::Scene scene{prism::Lights{spot_20_35}, prism::Object{prism::Plane<double>({0, 1, 0}, 0), prism::Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}}}};
    const prism::Whitted whitted(scene);
    for (const double x : {0.0, 0.5, 1.0, 1.3, 2.0}) {
        const double r2 = x * x + 4, cos = 2 / std::sqrt(r2);
        const double expected = 0.5 / prism::pi<double> * 10 * spot_20_35.falloff(cos) * cos / r2;
        CHECK(whitted.radiance(prism::Ray<double>{{x, 1, 0}, {0, -1, 0}}).x == doctest::Approx(expected));
    }
    const prism::PhotonMaps maps = prism::trace_photons(scene, {.global_photons = 200000, .caustic_photons = 0, .shadow_photons = false, .seed = 2});
    double total = 0;
    for (const prism::Photon& p : maps.global.photons()) total += p.power().x;
    CHECK(total == doctest::Approx(spot_20_35.power().x).epsilon(1.0 / 128));
}

TEST_CASE("a spot light refuses angles and values it cannot honour, naming them")
{
    auto bad = spot_20_35;
    bad.inner_angle = 40;
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("SpotLight inner_angle"), std::invalid_argument);
    bad = spot_20_35;
    bad.outer_angle = 190;
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("SpotLight outer_angle"), std::invalid_argument);
    bad = spot_20_35;
    bad.direction = {0, 0, 0};
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("SpotLight direction"), std::invalid_argument);
    bad = spot_20_35;
    bad.intensity = Rgb<double>(-1);
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("SpotLight intensity"), std::invalid_argument);
}

TEST_CASE("a spot light's emission carries its power, uniform over its outer cone and weighed by its falloff")
{
    using namespace prism;
    const SpotLight<double> light{.position = {0, 3, 0}, .direction = {0.2, -1, 0.1}, .intensity = Rgb<double>(2), .inner_angle = 20, .outer_angle = 35};
    const Rgb<double> power = test::emitted_power(light, BoundingSphere<double>{{0, 0, 0}, 5}, int(test::samples(200000)));
    CHECK(power.x == doctest::Approx(light.power().x).epsilon(test::resolved(0.005)));
    CHECK(light.emission_pdf(normalize(Vec3<double>{0, 1, 0}), {}).direction == 0.0); // behind the cone: none
}
