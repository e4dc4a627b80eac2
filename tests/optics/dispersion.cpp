// SPDX-License-Identifier: MIT
#include <prism/optics/dispersion.hpp>
#include <prism/optics/refract.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

using doctest::Approx;
namespace fraunhofer = prism::fraunhofer;

TEST_CASE("Schott's N-BK7 and F2 at the Fraunhofer lines: the data sheets' n_d, n_F, n_C and Abbe numbers")
{
    const auto& bk7 = prism::glass::bk7<double>;
    // N-BK7 data sheet: n_F = 1.52238, n_d = 1.51680, n_C = 1.51432, V_d = 64.17.
    CHECK(bk7.index(fraunhofer::d) == Approx(1.51680).epsilon(1e-5));
    CHECK(bk7.index(fraunhofer::F) == Approx(1.52238).epsilon(1e-5));
    CHECK(bk7.index(fraunhofer::C) == Approx(1.51432).epsilon(1e-5));
    CHECK(prism::abbe_number(bk7) == Approx(64.17).epsilon(2e-4));
    // F2 data sheet: n_d = 1.62004, V_d = 36.37.
    CHECK(prism::glass::f2<double>.index(fraunhofer::d) == Approx(1.62004).epsilon(1e-5));
    CHECK(prism::abbe_number(prism::glass::f2<double>) == Approx(36.37).epsilon(2e-4));
    // Normal dispersion: blue bends more than red, the flint more than the crown.
    CHECK(bk7.index(450) > bk7.index(650));
    CHECK(prism::glass::f2<double>.index(fraunhofer::F) - prism::glass::f2<double>.index(fraunhofer::C) >
          bk7.index(fraunhofer::F) - bk7.index(fraunhofer::C));
}

TEST_CASE("Sellmeier and Cauchy against their formulas written out")
{
    const prism::Sellmeier<double> s{{0.5, 0.25, 1.0}, {0.01, 0.04, 100}};
    const double l = 0.55, l2 = l * l;
    CHECK(s.index(550) == Approx(std::sqrt(1 + 0.5 * l2 / (l2 - 0.01) + 0.25 * l2 / (l2 - 0.04) + 1.0 * l2 / (l2 - 100))).epsilon(1e-14));
    const prism::Cauchy<double> c{.a = 1.45, .b = 0.0036, .c = 1e-5};
    CHECK(c.index(550) == Approx(1.45 + 0.0036 / l2 + 1e-5 / (l2 * l2)).epsilon(1e-14));
    CHECK_THROWS_WITH_AS((prism::Cauchy<double>{.a = -1}.validate()), doctest::Contains("Cauchy A"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((prism::Sellmeier<double>{{1, 1, 1}, {0, -1, 0}}.validate()), doctest::Contains("Sellmeier C"), std::invalid_argument);
}

TEST_CASE("a 60 degree BK7 prism at minimum deviation deviates each wavelength by 2 asin(n sin 30) - 60 degrees")
{
    // The symmetric path: inside, the ray runs parallel to the base, so it meets each face
    // at 30 degrees inside; outside, at i = asin(n sin 30). Traced here by refract() at the
    // two faces of the prism (apex up, faces tilted 30 degrees from the vertical).
    const double deg = std::acos(-1.0) / 180;
    const prism::Vec3<double> left_normal{-std::cos(30 * deg), std::sin(30 * deg), 0}, right_normal{std::cos(30 * deg), std::sin(30 * deg), 0};
    for (const double wavelength : {fraunhofer::F, 500.0, fraunhofer::d, 600.0, fraunhofer::C}) {
        const double n = prism::glass::bk7<double>.index(wavelength);
        const double i = std::asin(n * std::sin(30 * deg));
        // Incoming at angle i to the left face's normal, from below-left toward the face.
        const double a = std::atan2(left_normal.y, left_normal.x) + std::acos(-1.0) + i; // opposite the normal, turned by i
        const prism::Vec3<double> in{std::cos(a), std::sin(a), 0};
        const auto inside = prism::refract(in, left_normal, n);
        REQUIRE(inside);
        CHECK(std::abs(inside->y) < 1e-12); // parallel to the base
        const auto out = prism::refract(*inside, -right_normal, 1 / n);
        REQUIRE(out);
        const double deviation = std::acos(prism::clamp(prism::dot(in, *out), -1.0, 1.0)) / deg;
        CHECK(deviation == Approx(2 * std::asin(n * std::sin(30 * deg)) / deg - 60).epsilon(1e-6));
    }
    // Blue deviates more than red: dD = dn / cos(i) radians, (n_F - n_C) / cos(49.3 deg)
    // = 0.00806 / 0.652, about 0.71 degrees more for F than for C in BK7.
    const auto deviation = [&](double wavelength) { return 2 * std::asin(prism::glass::bk7<double>.index(wavelength) * 0.5) / deg - 60; };
    CHECK(deviation(fraunhofer::F) - deviation(fraunhofer::C) == Approx(0.708).epsilon(0.02));
}

TEST_CASE("Water at 20 C: the CRC Handbook's n_F, n_D, n_C and Abbe number")
{
    const auto& water = prism::glass::water<double>;
    CHECK(water.index(fraunhofer::F) == Approx(1.33712).epsilon(1e-6));
    CHECK(water.index(589.2938) == Approx(1.33299).epsilon(1e-6));
    CHECK(water.index(fraunhofer::C) == Approx(1.33115).epsilon(1e-6));
    CHECK((water.index(589.2938) - 1) / (water.index(fraunhofer::F) - water.index(fraunhofer::C)) == Approx(55.8).epsilon(2e-3));
    // The handbook's 1.34275 at the mercury violet line, 404.66 nm, from a fit through F, D, C.
    CHECK(std::abs(water.index(404.66) - 1.34275) < 1e-3);
    // Sellmeier with any number of terms: four, one of them zero, equals three.
    const prism::Sellmeier<double, 4> bk7_4{{1.03961212, 0.231792344, 1.01046945, 0}, {0.00600069867, 0.0200179144, 103.560653, 0}};
    CHECK(bk7_4.index(500) == prism::glass::bk7<double>.index(500));
}
