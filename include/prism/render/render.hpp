// SPDX-License-Identifier: MIT
// render(): camera rays per pixel, tiles dealt to worker threads (core/parallel.hpp), one RNG stream per
// sample of each pixel; a crop window or a range of the samples renders a part of the
// image that adds up with the other parts to the whole, bit for bit.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/config.hpp>
#include <prism/core/parallel.hpp>
#include <prism/core/rng.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/film.hpp>
#include <prism/render/layers.hpp>
#include <prism/render/progress.hpp>
#include <prism/scene/camera.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <cstdio>
#include <span>
#include <vector>

namespace prism {

/// What render() renders: size, samples, threads, seed, and the part of the image (crop, passes).
struct RenderConfig {
    int width = 512; ///< image width in pixels
    int height = 512; ///< image height in pixels
    int spp = 1;             ///< samples per pixel; 1 samples the pixel centre
    unsigned threads = 0;    ///< worker threads; 0 = all hardware threads
    std::uint64_t seed = 0;  ///< with the scene and spp, fixes every bit of the image
    bool progress = true;    ///< report progress on stderr once a render passes one second
    int tile_size = 16;      ///< pixels per side of the square work unit
    /// With spp = 1: the pixel's centre (true), or a uniform point in it (false: a render
    /// that is one pass of many, as progressive photon mapping's, then anti-aliases over
    /// its passes).
    bool single_sample_at_centre = true;
    /// The pixels to render, inside width x height; empty (the default): all of them. A
    /// pixel's samples depend only on the seed, the pixel and the sample's number, so a
    /// crop is the same bits as those pixels of the whole render.
    PixelWindow crop{};
    /// The samples of each pixel to take, [first, last) of spp; empty (the default):
    /// all. Renders of disjoint ranges add up (render_sums, Accumulation) to the render
    /// of their union, bit for bit.
    PassRange passes{};
};

/// An integrator of the first kind: the radiance along a camera ray, drawing random
/// numbers from rng (Whitted, PhotonMapper, PathTracer). render() takes config.spp
/// samples in every pixel of the crop window.
template <class I>
concept RayEstimator = requires(const I& integrator, const Ray<typename I::scalar_type>& ray, Pcg32& rng) {
    { integrator.radiance(ray, rng) } -> std::same_as<Rgb<typename I::scalar_type>>;
};

/// An integrator of the second kind: an estimate of the whole image in passes, each
/// splatting over it (LightTracer, ProgressivePhotonMapper, Reference).
/// add_passes(sums, camera, config) adds to `sums` (which holds the config's crop window)
/// the sums of passes config.passes of config.spp (all of them when empty) over the
/// window, and their weights (the samples they took in each pixel, or one per pass), so
/// that sums / weight is the mean of the passes' images; the same bits for any thread count, and windows or
/// ranges of passes rendered apart add up to the whole.
template <class I>
concept PassEstimator = requires(const I& integrator, Accumulation& sums, const Camera<typename I::scalar_type>& camera, const RenderConfig& config) {
    integrator.add_passes(sums, camera, config);
};

/// An integrator: either kind. render(camera, integrator, config) and its siblings take
/// both, and so do their MPI versions (distributed/mpi.hpp).
template <class I>
concept Integrator = RayEstimator<I> || PassEstimator<I>;

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

/// The seed of a pixel's sample s: the render's seed moved by a bijective 64-bit hash of
/// s (MurmurHash3's finaliser, which maps 0 to 0), so each sample starts its pixel's
/// stream at its own far-apart place and sample s is the same whichever samples are
/// taken with it.
[[nodiscard]] constexpr std::uint64_t sample_seed(std::uint64_t seed, std::uint64_t s) noexcept
{
    s ^= s >> 33;
    s *= 0xff51afd7ed558ccdULL;
    s ^= s >> 33;
    s *= 0xc4ceb9fe1a85ec53ULL;
    s ^= s >> 33;
    return seed + s;
}

/// The window a config renders, checked against its image.
[[nodiscard]] inline PixelWindow render_window(const RenderConfig& config)
{
    if (config.crop == PixelWindow{}) return PixelWindow::whole(config.width, config.height);
    const PixelWindow& c = config.crop;
    if (c.empty() || !PixelWindow::whole(config.width, config.height).contains(c))
        throw_invalid("RenderConfig crop [", c.x0, ", ", c.x1, ") x [", c.y0, ", ", c.y1, ") must be a non-empty part of the ", config.width, " x ",
                      config.height, " image");
    return c;
}

/// The samples a config takes, checked against its spp.
[[nodiscard]] inline PassRange render_passes(const RenderConfig& config)
{
    if (config.spp < 1) throw_invalid("RenderConfig spp must be >= 1, got ", config.spp);
    if (config.passes == PassRange{}) return {0, std::uint64_t(config.spp)};
    if (config.passes.empty() || config.passes.last > std::uint64_t(config.spp))
        throw_invalid("RenderConfig passes [", config.passes.first, ", ", config.passes.last, ") must be a non-empty range of the spp = ", config.spp,
                      " samples");
    return config.passes;
}

/// Add a radiance sample to sums [first, first + 3): radiance is never negative, so a
/// channel that is NaN, infinite, < 0 or past ExactSum::limit adds 0 and is counted.
template <Scalar T>
[[nodiscard]] std::size_t add_radiance(std::span<ExactSum> sums, std::size_t first, const Rgb<T>& radiance) noexcept
{
    std::size_t rejected = 0;
    for (int c = 0; c < 3; ++c) {
        const double v = double(radiance[c]);
        if (v >= 0.0 && ExactSum::takes(v)) (void)sums[first + std::size_t(c)].add(ExactSum::of(v));
        else ++rejected;
    }
    return rejected;
}

/// Add a signed sample (a normal's component) to sums[i]: one not finite, or past
/// ExactSum::limit, adds 0 and is counted.
[[nodiscard]] inline std::size_t add_value(std::span<ExactSum> sums, std::size_t i, double value) noexcept
{
    if (!ExactSum::takes(value)) return 1;
    (void)sums[i].add(ExactSum::of(value));
    return 0;
}

/// Says on stderr how many sample values a render rejected, if any: light the film could
/// not hold is said, not only counted (Film::rejected()).
inline void say_rejected(std::size_t values)
{
    if (values != 0)
        std::fprintf(stderr, "prism: %zu sample values were rejected (negative, NaN, infinite, or past the largest float, 3.4e38): their light is missing from the image\n",
                     values);
}

/// Render the config's window and samples: `sample(ray, rng, sums)` adds one sample to
/// a pixel's N sums and returns how many values it rejected; `store(x, y, sums,
/// samples, rejected)` then takes the pixel (one thread per pixel; any pixel on any
/// thread).
template <std::size_t N, Scalar T, class Sample, class Store>
void render_pixels(const Camera<T>& camera, const RenderConfig& config, Sample&& sample, Store&& store)
{
    if (config.tile_size < 1) throw_invalid("RenderConfig tile_size must be >= 1, got ", config.tile_size);
    const PassRange samples = render_passes(config);
    const CameraRays<T> rays = camera.rays(config.width, config.height);
    const PixelWindow window = render_window(config);

    // Tile arithmetic in 64 bits: a tile_size of INT_MAX, or 65536^2 one-pixel tiles,
    // overflows int.
    const std::int64_t tile = config.tile_size;
    const std::int64_t tiles_x = (std::int64_t(window.width()) - 1) / tile + 1;
    const std::int64_t tiles_y = (std::int64_t(window.height()) - 1) / tile + 1;
    const std::int64_t tile_count = tiles_x * tiles_y;
    // Report progress while waiting, once the render has taken more than a second.
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    ProgressLine line("rendering");
    std::atomic<std::size_t> rejected_values{0};
    const auto progress = [&](std::size_t tiles_done) {
        if (!config.progress) return;
        const double seconds = elapsed();
        line.update(seconds, formatted("%3d%% (%.1f s)", static_cast<int>(100 * std::int64_t(tiles_done) / tile_count), seconds));
    };
    parallel_blocks(std::size_t(tile_count), config.threads, [&](std::size_t block, unsigned) {
        const auto t = std::int64_t(block);
        const auto x0 = static_cast<int>(window.x0 + (t % tiles_x) * tile), y0 = static_cast<int>(window.y0 + (t / tiles_x) * tile);
        const auto x1 = static_cast<int>(std::min<std::int64_t>(std::int64_t(x0) + tile, window.x1));
        const auto y1 = static_cast<int>(std::min<std::int64_t>(std::int64_t(y0) + tile, window.y1));
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const auto pixel = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(config.width) + static_cast<std::uint64_t>(x);
                std::array<ExactSum, N> sum{};
                std::size_t rejected = 0;
                for (std::uint64_t s = samples.first; s < samples.last; ++s) {
                    Pcg32 rng(sample_seed(config.seed, s), pixel);
                    const auto [dx, dy] = pixel_sample<T>(int(s), config.spp, rng, config.single_sample_at_centre);
                    if (rays.thin_lens()) {
                        // The lens point from the sample's own stream, after the pixel's (a pinhole draws none).
                        const T u = rng.uniform<T>(), v = rng.uniform<T>();
                        rejected += sample(rays.ray(T(x) + dx, T(y) + dy, u, v), rng, sum);
                    } else {
                        rejected += sample(rays.ray(T(x) + dx, T(y) + dy), rng, sum);
                    }
                }
                store(x, y, std::span<const ExactSum>(sum), samples.count(), rejected);
                if (rejected != 0) rejected_values.fetch_add(rejected, std::memory_order_relaxed);
            }
    }, progress);
    if (config.progress) line.finish(elapsed(), formatted("100%% (%.1f s)", elapsed()));
    if (config.progress) say_rejected(rejected_values.load());
}

} // namespace detail

