// SPDX-License-Identifier: MIT
#include <prism/spectrum/cie.hpp>

#include <doctest/doctest.h>

#include <cmath>

using doctest::Approx;
namespace cie = prism::cie;

namespace {
std::array<double, 2> chromaticity(const std::array<double, 3>& xyz)
{
    const double sum = xyz[0] + xyz[1] + xyz[2];
    return {xyz[0] / sum, xyz[1] / sum};
}
} // namespace

TEST_CASE("The CIE 1931 tables: equal-energy white at (1/3, 1/3), D65 at the CIE's (0.31272, 0.32903)")
{
    // The three matching functions have equal areas, so illuminant E is achromatic.
    double x = 0, y = 0, z = 0;
    for (int i = 0; i < cie::tables::count; ++i) {
        x += cie::tables::x_bar[i];
        y += cie::tables::y_bar[i];
        z += cie::tables::z_bar[i];
    }
    CHECK(x / (x + y + z) == Approx(1.0 / 3).epsilon(2e-4));
    CHECK(y / (x + y + z) == Approx(1.0 / 3).epsilon(2e-4));
    // y-bar peaks at 1 at 555 nm; D65 is 1 at 560 nm.
    CHECK(cie::tables::y_bar[(555 - 360) / 5] == 1.0);
    CHECK(cie::tables::d65[(560 - 360) / 5] == 1.0);
    // CIE 015:2004, table T.3: D65 for the 2-degree observer at x = 0.31272, y = 0.32903.
    const auto d65 = chromaticity(cie::reflectance_to_xyz([](double) { return 1.0; }));
    CHECK(d65[0] == Approx(0.31272).epsilon(1e-4));
    CHECK(d65[1] == Approx(0.32903).epsilon(1e-4));
}

TEST_CASE("XYZ to linear sRGB: the matrix derived from the primaries matches IEC 61966-2-1's to its 4 decimals")
{
    constexpr double iec[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) CHECK(std::abs(cie::xyz_to_linear_srgb[r][c] - iec[r][c]) < 1e-3);
    // sRGB's white point maps to (1, 1, 1) and its primaries to the unit vectors.
    const auto white = cie::multiply(cie::xyz_to_linear_srgb, cie::xyz_of_chromaticity(0.3127, 0.3290));
    for (double c : white) CHECK(c == Approx(1).epsilon(1e-12));
    const auto red = cie::multiply(cie::xyz_to_linear_srgb, cie::xyz_of_chromaticity(0.64, 0.33));
    CHECK(std::abs(red[1]) < 1e-12);
    CHECK(std::abs(red[2]) < 1e-12);
}

TEST_CASE("A reflectance spectrum to RGB: white is exactly white, grey exactly grey, a step towards red is red")
{
    const auto white = cie::reflectance_to_rgb<double>([](double) { return 1.0; });
    CHECK(white.x == 1.0);
    CHECK(white.y == 1.0);
    CHECK(white.z == 1.0);
    const auto grey = cie::reflectance_to_rgb<double>([](double) { return 0.25; });
    CHECK(grey.x == Approx(0.25).epsilon(1e-15));
    CHECK(grey.y == Approx(0.25).epsilon(1e-15));
    CHECK(grey.z == Approx(0.25).epsilon(1e-15));
    // Light above 600 nm only: red, with a luminance Y equal to the share of D65's
    // y-bar-weighted power above 600 nm, computed here from the tables directly.
    const auto step = [](double lambda) { return lambda > 600 ? 1.0 : 0.0; };
    const auto rgb = cie::reflectance_to_rgb<double>(step);
    CHECK(rgb.x > 4 * rgb.y);
    CHECK(rgb.x > 4 * std::abs(rgb.z));
    double above = 0, all = 0;
    for (int i = 0; i < cie::tables::count; ++i) {
        all += cie::tables::y_bar[i] * cie::tables::d65[i];
        if (cie::wavelength(i) > 600) above += cie::tables::y_bar[i] * cie::tables::d65[i];
    }
    CHECK(cie::reflectance_to_xyz(step)[1] == Approx(above / all).epsilon(1e-14));
    // In gamut: clipped to [0, 1] per channel, equal where already inside.
    const auto clipped = cie::reflectance_to_rgb_in_gamut<double>(step);
    CHECK(clipped.x == rgb.x);
    CHECK(clipped.z == std::max(0.0, rgb.z));
}
