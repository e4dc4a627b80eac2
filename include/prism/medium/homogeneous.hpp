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
    using scalar_type = T;

    Rgb<T> absorption{T(0)};

    /// exp(-absorption distance), per channel.
    [[nodiscard]] Rgb<T> transmittance(T distance) const noexcept { return beer_lambert(absorption, distance); }

    constexpr void validate() const { detail::require_non_negative("Homogeneous absorption", absorption); }
};

static_assert(Medium<Homogeneous<float>> && Medium<Homogeneous<double>>);

} // namespace prism
