// SPDX-License-Identifier: MIT
// White light as a few wavelength bands, for dispersion in an RGB renderer.
//
// Where white light meets a dispersive interface, the renderer follows one ray per band,
// each refracting with the index at its band's wavelength and carrying the band's share
// of white (POV-Ray's `dispersion_samples`, with the shares from the CIE observer rather
// than a hue ramp). The visible range 380-780 nm (81 of the CIE table's 5 nm samples) is
// cut into `count` bands of adjacent samples; a band's share is the linear sRGB of its
// samples under D65 (spectrum/cie.hpp), every channel scaled so that the bands sum to
// (1, 1, 1) (to rounding): white light that meets nothing dispersive is unchanged.
//
// Spectral colours lie outside the sRGB gamut, so a band's share can be negative in a
// channel (blue-green light has negative red). `weight` keeps the sign: camera rays
// summed over all bands then integrate a spectrum exactly as cie::reflectance_to_rgb
// does (a gold mirror seen through a prism keeps gold's colour), and a pixel of pure
// spectral light may come out negative in a channel (written as 0). Photons carry power
// that must not be negative, so they use `photon_weight`: the negative channels set to 0
// and the bands rescaled to sum to white again (a gamut clip, which shifts the colour of
// strongly coloured surfaces seen in dispersed light by up to 0.1 for gold).
#pragma once

#include <prism/core/check.hpp>
#include <prism/spectrum/cie.hpp>

#include <array>

namespace prism {

/// One band: its wavelength (the mean of its samples, nanometres) and its share of
/// white, signed (for camera rays) and clipped to be non-negative (for photons).
template <Scalar T>
struct WavelengthBand {
    T wavelength_nm; ///< the band's wavelength in nanometres
    Rgb<T> weight; ///< its share of white for camera rays (signed)
    Rgb<T> photon_weight; ///< its share of white for photons (non-negative)
};

/// White light cut into `count` bands (1 to max_count).
template <Scalar T>
class SpectralBands {
public:
    /// The CIE table's entry at 380 nm.
    static constexpr int first_sample = (380 - cie::tables::first_nm) / cie::tables::step_nm;
    static constexpr int max_count = 81; ///< one band per 5 nm sample, 380-780 nm

    /// White cut into `count` bands; throws std::invalid_argument for count outside [1, max_count].
    constexpr explicit SpectralBands(int count) : count_(count)
    {
        if (count < 1 || count > max_count) detail::throw_invalid("dispersion_bands must be in [1, ", max_count, "], got ", count);
        std::array<double, 3> total{}, total_clipped{};
        std::array<std::array<double, 3>, max_count> rgb{};
        for (int b = 0; b < count; ++b) {
            // Samples [begin, end) of the 81, split as evenly as integers allow.
            const int begin = b * max_count / count, end = (b + 1) * max_count / count;
            std::array<double, 3> xyz{};
            double lambda = 0;
            for (int s = first_sample + begin; s < first_sample + end; ++s) {
                const double w = cie::tables::d65[s];
                xyz[0] += cie::tables::x_bar[s] * w;
                xyz[1] += cie::tables::y_bar[s] * w;
                xyz[2] += cie::tables::z_bar[s] * w;
                lambda += cie::wavelength(s);
            }
            rgb[std::size_t(b)] = cie::multiply(cie::xyz_to_linear_srgb, xyz);
            for (std::size_t c = 0; c < 3; ++c) {
                const double v = rgb[std::size_t(b)][c];
                total[c] += v;
                total_clipped[c] += v > 0 ? v : 0;
            }
            bands_[std::size_t(b)].wavelength_nm = T(lambda / (end - begin));
        }
        for (int b = 0; b < count; ++b) {
            const auto& v = rgb[std::size_t(b)];
            bands_[std::size_t(b)].weight = {T(v[0] / total[0]), T(v[1] / total[1]), T(v[2] / total[2])};
            const auto clipped = [&](std::size_t c) { return T((v[c] > 0 ? v[c] : 0) / total_clipped[c]); };
            bands_[std::size_t(b)].photon_weight = {clipped(0), clipped(1), clipped(2)};
        }
    }

    /// The number of bands.
    [[nodiscard]] constexpr int size() const noexcept { return count_; }
    /// Band i.
    [[nodiscard]] constexpr const WavelengthBand<T>& operator[](int i) const noexcept { return bands_[std::size_t(i)]; }
    /// The first band.
    [[nodiscard]] constexpr const WavelengthBand<T>* begin() const noexcept { return bands_.data(); }
    /// One past the last band.
    [[nodiscard]] constexpr const WavelengthBand<T>* end() const noexcept { return bands_.data() + count_; }

private:
    int count_;
    std::array<WavelengthBand<T>, max_count> bands_{};
};

} // namespace prism
