// SPDX-License-Identifier: MIT
#include <prism/material/conductor.hpp>
#include <prism/material/scattering.hpp>
#include <prism/spectrum/bands.hpp>
#include <prism/spectrum/metals.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

using doctest::Approx;
namespace metals = prism::metals;

TEST_CASE("Measured metals: normal-incidence R0 at tabulated wavelengths is ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2)")
{
    for (const auto* metal : {&metals::gold, &metals::silver, &metals::copper, &metals::aluminium}) {
        const prism::MeasuredConductor<double> conductor(*metal);
        for (int i = 0; i < metals::MeasuredIndex::count; i += 5) {
            const double n = metal->eta[std::size_t(i)], k = metal->k[std::size_t(i)];
            const double r0 = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
            CHECK(conductor.spectral_reflectance(1.0, metals::MeasuredIndex::wavelength(i)) == Approx(r0).epsilon(1e-12));
        }
        // Grazing incidence reflects everything, at every wavelength and in RGB.
        CHECK(conductor.spectral_reflectance(0.0, 550.0) == Approx(1).epsilon(1e-12));
        const auto grazing = conductor.reflectance(0.0);
        CHECK(grazing.x == Approx(1).epsilon(1e-9));
        CHECK(grazing.y == Approx(1).epsilon(1e-9));
        CHECK(grazing.z == Approx(1).epsilon(1e-9));
    }
    // The table is energy-ordered: entry 0 at 1.40 eV (885.6 nm), the last at 4.15 eV.
    CHECK(metals::MeasuredIndex::wavelength(0) == Approx(885.601).epsilon(1e-5));
    CHECK(metals::MeasuredIndex::wavelength(55) == Approx(298.757).epsilon(1e-5));
    // Between entries the index is linear in photon energy.
    const double e = 0.5 * (1.40 + 1.45), n_mid = 0.5 * (metals::gold.eta[0] + metals::gold.eta[1]);
    CHECK(metals::gold.at(metals::hc_ev_nm / e).real() == Approx(n_mid).epsilon(1e-12));
}

TEST_CASE("Measured metals in RGB: the colours published for these metals (Real-Time Rendering, 4th ed., table 9.2)")
{
    // Linear sRGB F0 of the same kind of measured data, integrated likewise; gold's red
    // is outside the sRGB gamut (1.022 here) and both clip it to 1.
    struct Case {
        const metals::MeasuredIndex* metal;
        prism::Rgb<double> published;
    };
    for (const Case& c : {Case{&metals::gold, {1.000, 0.782, 0.344}}, Case{&metals::silver, {0.972, 0.960, 0.915}},
                          Case{&metals::copper, {0.955, 0.638, 0.538}}, Case{&metals::aluminium, {0.913, 0.922, 0.924}}}) {
        const auto f0 = prism::MeasuredConductor<double>(*c.metal).reflectance(1.0);
        CHECK(std::abs(f0.x - c.published.x) < 3e-3);
        CHECK(std::abs(f0.y - c.published.y) < 3e-3);
        CHECK(std::abs(f0.z - c.published.z) < 3e-3);
    }
}

TEST_CASE("MeasuredConductor's table against its exact integral at 10^4 cosines")
{
    for (const auto* metal : {&metals::gold, &metals::silver, &metals::copper, &metals::aluminium}) {
        const prism::MeasuredConductor<double> conductor(*metal);
        double worst = 0;
        for (int i = 0; i <= 10000; ++i) {
            const double c = i / 10000.0;
            const auto a = conductor.reflectance(c), b = conductor.integrated_reflectance(c);
            worst = std::max({worst, std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
        }
        CHECK(worst < 5e-4);
    }
}

TEST_CASE("A band of dispersed light meets a measured metal at its own wavelength; the bands add up to the RGB integral")
{
    const auto gold = prism::measured_metal<double>(metals::gold);
    const prism::Vec3<double> d{0.6, -0.8, 0}, up{0, 1, 0};
    // One band: the exact reflectance at its wavelength, the same in every channel.
    const auto band = prism::delta_split(gold, d, up, true, {}, 550.0);
    CHECK(band.kr.x == Approx(gold.fresnel.spectral_reflectance(0.8, 550.0)).epsilon(1e-12));
    CHECK(band.kr.y == band.kr.x);
    CHECK(band.kr.z == band.kr.x);
    // All 81 bands, each weighted by its (signed) share of white, integrate gold's
    // spectrum as the RGB reduction does: gold seen in dispersed light is still gold.
    prism::Rgb<double> sum(0);
    for (const auto& b : prism::SpectralBands<double>(81)) sum += b.weight * gold.fresnel.spectral_reflectance(0.8, b.wavelength_nm);
    const auto integral = prism::cie::reflectance_to_rgb<double>([&](double l) { return gold.fresnel.spectral_reflectance(0.8, l); });
    CHECK(std::abs(sum.x - integral.x) < 3e-3);
    CHECK(std::abs(sum.y - integral.y) < 3e-3);
    CHECK(std::abs(sum.z - integral.z) < 3e-3);
    // White light reads the table: the same integral, clipped to the gamut.
    const auto white = prism::delta_split(gold, d, up, true, {});
    CHECK(white.kr.x == Approx(std::min(integral.x, 1.0)).epsilon(1e-3));
    CHECK(white.kr.z == Approx(integral.z).epsilon(1e-3));
}

TEST_CASE("A measured index with a non-physical entry is refused, naming it")
{
    metals::MeasuredIndex bad = metals::gold;
    bad.eta[7] = -0.2;
    CHECK_THROWS_WITH_AS(prism::MeasuredConductor<float>{bad}, doctest::Contains("MeasuredConductor eta"), std::invalid_argument);
    bad = metals::gold;
    bad.k[3] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH_AS(prism::MeasuredConductor<float>{bad}, doctest::Contains("MeasuredConductor k"), std::invalid_argument);
}
