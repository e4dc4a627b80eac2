// SPDX-License-Identifier: MIT
// render(): camera rays per pixel, tiles dealt to worker threads (core/parallel.hpp), each
// sample of each pixel drawing its own numbers (core/random.hpp: the sampler's by dimension,
// then a PCG stream of its own); a crop window or a range of the samples renders a part of
// the image that adds up with the other parts to the whole, bit for bit, and any prefix of
// the samples is an unbiased image.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/config.hpp>
#include <prism/core/parallel.hpp>
#include <prism/core/random.hpp>
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
    /// The points the samples draw (core/sampler.hpp): Owen-scrambled Sobol laid over the
    /// image in Morton order (zsobol, the default), each pixel's every prefix of 2^m
    /// samples stratified and the image's error blue noise once the render takes spp
    /// samples (the layout is spp's, rounded up to a power of two: a range of passes draws
    /// what it draws in the whole render of that spp; progressive photon mapping's passes
    /// draw sobol's); Sobol padded per pixel (sobol), as good per pixel, its error white;
    /// Halton's points per pixel (halton, for photons: as a camera's, between independent
    /// numbers and Sobol's); or independent numbers.
    SamplerKind sampler = SamplerKind::zsobol;
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
    /// > 0: a time budget. The samples (or passes) are taken in rounds, each pixel's
    /// count doubling, and the render stops at the round that the time per sample so far
    /// says the budget ends in, having taken [first, first + n) of the range for some n:
    /// the same bits as a render of that range. 0 (the default): all of them.
    double seconds = 0;
};

/// An integrator of the first kind: the radiance along a camera ray, drawing random
/// numbers from rng (Whitted, PhotonMapper, PathTracer). render() takes config.spp
/// samples in every pixel of the crop window.
template <class I>
concept RayEstimator = requires(const I& integrator, const Ray<typename I::scalar_type>& ray, Random& rng) {
    { integrator.radiance(ray, rng) } -> std::same_as<Rgb<typename I::scalar_type>>;
};

/// Whether a ray estimator says it draws no random number for its scene (`static
/// constexpr bool draws_nothing = true`: Whitted's with delta lights only and no medium
/// that scatters). One sample per pixel at its centre through a pinhole then takes no
/// number either, and render() skips the sampler's work for the pixel: its pixel key,
/// seeds and streams, which nothing would read.
template <class I>
inline constexpr bool draws_nothing = requires { requires bool(I::draws_nothing); };

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

/// Pixel (x, y)'s place in the samples of a render (PixelKey::in_image).
[[nodiscard]] constexpr PixelKey pixel_key(const RenderConfig& config, std::uint32_t x, std::uint32_t y) noexcept
{
    return PixelKey::in_image(config.sampler, config.seed, x, y, std::uint32_t(config.width), std::uint32_t(config.height), std::uint64_t(config.spp));
}

/// Sample s of a pixel: where in the pixel its ray starts, its point on the lens, and the
/// numbers its estimate goes on to draw (from its path's first bounce on).
template <Scalar T>
struct CameraSample {
    std::array<T, 2> footprint; ///< in the pixel, [0, 1)^2
    std::array<T, 2> lens;      ///< on the lens, [0, 1)^2 (a pinhole reads none)
    Random rng;                 ///< the rest of the sample's numbers
};

/// Sample s of pixel `pixel` of a render, its numbers from `sampler`: Sampler(config.sampler,
/// pixel_key(config, x, y), s), or the same sample reading its pixel's PixelSeeds.
template <Scalar T>
[[nodiscard]] constexpr CameraSample<T> camera_sample(const RenderConfig& config, const Sampler& sampler, std::uint64_t pixel, std::uint64_t s,
                                                      bool thin_lens) noexcept
{
    Random rng(sampler, Pcg32(sample_seed(config.seed, s), pixel));
    // At the pixel's centre the footprint's pair is not drawn: nothing after it moves.
    std::array<float, 2> footprint{0.5f, 0.5f};
    if (config.spp == 1 && config.single_sample_at_centre) rng.skip_pair();
    else footprint = rng.uniform2<float>();
    const std::array<T, 2> lens = thin_lens ? rng.uniform2<T>() : std::array<T, 2>{T(0.5), T(0.5)};
    rng.bounce(0);
    return {{T(footprint[0]), T(footprint[1])}, lens, rng};
}

