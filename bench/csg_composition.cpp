// SPDX-License-Identifier: MIT
// What composition costs: k spheres as one Union<...> CSG object, against the same k
// spheres as k separate scene objects, and as one ObjectArray; time per closest-hit
// query on the same rays (the picture is the same: a union's outside surface is the
// nearest of its spheres' surfaces). Output: results/csg_composition.csv.
//   bench_csg_composition [results-folder]
#include "common.hpp"

#include <array>
#include <utility>
#include <vector>

namespace {

using namespace prism;
using T = float;

constexpr int rays = 400000;

/// Spheres in a row, overlapping their neighbours, as a snowman lying down.
template <std::size_t K>
std::array<Sphere<T>, K> spheres()
{
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<Sphere<T>, K>{Sphere<T>({T(0.9) * T(I) - T(0.45) * T(K - 1), T(0), T(0)}, T(0.6))...};
    }(std::make_index_sequence<K>{});
}

template <class SceneT>
double ns_per_ray(const SceneT& scene, const std::vector<Ray<T>>& batch, long& hits)
{
    hits = 0;
    const double seconds = bench::min_seconds(5, [&] {
        long h = 0;
        for (const Ray<T>& r : batch) h += scene.closest_hit(r, {T(0), infinity<T>}).has_value();
        hits = h;
    });
    return 1e9 * seconds / double(batch.size());
}

template <std::size_t K>
void measure(bench::Csv& csv, const std::vector<Ray<T>>& batch)
{
    const auto s = spheres<K>();
    const Diffuse<T> m{};
    const Lights lights{PointLight<T>{}};
    long h_union = 0, h_slots = 0, h_array = 0;
    const auto as_union = [&]<std::size_t... I>(std::index_sequence<I...>) { return Scene{lights, Object{union_of(s[I]...), m}}; }(
        std::make_index_sequence<K>{});
    const auto as_slots = [&]<std::size_t... I>(std::index_sequence<I...>) { return Scene{lights, Object{s[I], m}...}; }(std::make_index_sequence<K>{});
    ObjectArray<Sphere<T>, Diffuse<T>> array;
    for (const auto& sphere : s) array.items.emplace_back(sphere, m);
    const Scene as_array{lights, std::move(array)};
    const double u = ns_per_ray(as_union, batch, h_union), o = ns_per_ray(as_slots, batch, h_slots), a = ns_per_ray(as_array, batch, h_array);
    csv.row("%zu,%.3f,%.3f,%.3f,%ld,%ld", K, u, o, a, h_union, h_slots);
    std::printf("%zu spheres: union %6.1f ns/ray, separate objects %6.1f, one ObjectArray %6.1f  (union / separate = %.2f; hits %ld vs %ld)\n",
                K, u, o, a, u / o, h_union, h_slots);
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    // Rays from a circle around the row, aimed at random points near it.
    Random rng(3u, 3u);
    std::vector<Ray<T>> batch;
    for (int i = 0; i < rays; ++i) {
        const T angle = T(2) * pi<T> * rng.uniform<T>();
        const Vec3<T> o{T(6) * std::cos(angle), T(2) * rng.uniform<T>() - T(1), T(6) * std::sin(angle)};
        const Vec3<T> aim{T(8) * rng.uniform<T>() - T(4), T(1.6) * rng.uniform<T>() - T(0.8), T(1.6) * rng.uniform<T>() - T(0.8)};
        batch.push_back({o, normalize(aim - o)});
    }
    bench::Csv csv(out / "csg_composition.csv", "spheres,union_ns,separate_ns,array_ns,union_hits,separate_hits");
    measure<2>(csv, batch);
    measure<4>(csv, batch);
    measure<8>(csv, batch);
    return 0;
}
