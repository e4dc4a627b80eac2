// SPDX-License-Identifier: MIT
// KdTree against brute force: the same neighbours, in the same order, ties included.
#include <prism/accel/kd_tree.hpp>
#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

using prism::ArrayPoints;
using prism::KdTree;
using prism::Neighbour;

namespace {

template <class T>
using P3 = std::array<T, 3>;

/// Every point's (distance, index), sorted: the brute-force answer.
template <class T>
std::vector<Neighbour<T>> brute_force(const std::vector<P3<T>>& points, const P3<T>& q)
{
    std::vector<Neighbour<T>> all;
    for (std::size_t i = 0; i < points.size(); ++i)
        all.push_back({KdTree<ArrayPoints<T, 3>>::distance2(q, points[i]), static_cast<std::uint32_t>(i)});
    std::sort(all.begin(), all.end());
    return all;
}

template <class T, std::size_t K, std::size_t Leaf = 8>
int knn_mismatches(const std::vector<P3<T>>& points, const std::vector<P3<T>>& queries)
{
    const KdTree<ArrayPoints<T, 3>, Leaf> tree(ArrayPoints<T, 3>{points});
    int mismatches = 0;
    for (const auto& q : queries) {
        const auto all = brute_force(points, q);
        const auto got = tree.template nearest<K>(q);
        const std::size_t expected = std::min(K, all.size());
        bool same = got.size() == expected;
        for (std::size_t i = 0; same && i < expected; ++i) same = got[i] == all[i];
        mismatches += !same;
    }
    return mismatches;
}

template <class T>
int radius_mismatches(const std::vector<P3<T>>& points, const std::vector<P3<T>>& queries, T radius)
{
    const KdTree<ArrayPoints<T, 3>> tree(ArrayPoints<T, 3>{points});
    int mismatches = 0;
    for (const auto& q : queries) {
        std::vector<Neighbour<T>> got;
        tree.within(q, radius, [&](std::uint32_t index, T d2) { got.push_back({d2, index}); });
        std::sort(got.begin(), got.end());
        std::vector<Neighbour<T>> expected;
        for (const auto& n : brute_force(points, q))
            if (n.distance2 <= radius * radius) expected.push_back(n);
        mismatches += got != expected;
    }
    return mismatches;
}

template <class T>
std::vector<P3<T>> uniform(prism::Random& rng, std::size_t n, T extent = T(1))
{
    std::vector<P3<T>> out(n);
    for (auto& p : out) p = {extent * rng.uniform<T>(), extent * rng.uniform<T>(), extent * rng.uniform<T>()};
    return out;
}

/// A dense blob (a caustic) in a sparse uniform background.
template <class T>
std::vector<P3<T>> clustered(prism::Random& rng, std::size_t n)
{
    std::vector<P3<T>> out = uniform<T>(rng, n / 4);
    while (out.size() < n) {
        const T r = T(0.02) * std::sqrt(rng.uniform<T>());
        const T a = T(6.2831853) * rng.uniform<T>();
        out.push_back({T(0.5) + r * std::cos(a), T(0.3) + r * std::sin(a), T(0.7)});
    }
    return out;
}

} // namespace

#if PRISM_CONSTEXPR_VECTORS
// Build and query in a constant expression: a 5 x 4 grid of points in the plane. (Where
// clang meets libstdc++ 12, whose vector fill is not constant-evaluable there, the same
// queries run at run time only: PRISM_KD_CONSTEXPR.)
#if defined(__clang__) && defined(__GLIBCXX__)
#define PRISM_KD_CONSTEXPR const
#else
#define PRISM_KD_CONSTEXPR constexpr
#endif
constexpr std::array<std::array<double, 2>, 20> plane_grid = [] {
    std::array<std::array<double, 2>, 20> p{};
    for (int i = 0; i < 20; ++i) p[static_cast<std::size_t>(i)] = {double(i % 5), double(i / 5)};
    return p;
}();
PRISM_KD_CONSTEXPR auto grid_nearest = [] {
    const KdTree<ArrayPoints<double, 2>, 2> tree(ArrayPoints<double, 2>{plane_grid});
    return tree.nearest<3>({2.1, 1.9});
}();
PRISM_KD_CONSTEXPR int grid_within = [] {
    const KdTree<ArrayPoints<double, 2>, 2> tree(ArrayPoints<double, 2>{plane_grid});
    int count = 0;
    tree.within({2.0, 2.0}, 1.0, [&](std::uint32_t, double) { ++count; });
    return count;
}();
#if !(defined(__clang__) && defined(__GLIBCXX__))
// (2, 2) is index 12 at 0.02; then (2, 1) index 7 at 0.82 and (3, 2) index 13 at 0.82: a tie, lower index first.
static_assert(grid_nearest.size() == 3 && grid_nearest[0].index == 12 && grid_nearest[1].index == 7 && grid_nearest[2].index == 13);
static_assert(grid_within == 5); // the point and its four neighbours at distance 1
#endif

