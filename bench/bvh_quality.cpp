// SPDX-License-Identifier: MIT
// The Bvh's build settings: build time against trace time (and the tree's SAH cost),
// for binned splits of 4, 16 and 64 bins and the full sweep, on spheres and triangles.
//
// Geometry: N random spheres in [-1, 1]^3 filling 5 % of it (N = 1e4, 1e5, 1e6), a
// geodesic sphere of 327,680 triangles and a terrain of 10^6 triangles. Rays: 512^2
// primary rays from a camera and one cosine bounce ray from each primary hit, closest
// hit on one thread. Times: the minimum over `repeats` rounds, the settings interleaved
// within each round.
//   bench_bvh_quality [results-folder] [repeats]
#include "common.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace prism;
using T = float;

struct Setting {
    const char* name;
    BvhConfig config;
};

const Setting settings[] = {
    {"binned 4", {.bins = 4}},
    {"binned 16", {.bins = 16}},
    {"binned 64", {.bins = 64}},
    {"sweep", {.split = BvhSplit::sweep}},
};

std::vector<Ray<T>> camera_rays(int size)
{
    std::vector<Ray<T>> rays;
    const Vec3<T> eye{T(0.3), T(0.4), T(-4)};
    const Vec3<T> forward = normalize(-eye);
    const Vec3<T> right = normalize(cross(forward, Vec3<T>(0, 1, 0))), up = cross(right, forward);
    const T scale = T(1.3) / length(eye);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const T u = (T(2) * (T(x) + T(0.5)) / T(size) - T(1)) * scale, v = (T(1) - T(2) * (T(y) + T(0.5)) / T(size)) * scale;
            rays.push_back({eye, normalize(forward + u * right + v * up)});
        }
    return rays;
}

/// Primary rays and a cosine bounce ray from each primary hit; hit(ray) gives the
/// crossing (with its surface) or nothing.
template <class Hit>
std::vector<Ray<T>> with_bounces(std::vector<Ray<T>> rays, Hit&& hit)
{
    Random rng(7u, 7u);
    const std::size_t primary = rays.size();
    for (std::size_t i = 0; i < primary; ++i)
        if (const auto c = hit(rays[i])) rays.push_back(spawn_ray(c->point, c->error, c->normal, cosine_hemisphere(c->facing_normal(), rng)));
    return rays;
}

/// Spheres through a Bvh over them: the nearest crossing's t.
struct SphereSet {
    std::vector<Sphere<T>> balls; ///< in the Bvh's leaf order
    Bvh<T> bvh;

    SphereSet(const std::vector<Sphere<T>>& input, const BvhConfig& config)
    {
        std::vector<Aabb<T>> boxes;
        for (const auto& b : input) boxes.push_back(b.bounds());
        bvh = Bvh<T>(boxes, config);
        for (const std::uint32_t p : bvh.primitives()) balls.push_back(input[p]);
    }

    [[nodiscard]] const Bvh<T>& tree() const { return bvh; }

    [[nodiscard]] T nearest(const Ray<T>& ray) const
    {
        Interval<T> range{T(0), infinity<T>};
        T best = infinity<T>;
        bvh.traverse_in_leaf_order(ray, range, [&](std::uint32_t k, Interval<T>& r) {
            const T t = balls[k].first_crossing(ray, r);
            if (t < r.max) r.max = best = t;
            return false;
        });
        return best;
    }

    [[nodiscard]] std::optional<Crossing<T>> hit(const Ray<T>& ray) const
    {
        Interval<T> range{T(0), infinity<T>};
        std::optional<Crossing<T>> best;
        bvh.traverse_in_leaf_order(ray, range, [&](std::uint32_t k, Interval<T>& r) {
            const auto c = balls[k].crossings(ray, r);
            if (!c.empty() && c.front().t < r.max) r.max = c.front().t, best = c.front();
            return false;
        });
        return best;
    }
};

struct MeshSet {
    TriangleMesh<T> mesh;