/// Render a part of an image into `sums`: the config's crop window (which `sums`'
/// window must contain) and samples (or passes), each pixel's sum and weight added to
/// those there. The parts of one render, added in any order, give the same bits.
template <Integrator I>
void render_into(Accumulation& sums, const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config)
{
    const PixelWindow window = detail::render_window(config);
    if (sums.width() != config.width || sums.height() != config.height || !sums.window().contains(window))
        detail::throw_invalid("render_into: the Accumulation (", sums.width(), " x ", sums.height(), ", window [", sums.window().x0, ", ",
                              sums.window().x1, ") x [", sums.window().y0, ", ", sums.window().y1, ")) does not hold the render's window");
    if (sums.channels().size() != 3) detail::throw_invalid("render_into renders R, G, B only, the Accumulation has ", sums.channels().size(), " channels");
    using T = typename I::scalar_type;
    if constexpr (RayEstimator<I>) {
        detail::render_pixels<3>(
            camera, config,
            [&](const Ray<T>& ray, Pcg32& rng, std::array<ExactSum, 3>& sum) { return detail::add_radiance(sum, 0, integrator.radiance(ray, rng)); },
            [&](int x, int y, std::span<const ExactSum> sum, std::uint64_t weight, std::size_t rejected) {
                sums.add(x, y, sum, weight);
                if (rejected != 0) sums.reject(rejected);
            });
    } else {
        (void)detail::render_passes(config);
        (void)camera.rays(config.width, config.height); // a bad size is the camera's to name
        const std::size_t before = sums.rejected();
        integrator.add_passes(sums, camera, config);
        if (config.progress) detail::say_rejected(sums.rejected() - before);
    }
}