TEST_CASE("the compile-time grid queries' answers, at run time")
{
    CHECK((grid_nearest.size() == 3 && grid_nearest[0].index == 12 && grid_nearest[1].index == 7 && grid_nearest[2].index == 13));
    CHECK(grid_within == 5);
}
#endif

TEST_CASE_TEMPLATE("k nearest neighbours equal brute force on random and clustered sets", T, float, double)
{
    prism::Random rng(1u, 1u);
    const auto random_points = uniform<T>(rng, 5000);
    const auto queries = uniform<T>(rng, 300);
    CHECK(knn_mismatches<T, 1>(random_points, queries) == 0);
    CHECK(knn_mismatches<T, 5>(random_points, queries) == 0);
    CHECK(knn_mismatches<T, 50>(random_points, queries) == 0);
    CHECK((knn_mismatches<T, 50, 1>(random_points, queries)) == 0);
    CHECK((knn_mismatches<T, 50, 32>(random_points, queries)) == 0);

    const auto blob = clustered<T>(rng, 5000);
    std::vector<P3<T>> near_blob = uniform<T>(rng, 100);
    for (int i = 0; i < 100; ++i) near_blob.push_back({T(0.5) + T(0.03) * rng.uniform<T>(), T(0.3), T(0.7)});
    CHECK(knn_mismatches<T, 50>(blob, near_blob) == 0);
}

TEST_CASE_TEMPLATE("ties, duplicates, flat sets, one point, none", T, float, double)
{
    prism::Random rng(2u, 2u);
    // 300 copies of one point among others: equal distances resolve by index.
    auto dupes = uniform<T>(rng, 200);
    for (int i = 0; i < 300; ++i) dupes.push_back({T(0.25), T(0.25), T(0.25)});
    for (int i = 0; i < 100; ++i) dupes.push_back(dupes[static_cast<std::size_t>(i)]);
    std::vector<P3<T>> queries = uniform<T>(rng, 50);
    queries.push_back({T(0.25), T(0.25), T(0.25)});
    CHECK(knn_mismatches<T, 50>(dupes, queries) == 0);
    CHECK(radius_mismatches<T>(dupes, queries, T(0.1)) == 0);
    // A regular grid: many equal distances.
    std::vector<P3<T>> lattice;
    for (int x = 0; x < 12; ++x)
        for (int y = 0; y < 12; ++y)
            for (int z = 0; z < 12; ++z) lattice.push_back({T(x), T(y), T(z)});
    std::vector<P3<T>> lattice_queries{{T(5), T(5), T(5)}, {T(5.5), T(5.5), T(5.5)}, {T(0), T(0), T(0)}, {T(11.5), T(3), T(-1)}};
    CHECK(knn_mismatches<T, 50>(lattice, lattice_queries) == 0);
    CHECK(radius_mismatches<T>(lattice, lattice_queries, T(1.5)) == 0);
    // All points on the plane z = 0.5.
    auto flat = uniform<T>(rng, 2000);
    for (auto& p : flat) p[2] = T(0.5);
    CHECK(knn_mismatches<T, 20>(flat, queries) == 0);
    CHECK(radius_mismatches<T>(flat, queries, T(0.05)) == 0);
    // One point, and none.
    const std::vector<P3<T>> one{{T(1), T(2), T(3)}};
    CHECK(knn_mismatches<T, 5>(one, queries) == 0);
    const std::vector<P3<T>> none;
    const KdTree<ArrayPoints<T, 3>> empty(ArrayPoints<T, 3>{none});
    CHECK(empty.template nearest<3>({T(0), T(0), T(0)}).size() == 0);
    int visited = 0;
    empty.within({T(0), T(0), T(0)}, T(10), [&](std::uint32_t, T) { ++visited; });
    CHECK(visited == 0);
}