    /// The setting, with the mesh's blocks of four triangles a leaf test.
    MeshSet(const MeshBuffers<T>& buffers, BvhConfig config)
        : mesh(buffers.positions, buffers.triangles, (config.leaf_block = TriangleMesh<T>::bvh_config().leaf_block, config))
    {
    }

    [[nodiscard]] const Bvh<T>& tree() const { return mesh.bvh(); }

    [[nodiscard]] T nearest(const Ray<T>& ray) const { return mesh.first_crossing(ray, {T(0), infinity<T>}); }

    [[nodiscard]] std::optional<Crossing<T>> hit(const Ray<T>& ray) const
    {
        const auto c = mesh.crossings(ray, {T(0), infinity<T>});
        if (c.empty()) return std::nullopt;
        return c.front();
    }
};

/// Builds every setting (timed), traces the rays through each (timed, interleaved) and
/// writes a row per setting.
template <class Set, class Input>
void measure(bench::Csv& csv, const std::string& geometry, std::size_t count, const Input& input, int repeats)
{
    std::vector<Set> sets;
    std::vector<double> build(std::size(settings), 1e300), trace(std::size(settings), 1e300);
    for (std::size_t s = 0; s < std::size(settings); ++s) {
        const auto start = std::chrono::steady_clock::now();
        sets.emplace_back(input, settings[s].config);
        build[s] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    const auto rays = with_bounces(camera_rays(512), [&](const Ray<T>& r) { return sets[1].hit(r); });
    std::vector<double> sums(std::size(settings), 0);
    for (int round = 0; round < repeats; ++round)
        for (std::size_t s = 0; s < std::size(settings); ++s) {
            double sum = 0;
            trace[s] = std::min(trace[s], bench::min_seconds(1, [&] {
                                    for (const Ray<T>& r : rays) sum += double(std::min(sets[s].nearest(r), T(100)));
                                }));
            sums[s] = sum;
        }
    for (std::size_t s = 0; s < std::size(settings); ++s) {
        const Bvh<T>& bvh = sets[s].tree();
        const double mrays = double(rays.size()) / trace[s] / 1e6;
        csv.row("%s,%zu,%s,%.5f,%.4f,%.4f,%zu,%d", geometry.c_str(), count, settings[s].name, build[s], mrays, bvh.sah_cost(), bvh.nodes().size(), int(sums[s] == sums[1]));
        std::printf("%-8s %8zu %-10s build %8.4f s, trace %6.2f Mrays/s, SAH cost %7.3f, %zu nodes, same hits as binned 16: %s\n", geometry.c_str(), count, settings[s].name,
                    build[s], mrays, bvh.sah_cost(), bvh.nodes().size(), sums[s] == sums[1] ? "yes" : "NO");
        std::fflush(stdout);
    }
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
    if (repeats < 1) {
        std::fprintf(stderr, "bench_bvh_quality: repeats must be >= 1, got '%s'\n", argv[2]);
        return 2;
    }
    bench::Csv csv(out / "bvh_quality.csv", "geometry,count,setting,build_s,mrays,sah_cost,nodes,same_hits");
    for (const std::size_t n : {std::size_t(10000), std::size_t(100000), std::size_t(1000000)}) {
        Random rng(1u, 1u);
        const T radius = T(std::cbrt(0.05 * 8 / (4.0 / 3 * pi<double> * double(n))));
        std::vector<Sphere<T>> balls;
        for (std::size_t i = 0; i < n; ++i)
            balls.emplace_back(Vec3<T>{T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1)}, radius);
        measure<SphereSet>(csv, "spheres", n, balls, repeats);
    }
    const auto sphere = icosphere<T>({T(0), T(0), T(0)}, T(1), 7);
    measure<MeshSet>(csv, "sphere", sphere.triangles.size(), sphere, repeats);
    const auto terrain = height_field<T>(T(-1.5), T(1.5), T(-1.5), T(1.5), 707, [](T x, T z) {
        return T(0.15) * std::sin(T(7) * x) * std::cos(T(5) * z) + T(0.05) * std::sin(T(31) * x + T(17) * z) - T(0.3);
    });
    measure<MeshSet>(csv, "terrain", terrain.triangles.size(), terrain, repeats);
    return 0;
}
