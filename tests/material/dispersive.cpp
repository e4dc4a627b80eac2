// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using doctest::Approx;
using namespace prism;

namespace {

constexpr double degrees_per_radian = 180.0 / std::numbers::pi;

/// A 60-degree prism of N-BK7 along z: apex up, base on y = 0, side 2, 4 deep.
auto bk7_prism()
{
    const double s = 2, h = 0.5 * s * std::tan(std::numbers::pi / 3);
    const Vec3<double> left{-std::sin(std::numbers::pi / 3), 0.5, 0}, right{std::sin(std::numbers::pi / 3), 0.5, 0};
    return intersection_of(Plane<double>(left, prism::dot(left, Vec3<double>{-s / 2, 0, 0})),
                           Plane<double>(right, prism::dot(right, Vec3<double>{s / 2, 0, 0})), Plane<double>({0, -1, 0}, 0),
                           Plane<double>({0, 0, 1}, 2), Plane<double>({0, 0, -1}, 2), Box<double>({-s, -0.1, -3}, {s, h + 0.1, 3}));
}

/// The direction of light entering the prism's left face at the angle theta1 from its
/// normal, on the side that takes it through to the right face (travelling up and right).
Vec3<double> incident(double theta1)
{
    const Vec3<double> inward{std::sin(std::numbers::pi / 3), -0.5, 0}, along{0.5, std::sin(std::numbers::pi / 3), 0};
    return std::cos(theta1) * inward + std::sin(theta1) * along;
}

/// The deviation of light of index n through a prism of apex A entering at theta1.
double deviation(double n, double theta1, double apex = std::numbers::pi / 3)
{
    const double theta2 = std::asin(std::sin(theta1) / n), theta3 = apex - theta2;
    return theta1 + std::asin(n * std::sin(theta3)) - apex;
}

} // namespace

TEST_CASE("A dispersive interface refracts each wavelength at its own index: a 60 degree N-BK7 prism at minimum deviation")
{
    const DispersiveDielectric<double> glass{};
    const Vec3<double> left{-std::sin(std::numbers::pi / 3), 0.5, 0}, right{std::sin(std::numbers::pi / 3), 0.5, 0};
    double previous = 0;
    for (double lambda : {fraunhofer::C, fraunhofer::d, fraunhofer::F, 404.66}) {
        const double n = glass::bk7<double>.index(lambda), theta1 = std::asin(n * 0.5);
        const Vec3<double> d0 = incident(theta1);
        const auto in = delta_split(glass, d0, left, true, {}, lambda);
        REQUIRE(in.refracted);
        const auto out = delta_split(glass, *in.refracted, -right, false, {}, lambda);
        REQUIRE(out.refracted);
        const double delta = std::acos(prism::dot(d0, *out.refracted)) * degrees_per_radian;
        CHECK(delta == Approx((2 * std::asin(n * 0.5) - std::numbers::pi / 3) * degrees_per_radian).epsilon(0).scale(1).epsilon(1e-4));
        CHECK(delta > previous); // blue bends more
        previous = delta;
    }
    // White light without a wavelength refracts at n_d.
    CHECK(glass.refractive_index() == Approx(1.51680).epsilon(1e-5));
}

