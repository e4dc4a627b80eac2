// SPDX-License-Identifier: MIT
// Homogeneous: a medium that absorbs the same everywhere (Beer-Lambert).
#pragma once

#include <prism/core/check.hpp>
#include <prism/medium/medium.hpp>
#include <prism/optics/beer.hpp>

namespace prism {

/// A uniform absorbing medium: `absorption` is Beer-Lambert's coefficient per unit
/// length, per channel (0: clear).
template <Scalar T = float>
struct Homogeneous {
    /// The precision of the coefficients.
    using scalar_type = T;

    Rgb<T> absorption{T(0)}; ///< absorption coefficient per channel, per unit length

    /// exp(-absorption distance), per channel.
    [[nodiscard]] Rgb<T> transmittance(T distance) const noexcept { return beer_lambert(absorption, distance); }

    /// Throws std::invalid_argument for a negative or non-finite absorption.
    constexpr void validate() const { detail::require_non_negative("Homogeneous absorption", absorption); }
};

static_assert(Medium<Homogeneous<float>> && Medium<Homogeneous<double>>);

} // namespace prism
