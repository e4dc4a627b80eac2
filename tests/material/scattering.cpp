// SPDX-License-Identifier: MIT
#include <prism/material/conductor.hpp>
#include <prism/material/dielectric.hpp>
#include <prism/material/diffuse.hpp>
#include <prism/material/scattering.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <utility>

using prism::Rgb;
using prism::Vec3;
using doctest::Approx;

TEST_CASE("the delta split: Fresnel times kr and kt for glass, all reflected past the critical angle, kr for metal")
{
    const prism::Dielectric<double> glass{.ior = 1.5, .kr = 1, .kt = 0.9};
    const Vec3<double> n{0, 1, 0};
    // Normal incidence going in: R = ((1.5 - 1) / (1.5 + 1))^2 = 0.04.
    const auto in = prism::delta_split(glass, Vec3<double>{0, -1, 0}, n, true, Vec3<double>{});
    CHECK(in.kr.x == Approx(0.04));
    CHECK(in.kt.x == Approx(0.9 * 0.96));
    REQUIRE(in.refracted);
    // 45 degrees going out of glass: past 41.8 degrees, total internal reflection.
    const auto out = prism::delta_split(glass, prism::normalize(Vec3<double>{1, -1, 0}), n, false, Vec3<double>{});
    CHECK_FALSE(out.refracted);
    CHECK(out.kr.x == 1);
    CHECK(out.kt.x == 0);
    // 30 degrees going in: Snell gives sin t = 0.5 / 1.5.
    const auto oblique = prism::delta_split(glass, Vec3<double>{0.5, -std::sqrt(0.75), 0}, n, true, Vec3<double>{});
    REQUIRE(oblique.refracted);
    CHECK(oblique.refracted->x == Approx(0.5 / 1.5));
    const prism::Mirror<double> mirror{{.kr = {0.9, 0.5, 0.1}}};
    const auto m = prism::delta_split(mirror, prism::normalize(Vec3<double>{1, -1, 0}), n, true, Vec3<double>{});
    CHECK(m.kr.y == 0.5);
    CHECK_FALSE(m.refracted);
}

TEST_CASE("the diffuse response: BRDF albedo kd / pi, the seed's ambient term, photons keep albedo kd at most 1")
{
    const prism::Diffuse<double> matte{.albedo = {.color = {0.5, 0.25, 0.8}}, .kd = 1.5, .ka = 0.2};
    const auto r = prism::diffuse_response(matte, prism::Crossing<double>::flat(1, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}, true));
    CHECK(r.brdf().x == Approx(0.75 / std::acos(-1.0)));
    // E = 2 from the lights, ambient 3 seen where half the light is blocked.
    CHECK(r.reflected(Rgb<double>(2), Rgb<double>(3), Rgb<double>(0.5)).y == Approx(0.25 * (1.5 / std::acos(-1.0) * 2 + 0.2 * 3 * 0.5)));
    CHECK(r.photon_reflectance().z == 1.0); // 0.8 * 1.5 = 1.2: a photon cannot gain power
    CHECK(r.photon_reflectance().x == Approx(0.75));
}

TEST_CASE("a highlight only where a material has one: POV-Ray's phong (R.L)^size / pi")
{
    const prism::Diffuse<double> shiny{.phong = 0.5, .phong_size = 4};
    const Vec3<double> mirror{0, 1, 0}, wi = prism::normalize(Vec3<double>{1, 1, 0});
    CHECK(prism::highlight(shiny, mirror, wi) == Approx(0.5 * 0.25 / std::acos(-1.0))); // cos^4 45 degrees = 1/4
    CHECK(prism::highlight(shiny, mirror, -wi) == 0.0);
    CHECK(prism::highlight(prism::Diffuse<double>{}, mirror, wi) == 0.0);
    CHECK(prism::highlight(prism::Mirror<double>{}, mirror, wi) == 0.0);
}

