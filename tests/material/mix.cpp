// SPDX-License-Identifier: MIT
#include <prism/material/mix.hpp>
#include <prism/integrator/path_tracer.hpp>
#include <prism/integrator/whitted.hpp>
#include <prism/prism.hpp>

#include "../bsdf_checks.hpp"

#include <doctest/doctest.h>

#include <cmath>

using prism::Rgb;
using prism::Vec3;

namespace {

using Matte = prism::Diffuse<double>;
using Varnish = prism::RoughConductor<double, prism::ComplexIor<double>>;

/// A dielectric's microfacet reflection (n = 1.5, no absorption) through the conductor Fresnel.
Varnish varnish(double roughness)
{
    return {.fresnel = {.eta = Rgb<double>(1.5), .k = Rgb<double>(0)}, .roughness = prism::Roughness<double>(roughness)};
}

/// The unpolarised Fresnel reflectance of a dielectric of index n in air, written out.
double fresnel_by_hand(double cos_i, double n)
{
    const double sin_t = std::sqrt(1 - cos_i * cos_i) / n, cos_t = std::sqrt(1 - sin_t * sin_t);
    const double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t), rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    return (rs * rs + rp * rp) / 2;
}

/// A weight texture: 0 left of u = 0.5, 1 right of it.
struct HalfAndHalf {
    using scalar_type = double;
    [[nodiscard]] double value(const prism::TexturePoint<double>& at) const noexcept { return at.uv.x < 0.5 ? 0.0 : 1.0; }
    void validate() const {}
};

} // namespace

static_assert(prism::Material<prism::Mix<double, Matte, Varnish>>);
static_assert(prism::has_glossy<prism::Mix<double, Matte, Varnish>> && !prism::reads_coordinates<prism::Mix<double, Matte, Varnish>>());
static_assert(prism::reads_coordinates<prism::Mix<double, Matte, Varnish, HalfAndHalf>>());
static_assert(!prism::MixPart<prism::Dielectric<double>> && !prism::MixPart<prism::Conductor<double>>);

TEST_CASE("a conductor's Fresnel with k = 0 is a dielectric's: the varnish of a mix")
{
    const prism::ComplexIor<double> ior{.eta = Rgb<double>(1.5), .k = Rgb<double>(0)};
    CHECK(ior.reflectance(1).x == doctest::Approx(0.04).epsilon(1e-12));
    for (const double c : {0.9, 0.5, 0.2, 0.05}) CHECK(ior.reflectance(c).y == doctest::Approx(fresnel_by_hand(c, 1.5)).epsilon(1e-9));
}

TEST_CASE("mix: its albedo is the parts' albedos by their weights; sampling follows its pdf; reciprocal")
{
    for (const double roughness : {0.1, 0.35, 0.8})
        for (const double theta : {0.0, 45.0, 80.0}) {
            CAPTURE(roughness);
            CAPTURE(theta);
            const double w = 0.3;
            const prism::Mix<double, Matte, Varnish> mix{.first = {.albedo = {.color = Rgb<double>(0.6)}}, .second = varnish(roughness), .weight = w};
            REQUIRE_NOTHROW(mix.validate());
            const auto lobe = mix.glossy({});
            const Vec3<double> wo = test::polar(theta, 60);
            // The varnish alone, by quadrature; the matte part's albedo is 0.6 exactly.
            const double expected = (1 - w) * 0.6 + w * test::albedo_by_quadrature(varnish(roughness).glossy({}), wo);
            const test::LobeSampling s = test::check_lobe_sampling(lobe, wo, 3e-3);
            CHECK(s.albedo == doctest::Approx(expected).epsilon(test::resolved(5e-3)));
            CHECK(test::albedo_by_quadrature(lobe, wo) == doctest::Approx(expected).epsilon(2e-3));
            const auto a = test::polar(30, 10), b = test::polar(65, 170);
            CHECK(lobe.f(a, b).x == doctest::Approx(lobe.f(b, a).x).epsilon(1e-12));
        }
}

