// SPDX-License-Identifier: MIT
#include <prism/core/dispatch.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <tuple>

namespace {

/// dispatch<N>(i, f) against the obvious answer: f(Index<I>) for I = i, for every i.
template <std::size_t N>
void check_every_index()
{
    std::array<std::size_t, N> squares{};
    for (std::size_t i = 0; i < N; ++i) squares[i] = i * i;
    for (std::size_t i = 0; i < N; ++i) {
        int calls = 0;
        const std::size_t got = prism::dispatch<N>(i, [&]<std::size_t I>(prism::Index<I>) {
            ++calls;
            static_assert(I < N);
            return I * I; // computed from the compile-time index
        });
        CHECK(got == squares[i]);
        CHECK(calls == 1);
    }
}

/// A function object that may not be copied: it counts the indices it is called with.
struct Counter {
    int count = 0;
    Counter() = default;
    Counter(const Counter&) = delete;
    Counter& operator=(const Counter&) = delete;
    template <std::size_t I>
    void operator()(prism::Index<I>) { count += int(I); }
};

} // namespace

TEST_CASE("dispatch calls f once, with the compile-time index equal to the run-time one: by comparisons and by a table")
{
    check_every_index<1>();
    check_every_index<3>();
    check_every_index<prism::dispatch_chain_up_to>();     // the longest chain
    check_every_index<prism::dispatch_chain_up_to + 1>(); // the shortest table
    check_every_index<300>();
}

TEST_CASE("dispatch hands back what f returns, a reference included, and calls f without copying it")
{
    std::tuple<int, double, char> values{1, 2.5, 'c'};
    // A reference into the tuple, by element type: every branch returns a const void*.
    for (std::size_t i = 0; i < 3; ++i) {
        const void* p = prism::dispatch<3>(i, [&]<std::size_t I>(prism::Index<I>) -> const void* { return &std::get<I>(values); });
        CHECK(p == (i == 0 ? static_cast<const void*>(&std::get<0>(values)) : i == 1 ? static_cast<const void*>(&std::get<1>(values)) : &std::get<2>(values)));
    }
    std::array<int, 20> cells{};
    int& cell = prism::dispatch<20>(13, [&]<std::size_t I>(prism::Index<I>) -> int& { return cells[I]; });
    cell = 7;
    CHECK(cells[13] == 7);
    // A function object that may not be copied is called in place.
    Counter counter;
    prism::dispatch<12>(9, counter);
    prism::dispatch<4>(2, counter);
    CHECK(counter.count == 11);
}