TEST_CASE("light inside glass: Beer-Lambert over the path, on leaving only; shadow rays add the tint per boundary")
{
    const prism::Dielectric<double> glass{.interior = {.absorption = {0.5, 1.0, 0.0}}, .kt = 0.9};
    const prism::Ray<double> ray{{0, 0, 0}, {2, 0, 0}}; // not unit: distance is t |d|
    prism::Crossing<double> leaving = prism::Crossing<double>::without_surface(1.5, false);
    Rgb<double> light(1);
    prism::attenuate_inside(glass, leaving, ray, light);
    CHECK(light.x == Approx(std::exp(-0.5 * 3)));
    CHECK(light.z == 1.0);
    const prism::Crossing<double> entering = prism::Crossing<double>::without_surface(1.5, true);
    Rgb<double> outside(1);
    prism::attenuate_inside(glass, entering, ray, outside);
    CHECK(outside == Rgb<double>(1));
    // A shadow ray through a ball: in at t = 1, out at t = 2, on to t_max = 5.
    prism::Crossings<double, 2> chord;
    chord.push_back(prism::Crossing<double>::without_surface(1, true));
    chord.push_back(prism::Crossing<double>::without_surface(2, false));
    Rgb<double> tr(1);
    prism::attenuate_shadow_ray(glass, chord, ray, 5.0, tr);
    CHECK(tr.y == Approx(std::exp(-1.0 * 2) * 0.81));
    // Starting inside, ending inside: the whole [0, t_max] is in the glass, no boundary.
    prism::Crossings<double, 2> within;
    within.inside_at_start = true;
    Rgb<double> inside(1);
    prism::attenuate_shadow_ray(glass, within, ray, 0.25, inside);
    CHECK(inside.y == Approx(std::exp(-1.0 * 0.5)));
}

namespace {

/// The mean power a photon of power 1 leaves with, per lobe, over n scatterings.
template <class M>
std::pair<Rgb<double>, Rgb<double>> mean_scattered(const M& material, const Vec3<double>& d, int n)
{
    prism::Random rng(7, 3);
    const Vec3<double> up{0, 1, 0};
    const auto hit = prism::Crossing<double>::flat(1, {0, 0, 0}, {0, 0, 0}, up, true);
    Rgb<double> diffuse(0), specular(0);
    for (int i = 0; i < n; ++i) {
        Rgb<double> power(1);
        const auto bounce = prism::scatter_photon(material, hit, d, power, rng);
        if (!bounce) continue;
        if (bounce->diffuse) {
            CHECK(prism::dot(bounce->direction, up) >= 0);
            diffuse += power;
        } else {
            specular += power;
        }
    }
    return {diffuse / double(n), specular / double(n)};
}

} // namespace

TEST_CASE("photon scattering is unbiased per channel: the mean power leaving is the reflectance, per lobe")
{
    const int n = 400000;
    const Vec3<double> d = prism::normalize(Vec3<double>{1, -1, 0});
    // Standard error of a roulette mean with survival p: sqrt(p (1 - p) / n) (r / p)
    // at most 1.6e-3 here; 4 sigma.
    const double tolerance = 7e-3;
    const prism::Diffuse<double> matte{.albedo = {.color = {0.6, 0.3, 0.1}}};
    const auto [d1, s1] = mean_scattered(matte, d, n);
    CHECK(d1.x == Approx(0.6).epsilon(tolerance / 0.6));
    CHECK(d1.y == Approx(0.3).epsilon(tolerance / 0.3));
    CHECK(d1.z == Approx(0.1).epsilon(tolerance / 0.1 * 2));
    CHECK(s1 == Rgb<double>(0));
    const prism::Mirror<double> mirror{{.kr = {0.9, 0.5, 0.2}}};
    const auto [d2, s2] = mean_scattered(mirror, d, n);
    CHECK(d2 == Rgb<double>(0));
    CHECK(s2.y == Approx(0.5).epsilon(tolerance / 0.5));
    // Glass at 45 degrees: F = 0.0502399 reflected, the rest refracted, both kr = kt = 1.
    const prism::Dielectric<double> glass{};
    const auto [d3, s3] = mean_scattered(glass, d, n);
    CHECK(s3.x == Approx(1.0).epsilon(1e-12)); // reflected or refracted, the power is kept
}

