// SPDX-License-Identifier: MIT
// From spectra to linear sRGB: the CIE 1931 observer, illuminant D65 and the sRGB
// primaries, so that a reflectance known per wavelength (a metal's, a thin film's)
// becomes the RGB triple the renderer multiplies by, by integration over the visible
// spectrum rather than by sampling three wavelengths.
//
// A reflectance R(lambda) seen under D65 has tristimulus values
//   X = sum R x-bar D65 / sum y-bar D65   (likewise Y, Z; 5 nm steps, as CIE 015 sums)
// and linear sRGB M X, with M the XYZ -> sRGB matrix derived below from the primaries
// and white point of IEC 61966-2-1. A perfect white (R = 1) should give (1, 1, 1); the
// tabulated D65 lands within 2e-3 of the rounded white point sRGB is defined with, so
// the result is divided by the white's RGB (a von Kries correction of that size): a
// reflectance of 1 is exactly white and a grey one exactly grey.
#pragma once

#include <prism/core/math.hpp>
#include <prism/spectrum/cie_tables.hpp>

#include <array>

namespace prism::cie {

/// The wavelengths the tables cover, in nanometres.
inline constexpr double lambda_min = tables::first_nm;
inline constexpr double lambda_max = tables::last_nm;

/// The wavelength of table entry i, in nanometres.
[[nodiscard]] constexpr double wavelength(int i) noexcept { return tables::first_nm + i * tables::step_nm; }

/// A 3x3 matrix in row-major order, usable in constant expressions.
using Matrix3 = std::array<std::array<double, 3>, 3>;

[[nodiscard]] constexpr std::array<double, 3> multiply(const Matrix3& m, const std::array<double, 3>& v) noexcept
{
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

[[nodiscard]] constexpr Matrix3 inverse(const Matrix3& m) noexcept
{
    const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    return {{{c00 / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det, (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det},
             {c01 / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det, (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det},
             {c02 / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det, (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det}}};
}

/// XYZ (Y = 1) of the colour with chromaticity (x, y).
[[nodiscard]] constexpr std::array<double, 3> xyz_of_chromaticity(double x, double y) noexcept
{
    return {x / y, 1.0, (1.0 - x - y) / y};
}

/// The XYZ -> linear sRGB matrix, derived from the sRGB primaries R (0.64, 0.33),
/// G (0.30, 0.60), B (0.15, 0.06) and the D65 white point (0.3127, 0.3290): the
/// columns of sRGB -> XYZ are the primaries scaled so that they sum to the white.
[[nodiscard]] constexpr Matrix3 xyz_to_linear_srgb_matrix() noexcept
{
    const auto r = xyz_of_chromaticity(0.64, 0.33), g = xyz_of_chromaticity(0.30, 0.60), b = xyz_of_chromaticity(0.15, 0.06);
    const Matrix3 primaries{{{r[0], g[0], b[0]}, {r[1], g[1], b[1]}, {r[2], g[2], b[2]}}};
    const auto scale = multiply(inverse(primaries), xyz_of_chromaticity(0.3127, 0.3290));
    Matrix3 to_xyz{};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) to_xyz[row][col] = primaries[row][col] * scale[col];
    return inverse(to_xyz);
}

inline constexpr Matrix3 xyz_to_linear_srgb = xyz_to_linear_srgb_matrix();

namespace detail {

/// Sum over the table of f(i) times D65 times each matching function, divided by the
/// sum of y-bar D65: the XYZ of the reflectance f under D65, with Y = 1 for f = 1.
template <class F>
[[nodiscard]] constexpr std::array<double, 3> xyz_under_d65(F&& f)
{
    std::array<double, 3> xyz{};
    double norm = 0;
    for (int i = 0; i < tables::count; ++i) {
        const double w = tables::d65[i], value = f(i);
        xyz[0] += value * tables::x_bar[i] * w;
        xyz[1] += value * tables::y_bar[i] * w;
        xyz[2] += value * tables::z_bar[i] * w;
        norm += tables::y_bar[i] * w;
    }
    for (double& c : xyz) c /= norm;
    return xyz;
}

/// The linear sRGB of a perfect white reflector under the tabulated D65.
inline constexpr std::array<double, 3> white_rgb = multiply(xyz_to_linear_srgb, xyz_under_d65([](int) { return 1.0; }));

} // namespace detail

/// The linear sRGB of a reflectance spectrum: `reflectance(lambda_nm)` is called at
/// every tabulated wavelength, 360 to 830 nm in 5 nm steps, and integrated under D65
/// (see the top of this file). A reflectance of 1 gives exactly (1, 1, 1).
template <Scalar T, class F>
[[nodiscard]] constexpr Rgb<T> reflectance_to_rgb(F&& reflectance)
{
    const auto rgb = multiply(xyz_to_linear_srgb, detail::xyz_under_d65([&](int i) { return double(reflectance(wavelength(i))); }));
    return {T(rgb[0] / detail::white_rgb[0]), T(rgb[1] / detail::white_rgb[1]), T(rgb[2] / detail::white_rgb[2])};
}

/// The linear sRGB of a reflectance spectrum (values in [0, 1]) clipped to [0, 1] per
/// channel: a colour outside the sRGB gamut (gold's red comes to 1.022, a saturated
/// thin-film green has a negative red) would otherwise make a surface return more light
/// than reaches it in one channel, or a negative amount. The clip is the gamut mapping
/// of every reflectance prism reduces from a spectrum; reflectance_to_rgb is exact.
template <Scalar T, class F>
[[nodiscard]] constexpr Rgb<T> reflectance_to_rgb_in_gamut(F&& reflectance)
{
    const Rgb<T> rgb = reflectance_to_rgb<T>(reflectance);
    return {clamp(rgb.x, T(0), T(1)), clamp(rgb.y, T(0), T(1)), clamp(rgb.z, T(0), T(1))};
}

/// The XYZ of a reflectance spectrum under D65 (Y = 1 for a perfect white), for tests
/// and for colours outside sRGB.
template <class F>
[[nodiscard]] constexpr std::array<double, 3> reflectance_to_xyz(F&& reflectance)
{
    return detail::xyz_under_d65([&](int i) { return double(reflectance(wavelength(i))); });
}

} // namespace prism::cie
