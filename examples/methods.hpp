// SPDX-License-Identifier: MIT
// The photon examples' --method: one scene rendered by any of prism's global
// illumination estimators, with the time each stage took.
#pragma once

#include "cli.hpp"

#include <chrono>
#include <cstdio>

namespace examples {

/// Render `scene` through `camera` by options.method, reporting the stages' times on stdout:
///   direct       the photon mapper reading the global map at the point
///   gather       final gathering (options.gather stratified rays)
///   cache        final gathering behind an irradiance cache built for this camera
///   progressive  options.passes passes of progressive photon mapping (photons per pass)
///   reference    path tracing (options.render.spp) plus light tracing (as many paths)
/// With options.povray_light (POV-Ray's model) the reference takes no diffuse bounce.
template <class SceneT>
prism::Film render_by_method(const char* name, const SceneT& scene, const prism::Camera<typename SceneT::scalar_type>& camera, const Options& options)
{
    using Mapper = prism::PhotonMapper<SceneT>;
    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    typename Mapper::Config config{.tracing = photon_tracer_config(options),
                                   .caustic = caustic_estimator(options),
                                   .global = {.radius = float(options.global_radius), .filter = options.filter,
                                              .max_height_ratio = float(options.max_height_ratio), .excluded = prism::Photon::direct | prism::Photon::caustic},
                                   .gather_rays = options.method == "gather" || options.method == "cache" ? options.gather : 0,
                                   .visibility_k = options.visibility};
    const std::string& method = options.method;
    if (method == "reference") {
        // POV-Ray's model lights the first diffuse surface only: no diffuse bounce.
        const int bounces = options.povray_light ? 0 : 256;
        const prism::Film paths = prism::render(camera, prism::PathTracer(scene, {.max_diffuse_bounces = bounces}), options.render);
        const double traced = seconds();
        const std::size_t light_paths = std::size_t(options.render.spp) * std::size_t(options.render.width) * std::size_t(options.render.height);
        const prism::Film light = prism::light_trace(scene, camera,
                                                     {.width = options.render.width, .height = options.render.height, .paths = light_paths,
                                                      .max_diffuse_bounces = bounces, .seed = options.render.seed, .threads = options.render.threads});
        prism::Film sum(paths.width(), paths.height());
        for (int y = 0; y < sum.height(); ++y)
            for (int x = 0; x < sum.width(); ++x) sum.set(x, y, paths.at(x, y) + light.at(x, y));
        std::printf("%s: reference, %d spp path tracing %.3f s + %zu light paths %.3f s = %.3f s\n", name, options.render.spp, traced, light_paths,
                    seconds() - traced, seconds());
        return sum;
    }
    if (method == "progressive") {
        prism::ProgressiveConfig<SceneT> progressive;
        progressive.pass = config;
        progressive.pass.caustic.k = 0; // progressive estimates are by radius
        progressive.passes = options.passes;
        const prism::ProgressiveResult result = prism::render_progressive(camera, scene, progressive, options.render);
        std::printf("%s: progressive photon mapping, %zu passes of %zu + %zu photons, %.3f s\n", name, result.passes, options.photons,
                    options.caustic_photons, seconds());
        return result.image();
    }
    Mapper mapper(scene, config);
    const double traced = seconds();
    std::printf("%s: %zu global and %zu caustic photons stored in %.3f s\n", name, mapper.maps().global.size(), mapper.maps().caustic.size(), traced);
    if (method == "cache") {
        mapper.cache_irradiance(camera, options.render);
        std::printf("%s: irradiance cache of %zu records in %.3f s\n", name, mapper.irradiance_cache().size(), seconds() - traced);
    }
    prism::Film film = timed_render(name, camera, mapper, options.render);
    std::printf("%s: %s, total %.3f s\n", name, method.c_str(), seconds());
    return film;
}

} // namespace examples