/// A part of an image as exact sums (its crop window, its samples): add the parts of a
/// render split across machines, then take image() for the whole render's bits.
template <Integrator I>
[[nodiscard]] Accumulation render_sums(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config = {})
{
    (void)camera.rays(config.width, config.height); // a bad size is the camera's to name
    Accumulation sums(config.width, config.height, detail::render_window(config));
    render_into(sums, camera, integrator, config);
    return sums;
}

/// A part of an image with its layers (render/layers.hpp): R, G, B and, as the
/// integrator allows, coverage, albedo, normal and distance of the first surface, and
/// the light's parts; layer_channels<I>() names them. Its R, G, B are render_sums' bits:
/// the layers are worked out beside the image, from the same camera rays. (An integrator
/// of passes has no camera rays of its own: R, G, B only.)
template <RayEstimator I>
[[nodiscard]] Accumulation render_layers(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config = {})
{
    using T = typename I::scalar_type;
    constexpr std::size_t surface = SeesSurfaces<I> ? 8 : 0, parts = SplitsLight<I> ? 9 : 0, n = 3 + surface + parts;
    Accumulation sums(config.width, config.height, detail::render_window(config), layer_channels<I>());
    detail::render_pixels<n>(
        camera, config,
        [&](const Ray<T>& ray, Pcg32& rng, std::array<ExactSum, n>& sum) {
            std::size_t rejected = 0;
            if constexpr (SplitsLight<I>) {
                const LightParts<T> light = integrator.radiance_parts(ray, rng);
                rejected += detail::add_radiance(sum, 0, light.sum());
                rejected += detail::add_radiance(sum, 3 + surface, light.direct);
                rejected += detail::add_radiance(sum, 6 + surface, light.caustic);
                rejected += detail::add_radiance(sum, 9 + surface, light.indirect);
            } else {
                rejected += detail::add_radiance(sum, 0, integrator.radiance(ray, rng));
            }
            if constexpr (SeesSurfaces<I>) {
                if (const auto seen = first_surface(integrator.scene(), integrator.air(), ray)) {
                    rejected += detail::add_value(sum, 3, 1.0);
                    rejected += detail::add_radiance(sum, 4, seen->albedo);
                    for (int c = 0; c < 3; ++c) rejected += detail::add_value(sum, 7 + std::size_t(c), double(seen->normal[c]));
                    rejected += detail::add_value(sum, 10, double(seen->distance));
                }
            }
            return rejected;
        },
        [&](int x, int y, std::span<const ExactSum> sum, std::uint64_t weight, std::size_t rejected) {
            sums.add(x, y, sum, weight);
            if (rejected != 0) sums.reject(rejected);
        });
    return sums;
}