/// Sample s of pixel `pixel` (y * width + x) of a render: the footprint and, through a
/// thin lens, the lens point from the sampler's pairs 0 and 1 (the footprint the pixel's
/// centre when spp = 1 and config.single_sample_at_centre; a pinhole draws no lens point,
/// which moves no later dimension: the path's first bounce starts at its own pair). The
/// footprint is drawn in float in every precision, so float and double renders of one
/// seed sample the same positions.
template <Scalar T>
[[nodiscard]] constexpr CameraSample<T> camera_sample(const RenderConfig& config, std::uint64_t pixel, std::uint64_t s, bool thin_lens = true) noexcept
{
    const auto width = std::uint64_t(config.width);
    return camera_sample<T>(config, Sampler(config.sampler, pixel_key(config, std::uint32_t(pixel % width), std::uint32_t(pixel / width)), std::uint32_t(s)),
                            pixel, s, thin_lens);
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

/// The config's time budget, checked.
[[nodiscard]] inline double render_seconds(const RenderConfig& config)
{
    if (!(config.seconds >= 0.0 && std::isfinite(config.seconds))) throw_invalid("RenderConfig seconds must be finite and >= 0, got ", config.seconds);
    return config.seconds;
}

/// Take the config's samples in rounds: add_round(part) adds the samples part.passes
/// to the sums, then on_round() is told how many of the range have been taken. The first
/// round takes one sample, each next as many as were taken before it (so a stop falls on
/// a power of two, where a Sobol sampler's samples are stratified), and with a budget
/// (config.seconds) none that the time per sample so far says would end past it (the
/// last round may be cut short to fit).
template <class AddRound, class OnRound>
void render_in_rounds(const RenderConfig& config, AddRound&& add_round, OnRound&& on_round)
{
    const PassRange range = render_passes(config);
    const double budget = render_seconds(config);
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    ProgressLine line("rendering");
    RenderConfig part = config;
    part.progress = false;
    std::uint64_t taken = 0;
    while (taken < range.count()) {
        std::uint64_t n = std::min(std::max<std::uint64_t>(taken, 1), range.count() - taken);
        if (budget > 0.0 && taken > 0) {
            const double spent = elapsed(), per_sample = spent / double(taken);
            if (spent >= budget) break;
            const double fits = std::floor((budget - spent) / per_sample);
            if (fits < 1.0) break;
            if (fits < double(n)) n = std::uint64_t(fits);
        }
        part.passes = {range.first + taken, range.first + taken + n};
        add_round(part);
        taken += n;
        on_round(taken);
        if (config.progress)
            line.update(elapsed(), formatted("%llu of %llu samples (%.1f s)", static_cast<unsigned long long>(taken),
                                             static_cast<unsigned long long>(range.count()), elapsed()));
    }
    if (config.progress) line.finish(elapsed(), formatted("%llu samples (%.1f s)", static_cast<unsigned long long>(taken), elapsed()));
}

/// Add a radiance sample to sums [first, first + 3): radiance is never negative, so a
/// channel that is NaN, infinite, < 0 or past ExactSum::limit adds 0 and is counted.
template <Scalar T>
[[nodiscard]] std::size_t add_radiance(std::span<ExactSum> sums, std::size_t first, const Rgb<T>& radiance) noexcept
{
    const T channel[3] = {radiance.x, radiance.y, radiance.z};
    std::size_t rejected = 0;
    for (std::size_t c = 0; c < 3; ++c) {
        if constexpr (std::same_as<T, float>) {
            // (A float's own bits: no trip through double. The same sum.)
            const float v = channel[c];
            if (v >= 0.0f && v <= float(ExactSum::limit)) (void)sums[first + c].add(ExactSum::of_float(v));
            else ++rejected;
        } else {
            const double v = double(channel[c]);
            if (v >= 0.0 && ExactSum::takes(v)) (void)sums[first + c].add(ExactSum::of(v));
            else ++rejected;
        }
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
template <std::size_t N, Scalar T, bool DrawsNothing = false, class Sample, class Store>
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
    // An integrator that draws nothing, at one sample at the pixel's centre through a
    // pinhole: the camera sample's ray, with a stream nothing reads.
    const bool centre_only = DrawsNothing && config.spp == 1 && config.single_sample_at_centre && !rays.thin_lens() && samples.count() == 1;
    parallel_blocks(std::size_t(tile_count), config.threads, [&](std::size_t block, unsigned) {
        const auto t = std::int64_t(block);
        const auto x0 = static_cast<int>(window.x0 + (t % tiles_x) * tile), y0 = static_cast<int>(window.y0 + (t / tiles_x) * tile);
        const auto x1 = static_cast<int>(std::min<std::int64_t>(std::int64_t(x0) + tile, window.x1));
        const auto y1 = static_cast<int>(std::min<std::int64_t>(std::int64_t(y0) + tile, window.y1));
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                std::array<ExactSum, N> sum; // (each element zero by its own initializers: `sum{}` cleared the array with a rep stos a pixel, slower here than the stores)
                std::size_t rejected = 0;
                if (centre_only) {
                    Random unread;
                    rejected = sample(rays.ray(T(x) + T(0.5f), T(y) + T(0.5f)), unread, sum);
                } else {
                    const auto pixel = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(config.width) + static_cast<std::uint64_t>(x);
                    PixelSeeds seeds(pixel_key(config, std::uint32_t(x), std::uint32_t(y))); // the scrambles' seeds, hashed once for the pixel's samples
                    for (std::uint64_t s = samples.first; s < samples.last; ++s) {
                        CameraSample<T> c = camera_sample<T>(config, Sampler(config.sampler, seeds, std::uint32_t(s)), pixel, s, rays.thin_lens());
                        const Ray<T> ray = rays.thin_lens() ? rays.ray(T(x) + c.footprint[0], T(y) + c.footprint[1], c.lens[0], c.lens[1])
                                                            : rays.ray(T(x) + c.footprint[0], T(y) + c.footprint[1]);
                        rejected += sample(ray, c.rng, sum);
                    }
                }
                store(x, y, std::span<const ExactSum>(sum), samples.count(), rejected);
                if (rejected != 0) rejected_values.fetch_add(rejected, std::memory_order_relaxed);
            }
    }, progress);
    if (config.progress) line.finish(elapsed(), formatted("100%% (%.1f s)", elapsed()));
    if (config.progress) say_rejected(rejected_values.load());
}

/// Check that `sums` holds the config's window of its image, with `channels` channels.
inline void check_sums(const Accumulation& sums, const RenderConfig& config, std::size_t channels, const char* who)
{
    const PixelWindow window = render_window(config);
    if (sums.width() != config.width || sums.height() != config.height || !sums.window().contains(window))
        throw_invalid(who, ": the Accumulation (", sums.width(), " x ", sums.height(), ", window [", sums.window().x0, ", ", sums.window().x1, ") x [",
                      sums.window().y0, ", ", sums.window().y1, ")) does not hold the render's window");
    if (sums.channels().size() != channels) throw_invalid(who, " renders ", channels, " channels, the Accumulation has ", sums.channels().size());
}

/// render_pixels' store of a pixel into `sums`: its sums, weight and rejected values.
[[nodiscard]] inline auto into(Accumulation& sums) noexcept
{
    return [&sums](int x, int y, std::span<const ExactSum> sum, std::uint64_t weight, std::size_t rejected) {
        sums.add(x, y, sum, weight);
        if (rejected != 0) sums.reject(rejected);
    };
}

/// render_pixels' sample of a ray estimator's R, G, B: its radiance into the pixel's sums.
template <RayEstimator I>
[[nodiscard]] auto radiance_sample(const I& integrator) noexcept
{
    return [&integrator](const Ray<typename I::scalar_type>& ray, Random& rng, std::array<ExactSum, 3>& sum) {
        return add_radiance(sum, 0, integrator.radiance(ray, rng));
    };
}

/// Add the config's samples (or passes) of R, G, B to `sums`, all in one go.
template <Integrator I>
void add_samples(Accumulation& sums, const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config)
{
    if constexpr (RayEstimator<I>) {
        render_pixels<3, typename I::scalar_type, draws_nothing<I>>(
            camera, config,
            radiance_sample(integrator),
            into(sums));
    } else {
        (void)render_passes(config);
        const std::size_t before = sums.rejected();
        integrator.add_passes(sums, camera, config);
        if (config.progress) say_rejected(sums.rejected() - before);
    }
}

/// Add the config's samples with the integrator's layers (render_layers) to `sums`, all in one go.
template <RayEstimator I>
void add_layers(Accumulation& sums, const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config)
{
    using T = typename I::scalar_type;
    constexpr std::size_t surface = SeesSurfaces<I> ? 8 : 0, parts = SplitsLight<I> ? 9 : 0, n = 3 + surface + parts;
    render_pixels<n, T, draws_nothing<I>>(
        camera, config,
        [&](const Ray<T>& ray, Random& rng, std::array<ExactSum, n>& sum) {
            std::size_t rejected = 0;
            if constexpr (SplitsLight<I>) {
                const LightParts<T> light = integrator.radiance_parts(ray, rng);
                rejected += add_radiance(sum, 0, light.sum());
                rejected += add_radiance(sum, 3 + surface, light.direct);
                rejected += add_radiance(sum, 6 + surface, light.caustic);
                rejected += add_radiance(sum, 9 + surface, light.indirect);
            } else {
                rejected += add_radiance(sum, 0, integrator.radiance(ray, rng));
            }
            if constexpr (SeesSurfaces<I>) {
                if (const auto seen = first_surface(integrator.scene(), integrator.air(), ray)) {
                    rejected += add_value(sum, 3, 1.0);
                    rejected += add_radiance(sum, 4, seen->albedo);
                    for (int c = 0; c < 3; ++c) rejected += add_value(sum, 7 + std::size_t(c), double(seen->normal[c]));
                    rejected += add_value(sum, 10, double(seen->distance));
                }
            }
            return rejected;
        },
        into(sums));
}

/// Add the config's samples to `sums` by add(part): in one go, or with a time budget in
/// rounds (render_in_rounds), on_round(sums) told of each.
template <class Add, class OnRound>
void add_in_rounds(Accumulation& sums, const RenderConfig& config, bool rounds, Add&& add, OnRound&& on_round)
{
    if (!rounds && render_seconds(config) == 0.0) {
        add(config);
        on_round(static_cast<const Accumulation&>(sums));
        return;
    }
    const std::size_t before = sums.rejected();
    render_in_rounds(config, add, [&](std::uint64_t) { on_round(static_cast<const Accumulation&>(sums)); });
    if (config.progress) say_rejected(sums.rejected() - before);
}

/// What a render without a preview does after each round: nothing.
struct NoPreview {
    /// Does nothing.
    constexpr void operator()(const Accumulation&) const noexcept {}
};

} // namespace detail