TEST_CASE("White light at a dispersive interface: one refracted ray per band, one white reflected ray, the weights summing to 1")
{
    const DispersiveDielectric<double> glass{};
    const SpectralBands<double> bands(8);
    const Vec3<double> n{0, 1, 0}, d = normalize(Vec3<double>{1, -1, 0});
    const auto hit = Crossing<double>::flat(1, {0, 0, 0}, {0, 0, 0}, n, true);
    Rgb<double> total(0);
    int refracted = 0, reflected = 0;
    const auto air = [](double) { return 1.0; };
    for_each_delta_ray(glass, d, hit, 0.0, bands, air, [&](const Vec3<double>& direction, const Rgb<double>& k, double lambda, bool transmitted) {
        total += k;
        CHECK(transmitted == (prism::dot(direction, n) < 0));
        if (prism::dot(direction, n) > 0) {
            ++reflected;
            CHECK(lambda == 0);
        } else {
            const auto expected = refraction(d, n, glass.refractive_index(lambda));
            CHECK(prism::length(direction - expected->direction) < 1e-15);
            CHECK(lambda == bands[refracted].wavelength_nm);
            ++refracted;
        }
    });
    CHECK(reflected == 1);
    CHECK(refracted == 8);
    CHECK(total.x == Approx(1).epsilon(1e-12));
    CHECK(total.y == Approx(1).epsilon(1e-12));
    CHECK(total.z == Approx(1).epsilon(1e-12));
    // Light that already has a wavelength is not split again.
    int rays = 0;
    for_each_delta_ray(glass, d, hit, 500.0, bands, air, [&](const Vec3<double>&, const Rgb<double>&, double lambda, bool) {
        CHECK(lambda == 500.0);
        ++rays;
    });
    CHECK(rays == 2);
}

