// SPDX-License-Identifier: MIT
// Interval: a range [min, max] of ray parameters or values.
#pragma once

#include <prism/core/math.hpp>

namespace prism {

/// A closed range of reals; empty when min > max.
template <Scalar T>
struct Interval {
    T min = infinity<T>; ///< the lower end
    T max = -infinity<T>; ///< the upper end

    /// Whether the interval holds no value (min > max, or NaN).
    [[nodiscard]] constexpr bool empty() const noexcept { return !(min <= max); }
    /// min <= x <= max.
    [[nodiscard]] constexpr bool contains(T x) const noexcept { return min <= x && x <= max; }
    /// min < x < max.
    [[nodiscard]] constexpr bool surrounds(T x) const noexcept { return min < x && x < max; }
    /// max - min.
    [[nodiscard]] constexpr T size() const noexcept { return max - min; }

    /// Every real number.
    [[nodiscard]] static constexpr Interval universe() noexcept { return {-infinity<T>, infinity<T>}; }
};

} // namespace prism
