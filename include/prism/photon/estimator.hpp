// SPDX-License-Identifier: MIT
// How a photon density estimate gathers and weighs photons: the Estimator's settings
// and the filter kernels over the disk that holds them (PhotonMap reads them).
#pragma once

#include <cmath>
#include <limits>
#include <cstddef>
#include <cstdint>

namespace prism {

/// The density estimate's kernel over the disk of radius r that holds the photons.
enum class Filter : std::uint8_t {
    box,      ///< every photon counts the same
    cone,     ///< weight 1 - d / r (Jensen 1996)
    gaussian, ///< Pavicic's truncated Gaussian, shape as in Jensen (2001), normalised exactly
};

/// How a density estimate gathers and weighs photons.
struct Estimator {
    std::size_t k = 0;   ///< 0: every photon within `radius`; else the k nearest, searched no further than `radius`
    float radius = 0.1f; ///< the fixed radius, or the k-nearest search's maximum distance
    Filter filter = Filter::box; ///< the kernel photons are weighed by
    float max_height_ratio = 1.0f; ///< keep photons within this times r of the tangent plane; < 1 flattens the sphere to a disk against light leaks
    /// Count a photon only where its surface's normal is within acos(surface_cos) of the
    /// query's (60 degrees): not the far side of a thin wall (whose normals are opposite,
    /// the Mitsuba bug), not a perpendicular wall in a corner, but a curved surface that
    /// turns by less than that within r. (Testing the photon's arrival direction instead
    /// drops grazing photons wherever the surface curves: a sphere seen from inside read
    /// 0.8 % low.)
    float surface_cos = 0.5f;
    std::uint8_t excluded = 0;  ///< leave out photons with any of these flags
    /// Leave out photons whose path took more segments from the light than this
    /// (Photon::segments; a path's depth limit: PhotonMapper::Config::max_length).
    int max_segments = std::numeric_limits<int>::max();
};

namespace detail {

/// A filter's weight at squared distance d2 within radius^2 r2, and its mean over the disk
/// (the normalisation: a uniform density gives back itself).
class FilterWeight {
public:
    static constexpr float gaussian_alpha = 0.918f, gaussian_beta = 1.953f;

    /// The Gaussian's constant denominator and every filter's mean are taken here, once
    /// per estimate, not once per photon.
    explicit FilterWeight(Filter filter) noexcept : filter_(filter)
    {
        switch (filter) {
        case Filter::cone: mean_ = 1.0f / 3.0f; break;
        case Filter::gaussian: {
            // With u = d^2 / r^2 uniform on [0, 1], E[exp(-beta u / 2)] = (1 - exp(-beta / 2))
            // / (beta / 2), which gives a mean of 0.531 for Jensen's alpha and beta, not 1:
            // dividing by pi r^2 alone would halve the estimate.
            gaussian_denominator_ = 1.0f - std::exp(-gaussian_beta);
            const float m = (1.0f - std::exp(-gaussian_beta / 2.0f)) / (gaussian_beta / 2.0f);
            mean_ = gaussian_alpha * (1.0f - (1.0f - m) / gaussian_denominator_);
            break;
        }
        case Filter::box: break;
        }
    }

    [[nodiscard]] float operator()(float d2, float r2) const noexcept
    {
        switch (filter_) {
        case Filter::cone: return 1.0f - std::sqrt(d2 / r2);
        case Filter::gaussian:
            return gaussian_alpha * (1.0f - (1.0f - std::exp(-gaussian_beta * d2 / (2.0f * r2))) / gaussian_denominator_);
        case Filter::box: break;
        }
        return 1.0f;
    }

    /// Mean weight over the disk. Box 1, cone 1/3, Gaussian 0.531.
    [[nodiscard]] float mean() const noexcept { return mean_; }

private:
    Filter filter_;
    float gaussian_denominator_ = 1.0f;
    float mean_ = 1.0f;
};

} // namespace detail

} // namespace prism
