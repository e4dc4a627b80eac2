// SPDX-License-Identifier: MIT
#include <doctest/doctest.h>

#include <prism/core/lanes.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>

#if PRISM_VECTOR_EXTENSIONS
namespace {

template <class T, int N>
struct LaneVector {
    typedef T type __attribute__((vector_size(N * sizeof(T))));
};

/// The same bits (so -0 and NaN compare as themselves).
template <class T>
bool lanes_same_bits(T a, T b)
{
    if constexpr (sizeof(T) == 4) return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
    else return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

template <class T, int N>
void check_lanes()
{
    using V = typename LaneVector<T, N>::type;
    using Narrow = typename LaneVector<T, 4>::type;
    static_assert(prism::detail::lane_count<V> == std::size_t(N));
    const T values[] = {T(0), -T(0), T(1.5), -T(3), std::numeric_limits<T>::infinity(), std::numeric_limits<T>::quiet_NaN(),
                        std::numeric_limits<T>::denorm_min()};
    for (const T x : values) {
        V v;
        prism::detail::splat(v, x);
        for (int lane = 0; lane < N; ++lane) CHECK(lanes_same_bits(v[lane], x)); // -0 stays -0: no 0 + x
    }
    const Narrow source{T(1), -T(0), T(7), std::numeric_limits<T>::quiet_NaN()};
    V wide;
    prism::detail::splat_lane<0>(wide, source);
    for (int lane = 0; lane < N; ++lane) CHECK(lanes_same_bits(wide[lane], source[0]));
    prism::detail::splat_lane<1>(wide, source);
    for (int lane = 0; lane < N; ++lane) CHECK(lanes_same_bits(wide[lane], source[1]));
    prism::detail::splat_lane<2>(wide, source);
    for (int lane = 0; lane < N; ++lane) CHECK(lanes_same_bits(wide[lane], source[2]));
    prism::detail::splat_lane<3>(wide, source);
    for (int lane = 0; lane < N; ++lane) CHECK(lanes_same_bits(wide[lane], source[3]));
    // lane_bits against the lane loop, over every mask a comparison can give.
    for (unsigned bits = 0; bits < (1u << N); ++bits) {
        V a, b;
        prism::detail::splat(a, T(0));
        prism::detail::splat(b, T(0));
        for (int lane = 0; lane < N; ++lane) b[lane] = (bits >> lane) & 1u ? T(1) : T(-1);
        CHECK(prism::detail::lane_bits(a < b) == bits);
    }
    // lane_min and lane_max against the scalar rule a < b ? a : b (a > b ? a : b), bit for
    // bit, over every pair of the values (NaN and -0 among them) in every lane.
    constexpr std::size_t count = std::size(values);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = 0; j < count; ++j) {
            V a, b, low, high;
            for (int lane = 0; lane < N; ++lane) a[lane] = values[(i + std::size_t(lane)) % count], b[lane] = values[(j + std::size_t(lane)) % count];
            prism::detail::lane_min(low, a, b);
            prism::detail::lane_max(high, a, b);
            for (int lane = 0; lane < N; ++lane) {
                CHECK(lanes_same_bits(low[lane], a[lane] < b[lane] ? a[lane] : b[lane]));
                CHECK(lanes_same_bits(high[lane], a[lane] > b[lane] ? a[lane] : b[lane]));
            }
        }
}

} // namespace

TEST_CASE("lanes: splat and splat_lane copy bits (a -0 and a NaN too), lane_bits is the comparison's lanes as bits, lane_min and lane_max are the scalar rule")
{
    check_lanes<float, 4>();
    check_lanes<float, 8>();
    check_lanes<double, 4>();
}
#endif
