// SPDX-License-Identifier: MIT
// prism's KdTree against nanoflann (libnanoflann-dev, used here only), on the same points
// and queries in one run: photons on the five walls of a unit box with a dense caustic
// blob on the floor (a tenth of them in a disk of radius 0.15, 8x the walls' density);
// N = 1e5, 1e6, 4e6; 200 000 queries at photon-like positions; k = 50 nearest and radius
// 0.05. Build time and ns per query (one thread): minimum of 3 runs, of 1 for 4e6 (its
// radius queries visit thousands of photons each). Memory. Output: results/kdtree.csv.
//   bench_kdtree [results-folder]
#include "common.hpp"

#include <prism/accel/kd_tree.hpp>

#include <nanoflann.hpp>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <optional>
#include <vector>

namespace {

using Point = std::array<float, 3>;

/// nanoflann's dataset adaptor over the same vector.
struct Cloud {
    const std::vector<Point>* points;
    [[nodiscard]] std::size_t kdtree_get_point_count() const { return points->size(); }
    [[nodiscard]] float kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][dim]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
};
using Nanoflann = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Cloud>, Cloud, 3, std::uint32_t>;

/// Counts and sums the indices it is given (so nothing is optimised away), allocating nothing.
struct CountingResult {
    float radius2;
    std::size_t found = 0;
    std::uint64_t checksum = 0;
    [[nodiscard]] std::size_t size() const { return found; }
    [[nodiscard]] bool full() const { return true; }
    bool addPoint(float d2, std::uint32_t index)
    {
        if (d2 < radius2) ++found, checksum += index;
        return true;
    }
    [[nodiscard]] float worstDist() const { return radius2; }
};

/// A point where photons land: on a wall of the unit box, or in the caustic blob.
Point photon_position(prism::Random& rng)
{
    const float u = rng.uniform<float>(), v = rng.uniform<float>();
    if (rng.uniform<float>() < 0.1f) { // the caustic: a dense disk of radius 0.15 on the floor
        const float r = 0.15f * std::sqrt(u), a = 6.2831853f * v;
        return {0.6f + r * std::cos(a), 0.0f, 0.4f + r * std::sin(a)};
    }
    switch (static_cast<int>(rng.uniform<float>() * 5)) {
    case 0: return {u, 0.0f, v};  // floor
    case 1: return {u, 1.0f, v};  // ceiling
    case 2: return {u, v, 1.0f};  // back
    case 3: return {0.0f, u, v};  // left
    default: return {1.0f, u, v}; // right
    }
}

void run(bench::Csv& csv, std::size_t n, std::size_t query_count)
{
    const int repeats = n >= 4000000 ? 1 : 3;
    prism::Random rng(7u, n);
    std::vector<Point> photons(n);
    for (auto& p : photons) p = photon_position(rng);
    std::vector<Point> queries(query_count);
    for (auto& q : queries) q = photon_position(rng);

    // Build
    using Tree = prism::KdTree<prism::ArrayPoints<float, 3>, 8>;
    std::optional<Tree> ours;
    const double build_ours = bench::min_seconds(repeats, [&] { ours.emplace(prism::ArrayPoints<float, 3>{photons}); });
    const Cloud cloud{&photons};
    std::optional<Nanoflann> theirs;
    const double build_theirs = bench::min_seconds(repeats, [&] {
        theirs.emplace(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
        theirs->buildIndex();
    });

    // k = 50 nearest
    double sum_ours = 0, sum_theirs = 0;
    const double knn_ours = bench::min_seconds(repeats, [&] {
        sum_ours = 0;
        for (const Point& q : queries) {
            const auto found = ours->nearest<50>(q);
            sum_ours += found[found.size() - 1].distance2;
        }
    });
    std::array<std::uint32_t, 50> indices{};
    std::array<float, 50> distances{};
    const double knn_theirs = bench::min_seconds(repeats, [&] {
        sum_theirs = 0;
        for (const Point& q : queries) {
            const std::size_t got = theirs->knnSearch(q.data(), 50, indices.data(), distances.data());
            sum_theirs += distances[got - 1];
        }
    });
    if (std::abs(sum_ours - sum_theirs) > 1e-4 * std::abs(sum_theirs)) std::printf("WARNING: k-NN results differ (%g vs %g)\n", sum_ours, sum_theirs);

    // radius 0.05
    constexpr float radius = 0.05f;
    std::uint64_t found_ours = 0, found_theirs = 0;
    const double radius_ours = bench::min_seconds(repeats, [&] {
        found_ours = 0;
        for (const Point& q : queries) ours->within(q, radius, [&](std::uint32_t, float) { ++found_ours; });
    });
    const double radius_theirs = bench::min_seconds(repeats, [&] {
        found_theirs = 0;
        for (const Point& q : queries) {
            CountingResult result{radius * radius};
            theirs->findNeighbors(result, q.data(), nanoflann::SearchParams());
            found_theirs += result.found;
        }
    });
    if (found_ours != found_theirs) std::printf("note: radius counts %llu vs %llu (nanoflann keeps d < r, prism d <= r)\n",
                                                (unsigned long long)found_ours, (unsigned long long)found_theirs);

    const double q = static_cast<double>(query_count);
    const std::size_t memory_ours = ours->memory_bytes();
    const std::size_t memory_theirs = theirs->usedMemory(*theirs) + n * sizeof(Point); // its index plus the points it reads
    csv.row("%zu,%.6f,%.6f,%.2f,%.2f,%.2f,%.2f,%zu,%zu", n, build_ours, build_theirs, 1e9 * knn_ours / q, 1e9 * knn_theirs / q,
            1e9 * radius_ours / q, 1e9 * radius_theirs / q, memory_ours, memory_theirs);
    std::printf("N = %8zu: build %.3f s vs %.3f s (%.2fx); k=50: %7.0f vs %7.0f ns/query (throughput %.2fx); r=0.05: %7.0f vs %7.0f ns/query "
                "(%.2fx); memory %.1f vs %.1f MB\n",
                n, build_ours, build_theirs, build_theirs / build_ours, 1e9 * knn_ours / q, 1e9 * knn_theirs / q, knn_theirs / knn_ours,
                1e9 * radius_ours / q, 1e9 * radius_theirs / q, radius_theirs / radius_ours, static_cast<double>(memory_ours) / 1e6,
                static_cast<double>(memory_theirs) / 1e6);
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    bench::Csv csv(out / "kdtree.csv", "points,build_prism_s,build_nanoflann_s,knn50_prism_ns,knn50_nanoflann_ns,radius_prism_ns,"
                                       "radius_nanoflann_ns,memory_prism_bytes,memory_nanoflann_bytes");
    const char* only = std::getenv("PRISM_KDTREE_ONLY");
    for (std::size_t n : {std::size_t(100000), std::size_t(1000000), std::size_t(4000000)})
        if (only == nullptr || std::to_string(n) == only) run(csv, n, 200000);
    return 0;
}
