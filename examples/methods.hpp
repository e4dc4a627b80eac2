// SPDX-License-Identifier: MIT
// The photon examples' --method: one scene rendered by any of prism's global
// illumination estimators, with the time each stage took.
#pragma once

#include "cli.hpp"

#include <prism/prism.hpp>

#include <chrono>
#include <cstdio>

namespace examples {

/// The photon tracer's settings from the command line (--sampler picks the photons' too,
/// unless --photon-sampler does).
inline prism::PhotonTracerConfig photon_tracer_config(const Options& options)
{
    return {.global_photons = options.photons, .caustic_photons = options.caustic_photons, .seed = options.render.seed,
            .sampler = options.photon_sampler.value_or(options.render.sampler), .threads = options.render.threads};
}

/// The photon mapper's settings from the command line (for --method direct, gather and
/// cache; progressive passes take them too).
template <class SceneT>
typename prism::PhotonMapper<SceneT>::Config photon_mapper_config(const Options& options)
{
    return {.tracing = photon_tracer_config(options),
            .caustic = caustic_estimator(options),
            .global = {.radius = float(options.global_radius), .filter = options.filter, .max_height_ratio = float(options.max_height_ratio),
                       .excluded = prism::Photon::direct | prism::Photon::caustic},
            .gather_rays = options.method == "gather" || options.method == "cache" ? options.gather : 0,
            .visibility_k = options.visibility};
}

/// Progressive photon mapping's settings from the command line (--method progressive):
/// --spp samples per pixel in each pass.
template <class SceneT>
prism::ProgressiveConfig<SceneT> progressive_config(const Options& options)
{
    prism::ProgressiveConfig<SceneT> progressive;
    progressive.pass = photon_mapper_config<SceneT>(options);
    progressive.pass.caustic.k = 0; // progressive estimates are by radius
    progressive.samples = options.render.spp;
    return progressive;
}

/// The render settings of an integrator of passes: progressive photon mapping's passes
/// are --passes N (or A:B), the reference's --spp.
inline prism::RenderConfig pass_render_config(const Options& options)
{
    prism::RenderConfig r = options.render;
    if (options.method == "progressive") {
        r.spp = int(options.first_pass + options.passes);
        r.passes = {options.first_pass, options.first_pass + options.passes};
    }
    return r;
}

/// Render `scene` through `camera` by options.method, reporting the stages' times on stdout:
///   direct       the photon mapper reading the global map at the point
///   gather       final gathering (options.gather stratified rays)
///   cache        final gathering behind an irradiance cache built for this camera
///   progressive  options.passes passes of progressive photon mapping (photons per pass)
///   reference    path tracing (options.render.spp) plus light tracing (as many paths)
///   bdpt, vcm    bidirectional path tracing, or vertex connection and merging: options.render.spp
///                passes of one camera path per pixel and as many light paths
/// With options.povray_light (POV-Ray's model) the reference takes no diffuse bounce.
template <class SceneT>
Rendered render_by_method(const std::string& name, const SceneT& scene, const prism::Camera<typename SceneT::scalar_type>& camera, const Options& options)
{
    using Mapper = prism::PhotonMapper<SceneT>;
    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const std::string& method = options.method;
    if (method == "reference") {
        // POV-Ray's model lights the first diffuse surface only: no diffuse bounce.
        const prism::Reference reference(scene, {.max_diffuse_bounces = options.povray_light ? 0 : 256});
        prism::Accumulation sums = render_with(name, camera, reference, pass_render_config(options), options);
        std::printf("%s: reference, %llu spp of path tracing and as many light paths, %.3f s\n", name.c_str(),
                    static_cast<unsigned long long>(samples_taken(sums)), seconds());
        return {name, std::move(sums), seconds()};
    }
    if (method == "bdpt" || method == "vcm") {
        if constexpr (!prism::renders_bidirectionally<SceneT>) {
            throw std::invalid_argument("--method " + method + " renders no light that casts its own shadow: this scene has POV-Ray's area_light");
        } else {
        const prism::Bidirectional estimator(scene, {.method = method == "vcm" ? prism::BidirectionalMethod::vcm : prism::BidirectionalMethod::bdpt});
        prism::Accumulation sums = render_with(name, camera, estimator, pass_render_config(options), options);
        std::printf("%s: %s, %llu passes, %.3f s\n", name.c_str(), method == "vcm" ? "vertex connection and merging" : "bidirectional path tracing",
                    static_cast<unsigned long long>(samples_taken(sums)), seconds());
        return {name, std::move(sums), seconds()};
        }
    }
    if (method == "progressive") {
        const prism::ProgressivePhotonMapper<SceneT> progressive(scene, progressive_config<SceneT>(options));
        prism::Accumulation sums = render_with(name, camera, progressive, pass_render_config(options), options);
        std::printf("%s: progressive photon mapping, %llu passes of %zu + %zu photons, %.3f s\n", name.c_str(),
                    static_cast<unsigned long long>(samples_taken(sums) / std::uint64_t(options.render.spp)), options.photons, options.caustic_photons, seconds());
        return {name, std::move(sums), seconds()};
    }
    Mapper mapper(scene, photon_mapper_config<SceneT>(options));
    const double traced = seconds();
    std::printf("%s: %zu global and %zu caustic photons stored in %.3f s\n", name.c_str(), mapper.maps().global.size(), mapper.maps().caustic.size(), traced);
    if (method == "cache") {
        mapper.cache_irradiance(camera, options.render);
        std::printf("%s: irradiance cache of %zu records in %.3f s\n", name.c_str(), mapper.irradiance_cache().size(), seconds() - traced);
    }
    Rendered rendered = timed_render(name, camera, mapper, options);
    std::printf("%s: %s, total %.3f s\n", name.c_str(), method.c_str(), seconds());
    rendered.seconds = seconds();
    return rendered;
}

} // namespace examples
