// SPDX-License-Identifier: MIT
// Crossings: every place a ray crosses a solid's boundary, sorted, in fixed capacity.
//
// This is the currency of prism's geometry. A shape reports all its boundary
// crossings inside a parameter range, together with whether the range starts inside
// the solid; CSG combines two such lists into a third (Roth 1982). The capacity N is
// known at compile time (a sphere crosses at most twice), so nothing is allocated.
#pragma once

#include <prism/core/config.hpp>
#include <prism/core/math.hpp>

#include <array>
#include <cstddef>

namespace prism {

/// One boundary crossing of a ray with a solid. Queries without the surface fill in
/// only t and entering.
template <Scalar T>
struct Crossing {
    T t = infinity<T>;    ///< ray parameter
    Vec3<T> point{};      ///< the crossing point, refined onto the surface
    Vec3<T> error{};      ///< absolute error bound of `point`, per axis
    Vec3<T> normal{};     ///< unit outward normal (the gradient of the inside function)
    bool entering = false; ///< the ray goes from outside to inside here (gradient . direction < 0)
};

/// The sorted boundary crossings of a ray within a range, at most N of them.
template <Scalar T, std::size_t N>
struct Crossings {
    static constexpr std::size_t capacity = N;

    std::array<Crossing<T>, N> items{};
    std::size_t count = 0;
    bool inside_at_start = false; ///< the ray is inside the solid at the start of the range

    [[nodiscard]] constexpr std::size_t size() const noexcept { return count; }
    [[nodiscard]] constexpr bool empty() const noexcept { return count == 0; }
    [[nodiscard]] constexpr const Crossing<T>& operator[](std::size_t i) const noexcept { return items[i]; }
    [[nodiscard]] constexpr const Crossing<T>& front() const noexcept { return items[0]; }
    [[nodiscard]] constexpr const Crossing<T>* begin() const noexcept { return items.data(); }
    [[nodiscard]] constexpr const Crossing<T>* end() const noexcept { return items.data() + count; }

    /// Append a crossing at or after the last one.
    constexpr void push_back(const Crossing<T>& c) noexcept
    {
        PRISM_ASSERT(count < N);
        PRISM_ASSERT(count == 0 || items[count - 1].t <= c.t);
        items[count++] = c;
    }
};

} // namespace prism
