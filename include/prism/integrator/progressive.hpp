// SPDX-License-Identifier: MIT
// ProgressivePhotonMapper: stochastic progressive photon mapping (Hachisuka and Jensen 2009)
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
// pass count is deterministic, and passes on different threads or machines add up: an
// integrator of passes (render/render.hpp's PassEstimator), whose RenderConfig::spp counts
// the passes and RenderConfig::passes picks a range of them.
// Direct light is by shadow rays (each pass at a new sample position in the pixel,
// even at one sample per pixel, which also anti-aliases; at the pixel's centre every
// pass, a light's hot spot kept an error of 0.11 in the Cornell box), caustics from the caustic map, the rest from the global
// map. Photons on the far side of a thin surface never count (their surface faces the
// other way: PhotonMap::irradiance).
// In a medium that scatters, camera rays read the volume photons by the beam radiance
// estimate, whose kernel is a disk across the ray: its radius (volume_radius) shrinks by
// the same schedule, r^2 by (p + alpha) / (p + 1) as the disks on surfaces (the
// two-dimensional kernel of Knaus and Zwicker's analysis; Jarosz et al. 2011 shrink a
// beam's one-dimensional blur by the ratio itself).
#pragma once

#include <prism/core/check.hpp>
#include <prism/integrator/photon_mapper.hpp>
#include <prism/medium/air.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/film.hpp>
#include <prism/render/progress.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace prism {

/// The radius of pass `pass` (from 0) when the first is r0: r^2 shrinks by
/// (p + alpha) / (p + 1) from pass p to p + 1 (p from 1).
[[nodiscard]] inline double progressive_radius(double r0, double alpha, std::size_t pass) noexcept
{
    double r2 = r0 * r0;
    for (std::size_t p = 1; p <= pass; ++p) r2 *= (double(p) + alpha) / double(p + 1);
    return std::sqrt(r2);
}

/// A ProgressivePhotonMapper's settings: each pass's photon mapper, the radius schedule's alpha,
/// and when to stop.
template <class SceneT, class Air = StraightAir>
struct ProgressiveConfig {
    /// Each pass's photon mapper: photons per pass (tracing), the first pass's radii
    /// (caustic, global and volume; the surfaces' by radius: k = 0) and the camera paths' settings.
    /// gather_rays and visibility_k must be 0.
    typename PhotonMapper<SceneT, Air>::Config pass{.caustic = {.radius = 0.1f},
                                                    .global = {.radius = 0.25f, .excluded = Photon::direct | Photon::caustic},
                                                    .gather_rays = 0};
    double alpha = 2.0 / 3.0; ///< in (0, 1): how much of the radius each pass keeps
    int samples = 1;          ///< jittered camera samples per pixel in each pass
    // A time budget is RenderConfig::seconds, as for every integrator.
};

/// Progressive photon mapping of `scene` in its air: pass p (from 0) traces photon pass p
/// (trace_photons) and renders `samples` jittered samples per pixel with the photon mapper
/// at pass p's radii. The same bits for any thread count.
template <class SceneT, class Air = StraightAir>
class ProgressivePhotonMapper {
public:
    /// The scene's precision.
    using scalar_type = typename SceneT::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;
    /// The settings' type.
    using Config = ProgressiveConfig<SceneT, Air>;

    /// Progressive photon mapping of `scene` (which must outlive it) in `air`; throws std::invalid_argument, naming the parameter, for a bad scene, air or setting.
    explicit ProgressivePhotonMapper(const SceneT& scene, Config config = {}, Air air = {}) : scene_(&scene), config_(config), air_(std::move(air))
    {
        scene.validate();
        air_.validate();
        if (!(config.alpha > 0.0 && config.alpha < 1.0)) detail::throw_invalid("ProgressiveConfig alpha must be in (0, 1), got ", config.alpha);
        if (config.pass.gather_rays != 0) detail::throw_invalid("ProgressiveConfig pass.gather_rays must be 0 (the maps are read directly), got ", config.pass.gather_rays);
        if (config.pass.visibility_k != 0) detail::throw_invalid("ProgressiveConfig pass.visibility_k must be 0, got ", config.pass.visibility_k);
        if (config.pass.caustic.k != 0 || config.pass.global.k != 0)
            detail::throw_invalid("ProgressiveConfig estimates must be by radius (k = 0), got k = ", config.pass.caustic.k, " and ", config.pass.global.k);
        if (config.samples < 1) detail::throw_invalid("ProgressiveConfig samples must be >= 1, got ", config.samples);
        detail::validate(config.pass.tracing);
    }
    ProgressivePhotonMapper(const SceneT&& scene, Config config = {}, Air air = {}) = delete;