/// Render a part of an image into `sums`: the config's crop window (which `sums`'
/// window must contain) and samples (or passes), each pixel's sum and weight added to
/// those there. The parts of one render, added in any order, give the same bits.
template <Integrator I>
void render_into(Accumulation& sums, const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config)
{
    detail::check_sums(sums, config, 3, "render_into");
    (void)camera.rays(config.width, config.height); // a bad size is the camera's to name
    detail::add_in_rounds(sums, config, false, [&](const RenderConfig& part) { detail::add_samples(sums, camera, integrator, part); }, detail::NoPreview{});
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
    (void)camera.rays(config.width, config.height); // a bad size is the camera's to name
    Accumulation sums(config.width, config.height, detail::render_window(config), layer_channels<I>());
    detail::add_in_rounds(sums, config, false, [&](const RenderConfig& part) { detail::add_layers(sums, camera, integrator, part); }, detail::NoPreview{});
    return sums;
}

/// A part of an image from an integrator of passes, with its layers: R, G, B only
/// (render_sums).
template <PassEstimator I>
[[nodiscard]] Accumulation render_layers(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config = {})
{
    return render_sums(camera, integrator, config);
}

/// Render a part of an image progressively: its samples (or passes) in rounds, each
/// pixel's count doubling (and with config.seconds, within the budget), calling
/// preview(sums) after each round with the sums so far, whose image() is the mean of the
/// samples taken: with a Sobol sampler a converging picture, unbiased at every round.
/// Returns the sums (R, G, B; with `layers`, render_layers' channels). The bits of a
/// render of the samples it took.
template <Integrator I, class Preview>
    requires std::invocable<Preview&, const Accumulation&>