TEST_CASE_TEMPLATE("radius queries equal brute force", T, float, double)
{
    prism::Random rng(3u, 3u);
    const auto points = clustered<T>(rng, 20000);
    const auto queries = uniform<T>(rng, 200);
    CHECK(radius_mismatches<T>(points, queries, T(0.05)) == 0);
    CHECK(radius_mismatches<T>(points, queries, T(0)) == 0);
    CHECK(radius_mismatches<T>(points, {{T(0.5), T(0.3), T(0.7)}}, T(0.01)) == 0); // inside the blob
}

TEST_CASE_TEMPLATE("k chosen at run time, with a maximum distance, equals brute force", T, float, double)
{
    prism::Random rng(5u, 5u);
    const auto points = clustered<T>(rng, 8000);
    auto queries = uniform<T>(rng, 150);
    queries.push_back({T(0.5), T(0.3), T(0.7)});
    const KdTree<ArrayPoints<T, 3>> tree(ArrayPoints<T, 3>{points});
    int mismatches = 0;
    for (const std::size_t k : {std::size_t(1), std::size_t(7), std::size_t(64), std::size_t(200)})
        for (const T max_radius : {T(0.01), T(0.04), T(0.2), prism::infinity<T>})
            for (const auto& q : queries) {
                std::vector<Neighbour<T>> expected;
                for (const auto& n : brute_force(points, q))
                    if (n.distance2 <= max_radius * max_radius && expected.size() < std::min<std::size_t>(k, 128)) expected.push_back(n);
                const auto got = tree.template nearest<128>(q, k, max_radius); // k = 200 is capped at the capacity 128
                mismatches += !std::equal(got.begin(), got.end(), expected.begin(), expected.end());
            }
    CHECK(mismatches == 0);
    // Unsorted: the same neighbours in heap order, the farthest first.
    for (const auto& q : queries) {
        const auto sorted = tree.template nearest<64>(q, 40, T(0.2));
        const auto heap = tree.template nearest<64, false>(q, 40, T(0.2));
        std::vector<Neighbour<T>> got(heap.begin(), heap.end());
        std::sort(got.begin(), got.end());
        mismatches += !std::equal(got.begin(), got.end(), sorted.begin(), sorted.end());
        if (heap.size() > 0) mismatches += !(heap[0] == sorted[sorted.size() - 1]);
    }
    CHECK(mismatches == 0);
    // Renumbered in tree order: index i is the point order()[i] of the set.
    KdTree<ArrayPoints<T, 3>> renumbered(ArrayPoints<T, 3>{points});
    const std::vector<std::uint32_t> order(renumbered.order().begin(), renumbered.order().end());
    renumbered.index_in_tree_order();
    for (const auto& q : queries) {
        const auto a = tree.template nearest<16>(q), b = renumbered.template nearest<16>(q);
        for (std::size_t i = 0; i < a.size(); ++i) mismatches += !(a[i].distance2 == b[i].distance2 && order[b[i].index] == a[i].index);
    }
    CHECK(mismatches == 0);
    CHECK(tree.template nearest<8>(queries[0], 0, T(1)).size() == 0);
    CHECK(tree.template nearest<8>(queries[0], 8, T(-1)).size() == 0);
}

TEST_CASE("memory and size")
{
    prism::Random rng(4u, 4u);
    const auto points = uniform<float>(rng, 1000);
    const KdTree<ArrayPoints<float, 3>> tree(ArrayPoints<float, 3>{points});
    CHECK(tree.size() == 1000);
    CHECK(tree.memory_bytes() >= 1000 * (12 + 4));
}

TEST_CASE("points with a NaN coordinate are refused, naming the point")
{
    // Regression: a tree over points with NaN coordinates answered 273 of 500 ordinary
    // k-nearest queries wrongly.
    std::vector<std::array<float, 3>> points(100, {0.5f, 0.5f, 0.5f});
    for (std::size_t i = 0; i < points.size(); ++i) points[i][0] = float(i);
    points[37][1] = std::nanf("");
    CHECK_THROWS_WITH_AS((prism::KdTree<prism::ArrayPoints<float, 3>>(prism::ArrayPoints<float, 3>{points})), doctest::Contains("point 37"),
                         std::invalid_argument);
    points[37][1] = std::numeric_limits<float>::infinity(); // infinite coordinates order like any other
    CHECK_NOTHROW((prism::KdTree<prism::ArrayPoints<float, 3>>(prism::ArrayPoints<float, 3>{points})));
}