namespace {

/// Two lobes: Lambert of albedo `base` under a mirror of reflectance `coat` (a material
/// only this file knows).
struct CoatedMatte {
    using scalar_type = double;
    static constexpr bool has_diffuse = true;
    static constexpr bool reflects = true;
    static constexpr bool transmits = false;

    Rgb<double> base;
    Rgb<double> coat;

    [[nodiscard]] prism::DiffuseResponse<double> diffuse(const Vec3<double>&) const noexcept { return {base, 1.0, 0.0}; }
    [[nodiscard]] Rgb<double> reflectance(double) const noexcept { return coat; }
    void validate() const {}
};

} // namespace

TEST_CASE("two lobes: one decision picks each with its reflectance, so the mean is right per lobe and a survivor's power never grows")
{
    // Before, a lobe was picked by its share of the two (0.6 and 0.3 here: 2/3 and
    // 1/3) and then played Russian roulette with its own reflectance, so a survivor came
    // out with power 1.5 (or 3 after the coat); over bounces that grew without bound.
    const int n = 400000;
    const double tolerance = 7e-3;
    const Vec3<double> d = prism::normalize(Vec3<double>{1, -1, 0});
    const auto hit = prism::Crossing<double>::flat(1, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}, true);
    for (const auto& [material, largest_allowed] : {std::pair{CoatedMatte{{0.6, 0.3, 0.1}, {0.2, 0.1, 0.3}}, 1.0},
                                                    // Lobes summing above 1 (1.4 in red) are scaled down together.
                                                    std::pair{CoatedMatte{{0.9, 0.3, 0.1}, {0.5, 0.1, 0.3}}, 1.4}}) {
        CAPTURE(material.base.x);
        for (const prism::Lobes lobes : {prism::Lobes::all, prism::Lobes::delta}) {
            CAPTURE(int(lobes));
            prism::Random rng(7, 3);
            Rgb<double> diffuse(0), specular(0);
            double largest = 0;
            for (int i = 0; i < n; ++i) {
                Rgb<double> power(1);
                const auto bounce = prism::scatter_photon(material, hit, d, power, rng, 0.0, 1.0, lobes);
                if (!bounce) continue;
                largest = std::max(largest, prism::max_component(power));
                (bounce->diffuse ? diffuse : specular) += power / double(n);
            }
            CHECK(largest <= largest_allowed * (1 + 1e-12));
            const Rgb<double> expected_diffuse = lobes == prism::Lobes::all ? material.base : Rgb<double>(0);
            for (int c = 0; c < 3; ++c) {
                CHECK(diffuse[c] == Approx(expected_diffuse[c]).epsilon(tolerance / std::max(expected_diffuse[c], 0.1)));
                CHECK(specular[c] == Approx(material.coat[c]).epsilon(tolerance / material.coat[c]));
            }
        }
        // No lobe at all: the path ends.
        prism::Random rng(1, 1);
        Rgb<double> power(1);
        CHECK(!prism::scatter_photon(material, hit, d, power, rng, 0.0, 1.0, prism::Lobes::none));
    }
}

namespace {

/// A crossing of the plane y = 0 from above whose shading normal leans alpha radians
/// toward +x.
prism::Crossing<double> leaning_hit(double alpha)
{
    auto hit = prism::Crossing<double>::flat(1, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}, true);
    hit.shading = {std::sin(alpha), std::cos(alpha), 0};
    return hit;
}

} // namespace