[[nodiscard]] Accumulation render_progressive(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config, Preview&& preview,
                                              bool layers = false)
{
    (void)camera.rays(config.width, config.height); // a bad size is the camera's to name
    if constexpr (RayEstimator<I>) {
        if (!layers) {
            Accumulation sums(config.width, config.height, detail::render_window(config));
            detail::add_in_rounds(sums, config, true, [&](const RenderConfig& part) { detail::add_samples(sums, camera, integrator, part); }, preview);
            return sums;
        }
        Accumulation sums(config.width, config.height, detail::render_window(config), layer_channels<I>());
        detail::add_in_rounds(sums, config, true, [&](const RenderConfig& part) { detail::add_layers(sums, camera, integrator, part); }, preview);
        return sums;
    } else {
        Accumulation sums(config.width, config.height, detail::render_window(config));
        detail::add_in_rounds(sums, config, true, [&](const RenderConfig& part) { detail::add_samples(sums, camera, integrator, part); }, preview);
        return sums;
    }
}

/// Render an image: the config's crop window (the whole image by default), each pixel
/// the mean of its passes.
template <PassEstimator I>
[[nodiscard]] Film render(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config = {})
{
    return render_sums(camera, integrator, config).image();
}

/// Render an image: the config's crop window (the whole image by default), each pixel
/// the mean of its samples. The same scene, seed and spp give the same bits for any
/// thread count, crop or split of the samples: every sample draws its own numbers, and a
/// pixel's samples are summed exactly (Accumulation).
template <RayEstimator I>
[[nodiscard]] Film render(const Camera<typename I::scalar_type>& camera, const I& integrator, const RenderConfig& config = {})
{
    if (detail::render_seconds(config) > 0.0) return render_sums(camera, integrator, config).image();
    const PixelWindow window = detail::render_window(config);
    Film film(window.width(), window.height());
    detail::render_pixels<3, typename I::scalar_type, draws_nothing<I>>(
        camera, config,
        detail::radiance_sample(integrator),
        [&](int x, int y, std::span<const ExactSum> sum, std::uint64_t weight, std::size_t rejected) {
            film.set(x - window.x0, y - window.y0, Rgb<float>(detail::mean(sum[0], weight), detail::mean(sum[1], weight), detail::mean(sum[2], weight)));
            if (rejected != 0) film.count_rejected(rejected);
        });
    return film;
}

} // namespace prism
