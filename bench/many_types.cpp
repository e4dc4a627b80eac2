// SPDX-License-Identifier: MIT
// A scene of many *different* object types against the same objects of one type: N
// spheres spread over S slots, each slot an ObjectArray of its own shape type
// (Kind<I>, a Sphere under another name), against the N spheres in one ObjectArray.
// Time per closest-hit query and per shadow query on the same rays; S is fixed when
// the program is compiled (-DPRISM_BENCH_TYPES=S), N at run time.
//   bench_many_types N [N ...]        prints one CSV line per N on stdout:
//   types,objects,closest_ns_types,closest_ns_one,shadow_ns_types,shadow_ns_one,hits_types,hits_one
// Compiled with -DPRISM_BENCH_RENDER=1 it also renders both scenes with the Whitted
// integrator (a 128 x 128 image, one sample per pixel, one thread), the issue's own
// measure of a scene's cost, and prints a second line per N:
//   render,types,objects,ms_types,ms_one,same_bits
// bench/compile_cost.py compiles it for S = 1 to 1024 and draws the chart.
#include <prism/core/random.hpp>
#include <prism/geometry/sphere.hpp>
#include <prism/light/point_light.hpp>
#include <prism/material/diffuse.hpp>
#include <prism/scene/scene.hpp>
#if PRISM_BENCH_RENDER
#include <prism/integrator/whitted.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#ifndef PRISM_BENCH_TYPES
#define PRISM_BENCH_TYPES 16
#endif

namespace {

using namespace prism;
using T = float;
constexpr std::size_t types = PRISM_BENCH_TYPES;

/// A sphere that is a type of its own: one scene slot per I.
template <std::size_t I>
struct Kind : Sphere<T> {
    using Sphere<T>::Sphere;
};

/// N spheres at random in the cube [-1, 1]^3, sized so that they fill about a tenth of it.
std::vector<Sphere<T>> spheres(std::size_t n)
{
    Random rng(7, 1);
    const T radius = T(0.58) * std::cbrt(T(0.1) / T(n));
    std::vector<Sphere<T>> out;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3<T> c{T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1)};
        out.emplace_back(c, radius);
    }
    return out;
}

/// Rays from a camera at (0, 0, 4) through the cube, and shadow rays from points inside
/// it towards a light at (3, 5, 3).
std::pair<std::vector<Ray<T>>, std::vector<Ray<T>>> rays(std::size_t n)
{
    Random rng(11, 2);
    std::vector<Ray<T>> primary, shadow;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3<T> target{T(2.4) * rng.uniform<T>() - T(1.2), T(2.4) * rng.uniform<T>() - T(1.2), T(0)};
        primary.push_back({{T(0), T(0), T(4)}, target - Vec3<T>{T(0), T(0), T(4)}});
        const Vec3<T> from{T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1)};
        shadow.push_back({from, Vec3<T>{T(3), T(5), T(3)} - from});
    }
    return {primary, shadow};
}

template <class SceneT>
std::pair<double, double> ns_per_ray(const SceneT& scene, const std::vector<Ray<T>>& primary, const std::vector<Ray<T>>& shadow, long& hits)
{
    const auto time = [](auto&& f) {
        double best = 1e300;
        for (int repeat = 0; repeat < 5; ++repeat) {
            const auto start = std::chrono::steady_clock::now();
            f();
            best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        return best;
    };
    long h = 0;
    const double closest = time([&] {
        h = 0;
        for (const Ray<T>& r : primary) h += scene.closest_hit(r, {T(0), infinity<T>}).has_value();
    });
    hits = h;
    volatile T sink = 0;
    const double occluded = time([&] {
        T sum = 0;
        for (const Ray<T>& r : shadow) sum += scene.transmittance(r, T(1)).r;
        sink = sink + sum;
    });
    return {1e9 * closest / double(primary.size()), 1e9 * occluded / double(shadow.size())};
}

template <std::size_t I>
ObjectArray<Kind<I>, Diffuse<T>> slot_of(const std::vector<Sphere<T>>& all)
{
    ObjectArray<Kind<I>, Diffuse<T>> slot;
    for (std::size_t k = I; k < all.size(); k += types) slot.items.emplace_back(Kind<I>(all[k].center(), all[k].radius()), Diffuse<T>{});
    return slot;
}

void measure(std::size_t n)
{
    const std::vector<Sphere<T>> all = spheres(n);
    const auto [primary, shadow] = rays(200000);
    const Lights lights{PointLight<T>{}};
    const auto many = [&]<std::size_t... I>(std::index_sequence<I...>) { return Scene{lights, slot_of<I>(all)...}; }(std::make_index_sequence<types>{});
    ObjectArray<Sphere<T>, Diffuse<T>> array;
    for (const Sphere<T>& s : all) array.items.emplace_back(s, Diffuse<T>{});
    const Scene one{lights, std::move(array)};
    long hits_many = 0, hits_one = 0;
    const auto [closest_many, shadow_many] = ns_per_ray(many, primary, shadow, hits_many);
    const auto [closest_one, shadow_one] = ns_per_ray(one, primary, shadow, hits_one);
    std::printf("%zu,%zu,%.2f,%.2f,%.2f,%.2f,%ld,%ld\n", types, n, closest_many, closest_one, shadow_many, shadow_one, hits_many, hits_one);
#if PRISM_BENCH_RENDER
    const Camera<T> camera{.position = {T(0), T(0), T(4)}, .look_at = {T(0), T(0), T(0)}, .up = {T(0), T(1), T(0)}, .fov = T(40)};
    const RenderConfig config{.width = 128, .height = 128, .spp = 1, .threads = 1, .progress = false};
    const auto render_ms = [&](const auto& scene, Film& film) {
        double best = 1e300;
        for (int repeat = 0; repeat < 3; ++repeat) {
            const auto start = std::chrono::steady_clock::now();
            film = render(camera, Whitted(scene), config);
            best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        return 1e3 * best;
    };
    Film film_many(1, 1), film_one(1, 1);
    const double ms_many = render_ms(many, film_many), ms_one = render_ms(one, film_one);
    bool same = true;
    for (int y = 0; y < config.height; ++y)
        for (int x = 0; x < config.width; ++x) same = same && film_many.at(x, y) == film_one.at(x, y);
    std::printf("render,%zu,%zu,%.2f,%.2f,%d\n", types, n, ms_many, ms_one, same ? 1 : 0);
#endif
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_many_types N [N ...]   (objects; S = %zu types, fixed at compile time)\n", types);
        return 2;
    }
    for (int a = 1; a < argc; ++a) {
        const long n = std::strtol(argv[a], nullptr, 10);
        if (n < long(types)) {
            std::fprintf(stderr, "bench_many_types: N must be at least S = %zu (every type gets an object), got '%s'\n", types, argv[a]);
            return 2;
        }
        measure(std::size_t(n));
    }
}
