// SPDX-License-Identifier: MIT
// Hit: the closest crossing of a ray with a scene, and which object it belongs to.
#pragma once

#include <prism/geometry/crossings.hpp>

#include <cstdint>

namespace prism {

/// The surface a ray meets first: the crossing (point, normal, side) and which object it is.
template <Scalar T>
struct Hit {
    Crossing<T> crossing{};  ///< where, with the outward normal and whether the ray enters
    std::uint32_t slot = 0;  ///< the scene slot (compile-time position) of the object
    std::uint32_t index = 0; ///< the object within its slot
};

} // namespace prism
