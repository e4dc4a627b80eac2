// SPDX-License-Identifier: MIT
// dispatch<N>(i, f): call f with the compile-time index I = i, through a table of one
// function per index, built once from the index pack (no recursion over the pack).
#pragma once

#include <prism/core/config.hpp>

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace prism {

/// A compile-time index, as dispatch passes it.
template <std::size_t I>
using Index = std::integral_constant<std::size_t, I>;

namespace detail {

template <std::size_t I, class R, class F>
R call_at(F& f)
{
    return f(Index<I>{});
}

/// One entry an index: a pack expansion, so a table of 1024 entries costs 1024 small
/// instantiations side by side, not a chain 1024 deep.
template <class R, class F, std::size_t... I>
inline constexpr std::array<R (*)(F&), sizeof...(I)> dispatch_table{&call_at<I, R, F>...};

template <class R, class F, std::size_t... I>
constexpr auto table_of(std::index_sequence<I...>) noexcept -> const std::array<R (*)(F&), sizeof...(I)>&
{
    return dispatch_table<R, F, I...>;
}

/// A chain of comparisons, for a few indices: each call inlined where it is made.
template <std::size_t I, std::size_t N, class F>
decltype(auto) dispatch_chain(std::size_t i, F& f)
{
    if constexpr (I + 1 < N) {
        if (i != I) return dispatch_chain<I + 1, N>(i, f);
    }
    return f(Index<I>{});
}

} // namespace detail

/// Up to this many indices, dispatch compares (each call inlined: the Cornell box's three
/// slots render 22 % slower through a table); beyond, it goes through a table.
inline constexpr std::size_t dispatch_chain_up_to = 8;

/// f(Index<i>{}) for a run-time i < N: a scene slot or a light, chosen at run time, with
/// its static type. Every f(Index<I>{}) must return the same type. A few indices are
/// compared in turn; more go through a table (one indirect call), so the cost of a
/// dispatch and the code the compiler instantiates for it grow with N no faster than
/// the table, and no chain of instantiations grows with it.
template <std::size_t N, class F>
decltype(auto) dispatch(std::size_t i, F&& f)
{
    static_assert(N > 0, "dispatch over no index");
    PRISM_ASSERT(i < N);
    using R = decltype(f(Index<0>{}));
    if constexpr (N <= dispatch_chain_up_to) {
        return detail::dispatch_chain<0, N>(i, f);
    } else {
        return detail::table_of<R, std::remove_reference_t<F>>(std::make_index_sequence<N>{})[i](f);
    }
}

} // namespace prism
