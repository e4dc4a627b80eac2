// SPDX-License-Identifier: MIT
// Where an object is in a scene (its slot, and its index in the slot), and the order that
// settles ties: whatever order a query meets objects in, the answer is the object a scan of
// the slots in turn would have met first.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

namespace prism::detail {

/// An object's place in a scene: its slot, and its index within the slot. Keys order the
/// objects as a scan of the slots in turn meets them, which is how ties are settled.
struct ObjectKey {
    std::uint32_t slot, index; // (no initializers: ShadowKeys' array is left uninitialized)
    [[nodiscard]] constexpr bool before(const ObjectKey& other) const noexcept
    {
        return slot < other.slot || (slot == other.slot && index < other.index);
    }
};

/// No object: a shadow ray that leaves none it may skip (Scene::transmittance).
inline constexpr ObjectKey no_object{~std::uint32_t(0), ~std::uint32_t(0)};

/// The transmissive objects whose boxes a shadow ray meets, gathered by the scene's tree
/// in its own order, to be attenuated in the order of a scan (a product is the same bits
/// only in the same order); a fixed number, no allocation.
struct ShadowKeys {
    static constexpr std::size_t capacity = 64;
    std::array<ObjectKey, capacity> items; // (left uninitialized: clearing it would cost more than most shadow rays)
    std::size_t count = 0;
    bool overflow = false;

    constexpr void add(const ObjectKey& key) noexcept
    {
        if (count == capacity) overflow = true;
        else items[count++] = key;
    }

    /// The keys gathered, sorted (insertion sort: a shadow ray meets few).
    [[nodiscard]] constexpr std::span<const ObjectKey> sorted() noexcept
    {
        for (std::size_t i = 1; i < count; ++i)
            for (std::size_t j = i; j > 0 && items[j].before(items[j - 1]); --j) std::swap(items[j], items[j - 1]);
        return {items.data(), count};
    }
};

} // namespace prism::detail
