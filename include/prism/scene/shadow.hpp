// SPDX-License-Identifier: MIT
// How a shadow ray crosses glass: blocked (its light arrives by a caustic map instead), or
// attenuated by what each dielectric it crosses lets through, and where transmissive
// objects overlap, walked boundary by boundary in the order of their priorities
// (medium/nesting.hpp).
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/nesting.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace prism {

/// How shadow rays treat dielectrics.
enum class ShadowsThroughGlass : bool {
    attenuated, ///< light passes, attenuated by the medium and the transmission tint (Whitted)
    blocked,    ///< glass casts a full shadow: its light arrives by a caustic map instead
};

namespace detail {

/// Where a shadow ray meets a transmissive object's boundary (or starts inside it), kept
/// to resolve overlapping objects by priority; a fixed number, no allocation.
template <Scalar T>
struct ShadowBoundaries {
    struct Boundary {
        T t;
        std::uint32_t slot;
        std::uint32_t index;
        bool entering;
        bool at_start; ///< the ray starts inside the object (no boundary crossed)
    };
    static constexpr std::size_t capacity = 32;
    std::array<Boundary, capacity> items;
    std::size_t count = 0;
    bool overflow = false;

    constexpr void add(const Boundary& b) noexcept
    {
        if (count == capacity) overflow = true;
        else items[count++] = b;
    }

    /// Sort by t; whether two objects' insides overlap anywhere along the ray.
    constexpr bool sort_and_find_overlap() noexcept
    {
        if (overflow) return false;
        for (std::size_t i = 1; i < count; ++i)
            for (std::size_t j = i; j > 0 && items[j].t < items[j - 1].t; --j) std::swap(items[j], items[j - 1]);
        int depth = 0;
        for (std::size_t i = 0; i < count; ++i) {
            depth += items[i].entering || items[i].at_start ? 1 : -1;
            if (depth >= 2) return true;
        }
        return false;
    }
};

/// A shadow ray through overlapping transmissive objects of `scene`: each stretch
/// attenuated by the medium of the object it is in (the highest priority), a
/// transmission tint at each real interface, none at a false one.
template <class SceneT, Scalar T>
[[nodiscard]] Rgb<T> transmittance_by_priority(const SceneT& scene, const Ray<T>& ray, T t_max, const ShadowBoundaries<T>& boundaries) noexcept
{
    Rgb<T> tr{T(1)};
    MediumStack media;
    T previous = T(0);
    const auto attenuate_to = [&](T t) {
        if (const Inside* in = media.top()) {
            scene.visit_material(in->slot, in->index, [&]<class N>(const N& material) {
                if constexpr (transmits<N>) tr *= transmittance_along(material.medium(), ray, previous, t);
            });
        }
        previous = t;
    };
    for (std::size_t i = 0; i < boundaries.count; ++i) {
        const auto& b = boundaries.items[i];
        attenuate_to(b.t);
        scene.visit_material(b.slot, b.index, [&]<class N>(const N& material) {
            if constexpr (transmits<N>) {
                const Inside object{b.slot, b.index, nesting_priority(material)};
                if (b.at_start) {
                    media = media.entered(object);
                    return;
                }
                const Interface face = nested_interface(media, object, b.entering);
                if (face.real) tr *= material.transmission_tint();
                media = face.beyond;
            }
        });
    }
    attenuate_to(t_max);
    return tr;
}

} // namespace detail

} // namespace prism
