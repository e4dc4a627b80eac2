// SPDX-License-Identifier: MIT
// Object: a shape with a material; ObjectArray: many of one type in one scene slot.
#pragma once

#include <prism/geometry/shape.hpp>
#include <prism/material/traits.hpp>

#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace prism {

/// One scene object. Construction validates the material (the shape validated itself).
template <Shape S, Material M>
    requires std::same_as<typename S::scalar_type, typename M::scalar_type>
struct Object {
    /// The shape's precision.
    using scalar_type = typename S::scalar_type;
    /// The shape's type.
    using shape_type = S;
    /// The material's type.
    using material_type = M;

    S shape; ///< where the object is
    M material; ///< what its surface does to light
    bool bounded = false; ///< the shape has finite bounds (set at construction, for culling)

    /// The object of shape `s` and material `m`; throws std::invalid_argument, naming the parameter, for a bad material.
    constexpr Object(S s, M m) : shape(std::move(s)), material(std::move(m))
    {
        material.validate();
        bounded = shape.bounds().bounded();
    }
};

/// Many objects of one shape and material type, chosen at run time, in one scene slot.
template <Shape S, Material M>
    requires std::same_as<typename S::scalar_type, typename M::scalar_type>
struct ObjectArray {
    /// The shapes' precision.
    using scalar_type = typename S::scalar_type;
    /// The shapes' type.
    using shape_type = S;
    /// The materials' type.
    using material_type = M;

    std::vector<Object<S, M>> items; ///< the objects, filled at run time
};

namespace detail {

template <class X>
struct is_slot : std::false_type {};
template <class S, class M>
struct is_slot<Object<S, M>> : std::true_type {};
template <class S, class M>
struct is_slot<ObjectArray<S, M>> : std::true_type {};

} // namespace detail

/// A scene slot: an Object or an ObjectArray.
template <class X>
concept Slot = detail::is_slot<X>::value;

/// The objects of a slot, as a contiguous range.
template <class S, class M>
[[nodiscard]] constexpr std::span<const Object<S, M>> objects_of(const Object<S, M>& object) noexcept
{
    return {&object, 1};
}

template <class S, class M>
[[nodiscard]] constexpr std::span<const Object<S, M>> objects_of(const ObjectArray<S, M>& array) noexcept
{
    return {array.items};
}

} // namespace prism
