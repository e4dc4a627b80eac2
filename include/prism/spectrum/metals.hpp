// SPDX-License-Identifier: MIT
// Measured complex refractive indices n + i k of metals, for Fresnel reflectance per
// wavelength (optics/fresnel.hpp: fresnel_conductor) and, integrated against the CIE
// observer, per RGB channel (material/conductor.hpp: MeasuredConductor).
//
// The data are measurements of evaporated films (P. B. Johnson and R. W. Christy,
// Phys. Rev. B 6, 4370 (1972), for Au, Ag and Cu; Palik's Handbook of Optical Constants
// of Solids for Al), as resampled to photon energies 1.40 to 4.15 eV in 0.05 eV steps
// (886 to 299 nm) in the metal tables pbrt-v4 ships (Apache-2.0). prism stores them in
// order of increasing photon energy and interpolates linearly in photon energy, the
// variable they were measured on.
#pragma once

#include <prism/core/math.hpp>

#include <array>
#include <complex>

namespace prism::metals {

/// Photon energy (eV) times wavelength (nm): h c.
inline constexpr double hc_ev_nm = 1239.84193;

/// A metal's index n + i k at photon energies 1.40 + 0.05 i eV, i = 0 .. 55 (so in
/// order of increasing energy, decreasing wavelength).
struct MeasuredIndex {
    /// The number of entries.
    static constexpr int count = 56;
    static constexpr double lowest_ev = 1.40; ///< entry 0: 885.6 nm
    static constexpr double step_ev = 0.05;   ///< entry count - 1: 4.15 eV, 298.8 nm

    std::array<double, count> eta; ///< real part n, entry i at energy lowest_ev + i step_ev
    std::array<double, count> k;   ///< extinction coefficient

    /// The wavelength of entry i, in nanometres.
    [[nodiscard]] static constexpr double wavelength(int i) noexcept { return hc_ev_nm / (lowest_ev + step_ev * i); }

