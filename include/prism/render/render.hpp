// SPDX-License-Identifier: MIT
// render(): camera rays per pixel, tiles on std::thread workers, one RNG stream per pixel.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/parallel.hpp>
#include <prism/core/rng.hpp>
#include <prism/render/film.hpp>
#include <prism/scene/camera.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <concepts>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

namespace prism {

/// An integrator: the radiance along a camera ray, drawing random numbers from rng.
template <class I>
concept Integrator = requires(const I& integrator, const Ray<typename I::scalar_type>& ray, Pcg32& rng) {
    { integrator.radiance(ray, rng) } -> std::same_as<Rgb<typename I::scalar_type>>;
};

struct RenderConfig {
    int width = 512;
    int height = 512;
    int spp = 1;             ///< samples per pixel; 1 samples the pixel centre
    unsigned threads = 0;    ///< worker threads; 0 = all hardware threads
    std::uint64_t seed = 0;  ///< with the scene and spp, fixes every bit of the image
    bool progress = true;    ///< report progress on stderr once a render passes one second
    int tile_size = 16;      ///< pixels per side of the square work unit
    /// With spp = 1: the pixel's centre (true), or a uniform point in it (false: a render
    /// that is one pass of many, as progressive photon mapping's, then anti-aliases over
    /// its passes).
    bool single_sample_at_centre = true;
};

namespace detail {

/// Sub-pixel position of sample s of n: the centre when n = 1 and `centre`; otherwise
/// jittered in an m x m grid of strata (m = floor(sqrt(n))), any further samples
/// uniform. The jitter is drawn as float in every precision, so float and double renders
/// of one seed sample the same positions and differ only by their arithmetic.
template <Scalar T>
[[nodiscard]] inline std::pair<T, T> pixel_sample(int s, int n, Pcg32& rng, bool centre = true) noexcept
{
    if (n == 1 && centre) return {T(0.5), T(0.5)};
    const int m = static_cast<int>(std::sqrt(static_cast<double>(n)));
    const T u = T(rng.uniform<float>()), v = T(rng.uniform<float>());
    if (s < m * m) return {(T(s % m) + u) / T(m), (T(s / m) + v) / T(m)};
    return {u, v};
}

} // namespace detail

/// Render an image. The same scene, seed and spp give the same bits for any thread
/// count: every pixel draws from its own random stream and is written by one thread.
template <Integrator I>
[[nodiscard]] Film render(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config = {})
{
    using T = typename I::scalar_type;
    if (config.spp < 1) detail::throw_invalid("RenderConfig spp must be >= 1, got ", config.spp);
    if (config.tile_size < 1) detail::throw_invalid("RenderConfig tile_size must be >= 1, got ", config.tile_size);
    const CameraRays<T> rays = camera.rays(config.width, config.height);
    Film film(config.width, config.height);

    // Tile arithmetic in 64 bits: a tile_size of INT_MAX, or 65536^2 one-pixel tiles,
    // overflows int.
    const std::int64_t tile = config.tile_size;
    const std::int64_t tiles_x = (std::int64_t(config.width) - 1) / tile + 1;
    const std::int64_t tiles_y = (std::int64_t(config.height) - 1) / tile + 1;
    const std::int64_t tile_count = tiles_x * tiles_y;
    std::atomic<std::int64_t> next_tile{0};
    std::atomic<std::int64_t> tiles_done{0};
    std::mutex mutex;
    std::condition_variable finished;
    unsigned running = 0;

    const auto work = [&] {
        for (std::int64_t t = next_tile++; t < tile_count; t = next_tile++) {
            const auto x0 = static_cast<int>((t % tiles_x) * tile), y0 = static_cast<int>((t / tiles_x) * tile);
            const auto x1 = static_cast<int>(std::min<std::int64_t>(x0 + tile, config.width));
            const auto y1 = static_cast<int>(std::min<std::int64_t>(y0 + tile, config.height));
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    const auto pixel = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(config.width) + x;
                    Pcg32 rng(config.seed, pixel);
                    Rgb<T> sum{T(0)};
                    for (int s = 0; s < config.spp; ++s) {
                        const auto [dx, dy] = detail::pixel_sample<T>(s, config.spp, rng, config.single_sample_at_centre);
                        sum += integrator.radiance(rays.ray(T(x) + dx, T(y) + dy), rng);
                    }
                    film.set(x, y, sum / T(config.spp));
                }
            ++tiles_done;
        }
        const std::lock_guard lock(mutex);
        if (--running == 0) finished.notify_all();
    };

    unsigned threads = detail::worker_count(config.threads);
    threads = static_cast<unsigned>(std::min<std::int64_t>(threads, tile_count));
    running = threads;
    std::vector<std::thread> workers;
    workers.reserve(threads);
    for (unsigned i = 0; i < threads; ++i) workers.emplace_back(work);

    // Report progress while waiting, once the render has taken more than a second.
    const auto start = std::chrono::steady_clock::now();
    bool reported = false;
    {
        std::unique_lock lock(mutex);
        while (!finished.wait_for(lock, std::chrono::milliseconds(250), [&] { return running == 0; })) {
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (config.progress && seconds > 1.0) {
                std::fprintf(stderr, "\rprism: rendering %3d%% (%.1f s)", static_cast<int>(100 * tiles_done.load() / tile_count), seconds);
                reported = true;
            }
        }
    }
    for (auto& worker : workers) worker.join();
    if (reported) std::fprintf(stderr, "\rprism: rendering 100%%          \n");
    return film;
}

} // namespace prism
