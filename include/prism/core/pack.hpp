// SPDX-License-Identifier: MIT
// Pack<Ts...>: a tuple without recursion, for packs of hundreds of types (a scene's slots).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <type_traits>
#include <utility>

namespace prism {

namespace detail {

template <std::size_t I, class T>
struct PackItem {
    T value;
};

/// Every item a base of its own, side by side: std::tuple (libstdc++, libc++) nests one
/// base in the next, so a tuple of N types is N instantiations deep, and 1024 slots pass
/// the compilers' depth limit (900 for g++).
template <class Sequence, class... Ts>
struct PackItems;

template <std::size_t... I, class... Ts>
struct PackItems<std::index_sequence<I...>, Ts...> : PackItem<I, Ts>... {
    constexpr explicit PackItems(Ts... values) : PackItem<I, Ts>{std::move(values)}... {}
};

// Item I by the one base PackItem<I, T>, T deduced: no walk over the pack.
template <std::size_t I, class T>
constexpr const T& item(const PackItem<I, T>& p) noexcept
{
    return p.value;
}

template <std::size_t I, class T>
constexpr T& item(PackItem<I, T>& p) noexcept
{
    return p.value;
}

template <std::size_t I, class T>
T item_type(const PackItem<I, T>&); // only in decltype

/// Whether every / some value is true: for a pack expanded into a braced list, which has
/// no depth (clang nests a fold expression's terms, and refuses more than 256).
constexpr bool all_of(std::initializer_list<bool> values) noexcept
{
    for (const bool v : values)
        if (!v) return false;
    return true;
}

constexpr bool any_of(std::initializer_list<bool> values) noexcept
{
    for (const bool v : values)
        if (v) return true;
    return false;
}

} // namespace detail

/// A fixed list of values of the types Ts, item I read by get<I>(pack).
template <class... Ts>
struct Pack : detail::PackItems<std::index_sequence_for<Ts...>, Ts...> {
    /// The number of items.
    static constexpr std::size_t size = sizeof...(Ts);

    /// A pack of `values`, each moved into its item.
    constexpr explicit Pack(Ts... values) : detail::PackItems<std::index_sequence_for<Ts...>, Ts...>(std::move(values)...) {}

    /// f(item 0, item 1, ...), as std::apply.
    template <class F>
    constexpr decltype(auto) apply(F&& f) const
    {
        return [&]<std::size_t... I>(std::index_sequence<I...>) -> decltype(auto) {
            return f(detail::item<I>(*this)...);
        }(std::index_sequence_for<Ts...>{});
    }
};

/// Item I of a pack.
template <std::size_t I, class... Ts>
[[nodiscard]] constexpr const auto& get(const Pack<Ts...>& pack) noexcept
{
    static_assert(I < sizeof...(Ts), "get<I>: I is past the pack's end");
    return detail::item<I>(pack);
}

template <std::size_t I, class... Ts>
[[nodiscard]] constexpr auto& get(Pack<Ts...>& pack) noexcept
{
    static_assert(I < sizeof...(Ts), "get<I>: I is past the pack's end");
    return detail::item<I>(pack);
}

/// The type of item I of a pack.
template <std::size_t I, class P>
using pack_element_t = decltype(detail::item_type<I>(std::declval<const P&>()));

} // namespace prism