    /// The index at `lambda_nm`, linear in photon energy between entries; beyond the
    /// table (below 298.8 or above 885.6 nm, outside the visible) the end entry.
    [[nodiscard]] constexpr std::complex<double> at(double lambda_nm) const noexcept
    {
        const double u = (hc_ev_nm / lambda_nm - lowest_ev) / step_ev;
        if (!(u > 0)) return {eta[0], k[0]};
        if (u >= count - 1) return {eta[count - 1], k[count - 1]};
        const int i = int(u);
        const double f = u - i;
        return {eta[i] + f * (eta[i + 1] - eta[i]), k[i] + f * (k[i + 1] - k[i])};
    }
};

/// Gold (Au).
inline constexpr MeasuredIndex gold{
    .eta = {0.21, 0.198125, 0.188, 0.181375, 0.176, 0.1695, 0.164, 0.160875,
      0.16, 0.161, 0.166, 0.17775, 0.194, 0.212375, 0.236, 0.267625,
      0.306, 0.3455, 0.402, 0.49175, 0.608, 0.7545, 0.916, 1.08675,
      1.242, 1.345875, 1.426, 1.502125, 1.562, 1.59625, 1.616, 1.628,
      1.636, 1.64725, 1.658, 1.666, 1.674, 1.68475, 1.696, 1.705875,
      1.716, 1.727625, 1.74, 1.7525, 1.766, 1.782, 1.798, 1.812,
      1.824, 1.83425, 1.84, 1.837125, 1.83, 1.822625, 1.812, 1.795},
    .k = {5.88, 5.63125, 5.39, 5.125813, 4.86, 4.610188, 4.357, 4.087687,
      3.8, 3.445812, 3.15, 3.07, 3.06, 3.015, 2.97, 2.940625,
      2.88, 2.730625, 2.54, 2.32625, 2.12, 1.9565, 1.84, 1.797375,
      1.796, 1.814625, 1.846, 1.875875, 1.904, 1.9245, 1.94, 1.951375,
      1.958, 1.959375, 1.956, 1.94775, 1.936, 1.9225, 1.906, 1.883,
      1.862, 1.852375, 1.848, 1.84525, 1.846, 1.85175, 1.86, 1.86825,
      1.878, 1.891375, 1.904, 1.911375, 1.916, 1.918875, 1.92, 1.920375}};

/// Silver (Ag).
inline constexpr MeasuredIndex silver{
    .eta = {0.163, 0.151938, 0.145, 0.142563, 0.143, 0.145875, 0.148, 0.144313,
      0.14, 0.140063, 0.14, 0.136125, 0.131, 0.1255, 0.121, 0.119313,
      0.12, 0.124375, 0.129, 0.130063, 0.13, 0.129938, 0.13, 0.13025,
      0.132, 0.137313, 0.144, 0.151063, 0.157, 0.1585, 0.16, 0.166688,
      0.173, 0.172625, 0.173, 0.182, 0.192, 0.198063, 0.2, 0.192063,
      0.186, 0.194813, 0.209, 0.221438, 0.238, 0.253313, 0.294, 0.388125,
      0.526, 0.719062, 0.932, 1.142062, 1.323, 1.4325, 1.496, 1.519},
    .k = {5.95, 5.720624, 5.5, 5.28875, 5.09, 4.908125, 4.74, 4.58625,
      4.44, 4.293125, 4.15, 4.010625, 3.88, 3.76625, 3.66, 3.55375,
      3.45, 3.348125, 3.25, 3.159375, 3.07, 2.97375, 2.88, 2.798125,
      2.72, 2.64, 2.56, 2.47875, 2.4, 2.329375, 2.26, 2.18625,
      2.11, 2.029375, 1.95, 1.87875, 1.81, 1.735, 1.67, 1.641875,
      1.61, 1.53375, 1.44, 1.34525, 1.24, 1.120687, 0.986, 0.818563,
      0.663, 0.554375, 0.504, 0.550875, 0.647, 0.761063, 0.882, 1.08}};

/// Copper (Cu).
inline constexpr MeasuredIndex copper{
    .eta = {0.3, 0.28, 0.26, 0.254188, 0.25, 0.2365, 0.223, 0.21625,
      0.213, 0.20925, 0.214, 0.230813, 0.272, 0.35125, 0.468, 0.645875,
      0.826, 0.950375, 1.04, 1.092437, 1.12, 1.131562, 1.135, 1.142812,
      1.15, 1.155312, 1.16, 1.165312, 1.17, 1.172812, 1.175, 1.178125,
      1.18, 1.1775, 1.175, 1.174375, 1.18, 1.2, 1.225, 1.249062,
      1.27, 1.281563, 1.29, 1.300313, 1.31, 1.317812, 1.325, 1.334375,
      1.34, 1.3325, 1.325, 1.329063, 1.34, 1.358438, 1.38, 1.400313},
    .k = {5.717, 5.485625, 5.26, 5.034125, 4.817, 4.619563, 4.43, 4.239563,
      4.05, 3.863125, 3.67, 3.458187, 3.24, 3.01075, 2.809, 2.678062,
      2.599, 2.5765, 2.583, 2.595562, 2.605, 2.589625, 2.564, 2.535875,
      2.504, 2.469187, 2.433, 2.397625, 2.362, 2.326, 2.289, 2.249938,
      2.21, 2.160063, 2.13, 2.177188, 2.21, 2.121562, 2.015, 1.972438,
      1.95, 1.931688, 1.916, 1.89425, 1.872, 1.85175, 1.834, 1.822125,
      1.81, 1.791625, 1.77, 1.744563, 1.72, 1.703313, 1.687, 1.662125}};

/// Aluminium (Al).
inline constexpr MeasuredIndex aluminium{
    .eta = {2.24, 2.58, 2.74, 2.8, 2.63, 2.41, 2.14, 1.91,
      1.74, 1.6, 1.49, 1.39, 1.3, 1.22, 1.15, 1.08,
      1.02, 0.963, 0.912, 0.867, 0.826, 0.789, 0.755, 0.72375,
      0.695, 0.668625, 0.644, 0.620313, 0.598, 0.577313, 0.558, 0.540063,
      0.523, 0.506188, 0.49, 0.474688, 0.46, 0.445688, 0.432, 0.419125,
      0.407, 0.39575, 0.385, 0.374375, 0.364, 0.353813, 0.344, 0.33475,
      0.326, 0.317875, 0.31, 0.301875, 0.294, 0.286813, 0.28, 0.273375},
    .k = {8.21, 8.21, 8.31, 8.45, 8.6, 8.62, 8.57, 8.39,
      8.21, 8.01, 7.82, 7.65, 7.48, 7.31, 7.15, 7.0,
      6.85, 6.7, 6.55, 6.42, 6.28, 6.15, 6.03, 5.915,
      5.8, 5.69, 5.58, 5.48, 5.38, 5.29, 5.2, 5.10875,
      5.02, 4.938125, 4.86, 4.784375, 4.71, 4.63375, 4.56, 4.49375,
      4.43, 4.365, 4.3, 4.23375, 4.17, 4.11375, 4.06, 4.005,
      3.95, 3.894375, 3.84, 3.789375, 3.74, 3.689375, 3.64, 3.59375}};

} // namespace prism::metals