    /// The settings.
    [[nodiscard]] const Config& config() const noexcept { return config_; }

    /// Throws std::invalid_argument when the passes `config` asks for would reach past
    /// photon index 2^32, before any is traced (mpi::render_sums asks for the whole range
    /// before it deals passes to the ranks).
    void check_passes(const RenderConfig& config) const
    {
        const std::uint64_t last = detail::render_passes(config).last;
        check_photon_passes(config_.pass.tracing, last);
        // The camera's samples of every pass are one sequence, counted in an int.
        if (last > std::uint64_t(std::numeric_limits<int>::max()) / std::uint64_t(config_.samples))
            detail::throw_invalid("ProgressivePhotonMapper: ", last, " passes of ", config_.samples, " samples reach past sample 2^31 of a pixel");
    }

    /// Passes config.passes of config.spp, each of `samples` samples per pixel, in order
    /// (the samples of the passes rendered are the pixels' weight; a time budget,
    /// RenderConfig::seconds, is render()'s, which calls this with the passes of a round).
    void add_passes(Accumulation& sums, const Camera<T>& camera, const RenderConfig& config) const
    {
        const PassRange passes = detail::render_passes(config);
        check_passes(config);
        const auto start = std::chrono::steady_clock::now();
        const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
        detail::ProgressLine line("progressive photon mapping");
        for (std::uint64_t pass = passes.first; pass < passes.last; ++pass) {
            typename PhotonMapper<SceneT, Air>::Config mapper_config = config_.pass;
            mapper_config.caustic.radius = float(progressive_radius(config_.pass.caustic.radius, config_.alpha, pass));
            mapper_config.global.radius = float(progressive_radius(config_.pass.global.radius, config_.alpha, pass));
            mapper_config.volume_radius = float(progressive_radius(config_.pass.volume_radius, config_.alpha, pass));
            if (config_.pass.indirect_volume_radius > 0.0f)
                mapper_config.indirect_volume_radius = float(progressive_radius(config_.pass.indirect_volume_radius, config_.alpha, pass));
            const PhotonMapper<SceneT, Air> mapper(*scene_, mapper_config, trace_photons(*scene_, PhotonMapper<SceneT, Air>::tracing_for(config_.pass), air_, pass), air_);
            // Pass p takes the pixels' samples p s to (p + 1) s of one sequence (s = samples),
            // so that the camera's samples of any 2^m passes are stratified over the pixel.
            // Under zsobol, each pixel's own Sobol sequence: the image's layout would be that
            // of all the render's passes, which a part rendered on its own (the examples'
            // --passes A:B) does not know, and a layout per pass would lose the
            // stratification across passes (a fresh sequence a pass: the diffuse box's
            // error at 256 passes 2.4 x).
            RenderConfig pass_render = config;
            if (pass_render.sampler == SamplerKind::zsobol) pass_render.sampler = SamplerKind::sobol;
            pass_render.spp = int((pass + 1) * std::uint64_t(config_.samples));
            pass_render.passes = {pass * std::uint64_t(config_.samples), (pass + 1) * std::uint64_t(config_.samples)};
            pass_render.seconds = 0;
            pass_render.progress = false;
            pass_render.single_sample_at_centre = false; // anti-aliased over the passes
            render_into(sums, camera, mapper, pass_render);
            if (config.progress)
                line.update(elapsed(), detail::formatted("pass %llu, r = %.4g / %.4g (%.1f s)", static_cast<unsigned long long>(pass + 1),
                                                         double(mapper_config.caustic.radius), double(mapper_config.global.radius), elapsed()));
        }
        if (config.progress)
            line.finish(elapsed(), detail::formatted("%llu passes (%.1f s)", static_cast<unsigned long long>(passes.count()), elapsed()));
    }

private:
    const SceneT* scene_;
    Config config_;
    Air air_;
};

} // namespace prism
