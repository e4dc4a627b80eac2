// SPDX-License-Identifier: MIT
#include <prism/core/random.hpp>
#include <prism/optics/fresnel.hpp>
#include <prism/optics/thin_film.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <complex>

using doctest::Approx;
using C = std::complex<double>;

namespace {

/// Airy's reflectance in the intensity form for real indices and s polarisation,
/// written independently of the complex amplitudes in thin_film.hpp:
/// R = (r01^2 + r12^2 + 2 r01 r12 cos 2b) / (1 + r01^2 r12^2 + 2 r01 r12 cos 2b).
double airy_intensity_s(double n0, double n1, double n2, double d, double cos0, double lambda)
{
    const double sin0 = std::sqrt(1 - cos0 * cos0);
    const double cos1 = std::sqrt(1 - std::pow(n0 * sin0 / n1, 2)), cos2 = std::sqrt(1 - std::pow(n0 * sin0 / n2, 2));
    const double r01 = (n0 * cos0 - n1 * cos1) / (n0 * cos0 + n1 * cos1);
    const double r12 = (n1 * cos1 - n2 * cos2) / (n1 * cos1 + n2 * cos2);
    const double two_beta = 4 * std::numbers::pi * n1 * d * cos1 / lambda;
    return (r01 * r01 + r12 * r12 + 2 * r01 * r12 * std::cos(two_beta)) /
           (1 + r01 * r01 * r12 * r12 + 2 * r01 * r12 * std::cos(two_beta));
}

} // namespace

TEST_CASE("A film of zero thickness leaves the bare substrate's Fresnel reflectance")
{
    for (double cos0 = 0.02; cos0 <= 1.0; cos0 += 0.07) {
        const prism::FilmStack<double> on_glass{.incident = 1, .film = C(1.38), .thickness_nm = 0, .substrate = C(1.5)};
        CHECK(prism::thin_film(on_glass, cos0, 550.0).reflected() == Approx(prism::fresnel_dielectric(cos0, 1.5)).epsilon(1e-12));
        const C gold(0.306, 2.88);
        const prism::FilmStack<double> on_gold{.incident = 1, .film = C(1.6), .thickness_nm = 0, .substrate = gold};
        CHECK(prism::thin_film(on_gold, cos0, 563.6).reflected() == Approx(prism::fresnel_conductor(cos0, gold)).epsilon(1e-12));
    }
}

TEST_CASE("A non-absorbing film over a non-absorbing substrate has R + T = 1, per polarisation")
{
    prism::Random rng(12, 1);
    for (int i = 0; i < 20000; ++i) {
        const double n0 = 1 + 0.6 * rng.uniform<double>(), n1 = 1 + 1.5 * rng.uniform<double>(), n2 = 1 + rng.uniform<double>();
        const double d = 2000 * rng.uniform<double>(), lambda = 380 + 400 * rng.uniform<double>();
        // Below the critical angle into the substrate (above it, T = 0 and R = 1).
        const double sin_max = std::min(1.0, n2 / n0) * 0.999;
        const double cos0 = std::sqrt(1 - std::pow(sin_max * rng.uniform<double>(), 2));
        const auto f = prism::thin_film(prism::FilmStack<double>{n0, C(n1), d, C(n2)}, cos0, lambda);
        REQUIRE(f.reflectance.s + f.transmittance.s == Approx(1).epsilon(1e-12));
        REQUIRE(f.reflectance.p + f.transmittance.p == Approx(1).epsilon(1e-12));
    }
}

TEST_CASE("A quarter-wave film at its design wavelength gives the textbook minimum ((n0 ns - nf^2) / (n0 ns + nf^2))^2")
{
    // MgF2 (1.38) on crown glass (1.52), designed for 550 nm: the classic 1.26 % coating.
    const double nf = 1.38, ns = 1.52, lambda = 550;
    const prism::FilmStack<double> coating{.incident = 1, .film = C(nf), .thickness_nm = lambda / (4 * nf), .substrate = C(ns)};
    const double expected = std::pow((ns - nf * nf) / (ns + nf * nf), 2);
    CHECK(expected == Approx(0.0126).epsilon(0.01));
    CHECK(prism::thin_film(coating, 1.0, lambda).reflected() == Approx(expected).epsilon(1e-12));
    // It is a minimum: thinner or thicker films reflect more.
    for (double scale : {0.9, 1.1}) {
        auto other = coating;
        other.thickness_nm *= scale;
        CHECK(prism::thin_film(other, 1.0, lambda).reflected() > expected);
    }
    // A half-wave film is absent: a soap film of n d = lambda / 2 in air reflects nothing.
    const prism::FilmStack<double> soap{.incident = 1, .film = C(1.33), .thickness_nm = lambda / (2 * 1.33), .substrate = C(1)};
    CHECK(prism::thin_film(soap, 1.0, lambda).reflected() == Approx(0).epsilon(1e-12));
}

TEST_CASE("Airy's amplitudes against the intensity form of Airy's formula, at chosen angles and wavelengths")
{
    for (double cos0 : {1.0, 0.8, 0.5, 0.2})
        for (double lambda : {420.0, 510.0, 633.0, 700.0})
            for (double d : {80.0, 300.0, 1234.0}) {
                const prism::FilmStack<double> soap{.incident = 1, .film = C(1.33), .thickness_nm = d, .substrate = C(1)};
                CHECK(prism::thin_film(soap, cos0, lambda).reflectance.s == Approx(airy_intensity_s(1, 1.33, 1, d, cos0, lambda)).epsilon(1e-12));
                const prism::FilmStack<double> oil{.incident = 1, .film = C(1.47), .thickness_nm = d, .substrate = C(1.333)};
                CHECK(prism::thin_film(oil, cos0, lambda).reflectance.s == Approx(airy_intensity_s(1, 1.47, 1.333, d, cos0, lambda)).epsilon(1e-12));
            }
}
