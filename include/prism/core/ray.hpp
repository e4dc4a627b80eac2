// SPDX-License-Identifier: MIT
// Ray: an origin and a direction; points along it are origin + t * direction.
#pragma once

#include <prism/core/math.hpp>

namespace prism {

/// A ray. The direction need not be unit length: t is measured in multiples of it.
template <Scalar T>
struct Ray {
    Vec3<T> origin{}; ///< where the ray starts
    Vec3<T> direction{T(0), T(0), T(-1)}; ///< where it goes, of any non-zero length: t counts multiples of it

    /// The point origin + t * direction.
    [[nodiscard]] constexpr Vec3<T> at(T t) const noexcept { return origin + t * direction; }
};

} // namespace prism
