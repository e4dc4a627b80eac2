// SPDX-License-Identifier: MIT
// render_progressive: stochastic progressive photon mapping (Hachisuka and Jensen 2009)
// in the probabilistic form of Knaus and Zwicker (2011), which converges to the right
// image as the passes go on.
//
// Each pass traces fresh photon maps (photons [p N, (p + 1) N) of each map's Sobol
// sequence: trace_photons' pass p) and renders one image with the photon mapper, reading
// the maps directly (no final gather) with radii that shrink from pass to pass,
//     r_{p+1}^2 = r_p^2 (p + alpha) / (p + 1)      (p counted from 1, alpha = 2/3),
// the same for every pixel. The image is the mean of the passes' images. A pass's
// estimate is biased by its radius and noisy by its photon count; as r^2 falls as
// p^(alpha - 1), the bias vanishes, while the mean of p passes still averages the noise
// down: the error falls as p^(-alpha / 2) = p^(-1/3) (Knaus and Zwicker, section 4).
// No per-pixel statistics are kept, so a pass is as cheap as the photon mapper's, any
// pass count is deterministic, and passes on different threads or machines add up.
// Direct light is by shadow rays (each pass at a new sample position in the pixel,
// even at one sample per pixel, which also anti-aliases; at the pixel's centre every
// pass, a light's hot spot kept an error of 0.11 in the Cornell box), caustics from the caustic map, the rest from the global
// map. Photons on the far side of a thin surface never count (their surface faces the
// other way: PhotonMap::irradiance).
#pragma once

#include <prism/core/check.hpp>
#include <prism/integrator/photon_mapper.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/film.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace prism {

/// The radius of pass `pass` (from 0) when the first is r0: r^2 shrinks by
/// (p + alpha) / (p + 1) from pass p to p + 1 (p from 1).
[[nodiscard]] inline double progressive_radius(double r0, double alpha, std::size_t pass) noexcept
{
    double r2 = r0 * r0;
    for (std::size_t p = 1; p <= pass; ++p) r2 *= (double(p) + alpha) / double(p + 1);
    return std::sqrt(r2);
}

template <class SceneT, class Air = StraightAir>
struct ProgressiveConfig {
    /// Each pass's photon mapper: photons per pass (tracing), the first pass's radii
    /// (caustic and global, radius estimates: k = 0) and the camera paths' settings.
    /// gather_rays and visibility_k must be 0.
    typename PhotonMapper<SceneT, Air>::Config pass{.caustic = {.radius = 0.1f},
                                                    .global = {.radius = 0.25f, .excluded = Photon::direct | Photon::caustic},
                                                    .gather_rays = 0};
    double alpha = 2.0 / 3.0; ///< in (0, 1): how much of the radius each pass keeps
    std::size_t passes = 64;  ///< at most this many; 0 = until `seconds`
    double seconds = 0;       ///< > 0: stop after the pass that ends past this time (the pass count then varies)
    std::size_t first_pass = 0; ///< passes [first_pass, first_pass + passes): one share of a render split across machines
};

/// What a run of passes made: the exact sums of their samples (Accumulation), so that
/// the sums of shares of one render (first_pass) add up to the whole render's, bit for
/// bit, in any order.
struct ProgressiveResult {
    Accumulation sums;    ///< every pass's samples; a pixel's weight is passes x spp
    std::size_t passes{}; ///< how many were rendered
    double seconds{};

    /// Add another share of the same render.
    ProgressiveResult& operator+=(const ProgressiveResult& other)
    {
        sums += other.sums;
        passes += other.passes;
        seconds += other.seconds;
        return *this;
    }

    /// The mean of the passes' images.
    [[nodiscard]] Film image() const { return sums.image(); }
};

namespace detail {

/// render_progressive's checks, before its first pass (and before a distributed render
/// deals any: every process refuses alike).
template <class SceneT, class Air>
void validate_progressive(const Camera<typename SceneT::scalar_type>& camera, const ProgressiveConfig<SceneT, Air>& config, const RenderConfig& render_config)
{
    if (!(config.alpha > 0.0 && config.alpha < 1.0)) detail::throw_invalid("ProgressiveConfig alpha must be in (0, 1), got ", config.alpha);
    if (config.pass.gather_rays != 0) detail::throw_invalid("ProgressiveConfig pass.gather_rays must be 0 (the maps are read directly), got ", config.pass.gather_rays);
    if (config.pass.visibility_k != 0) detail::throw_invalid("ProgressiveConfig pass.visibility_k must be 0, got ", config.pass.visibility_k);
    if (config.pass.caustic.k != 0 || config.pass.global.k != 0)
        detail::throw_invalid("ProgressiveConfig estimates must be by radius (k = 0), got k = ", config.pass.caustic.k, " and ", config.pass.global.k);
    if (!(config.seconds >= 0.0 && std::isfinite(config.seconds))) detail::throw_invalid("ProgressiveConfig seconds must be finite and >= 0, got ", config.seconds);
    if (config.passes == 0 && config.seconds == 0.0) detail::throw_invalid("ProgressiveConfig needs passes > 0 or seconds > 0");
    (void)camera.rays(render_config.width, render_config.height); // validates both before the first pass
    if (render_config.passes != PassRange{})
        detail::throw_invalid("render_progressive takes its passes from ProgressiveConfig (first_pass, passes), not RenderConfig passes [",
                              render_config.passes.first, ", ", render_config.passes.last, ")");
}

} // namespace detail

/// Render `scene` by progressive photon mapping: `render`'s size, samples per pixel per
/// pass, threads and seed; the same bits for any thread count.
template <class SceneT, class Air = StraightAir>
[[nodiscard]] ProgressiveResult render_progressive(const Camera<typename SceneT::scalar_type>& camera, const SceneT& scene,
                                                   const ProgressiveConfig<SceneT, Air>& config, const RenderConfig& render_config, const Air& air = {})
{
    detail::validate_progressive(camera, config, render_config);

    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    ProgressiveResult result{Accumulation(render_config.width, render_config.height, detail::render_window(render_config)), 0, 0.0};
    for (std::size_t pass = config.first_pass; config.passes == 0 || pass < config.first_pass + config.passes; ++pass) {
        typename PhotonMapper<SceneT, Air>::Config mapper_config = config.pass;
        mapper_config.caustic.radius = float(progressive_radius(config.pass.caustic.radius, config.alpha, pass));
        mapper_config.global.radius = float(progressive_radius(config.pass.global.radius, config.alpha, pass));
        const PhotonMapper<SceneT, Air> mapper(scene, mapper_config, trace_photons(scene, config.pass.tracing, air, pass), air);
        RenderConfig pass_render = render_config;
        pass_render.seed = render_config.seed + 0x9e3779b97f4a7c15ULL * (pass + 1); // a fresh sample in every pixel
        pass_render.progress = false;
        pass_render.single_sample_at_centre = false; // anti-aliased over the passes
        render_into(result.sums, camera, mapper, pass_render);
        ++result.passes;
        if (render_config.progress)
            std::fprintf(stderr, "\rprism: progressive pass %zu, r = %.4g / %.4g (%.1f s)", pass + 1, double(mapper_config.caustic.radius),
                         double(mapper_config.global.radius), elapsed());
        if (config.seconds > 0.0 && elapsed() >= config.seconds) break;
    }
    if (render_config.progress) std::fprintf(stderr, "\n");
    result.seconds = elapsed();
    return result;
}

} // namespace prism