TEST_CASE("mix: a smooth part's mirror stays a delta of its share; the weight can be a texture")
{
    using Mirror = prism::RoughConductor<double>;
    const prism::Mix<double, Matte, Mirror> mix{.first = {.albedo = {.color = Rgb<double>(0.5)}},
                                                .second = {.fresnel = {.kr = Rgb<double>(0.9)}, .roughness = prism::Roughness<double>(0)}, .weight = 0.25};
    const auto lobe = mix.glossy({});
    const Vec3<double> wo = test::polar(40, 0);
    CHECK(!lobe.smooth());
    const auto delta = lobe.delta_part(wo);
    REQUIRE(delta);
    CHECK(delta->weight.x == doctest::Approx(0.25 * 0.9));
    CHECK(delta->wi.z == doctest::Approx(wo.z));
    CHECK(lobe.mirror_albedo(wo).x == doctest::Approx(0.25 * 0.9));
    // Over many draws a quarter are the mirror, each weighted 0.9: the mean weight is the albedo 0.75 0.5 + 0.25 0.9.
    const test::LobeSampling s = test::sample_lobe(lobe, wo, 200000);
    CHECK(s.albedo == doctest::Approx(0.75 * 0.5 + 0.25 * 0.9).epsilon(5e-3));
    CHECK(s.worst_weight < 1e-9);

    const prism::Mix<double, Matte, Matte, HalfAndHalf> halves{.first = {.albedo = {.color = Rgb<double>(0.2)}},
                                                               .second = {.albedo = {.color = Rgb<double>(0.8)}}};
    const Vec3<double> up{0, 0, 1};
    CHECK(halves.glossy({.point = {}, .uv = {0.25, 0.5}}).f(up, up).x == doctest::Approx(0.2 / prism::pi<double>));
    CHECK(halves.glossy({.point = {}, .uv = {0.75, 0.5}}).f(up, up).x == doctest::Approx(0.8 / prism::pi<double>));
}

TEST_CASE("mix: a weight outside [0, 1] and a Diffuse part with a highlight are refused, naming them")
{
    const prism::Mix<double, Matte, Varnish> heavy{.second = varnish(0.3), .weight = 1.5};
    CHECK_THROWS_WITH_AS(heavy.validate(), doctest::Contains("Mix weight"), std::invalid_argument);
    const prism::Mix<double, Matte, Varnish> shiny{.first = {.phong = 0.5}, .second = varnish(0.3), .weight = 0.5};
    CHECK_THROWS_WITH_AS(shiny.validate(), doctest::Contains("Mix first"), std::invalid_argument);
}

TEST_CASE("mix of two Lambertians in Whitted and the path tracer: the Lambertian of their blended albedo")
{
    // A floor under a directional light, seen from straight above: albedo E cos / pi,
    // the albedo 0.6 0.2 + 0.4 0.7 = 0.4 (no other surface, so no indirect light).
    using namespace prism;
    const Vec3<double> to_light = normalize(Vec3<double>{std::sin(0.6), std::cos(0.6), 0});
    const Scene scene{Lights{DirectionalLight<double>{.direction = -to_light, .irradiance = Rgb<double>(2)}},
                      Object{Plane<double>({0, 1, 0}, 0), Mix<double, Matte, Matte>{.first = {.albedo = {.color = Rgb<double>(0.2)}},
                                                                                    .second = {.albedo = {.color = Rgb<double>(0.7)}}, .weight = 0.4}}};
    const Camera<double> camera{.position = {0, 3, 0}, .look_at = {0, 0, 0}, .up = {0, 0, -1}, .fov = 20};
    const double expected = 0.4 / pi<double> * 2 * to_light.y;
    const RenderConfig config{.width = 8, .height = 8, .spp = 4, .threads = 1, .progress = false};
    CHECK(render(camera, Whitted(scene), config).at(4, 4).x == doctest::Approx(expected).epsilon(1e-6));
    CHECK(render(camera, PathTracer(scene, {.max_diffuse_bounces = 0}), config).at(4, 4).x == doctest::Approx(expected).epsilon(1e-6));
}
