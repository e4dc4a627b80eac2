// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include "guide_material.hpp" // docs/guide.md's recipe for a material

#include <doctest/doctest.h>

// Every material states its traits; the scene derives what code its integrator needs.
static_assert(prism::Material<prism::Diffuse<float, prism::Checker<float>>>);
static_assert(!prism::Material<int>);

using DiffuseOnly = prism::Scene<prism::Lights<prism::PointLight<float>>, prism::Object<prism::Sphere<float>, prism::Diffuse<float>>,
                                 prism::Object<prism::Plane<float>, prism::Diffuse<float>>>;
using WithMirror = prism::Scene<prism::Lights<prism::PointLight<float>>, prism::Object<prism::Sphere<float>, prism::Mirror<float>>>;
using WithGlass = prism::Scene<prism::Lights<prism::PointLight<float>>, prism::Object<prism::Sphere<float>, prism::Diffuse<float>>,
                               prism::ObjectArray<prism::Sphere<float>, prism::Dielectric<float>>>;
static_assert(!DiffuseOnly::has_transmissive && !DiffuseOnly::has_specular);
static_assert(!WithMirror::has_transmissive && WithMirror::has_specular);
static_assert(WithGlass::has_transmissive && WithGlass::has_specular);

TEST_CASE("scene traits follow from the material types")
{
    CHECK(WithGlass::slot_count == 2);
}

// Materials defined here only, with no change to any integrator: the proof that a new
// material is one header (see docs/guide.md, "Materials", and docs/contributing.md).

namespace {

using prism::Rgb;
using prism::Vec3;

/// A diffuse base under a clear varnish: Lambert plus a mirror reflection weighted by
/// Schlick's Fresnel of the varnish (n = 1.5).
struct Varnished {
    using scalar_type = double;
    static constexpr bool has_diffuse = true;
    static constexpr bool reflects = true;
    static constexpr bool transmits = false;

    Rgb<double> base{0.5};

    [[nodiscard]] prism::DiffuseResponse<double> diffuse(const Vec3<double>&) const noexcept { return {base, 1.0, 0.0}; }
    [[nodiscard]] Rgb<double> reflectance(double cos_i) const noexcept { return Rgb<double>(prism::fresnel_schlick(cos_i, 1.5)); }
    void validate() const {}
};

/// Glass with an anti-reflection coating (its own Fresnel: 1 % at any angle) and a
/// green tint at each surface, over an absorbing interior.
struct CoatedGlass {
    using scalar_type = double;
    static constexpr bool has_diffuse = false;
    static constexpr bool reflects = true;
    static constexpr bool transmits = true;

    [[nodiscard]] double refractive_index() const noexcept { return 1.5; }
    [[nodiscard]] double fresnel(double, double, double) const noexcept { return 0.01; }
    [[nodiscard]] Rgb<double> reflection_tint() const noexcept { return Rgb<double>(1); }
    [[nodiscard]] Rgb<double> transmission_tint() const noexcept { return {0.5, 1, 0.5}; }
    [[nodiscard]] prism::Homogeneous<double> medium() const noexcept { return {.absorption = {0, 0, 0.4}}; }
    void validate() const {}
};

/// It declares a diffuse lobe but has no diffuse(p): not a Material.
struct MatteWithoutDiffuse {
    using scalar_type = float;
    static constexpr bool has_diffuse = true;
    static constexpr bool reflects = false;
    static constexpr bool transmits = false;
    void validate() const {}
};

/// A dielectric without the medium that fills it: not a Material.
struct GlassWithoutMedium {
    using scalar_type = double;
    static constexpr bool has_diffuse = false;
    static constexpr bool reflects = true;
    static constexpr bool transmits = true;
    [[nodiscard]] double refractive_index() const noexcept { return 1.5; }
    [[nodiscard]] double fresnel(double, double, double) const noexcept { return 0.04; }
    [[nodiscard]] Rgb<double> reflection_tint() const noexcept { return Rgb<double>(1); }
    [[nodiscard]] Rgb<double> transmission_tint() const noexcept { return Rgb<double>(1); }
    void validate() const {}
};

} // namespace

static_assert(prism::Material<Varnished> && prism::Material<CoatedGlass>);
static_assert(!prism::Material<MatteWithoutDiffuse> && !prism::Material<GlassWithoutMedium>);

TEST_CASE("a varnished floor defined in a test renders the same in Whitted and the photon mapper: Lambert plus Schlick's mirror")
{
    const double intensity = 16;
    prism::Scene scene{prism::Lights{prism::PointLight<double>{.position = {0, 4, 0}, .intensity = Rgb<double>(intensity)}},
                       prism::Object{prism::Plane<double>({0, 1, 0}, 0), Varnished{}}};
    scene.background = {0.2, 0.3, 0.4};
    // At 45 degrees onto the point under the light: E = I / 16, and the mirror sees the sky.
    const prism::Ray<double> ray{{-1, 1, 0}, prism::normalize(Vec3<double>{1, -1, 0})};
    const double r = prism::fresnel_schlick(std::sqrt(0.5), 1.5);
    const Rgb<double> expected = Rgb<double>(0.5 / prism::pi<double> * intensity / 16) + r * scene.background;
    const Rgb<double> whitted = prism::Whitted(scene).radiance(ray);
    prism::Random rng(1, 1);
    const Rgb<double> mapped = prism::PhotonMapper(scene, {.tracing = {.global_photons = 1000, .caustic_photons = 0}, .gather_rays = 0}).radiance(ray, rng);
    for (int c = 0; c < 3; ++c) {
        CHECK(whitted[c] == doctest::Approx(expected[c]).epsilon(1e-12));
        CHECK(mapped[c] == doctest::Approx(expected[c]).epsilon(1e-12));
    }
}

