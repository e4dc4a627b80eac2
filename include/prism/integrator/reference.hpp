// SPDX-License-Identifier: MIT
// Reference: prism's unbiased estimator, a path tracer's camera samples plus a light
// tracer's splats (integrator/path_tracer.hpp, integrator/light_tracer.hpp). The two count
// disjoint sets of paths, so their sum is every path either can sample: the path tracer
// leaves an area or environment light met through mirrors and glass after a diffuse bounce
// (E D ... S+ L) to the light tracer, which finds it as L S+ ... D E (PathTracer's
// caustics_of_area_lights), but keeps the paths the camera sees through a mirror or glass
// first (E S+ D ... S+ L), which the light tracer cannot join to the camera. (Those of a
// point light neither half finds: no estimator here does.) An integrator of
// passes: pass s is the path tracer's sample s of every pixel and the light tracer's pass
// s, of as many light paths as the image has pixels (LightTracerConfig::paths = width x
// height), so each pass costs about as many paths from either end.
#pragma once

#include <prism/integrator/light_tracer.hpp>
#include <prism/integrator/path_tracer.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>

#include <cstdint>
#include <utility>

namespace prism {

/// prism's unbiased reference: a PathTracer and a LightTracer, which count disjoint sets of
/// paths, summed in every pass.
template <class SceneT, class Air = StraightAir>
class Reference {
public:
    /// The scene's precision.
    using scalar_type = typename SceneT::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;

    /// A Reference's settings, shared by its two halves.
    struct Config {
        /// Segments a path may have from the camera to the light, in either half (as
        /// PathTracer's: 2 is direct light, vertices in media count as those on surfaces).
        int max_length = 1024;
        /// Diffuse bounces either half may take (0: direct light only, as POV-Ray without
        /// radiosity; the light tracer then joins a path to the camera at its first diffuse
        /// surface only).
        int max_diffuse_bounces = 256;
    };

    /// The reference for `scene` (which must outlive it) in `air`; throws std::invalid_argument, naming the parameter, for a bad scene, air or setting.
    explicit Reference(const SceneT& scene, Config config = {}, Air air = {})
        : scene_(&scene), config_(config), air_(std::move(air)), paths_(scene, {.max_length = config.max_length, .max_diffuse_bounces = config.max_diffuse_bounces, .caustics_of_area_lights = false}, air_)
    {
    }
    Reference(const SceneT&& scene, Config config = {}, Air air = {}) = delete;

    /// Passes config.passes of config.spp: the path tracer's samples, weighted as they
    /// are, and the light tracer's passes of width x height paths each, splatted beside
    /// them with no weight of their own.
    void add_passes(Accumulation& sums, const Camera<T>& camera, const RenderConfig& config) const
    {
        render_into(sums, camera, paths_, config);
        const LightTracer<SceneT, Air> lights(
            *scene_, {.paths = std::uint64_t(config.width) * std::uint64_t(config.height), .max_length = config_.max_length, .max_diffuse_bounces = config_.max_diffuse_bounces}, air_);
        lights.add_splats(sums, camera, config);
    }

private:
    const SceneT* scene_;
    Config config_;
    Air air_;
    PathTracer<SceneT, Air> paths_;
};

} // namespace prism
