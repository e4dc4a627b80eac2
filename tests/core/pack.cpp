// SPDX-License-Identifier: MIT
#include <prism/core/pack.hpp>

#include <doctest/doctest.h>

#include <string>
#include <type_traits>
#include <utility>

namespace {

template <std::size_t I>
struct Tag {
    std::size_t value = I;
};

/// A pack of 1200 distinct types (past g++'s instantiation depth of 900, which a
/// std::tuple of them reaches): every item where it was put.
template <std::size_t... I>
bool every_item_in_place(std::index_sequence<I...>)
{
    const prism::Pack<Tag<I>...> pack{Tag<I>{I * 3}...};
    static_assert(std::is_same_v<prism::pack_element_t<1100, decltype(pack)>, Tag<1100>>);
    const bool in_place[] = {prism::get<I>(pack).value == I * 3 ...}; // (no fold: clang nests one at most 256 deep)
    for (const bool b : in_place)
        if (!b) return false;
    return true;
}

} // namespace

TEST_CASE("a pack holds its items by index, with their types, and applies a function to them all")
{
    constexpr prism::Pack<int, double, char> small{1, 2.5, 'c'};
    static_assert(prism::get<0>(small) == 1 && prism::get<1>(small) == 2.5 && prism::get<2>(small) == 'c');
    static_assert(std::is_same_v<prism::pack_element_t<1, decltype(small)>, double>);
    static_assert(decltype(small)::size == 3);
    CHECK(small.apply([](int a, double b, char c) { return double(a) + b + double(c - 'a'); }) == 5.5);

    prism::Pack<std::string, int> mutable_pack{std::string("moved in"), 4};
    get<0>(mutable_pack) += ", changed"; // found by argument-dependent lookup
    get<1>(mutable_pack) *= 2;
    CHECK(get<0>(mutable_pack) == "moved in, changed");
    CHECK(get<1>(mutable_pack) == 8);
    CHECK(every_item_in_place(std::make_index_sequence<1200>{}));
}