TEST_CASE("Wavelength bands: summing to white, signed for camera rays, non-negative for photons, each wavelength inside its band")
{
    for (int count : {1, 2, 3, 7, 8, 16, 32, 64, 81}) {
        const SpectralBands<double> bands(count);
        Rgb<double> sum(0), photon_sum(0);
        double previous = 0;
        for (const auto& band : bands) {
            CHECK(band.photon_weight.x >= 0);
            CHECK(band.photon_weight.y >= 0);
            CHECK(band.photon_weight.z >= 0);
            CHECK(band.wavelength_nm > previous);
            CHECK(band.wavelength_nm >= 380);
            CHECK(band.wavelength_nm <= 780);
            previous = band.wavelength_nm;
            sum += band.weight;
            photon_sum += band.photon_weight;
        }
        for (const Rgb<double>& s : {sum, photon_sum}) {
            CHECK(s.x == Approx(1).epsilon(1e-12));
            CHECK(s.y == Approx(1).epsilon(1e-12));
            CHECK(s.z == Approx(1).epsilon(1e-12));
        }
    }
    // With one band per sample, the signed weights integrate a spectrum as
    // cie::reflectance_to_rgb does (over 380-780 nm rather than 360-830).
    const auto spectrum = [](double lambda) { return 0.5 + 0.4 * std::sin(lambda / 37.0); };
    Rgb<double> banded(0);
    for (const auto& band : SpectralBands<double>(81)) banded += band.weight * spectrum(band.wavelength_nm);
    const Rgb<double> integral = cie::reflectance_to_rgb<double>(spectrum);
    CHECK(std::abs(banded.x - integral.x) < 2e-3);
    CHECK(std::abs(banded.y - integral.y) < 2e-3);
    CHECK(std::abs(banded.z - integral.z) < 2e-3);
    // Blue-green light has negative red: kept for camera rays, clipped for photons.
    const SpectralBands<double> three(3);
    CHECK(three[0].photon_weight.z > 0.9); // 380-515 nm: most of the blue
    CHECK(three[2].photon_weight.y == 0);
    CHECK(three[0].weight.x < 0);
    CHECK(three[0].photon_weight.x == 0);
    CHECK_THROWS_WITH_AS(SpectralBands<double>(0), doctest::Contains("dispersion_bands"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(SpectralBands<double>(82), doctest::Contains("dispersion_bands"), std::invalid_argument);
}

TEST_CASE("Whitted through a glass that does not disperse: the bands add up to the plain dielectric's picture")
{
    const auto scene_with = [](const auto& material) {
        Scene scene{Lights{DirectionalLight<double>{.direction = {0.3, -1, -0.2}, .irradiance = Rgb<double>(3)}},
                    Object{Plane<double>({0, 1, 0}, 0), Diffuse<double, Checker<double>>{.albedo = {.even = {0.9, 0.2, 0.1}, .odd = {0.1, 0.3, 0.9}, .size = 0.5}}},
                    Object{Sphere<double>({0, 1, 0}, 1), material}};
        scene.background = {0.4, 0.6, 0.9};
        return scene;
    };
    const auto flat = scene_with(DispersiveDielectric<double, Cauchy<double>>{.glass = {.a = 1.5, .b = 0, .c = 0}});
    const auto plain = scene_with(Dielectric<double>{.ior = 1.5});
    // No adaptive cut-off: a band's weight is below white's, so it would be cut sooner.
    const Whitted with_bands(flat, {.min_weight = 0, .dispersion_bands = 8});
    const Whitted without(plain, {.min_weight = 0});
    const Camera<double> camera{.position = {0, 1.5, 5}, .look_at = {0, 1, 0}, .up = {0, 1, 0}, .fov = 40};
    const auto rays = camera.rays(32, 24);
    double worst = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) {
            const Ray<double> ray = rays.ray(x + 0.5, y + 0.5);
            const Rgb<double> a = with_bands.radiance(ray), b = without.radiance(ray);
            worst = std::max({worst, std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
        }
    CHECK(worst < 1e-12);
}

TEST_CASE("Photons through a glass prism: every wavelength leaves at 2 asin... its own deviation, blue bent most")
{
    // A parallel beam enters the left face at N-BK7's minimum-deviation angle for the d
    // line; a white wall at x = 8 catches what leaves the right face. With 3 bands each
    // caustic photon's colour names its band; it must arrive along the direction the
    // prism formula gives for its band's wavelength.
    const double theta1 = std::asin(glass::bk7<double>.index(fraunhofer::d) * 0.5);
    const Vec3<double> beam = incident(theta1);
    const Scene scene{Lights{DirectionalLight<double>{.direction = beam, .irradiance = Rgb<double>(1)}},
                      Object{bk7_prism(), DispersiveDielectric<double>{}},
                      Object{Plane<double>({-1, 0, 0}, -8), Diffuse<double>{.albedo = {.color = Rgb<double>(1)}}}};
    const SpectralBands<double> bands(3);
    const PhotonMaps maps = trace_photons(scene, {.global_photons = 0, .caustic_photons = 200000, .shadow_photons = false, .dispersion_bands = 3});
    const auto predicted = [&](int band) { return deviation(glass::bk7<double>.index(bands[band].wavelength_nm), theta1) * degrees_per_radian; };
    int matched[3] = {0, 0, 0}, wrong = 0, others = 0;
    for (const Photon& photon : maps.caustic.photons()) {
        const Rgb<float> p = photon.power();
        // Band 0 (blue) has no red, band 2 (red) no green or blue, band 1 (yellow) no blue.
        const int band = p.z > 0.2f * p.x ? 0 : (p.y > 0.1f * p.x ? 1 : 2);
        const Vec3<double> arrived = -Vec3<double>(photon.toward_source());
        const double delta = std::acos(std::min(1.0, prism::dot(normalize(arrived), beam))) * degrees_per_radian;
        if (std::abs(delta - predicted(band)) < 0.01)
            ++matched[band];
        else if (std::abs(delta - predicted(0)) < 0.01 || std::abs(delta - predicted(1)) < 0.01 || std::abs(delta - predicted(2)) < 0.01)
            ++wrong; // another band's direction: refracted at the wrong index
        else
            ++others; // in through the base, or reflected inside: other deviations
    }
    INFO("matched blue ", matched[0], ", yellow ", matched[1], ", red ", matched[2], "; wrong ", wrong, "; other paths ", others);
    CHECK(wrong == 0);
    for (int b : {0, 1, 2}) CHECK(matched[b] > 1000);
    CHECK(deviation(glass::bk7<double>.index(bands[0].wavelength_nm), theta1) > deviation(glass::bk7<double>.index(bands[2].wavelength_nm), theta1));
}
