// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>

// A light defined here only, with no change to the photon tracer: the proof that a new
// light is one header (see README, "Adding a material, a light or a shape").

namespace {

using prism::Rgb;
using prism::Vec3;

/// A spot light with a hard edge: intensity I inside a cone of half-angle acos(cos_cutoff) about `axis`,
/// nothing outside (a hard edge).
struct HardSpot {
    using scalar_type = double;
    static constexpr bool delta = true; // from one point

    Vec3<double> position{};
    Vec3<double> axis{0, -1, 0};
    double cos_cutoff = 0.9;
    Rgb<double> intensity{1};

    [[nodiscard]] bool shines(const Vec3<double>& direction) const noexcept { return prism::dot(direction, axis) >= cos_cutoff; }

    [[nodiscard]] prism::LightSample<double> sample(const Vec3<double>& p) const noexcept
    {
        const Vec3<double> to_light = position - p;
        const double r2 = prism::length_squared(to_light), r = std::sqrt(r2);
        return {to_light / r, r, shines(-to_light / r) ? intensity / r2 : Rgb<double>(0)};
    }
    [[nodiscard]] prism::LightSample<double> sample(const Vec3<double>& p, const prism::Vec2<double>&) const noexcept { return sample(p); }

    /// Everywhere: I times the cone's solid angle 2 pi (1 - cos_cutoff). Toward a target,
    /// the same: photons outside the target's cone are not asked for.
    [[nodiscard]] Rgb<double> photon_power(const prism::PhotonAim<double>&) const noexcept
    {
        return intensity * (2 * prism::pi<double> * (1 - cos_cutoff));
    }

    [[nodiscard]] prism::EmittedPhoton<double> emit_photon(const prism::PhotonAim<double>&, double u, double v) const noexcept
    {
        return {{position, prism::uniform_cone(axis, cos_cutoff, u, v)}};
    }

    void validate() const {}
};

static_assert(prism::Light<HardSpot>);

} // namespace

TEST_CASE("a spot light defined in a test lights a disk, by shadow rays and by its own photons alike")
{
    // 2 above a floor, cos_cutoff 0.8: the lit disk has radius 2 tan(acos 0.8) = 1.5.
    const double intensity = 10;
    const prism::Scene scene{prism::Lights{HardSpot{.position = {0, 2, 0}, .cos_cutoff = 0.8, .intensity = Rgb<double>(intensity)}},
                             prism::Object{prism::Plane<double>({0, 1, 0}, 0), prism::Diffuse<double>{.albedo = {.color = Rgb<double>(0)}}}};
    const prism::PhotonMaps maps = prism::trace_photons(scene, {.global_photons = 200000, .caustic_photons = 0, .shadow_photons = false, .seed = 9});
    double total = 0, outside = 0;
    for (const prism::Photon& p : maps.global.photons()) {
        total += p.power().x;
        if (std::hypot(p.position.x, p.position.z) > 1.5f + 1e-3f) outside += p.power().x;
    }
    // Every photon lands; each carries the same power, rounded once to RGBE's 8-bit mantissa.
    CHECK(total == doctest::Approx(intensity * 2 * prism::pi<double> * 0.2).epsilon(1.0 / 256));
    CHECK(outside == 0);
    // E = I cos / r^2 at (x, 0, 0): the photons' estimate matches the light's own sample.
    for (const double x : {0.0, 0.5, 1.0}) {
        const double r2 = x * x + 4, expected = intensity * (2 / std::sqrt(r2)) / r2;
        CHECK(maps.global.irradiance_within({float(x), 0, 0}, {0, 1, 0}, 0.15f).x == doctest::Approx(expected).epsilon(0.05));
    }
    // Whitted's shadow rays: L = albedo / pi E inside the disk, nothing outside it.
    const prism::Scene grey{prism::Lights{HardSpot{.position = {0, 2, 0}, .cos_cutoff = 0.8, .intensity = Rgb<double>(intensity)}},
                            prism::Object{prism::Plane<double>({0, 1, 0}, 0), prism::Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}}}};
    const prism::Whitted whitted(grey);
    const double r2 = 1 + 4;
    CHECK(whitted.radiance(prism::Ray<double>{{1, 1, 0}, {0, -1, 0}}).x == doctest::Approx(0.5 / prism::pi<double> * intensity * (2 / std::sqrt(r2)) / r2));
    CHECK(whitted.radiance(prism::Ray<double>{{2, 1, 0}, {0, -1, 0}}).x == 0);
}

TEST_CASE("photon aims: a point light into a target's cone carries Phi times its solid angle / 4 pi; a parallel light E pi r^2")
{
    const prism::PointLight<double> point{.position = {0, 0, 0}, .intensity = Rgb<double>(1)};
    const prism::BoundingSphere<double> target{{0, 0, 10}, 6};
    // sin(half angle) = 0.6, cos = 0.8: the cone holds (1 - 0.8) / 2 of the sphere.
    CHECK(point.photon_power({&target, nullptr}).x == doctest::Approx(4 * prism::pi<double> * 0.1));
    CHECK(point.photon_power({nullptr, nullptr}).x == doctest::Approx(4 * prism::pi<double>));
    for (const double u : {0.0, 0.3, 0.999}) {
        const auto photon = point.emit_photon({&target, nullptr}, u, 0.7);
        CHECK(photon.ray.direction.z >= 0.8 - 1e-12);
        CHECK(prism::length(photon.ray.direction) == doctest::Approx(1));
    }
    // Inside the target: every direction, the whole power.
    const prism::BoundingSphere<double> around{{0, 0, 1}, 2};
    CHECK(point.photon_power({&around, nullptr}).x == doctest::Approx(4 * prism::pi<double>));
    const prism::DirectionalLight<double> sun{.direction = {0, -1, 0}, .irradiance = Rgb<double>(2)};
    const prism::BoundingSphere<double> scene{{0, 0, 0}, 5};
    CHECK(sun.photon_power({nullptr, &scene}).x == doctest::Approx(2 * prism::pi<double> * 25));
    CHECK(sun.photon_power({&target, &scene}).x == doctest::Approx(2 * prism::pi<double> * 36));
    CHECK(sun.photon_power({nullptr, nullptr}).x == 0); // nothing bounded to light
    const auto photon = sun.emit_photon({nullptr, &scene}, 0.25, 0.5);
    CHECK(photon.ray.direction.y == doctest::Approx(-1));
    CHECK(photon.ray.origin.y >= 5); // upstream of the scene
    CHECK(std::hypot(photon.ray.origin.x, photon.ray.origin.z) == doctest::Approx(5 * 0.5)); // radius r sqrt(u)
}
