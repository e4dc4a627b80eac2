// SPDX-License-Identifier: MIT
#include <prism/material/coated_diffuse.hpp>
#include <prism/material/image_texture.hpp>

#include "../bsdf_checks.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using prism::Vec3;

static_assert(prism::has_glossy<prism::CoatedDiffuse<float>>);

namespace {

prism::CoatedDiffuse<double> coated(double rho, double roughness, double ior = 1.5)
{
    return prism::CoatedDiffuse<double>({.color = prism::Rgb<double>(rho)}, {.ior = ior, .roughness = roughness});
}

} // namespace

TEST_CASE("coated diffuse: a white base under any coat reflects all the light, a grey one less, and never more")
{
    for (const double roughness : {0.0, 0.2, 0.5, 1.0})
        for (const double theta : {0.0, 50.0, 80.0}) {
            CAPTURE(roughness);
            CAPTURE(theta);
            const Vec3<double> wo = test::polar(theta, 20);
            const auto white = coated(1, roughness);
            const test::LobeSampling s = test::sample_lobe(white.glossy({}), wo, 400000);
            CHECK(s.albedo == doctest::Approx(1).epsilon(4e-3));
            // A base of 0.5: the coat's E plus T times the base's escaping albedo, rho (1 - F) / (1 - rho F).
            const auto grey = coated(0.5, roughness);
            const double t = grey.transmission().at(wo.z), f_in = grey.transmission().inside_reflectance();
            const double expected = (1 - t) + t * 0.5 * (1 - f_in) / (1 - 0.5 * f_in);
            const test::LobeSampling g = test::sample_lobe(grey.glossy({}), wo, 400000);
            CHECK(g.albedo == doctest::Approx(expected).epsilon(4e-3));
            CHECK(g.albedo < 1);
            if (roughness > 0) CHECK(test::albedo_by_quadrature(grey.glossy({}), wo) == doctest::Approx(expected).epsilon(4e-3));
        }
}

TEST_CASE("coated diffuse: the coat's table against the smooth Fresnel equations and their diffuse mean")
{
    // A smooth coat lets in 1 - F(cos): 0.96 at normal incidence for n = 1.5. Its diffuse
    // reflectance from inside, 1 - T_avg / n^2, is 0.5963 for n = 1.5 (the internal
    // diffuse Fresnel reflectance: Egan and Hilgeman's fit gives 0.596).
    const auto smooth = coated(0.8, 0);
    CHECK(smooth.transmission().at(1) == doctest::Approx(0.96).epsilon(1e-6));
    CHECK(smooth.transmission().inside_reflectance() == doctest::Approx(0.5963).epsilon(2e-3));
    // Rough coats let in more at grazing angles than a smooth one (the facets turn toward the light).
    CHECK(coated(0.8, 0.5).transmission().at(0.1) > smooth.transmission().at(0.1));
}

TEST_CASE("coated diffuse: sampling follows the pdf, weights are f cos / pdf, reciprocal; a smooth coat's mirror is a delta")
{
    for (const double roughness : {0.15, 0.4, 0.9})
        for (const double theta : {0.0, 45.0, 85.0}) {
            CAPTURE(roughness);
            CAPTURE(theta);
            const auto material = coated(0.6, roughness);
            const auto lobe = material.glossy({});
            test::check_lobe_sampling(lobe, test::polar(theta, 60), 3e-3, 20000);
            const auto a = test::polar(30, 10), b = test::polar(65, 170);
            CHECK(lobe.f(a, b).x == doctest::Approx(lobe.f(b, a).x).epsilon(1e-12));
        }
    const auto smooth = coated(0.6, 0);
    const Vec3<double> wo = test::polar(40, 0);
    const auto lobe = smooth.glossy({});
    int deltas = 0;
    for (int i = 0; i < 100; ++i) {
        const auto s = lobe.sample(wo, (i + 0.5) / 100, 0.3, 0.6, prism::Transport::radiance);
        REQUIRE(s);
        if (s->delta) {
            ++deltas;
            CHECK(s->wi.z == doctest::Approx(wo.z));
        }
    }
    CHECK(deltas > 0);
    CHECK(deltas < 100);
    CHECK_THROWS_WITH_AS(coated(1.2, 0.1), doctest::Contains("CoatedDiffuse albedo"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(coated(0.5, 0.1, 0.9), doctest::Contains("Coat ior"), std::invalid_argument);
}

TEST_CASE("coated diffuse under a coat of textured roughness: the tables' coat at their levels, close between them, white still keeps all")
{
    using prism::ImageTexture;
    using Textured = prism::CoatedDiffuse<double, prism::Solid<double>, ImageTexture<double>>;
    static_assert(prism::Material<Textured> && prism::reads_coordinates<Textured>());
    // A 2 x 1 roughness picture, read by nearest texel: r0 on the left (u < 1/2), r1 on the right.
    const auto coat_of = [](double rho, double r0, double r1) {
        const std::vector<float> texels{float(r0), float(r1)};
        return Textured({.color = prism::Rgb<double>(rho)}, {.ior = 1.5, .roughness = 0.9},
                        ImageTexture<double>(2, 1, 1, texels, {prism::Wrap::clamp, prism::TextureFilter::nearest}));
    };
    const auto at = [](double u) { return prism::GlossyQuery<double>{.point = {}, .uv = {u, 0.5}}; };
    const auto textured = coat_of(0.6, 0.25, 0.37); // 0.25 is a table's level (4 / 16); 0.37 lies between two
    double worst_level = 0, worst_between = 0;
    for (const double theta_o : {0.0, 40.0, 75.0})
        for (const double theta_i : {10.0, 45.0, 80.0})
            for (const double phi : {0.0, 120.0, 180.0}) {
                const Vec3<double> wo = test::polar(theta_o, 0), wi = test::polar(theta_i, phi);
                const auto rel = [&](double r, double u) {
                    const double a = textured.glossy(at(u)).f(wo, wi).x, b = coated(0.6, double(float(r))).glossy({}).f(wo, wi).x;
                    return std::abs(a - b) / b;
                };
                worst_level = std::max(worst_level, rel(0.25, 0.25));
                worst_between = std::max(worst_between, rel(0.37, 0.75));
            }
    MESSAGE("largest relative difference of f from the untextured coat: ", worst_level, " at a level, ", worst_between, " between levels");
    CHECK(worst_level < 1e-6);
    CHECK(worst_between < 0.01);
    // A white base under it reflects all the light wherever it is read, a grey one as the blended tables say.
    for (const double u : {0.25, 0.75})
        for (const double theta : {0.0, 60.0}) {
            CAPTURE(u);
            CAPTURE(theta);
            const test::LobeSampling s = test::sample_lobe(coat_of(1, 0.25, 0.37).glossy(at(u)), test::polar(theta, 20), 400000);
            CHECK(s.albedo == doctest::Approx(1).epsilon(4e-3));
        }
    // Sampling still follows the pdf between levels.
    test::check_lobe_sampling(textured.glossy(at(0.75)), test::polar(45, 0), 3e-3, 20000);
    CHECK_THROWS_WITH_AS(coat_of(0.5, 0.2, 1.5), doctest::Contains("CoatedDiffuse coat roughness texture's values must be in [0, 1], got up to 1.5"),
                         std::invalid_argument);
}