/// Render an image: the config's crop window (the whole image by default), each pixel
/// the mean of its samples. The same scene, seed and spp give the same bits for any
/// thread count, crop or split of the samples: every sample draws from its own random
/// stream, and a pixel's samples are summed exactly (Accumulation).
template <PassEstimator I>
[[nodiscard]] Accumulation render_layers(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config = {})
{
    return render_sums(camera, integrator, config);
}

/// Render an image: the config's crop window (the whole image by default), each pixel
/// the mean of its samples (or passes).
template <PassEstimator I>
[[nodiscard]] Film render(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config = {})
{
    return render_sums(camera, integrator, config).image();
}

template <RayEstimator I>
[[nodiscard]] Film render(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config = {})
{
    const PixelWindow window = detail::render_window(config);
    Film film(window.width(), window.height());
    using T = typename I::scalar_type;
    detail::render_pixels<3>(
        camera, config,
        [&](const Ray<T>& ray, Pcg32& rng, std::array<ExactSum, 3>& sum) { return detail::add_radiance(sum, 0, integrator.radiance(ray, rng)); },
        [&](int x, int y, std::span<const ExactSum> sum, std::uint64_t weight, std::size_t rejected) {
            film.set(x - window.x0, y - window.y0, Rgb<float>(detail::mean(sum[0], weight), detail::mean(sum[1], weight), detail::mean(sum[2], weight)));
            if (rejected != 0) film.count_rejected(rejected);
        });
    return film;
}

} // namespace prism