namespace {

/// A result set of the caller's own: the summed weight 1 - d/r of every point within r
/// (a cone filter), with no list kept at all.
template <class T>
struct ConeSum {
    T radius2;
    T sum = T(0);
    [[nodiscard]] T bound() const noexcept { return radius2; }
    void add(T distance2, std::uint32_t) noexcept { sum += T(1) - std::sqrt(distance2 / radius2); }
};

} // namespace

TEST_CASE_TEMPLATE("the one search takes a result set of the caller's own; KNearest fills the caller's buffer", T, float, double)
{
    static_assert(prism::ResultSet<ConeSum<T>, T> && prism::ResultSet<prism::KNearest<T>, T>);
    prism::Random rng(9u, 9u);
    const auto points = clustered<T>(rng, 5000);
    const KdTree<ArrayPoints<T, 3>> tree(ArrayPoints<T, 3>{points});
    for (const auto& q : uniform<T>(rng, 50)) {
        ConeSum<T> cone{T(0.1) * T(0.1)};
        tree.search(q, cone);
        T expected = T(0);
        for (const auto& n : brute_force(points, q))
            if (n.distance2 <= cone.radius2) expected += T(1) - std::sqrt(n.distance2 / cone.radius2);
        CHECK(cone.sum == doctest::Approx(expected).epsilon(1e-4));
        // A buffer of 10 caps k = 30 at 10: the 10 nearest.
        std::array<Neighbour<T>, 10> buffer;
        prism::KNearest<T> found(buffer, 30, prism::infinity<T>);
        tree.search(q, found);
        found.sort();
        const auto all = brute_force(points, q);
        CHECK(found.size() == 10);
        CHECK(std::equal(found.begin(), found.end(), all.begin()));
    }
}

TEST_CASE("a tree built on several threads is the tree built on one, and answers as brute force")
{
    // 300 000 points: ranges above 2^15 are split on threads of their own.
    prism::Random rng(21u, 21u);
    const auto points = clustered<float>(rng, 300000);
    const KdTree<ArrayPoints<float, 3>> one(ArrayPoints<float, 3>{points}, 1), three(ArrayPoints<float, 3>{points}, 3);
    CHECK(std::ranges::equal(one.order(), three.order()));
    const auto queries = uniform<float>(rng, 20);
    for (const auto& q : queries) {
        const auto got = three.nearest<8>(q);
        const auto all = brute_force(points, q);
        for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i] == all[i]);
    }
}

TEST_CASE_TEMPLATE("segment queries (the beam estimate's) equal brute force: the points within r of the line whose projections lie on the segment", T, float, double)
{
    prism::Random rng(5u, 8u);
    const auto points = clustered<T>(rng, 20000);
    const KdTree<ArrayPoints<T, 3>> tree(ArrayPoints<T, 3>{points});
    int mismatches = 0, found = 0;
    for (int q = 0; q < 300; ++q) {
        const auto start = uniform<T>(rng, 1)[0];
        // Random directions, some along an axis (a zero component), lengths and radii.
        prism::Vec3<T> d = prism::uniform_sphere<T>(rng);
        if (q % 5 == 0) d = {T(0), q % 2 ? T(1) : T(-1), T(0)};
        const P3<T> direction{d.x, d.y, d.z};
        const T t_min = q % 3 == 0 ? T(0) : rng.uniform<T>() * T(0.2), t_max = q % 7 == 0 ? prism::infinity<T> : t_min + rng.uniform<T>() * T(1.5);
        const T radius = T(0.002) + rng.uniform<T>() * T(0.05);
        std::vector<std::uint32_t> got, expected;
        tree.along(start, direction, t_min, t_max, radius, [&](std::uint32_t index, T, T) { got.push_back(index); });
        for (std::size_t i = 0; i < points.size(); ++i) {
            const P3<T>& p = points[i];
            const T t = (p[0] - start[0]) * direction[0] + (p[1] - start[1]) * direction[1] + (p[2] - start[2]) * direction[2];
            if (!(t >= t_min && t <= t_max)) continue;
            const T x = p[0] - start[0] - t * direction[0], y = p[1] - start[1] - t * direction[1], z = p[2] - start[2] - t * direction[2];
            if (x * x + y * y + z * z <= radius * radius) expected.push_back(static_cast<std::uint32_t>(i));
        }
        std::sort(got.begin(), got.end());
        if (got != expected) ++mismatches;
        found += int(expected.size());
    }
    CHECK(mismatches == 0);
    CHECK(found > 1000); // the segments pass through the points, not beside them
}
