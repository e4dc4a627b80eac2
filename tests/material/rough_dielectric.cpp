// SPDX-License-Identifier: MIT
#include <prism/material/rough_dielectric.hpp>

#include "../bsdf_checks.hpp"

#include <prism/optics/fresnel.hpp>

#include <doctest/doctest.h>

using prism::Vec3;

static_assert(prism::has_glossy<prism::RoughDielectric<float>> && prism::transmits<prism::RoughDielectric<float>>);
static_assert(prism::Material<prism::RoughDielectric<double>>);

namespace {

prism::MicrofacetDielectric<double> frosted(double roughness, double eta)
{
    return {prism::TrowbridgeReitz<double>::from(prism::Roughness<double>(roughness)), eta};
}

} // namespace

TEST_CASE("rough dielectric: sampling follows the pdf from either side, into denser and into thinner glass, weights are f cos / pdf")
{
    // Every pair of the four factors' values meets in one of the 12 cases (three
    // roughnesses, each with both glasses from both sides, the angle turning through
    // three values), as in all 36 combinations, at a third of the time.
    const double roughnesses[] = {0.2, 0.5, 0.9}, thetas[] = {10.0, 50.0, 80.0};
    for (int r = 0; r < 3; ++r)
        for (int e = 0; e < 4; ++e) {
            const double roughness = roughnesses[r], eta = e < 2 ? 1.5 : 1 / 1.5, side = e % 2 == 0 ? 1.0 : -1.0, theta = thetas[(r + e) % 3];
            CAPTURE(roughness);
            CAPTURE(eta);
            CAPTURE(theta);
            CAPTURE(side);
            Vec3<double> wo = test::polar(theta, 25);
            wo.z *= side;
            test::check_lobe_sampling(frosted(roughness, eta), wo, 5e-3, 20000);
        }
}

TEST_CASE("rough dielectric: what the facets reflect and refract is at most what arrives, nearly all of it when smooth, and F of it reflected")
{
    // In power (a photon's measure) an interface without absorption sends on all the light
    // one facet does; single scattering loses what would meet a second facet. The albedo
    // by sampling against quadrature of f (about the mirror and the Snell direction), and
    // at a nearly smooth surface, the reflected share of the draws against Fresnel's.
    struct Case {
        double roughness, eta, theta;
    };
    for (const Case c : {Case{0.05, 1.5, 30}, Case{0.05, 1 / 1.5, 30}, Case{0.3, 1.5, 0}, Case{0.3, 1.5, 70}, Case{0.8, 1.5, 45}, Case{0.8, 1 / 1.5, 20},
                         Case{0.5, 1 / 1.5, 60}}) {
        CAPTURE(c.roughness);
        CAPTURE(c.eta);
        CAPTURE(c.theta);
        const auto lobe = frosted(c.roughness, c.eta);
        const Vec3<double> wo = test::polar(c.theta, 0);
        prism::Random rng(8, 8);
        double all = 0, reflected = 0;
        constexpr int n = 400000;
        for (int i = 0; i < n; ++i) {
            const auto s = lobe.sample(wo, rng.uniform<double>(), rng.uniform<double>(), rng.uniform<double>(), prism::Transport::importance);
            if (!s) continue;
            all += s->weight.x / n;
            if (s->wi.z > 0) reflected += s->weight.x / n;
        }
        CHECK(all <= 1.0 + 1e-9);
        if (c.roughness < 0.1) {
            CHECK(all == doctest::Approx(1).epsilon(5e-3));
            CHECK(reflected == doctest::Approx(prism::fresnel_dielectric(wo.z, c.eta)).epsilon(0.03));
        } else {
            const auto f = [&](const Vec3<double>& wi) { return lobe.f(wo, wi, prism::Transport::importance).x * std::abs(wi.z); };
            const double by_quadrature = test::sphere_integral([&](const Vec3<double>& wi) { return wi.z > 0 ? f(wi) : 0.0; }, test::local_mirror(wo)) +
                                         test::sphere_integral([&](const Vec3<double>& wi) { return wi.z < 0 ? f(wi) : 0.0; }, test::snell_direction(wo, c.eta));
            CHECK(all == doctest::Approx(by_quadrature).epsilon(5e-3));
            MESSAGE("roughness ", c.roughness, ", eta ", c.eta, ", ", c.theta, " degrees: reflects and refracts ", all);
        }
    }
}

TEST_CASE("rough dielectric: f(wo, wi) / n(wi)^2 = f(wi, wo) / n(wo)^2 across, and reflection reciprocal")
{
    const auto lobe = frosted(0.4, 1.5); // n = 1 above, 1.5 below
    prism::Random rng(4, 4);
    int pairs = 0;
    for (const double theta : {20.0, 45.0, 60.0, 75.0}) {
        const Vec3<double> a = test::polar(theta, 10 * theta);
        // Directions a refracts into, drawn from the lobe (so each pair has a facet between them).
        for (int k = 0; k < 20; ++k) {
            const auto s = lobe.sample(a, 0.999, rng.uniform<double>(), rng.uniform<double>(), prism::Transport::importance);
            if (!s || !(s->wi.z < 0)) continue;
            const Vec3<double> b = s->wi;
            const double ab = lobe.f(a, b, prism::Transport::importance).x, ba = lobe.f(b, a, prism::Transport::importance).x;
            REQUIRE(ab > 0);
            CHECK(ab / (1.5 * 1.5) == doctest::Approx(ba / 1.0).epsilon(1e-9));
            ++pairs;
        }
    }
    CHECK(pairs > 60);
    const Vec3<double> a = test::polar(30, 0), b = test::polar(50, 120);
    CHECK(lobe.f(a, b, prism::Transport::radiance).x == doctest::Approx(lobe.f(b, a, prism::Transport::radiance).x).epsilon(1e-12));
}

TEST_CASE("rough dielectric at roughness 0: Dielectric's interface, reflecting by Fresnel's share and refracting by Snell")
{
    const auto lobe = frosted(0, 1.5);
    CHECK(lobe.smooth());
    const Vec3<double> wo = test::polar(50, 30);
    int reflected = 0;
    constexpr int n = 20000;
    for (int i = 0; i < n; ++i) {
        const auto s = lobe.sample(wo, (i + 0.5) / n, 0.5, 0.5, prism::Transport::radiance);
        REQUIRE(s);
        CHECK(s->delta);
        if (s->wi.z > 0) {
            ++reflected;
            CHECK(s->wi.x == doctest::Approx(-wo.x));
        } else {
            // Snell: sin_t = sin_i / 1.5.
            CHECK(std::sqrt(s->wi.x * s->wi.x + s->wi.y * s->wi.y) == doctest::Approx(std::sin(50 * prism::pi<double> / 180) / 1.5));
        }
    }
    CHECK(double(reflected) / n == doctest::Approx(prism::fresnel_dielectric(wo.z, 1.5)).epsilon(1e-3));
    // From inside beyond the critical angle, all of it reflects.
    Vec3<double> inside = test::polar(60, 0);
    inside.z = -inside.z;
    const auto tir = lobe.sample(inside, 0.99, 0.5, 0.5, prism::Transport::radiance);
    REQUIRE(tir);
    CHECK(tir->wi.z < 0);
    const prism::RoughDielectric<float> bad{.roughness = 2.0f};
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("RoughDielectric roughness"), std::invalid_argument);
    const prism::RoughDielectric<float> tiny{.ior = 1e-45f};
    CHECK_THROWS_WITH_AS(tiny.validate(), doctest::Contains("RoughDielectric ior must be an index of refraction from 0.01 to 100"), std::invalid_argument);
}
