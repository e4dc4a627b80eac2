// SPDX-License-Identifier: MIT
#include <prism/material/rough_conductor.hpp>

#include "../bsdf_checks.hpp"

#include <prism/spectrum/metals.hpp>

#include <doctest/doctest.h>

using prism::Vec3;

static_assert(prism::has_glossy<prism::RoughConductor<float>> && !prism::is_delta<prism::RoughConductor<float>>);
static_assert(prism::Material<prism::RoughConductor<double, prism::ComplexIor<double>>>);

namespace {

prism::RoughConductor<double> white_metal(double roughness_u, double roughness_v)
{
    return {.fresnel = {.kr = prism::Rgb<double>(1)}, .roughness = {roughness_u, roughness_v}};
}

} // namespace

TEST_CASE("rough conductor: sampling follows the pdf it claims, weights are f cos / pdf, the pdf's mass is the share of draws that land")
{
    for (const auto& [ru, rv] : {std::pair{0.3, 0.3}, std::pair{0.6, 0.6}, std::pair{1.0, 1.0}, std::pair{0.3, 0.8}}) {
        const auto metal = white_metal(ru, rv);
        const auto lobe = metal.glossy({});
        for (const double theta : {10.0, 45.0, 80.0}) {
            CAPTURE(ru);
            CAPTURE(rv);
            CAPTURE(theta);
            test::check_lobe_sampling(lobe, test::polar(theta, 35), 5e-3, 20000);
        }
    }
}

TEST_CASE("rough conductor: the white furnace loses what single scattering loses, and no more")
{
    // A white metal (kr 1) reflects everything one facet reflects; light that would meet
    // a second facet is lost. The albedo by quadrature and by sampling agree, never exceed
    // 1, approach 1 as the surface smooths, and at roughness 1 (alpha 1) lose, measured:
    //   normal incidence 0.693, 60 degrees 0.549, 80 degrees 0.332.
    // At normal incidence alpha 1 makes D = 1 / pi, and facets tilted past 45 degrees send
    // light below the horizon; what is left is a one-dimensional integral over the
    // facets' tilt t, wi at 2t: E = 2 int_0^{pi/4} cos t sin t / (1 + Lambda(2t)) dt
    // with Lambda = (1 / cos 2t - 1) / 2 (checked below by the midpoint rule).
    double closed = 0;
    for (int k = 0; k < 100000; ++k) {
        const double t = (k + 0.5) / 100000 * prism::pi<double> / 4;
        closed += 2 * std::cos(t) * std::sin(t) / (1 + (1 / std::cos(2 * t) - 1) / 2) * (prism::pi<double> / 4 / 100000);
    }
    CHECK(closed == doctest::Approx(0.3069).epsilon(1e-3));
    struct Case {
        double roughness, theta, albedo;
    };
    for (const Case c : {Case{0.1, 0.0, 1.0}, Case{0.1, 60.0, 0.999}, Case{1.0, 0.0, closed}, Case{1.0, 60.0, 0.4507}, Case{1.0, 80.0, 0.6682}}) {
        CAPTURE(c.roughness);
        CAPTURE(c.theta);
        const auto metal = white_metal(c.roughness, c.roughness);
        const auto lobe = metal.glossy({});
        const Vec3<double> wo = test::polar(c.theta, 0);
        const double by_quadrature = test::albedo_by_quadrature(lobe, wo);
        const test::LobeSampling s = test::sample_lobe(lobe, wo, 400000);
        CHECK(by_quadrature <= 1 + 1e-3);
        CHECK(s.albedo == doctest::Approx(by_quadrature).epsilon(3e-3));
        CHECK(by_quadrature == doctest::Approx(c.albedo).epsilon(3e-3));
    }
}

TEST_CASE("rough conductor: reciprocal, and at roughness 0 the mirror of Conductor")
{
    const prism::RoughConductor<double, prism::ComplexIor<double>> gold{.fresnel = {.eta = {0.18, 0.42, 1.37}, .k = {3.42, 2.35, 1.77}},
                                                                       .roughness = {0.4, 0.2}};
    const auto lobe = gold.glossy({});
    for (const auto& [a, b] : {std::pair{test::polar(20, 10), test::polar(50, 200)}, std::pair{test::polar(70, 0), test::polar(5, 90)}}) {
        const auto fab = lobe.f(a, b, prism::Transport::radiance), fba = lobe.f(b, a, prism::Transport::radiance);
        CHECK(fab.x == doctest::Approx(fba.x).epsilon(1e-12));
        CHECK(fab.z == doctest::Approx(fba.z).epsilon(1e-12));
    }
    const prism::RoughConductor<double, prism::ComplexIor<double>> smooth{.fresnel = gold.fresnel, .roughness = 0.0};
    const prism::Metal<double> mirror{gold.fresnel};
    const Vec3<double> wo = test::polar(40, 60);
    const auto s = smooth.glossy({}).sample(wo, 0.5, 0.3, 0.7, prism::Transport::radiance);
    REQUIRE(s);
    CHECK(s->delta);
    CHECK(s->wi.z == doctest::Approx(wo.z));
    CHECK(s->wi.x == doctest::Approx(-wo.x));
    CHECK(s->weight == mirror.reflectance(wo.z));
    CHECK(smooth.glossy({}).f(wo, s->wi, prism::Transport::radiance) == prism::Rgb<double>(0));
    const prism::RoughConductor<float> bad{.roughness = 1.5f};
    CHECK_THROWS_WITH_AS(bad.validate(), doctest::Contains("RoughConductor roughness"), std::invalid_argument);
}
