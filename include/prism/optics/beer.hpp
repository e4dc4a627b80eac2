// SPDX-License-Identifier: MIT
// Beer-Lambert absorption in a homogeneous medium.
#pragma once

#include <prism/core/math.hpp>

#include <cmath>

namespace prism {

/// Fraction of light left after `distance` through a medium with per-channel
/// attenuation coefficients sigma (solution of dI/dx = -sigma I): exp(-sigma x).
template <Scalar T>
[[nodiscard]] inline Rgb<T> beer_lambert(const Rgb<T>& sigma, T distance) noexcept
{
    return {std::exp(-sigma.x * distance), std::exp(-sigma.y * distance), std::exp(-sigma.z * distance)};
}

} // namespace prism