TEST_CASE("photons scatter off the varnished floor by both lobes: the black ceiling receives Phi/2 rho_d and Phi/2 (R0 + (1 - R0)/6)")
{
    // A point light between the floor and a ceiling that absorbs everything: each sees
    // half the power directly. Directions toward the floor are uniform in cos, so the
    // mirror lobe sends up the mean of Schlick's R over cos in [0, 1], R0 + (1 - R0) / 6;
    // the diffuse lobe sends up rho_d = 0.5. On the ceiling the mirrored photons are
    // caustic (L S D), the diffusely reflected ones are neither caustic nor direct.
    const double intensity = 1, phi = 4 * prism::pi<double> * intensity;
    const prism::Scene scene{prism::Lights{prism::PointLight<double>{.position = {0, 1, 0}, .intensity = Rgb<double>(intensity)}},
                             prism::Object{prism::Plane<double>({0, 1, 0}, 0), Varnished{}},
                             prism::Object{prism::Plane<double>({0, -1, 0}, -2), prism::Diffuse<double>{.albedo = {.color = Rgb<double>(0)}}}};
    const std::size_t photons = 400000;
    const prism::PhotonMaps maps = prism::trace_photons(scene, {.global_photons = photons, .caustic_photons = 0, .shadow_photons = false, .seed = 3});
    double direct = 0, mirrored = 0, diffused = 0;
    for (const prism::Photon& p : maps.global.photons()) {
        if (p.position.y < 1.0f) continue; // on the floor
        if (p.flags & prism::Photon::direct) direct += p.power().x;
        else if (p.flags & prism::Photon::caustic) mirrored += p.power().x;
        else diffused += p.power().x;
    }
    const double r0 = 0.04;
    CHECK(direct / (phi / 2) == doctest::Approx(1).epsilon(0.01));
    CHECK(diffused / (phi / 2) == doctest::Approx(0.5).epsilon(0.02));
    CHECK(mirrored / (phi / 2) == doctest::Approx(r0 + (1 - r0) / 6).epsilon(0.05));
}

TEST_CASE("coated glass defined in a test: Whitted sums its own Fresnel, tint and medium; its caustic is the paraxial image's")
{
    // Straight down through a slab 1 thick onto the sky: L = R B + T^2 e B / (1 - R e)
    // with T = 0.99 tint, R = 0.01, e = exp(-sigma): inside, the light going up and the
    // light going down are the same, D = e (T B + R D) (every internal reflection).
    prism::Scene slab{prism::Lights{prism::PointLight<double>{.position = {3, 5, 0}}},
                      prism::Object{prism::Box<double>({-5, 1, -5}, {5, 2, 5}), CoatedGlass{}}};
    slab.background = {0.2, 0.4, 0.8};
    const Rgb<double> l = prism::Whitted(slab, {.max_depth = 40, .min_weight = 0}).radiance(prism::Ray<double>{{0, 5, 0}, {0, -1, 0}});
    const Rgb<double> tint{0.5, 1, 0.5}, e{1, 1, std::exp(-0.4)};
    for (int c = 0; c < 3; ++c) {
        const double t = 0.99 * tint[c];
        CHECK(l[c] == doctest::Approx(0.01 * slab.background[c] + t * t * e[c] * slab.background[c] / (1 - 0.01 * e[c])).epsilon(1e-9));
    }
    // A point light 2.5 above a slab 0.5 thick over the floor at 1.5 below it: the slab
    // shows the light t (1 - 1/n) nearer, so under it E = T^2 e I / (4 - 0.5 / 3)^2
    // (paraxial), by caustic photons alone.
    const prism::Scene lit{prism::Lights{prism::PointLight<double>{.position = {0, 4, 0}, .intensity = Rgb<double>(10)}},
                           prism::Object{prism::Plane<double>({0, 1, 0}, 0), prism::Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}}},
                           prism::Object{prism::Box<double>({-3, 1, -3}, {3, 1.5, 3}), CoatedGlass{}}};
    const prism::PhotonMaps maps = prism::trace_photons(lit, {.global_photons = 0, .caustic_photons = 400000, .seed = 5});
    const double apparent = 4 - 0.5 / 3;
    for (int c = 0; c < 3; ++c) {
        const double t = 0.99 * tint[c];
        const double expected = t * t * std::exp(c == 2 ? -0.4 * 0.5 : 0.0) * 10 / (apparent * apparent);
        CHECK(maps.caustic.irradiance_within({0, 0, 0}, {0, 1, 0}, 0.25f)[c] == doctest::Approx(expected).epsilon(0.03));
    }
}

TEST_CASE("The user guide's recipe for a material compiles as written and refuses a bad parameter by name")
{
    // docs/guide.md's code block, compiled from there (tools/snippets.py); tests/furnace.hpp
    // renders it in every integrator.
    static_assert(prism::Material<ClearCoat>);
    CHECK_NOTHROW(ClearCoat{}.validate());
    CHECK_THROWS_WITH_AS(ClearCoat{.coat = 0.6f}.validate(), doctest::Contains("ClearCoat coat must be >= 0 and coat + base at most 1, got 0.6"),
                         std::invalid_argument);
}