TEST_CASE("a diffuse photon at a shading normal: Veach's adjoint correction, against the integral over both hemispheres")
{
    // For a photon arriving along d, the lobe scatters f_s(d -> w) = rho / pi |d.ns| / |d.ng|
    // toward every w above both the shading and the true normal (Veach 1997, 5.3.6), so the
    // power leaving is rho |d.ns| / |d.ng| (1 / pi) int over both hemispheres of |w.ng| dw
    // = rho |d.ns| / |d.ng| (1 + cos alpha) / 2 (the two hemispheres overlap in all but a
    // lune of angle alpha, whose projected solid angle is pi (1 - cos alpha) / 2). A camera
    // path (radiance) keeps rho for every direction above both: rho (1 + cos alpha) / 2.
    const prism::Diffuse<double> matte{.albedo = {.color = {0.8, 0.8, 0.8}}};
    const int n = 400000;
    for (const double alpha : {0.2, 0.6}) {
        const auto hit = leaning_hit(alpha);
        for (const Vec3<double> d : {prism::normalize(Vec3<double>{1, -1, 0}), prism::normalize(Vec3<double>{-0.3, -1, 0.2})}) {
            prism::Random rng(11, 5);
            double importance = 0, radiance = 0;
            for (int i = 0; i < n; ++i) {
                Rgb<double> power(1);
                if (const auto b = prism::scatter_photon<prism::Transport::importance>(matte, hit, d, power, rng)) {
                    CHECK(prism::dot(b->direction, hit.normal) > 0);
                    importance += power.x;
                }
                power = Rgb<double>(1);
                if (prism::scatter_photon<prism::Transport::radiance>(matte, hit, d, power, rng)) radiance += power.x;
            }
            const double overlap = (1 + std::cos(alpha)) / 2;
            const double ratio = -prism::dot(d, hit.shading) / -prism::dot(d, hit.normal);
            CHECK(importance / n == Approx(0.8 * ratio * overlap).epsilon(0.01));
            CHECK(radiance / n == Approx(0.8 * overlap).epsilon(0.01));
        }
    }
}

TEST_CASE("a shading normal: light counts by its cosine above both normals; a mirror turns about it unless a ray would cross the true surface")
{
    const auto hit = leaning_hit(0.3);
    const Vec3<double> ns = hit.shading, ng = hit.normal;
    const Vec3<double> wi = prism::normalize(Vec3<double>{1, 2, 0.5});
    CHECK(prism::shading_cosine(ns, ng, wi) == prism::dot(ns, wi));
    CHECK(prism::shading_cosine(ns, ng, prism::normalize(Vec3<double>{-1, 0.2, 0})) == 0); // above the surface, behind the shading normal
    CHECK(prism::shading_cosine(ns, ng, prism::normalize(Vec3<double>{1, -0.1, 0})) == 0); // below the surface
    const prism::Mirror<double> mirror{};
    // Steep: the mirror direction about ns stays above the surface.
    const Vec3<double> steep = prism::normalize(Vec3<double>{0.2, -1, 0});
    CHECK(prism::delta_normal(mirror, steep, hit) == ns);
    // Low toward +x, still against ns: reflected about ns it would go under the surface.
    const Vec3<double> grazing = prism::normalize(Vec3<double>{1, -0.4, 0});
    CHECK(prism::dot(grazing, ns) < 0);
    CHECK(prism::reflect(grazing, ns).y < 0);
    CHECK(prism::delta_normal(mirror, grazing, hit) == ng);
    // Glass: the refracted ray about ns must go down through the surface.
    const prism::Dielectric<double> glass{};
    CHECK(prism::delta_normal(glass, steep, hit) == ns);
    const auto split = prism::delta_split(glass, steep, ns, true, Vec3<double>{});
    REQUIRE(split.refracted);
    CHECK(prism::dot(*split.refracted, ng) < 0);
    // Arriving behind ns: the true normal.
    CHECK(prism::delta_normal(mirror, prism::normalize(Vec3<double>{1, -0.1, 0}), hit) == ng);
    // A flat hit turns about its true normal, facing the ray.
    const auto flat = prism::Crossing<double>::flat(1, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}, false);
    CHECK(prism::delta_normal(glass, Vec3<double>{0, 1, 0}, flat) == Vec3<double>{0, -1, 0});
}
