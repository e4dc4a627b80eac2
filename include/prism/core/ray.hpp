// SPDX-License-Identifier: MIT
// Ray: an origin and a direction; points along it are origin + t * direction.
#pragma once

#include <prism/core/math.hpp>

namespace prism {

/// A ray. The direction need not be unit length: t is measured in multiples of it.
template <Scalar T>
struct Ray {
    Vec3<T> origin{};
    Vec3<T> direction{T(0), T(0), T(-1)};

    /// The point origin + t * direction.
    [[nodiscard]] constexpr Vec3<T> at(T t) const noexcept { return origin + t * direction; }
};

} // namespace prism
