// SPDX-License-Identifier: MIT
// White light as a few wavelength bands, for dispersion in an RGB renderer.
//
// Where white light meets a dispersive interface, the renderer follows one ray per band,
// each refracting with the index at its band's wavelength and carrying the band's share
// of white (POV-Ray's `dispersion_samples`, with the shares from the CIE observer rather
// than a hue ramp). The visible range 380-780 nm (81 of the CIE table's 5 nm samples) is
// cut into `count` bands of adjacent samples; a band's RGB is the linear sRGB of its
// samples under D65 (spectrum/cie.hpp), negative channels (spectral colours lie outside
// the sRGB gamut) set to 0, and every channel then scaled so that the bands sum to
// exactly (1, 1, 1): white light that meets nothing dispersive is unchanged, and a band
// never carries negative light.
#pragma once

#include <prism/core/check.hpp>
#include <prism/spectrum/cie.hpp>

#include <array>

namespace prism {

/// One band: its wavelength (the mean of its samples, nanometres) and its share of white.
template <Scalar T>
struct WavelengthBand {
    T wavelength_nm;
    Rgb<T> weight;
};

/// White light cut into `count` bands (1 to max_count).
template <Scalar T>
class SpectralBands {
public:
    static constexpr int first_sample = (380 - cie::tables::first_nm) / cie::tables::step_nm;
    static constexpr int max_count = 81; ///< one band per 5 nm sample, 380-780 nm

    constexpr explicit SpectralBands(int count) : count_(count)
    {
        if (count < 1 || count > max_count) detail::throw_invalid("dispersion_bands must be in [1, ", max_count, "], got ", count);
        std::array<double, 3> total{};
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
            for (int c = 0; c < 3; ++c) {
                double& v = rgb[std::size_t(b)][std::size_t(c)];
                v = v > 0 ? v : 0;
                total[std::size_t(c)] += v;
            }
            bands_[std::size_t(b)].wavelength_nm = T(lambda / (end - begin));
        }
        for (int b = 0; b < count; ++b) {
            const auto& v = rgb[std::size_t(b)];
            bands_[std::size_t(b)].weight = {T(v[0] / total[0]), T(v[1] / total[1]), T(v[2] / total[2])};
        }
    }

    [[nodiscard]] constexpr int size() const noexcept { return count_; }
    [[nodiscard]] constexpr const WavelengthBand<T>& operator[](int i) const noexcept { return bands_[std::size_t(i)]; }
    [[nodiscard]] constexpr const WavelengthBand<T>* begin() const noexcept { return bands_.data(); }
    [[nodiscard]] constexpr const WavelengthBand<T>* end() const noexcept { return bands_.data() + count_; }

private:
    int count_;
    std::array<WavelengthBand<T>, max_count> bands_{};
};

} // namespace prism
