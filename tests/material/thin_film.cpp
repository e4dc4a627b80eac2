// SPDX-License-Identifier: MIT
#include <prism/material/conductor.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/thin_film.hpp>
#include <prism/optics/fresnel.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using doctest::Approx;
using prism::Rgb;
using prism::Vec3;

namespace {

double worst_channel(const Rgb<double>& a, const Rgb<double>& b)
{
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

/// A soap film 100-900 nm thick, thinning towards +y (drained at the top of a bubble).
struct Draining {
    double operator()(const Vec3<double>& p) const { return 500 - 400 * p.y; }
};

} // namespace

TEST_CASE("A film of zero thickness on glass reflects as the bare glass, grey, from either side")
{
    const prism::CoatedDielectric<double> bare(1.5, 1.33, prism::UniformThickness<double>{0});
    for (double c = 0; c <= 1.0; c += 0.05) {
        for (bool entering : {true, false}) {
            const double eta = entering ? 1.5 : 1 / 1.5;
            const double sin_t2 = (1 - c * c) / (eta * eta);
            if (sin_t2 >= 1) continue; // total internal reflection: never asked
            const double cos_t = std::sqrt(1 - sin_t2);
            const Rgb<double> f = bare.fresnel({c, cos_t, eta, entering, {}});
            const double expected = prism::fresnel_dielectric(c, eta);
            CHECK(worst_channel(f, Rgb<double>(expected)) < 2e-3); // table interpolation in cos_i
        }
    }
}

TEST_CASE("A non-absorbing coated interface reflects alike from inside and along the refracted path from outside")
{
    const prism::CoatedDielectric<double> oil(1.333, 1.47, prism::UniformThickness<double>{300});
    for (double c_out = 0.02; c_out <= 1.0; c_out += 0.07) {
        const double c_in = std::sqrt(1 - (1 - c_out * c_out) / (1.333 * 1.333));
        for (double lambda : {430.0, 550.0, 680.0})
            CHECK(oil.spectral_reflectance(c_in, lambda, 300, false) == Approx(oil.spectral_reflectance(c_out, lambda, 300, true)).epsilon(1e-10));
    }
}

TEST_CASE("FilmTable holds the exact integral at its entries and stays within 1e-2 of it between them (default resolution)")
{
    using Texture = prism::ThicknessTexture<double, Draining>;
    const Texture texture{Draining{}, 100, 900};
    const prism::CoatedDielectric<double, Texture> bubble(1.0, 1.33, texture);
    const auto spectral = [&](double c, double l, double d) { return bubble.spectral_reflectance(c, l, d, true); };
    double worst = 0;
    for (int i = 0; i <= 200; ++i) {
        const double c = 0.05 + 0.95 * i / 200.0;
        for (int j = 0; j <= 40; ++j) {
            const double y = -1 + 2 * j / 40.0, d = Draining{}({0, y, 0});
            const Rgb<double> table = bubble.fresnel({c, c, 1.0, true, {0, y, 0}});
            worst = std::max(worst, worst_channel(table, prism::FilmTable<double>::integrate(spectral, c, d)));
        }
    }
    CHECK(worst < 1e-2); // 7.7e-3 measured, at grazing incidence (bench/thin_film.cpp)
    // At the entries themselves (cos_i = 1, d = 100 + 2 k nm): the integral itself.
    const Rgb<double> at_entry = bubble.fresnel({1.0, 1.0, 1.0, true, {0, 1, 0}}); // d = 100 nm
    CHECK(worst_channel(at_entry, prism::FilmTable<double>::integrate(spectral, 1.0, 100.0)) < 1e-12);
}

TEST_CASE("Soap films: black when far thinner than light's wavelength, coloured at a few hundred nm")
{
    const auto at = [](double d) {
        const prism::CoatedDielectric<double> film(1.0, 1.33, prism::UniformThickness<double>{d});
        return film.fresnel({1.0, 1.0, 1.0, true, {}});
    };
    // A 10 nm film (a bubble about to burst) reflects under 1 % (Isenberg, "The Science of
    // Soap Films and Soap Bubbles": the "black film").
    const Rgb<double> black = at(10);
    CHECK(std::max({black.x, black.y, black.z}) < 0.01);
    // A 4 nd = lambda film for green (n d = 137.5 nm) reflects green most... and its
    // complementary order: the channels differ by far more than the table's error.
    const Rgb<double> coloured = at(550 / (4 * 1.33));
    CHECK(coloured.y > coloured.x);
    CHECK(coloured.y > coloured.z);
    const Rgb<double> magenta = at(550 / (2 * 1.33)); // half-wave for green: green vanishes
    CHECK(magenta.y < 0.5 * magenta.x);
    CHECK(magenta.y < 0.5 * magenta.z);
}

TEST_CASE("A thin film over gold: thickness 0 is bare gold; photons through a coated interface keep their power")
{
    const prism::ThinFilmConductor<double> none(1.6, prism::UniformThickness<double>{0}, prism::metals::gold);
    const prism::MeasuredConductor<double> gold(prism::metals::gold);
    for (double c = 0; c <= 1.0; c += 0.1) CHECK(worst_channel(none.reflectance({c, 0, 1, true, {}}), gold.reflectance(c)) < 2e-3);
    const prism::Conductor<double, prism::ThinFilmConductor<double>> anodised{
        prism::ThinFilmConductor<double>(1.6, prism::UniformThickness<double>{250}, prism::metals::aluminium)};
    static_assert(prism::Material<decltype(anodised)>);
    const auto split = prism::delta_split(anodised, prism::normalize(Vec3<double>{1, -1, 0}), {0, 1, 0}, true, {});
    CHECK(split.kr.x != split.kr.y); // coloured

    // A coated interface splits per channel, R + T = 1 (the film absorbs nothing), and
    // photons choosing between the two by the mean R carry R / mean and T / (1 - mean):
    // the mean power leaving is 1 in every channel.
    const prism::CoatedDielectric<double> oil(1.333, 1.47, prism::UniformThickness<double>{300});
    const Vec3<double> up{0, 1, 0}, d = prism::normalize(Vec3<double>{1, -2, 0});
    const auto s = prism::delta_split(oil, d, up, true, {});
    CHECK(worst_channel(s.kr + s.kt, Rgb<double>(1)) < 1e-12);
    CHECK(!s.fresnel_is_grey());
    // Light of one wavelength (a band of dispersed light) reads the exact Airy value.
    const auto band = prism::delta_split(oil, d, up, true, {}, 550.0);
    const double cos_i = -prism::dot(d, up);
    CHECK(band.kr.x == Approx(oil.spectral_reflectance(cos_i, 550.0, 300.0, true)).epsilon(1e-6));
    CHECK(band.fresnel_is_grey());
    prism::Random rng(5, 9);
    const auto hit = prism::Crossing<double>::flat(1, {0, 0, 0}, {0, 0, 0}, up, true);
    Rgb<double> reflected(0), refracted(0);
    const int n = 400000;
    for (int i = 0; i < n; ++i) {
        Rgb<double> power(1);
        const auto bounce = prism::scatter_photon(oil, hit, d, power, rng);
        REQUIRE(bounce);
        (prism::dot(bounce->direction, up) > 0 ? reflected : refracted) += power;
    }
    reflected /= double(n);
    refracted /= double(n);
    CHECK(worst_channel(reflected, s.kr) < 4e-3);
    CHECK(worst_channel(refracted, s.kt) < 4e-3);
}

TEST_CASE("Bad film parameters are refused, naming them")
{
    CHECK_THROWS_WITH_AS(prism::CoatedDielectric<double>(1.0, -1.33, prism::UniformThickness<double>{300}),
                         doctest::Contains("CoatedDielectric film_index"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(prism::CoatedDielectric<double>(1.0, 1.33, prism::UniformThickness<double>{-3}),
                         doctest::Contains("UniformThickness nm"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(prism::ThinFilmConductor<double>(1.6, prism::UniformThickness<double>{100}, std::complex<double>(0, 3)),
                         doctest::Contains("substrate eta"), std::invalid_argument);
    using Texture = prism::ThicknessTexture<double, Draining>;
    CHECK_THROWS_WITH_AS((prism::CoatedDielectric<double, Texture>(1.0, 1.33, Texture{Draining{}, 900, 100})),
                         doctest::Contains("ThicknessTexture highest"), std::invalid_argument);
}
