// SPDX-License-Identifier: MIT
// Lights{...}: a scene's lights, each of its own type, all of one scalar type.
#pragma once

#include <prism/light/light.hpp>

#include <concepts>
#include <tuple>
#include <type_traits>
#include <utility>

namespace prism {

/// The lights of a scene, each of its own type; none (Lights{}) where the scene's only
/// lights are its emitting objects.
template <Light... Ls>
struct Lights {

    std::tuple<Ls...> items; ///< the lights

    /// The list of `lights`; checks each.
    constexpr explicit Lights(Ls... lights) : items(std::move(lights)...)
    {
        std::apply([](const auto&... light) { (light.validate(), ...); }, items);
    }
};

namespace detail {

template <class X>
struct is_light_list : std::false_type {};
template <class... Ls>
struct is_light_list<Lights<Ls...>> : std::true_type {};

/// The number of lights in a Lights{...}.
template <class List>
inline constexpr std::size_t light_count_of = 0;
template <class... Ls>
inline constexpr std::size_t light_count_of<Lights<Ls...>> = sizeof...(Ls);

/// Whether every light of a Lights{...} is a delta light.
template <class List>
inline constexpr bool all_delta = true;
template <class... Ls>
inline constexpr bool all_delta<Lights<Ls...>> = (is_delta_light<Ls> && ...);

/// Whether some light of a Lights{...} casts its own shadow (has_own_shadow: it may jitter).
template <class List>
inline constexpr bool any_own_shadow = false;
template <class... Ls>
inline constexpr bool any_own_shadow<Lights<Ls...>> = (has_own_shadow<Ls> || ...);

/// Whether every light of the list has scalar type T (true for what is no list: that
/// has its own error).
template <class List, class T>
inline constexpr bool lights_of_scalar = true;
template <class... Ls, class T>
inline constexpr bool lights_of_scalar<Lights<Ls...>, T> = (std::same_as<typename Ls::scalar_type, T> && ...);

} // namespace detail

/// A scene's first argument: Lights{...}.
template <class X>
concept LightList = detail::is_light_list<X>::value;

} // namespace prism
