// SPDX-License-Identifier: MIT
// One render of a Cornell box by one global illumination method, for
// bench/methods_vs_time.py: writes the image as PFM and prints "seconds S" (the whole
// render: photons, cache, passes or paths, and camera rays), 2 threads.
//
// usage: bench_methods diffuse|area|glass|povray METHOD EFFORT OUT.pfm [SIZE] [SEED] [SPP]
//   area is the diffuse box under its ceiling light (an area light) instead of the point light.
//   povray is the glass box in POV-Ray's model (shared/scenes/cornell_caustics.pov: its
//   no-falloff light, direct light and caustics only; no global photons, and the
//   reference takes no diffuse bounce).
//   METHOD direct | gather | cache | progressive | reference | bdpt | vcm | path | path_bounces | path_grid2 | mask,
//   with ":independent" after it for independent samples instead of Owen-scrambled Sobol
//   points (RenderConfig::sampler); EFFORT is, per method:
//   direct: photons (global and caustic); gather: final-gather rays (2e5 photons);
//   cache: rays per record (2e5 photons); progressive: passes (5e4 + 5e4 photons each);
//   reference: samples per pixel (and as many light paths); bdpt, vcm: passes (one camera
//   path per pixel and as many light paths each); path: the path tracer alone,
//   light samples and bounces combined by multiple importance sampling, samples per
//   pixel; path_bounces: the same without light samples for area lights (their light
//   found only by the bounces that meet them); path_grid2: the path tracer with 2 x 2
//   stratified light samples at each vertex instead of one; path_rrN: the path tracer with
//   Russian roulette from the Nth surface on (PathTracer::Config::roulette_depth, 3 by
//   default); path_lengthN: the path tracer's paths of at most N segments
//   (PathTracer::Config::max_length: path_length2 is direct light, a light met at the
//   first surface or at the one a bounce from it reaches); mask: samples per pixel, and the image is
//   the share of each pixel whose camera ray meets a diffuse surface first (1 where the
//   pixel sees only walls).
#include "common.hpp"
#include "methods.hpp"
#include "scenes/cornell.hpp"

#include <prism/io/image.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace {

template <class SceneT>
double render_one(const SceneT& scene, examples::Options options, const std::string& out)
{
    const auto start = std::chrono::steady_clock::now();
    const prism::Film film = examples::render_by_method("bench", scene, scenes::cornell_camera<float>(), options).image();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    prism::write_pfm(film, out);
    return seconds;
}

/// The share of a pixel whose camera rays meet a diffuse surface first (an Integrator).
template <class SceneT>
struct SeesDiffuseFirst {
    using scalar_type = float;
    const SceneT* scene;
    [[nodiscard]] prism::Rgb<float> radiance(const prism::Ray<float>& ray, prism::Random&) const noexcept
    {
        const auto hit = scene->closest_hit(ray, {0.0f, std::numeric_limits<float>::infinity()});
        const bool diffuse = hit && scene->visit_material(*hit, []<class M>(const M&) { return prism::has_diffuse<M> && !prism::reflects<M> && !prism::transmits<M>; });
        return prism::Rgb<float>(diffuse ? 1.0f : 0.0f);
    }
};

} // namespace

int main(int argc, char** argv)
{
    if (argc < 5) {
        std::fprintf(stderr, "usage: bench_methods diffuse|area|glass|povray METHOD EFFORT OUT.pfm [SIZE] [SEED] [SPP]\n");
        return 1;
    }
    const std::string which = argv[1], out = argv[4];
    std::string method = argv[2];
    examples::Options options;
    // "METHOD:KIND-photons": only the photons draw KIND's points, the camera Sobol's.
    options.photon_sampler = bench::take_sampler_suffix(method, "-photons");
    options.render.sampler = bench::take_sampler(method);
    const double effort = std::atof(argv[3]);
    options.render.width = options.render.height = argc > 5 ? std::atoi(argv[5]) : 256;
    options.render.threads = 2;
    options.render.seed = argc > 6 ? std::strtoull(argv[6], nullptr, 10) : 0;
    options.render.progress = false;
    options.render.spp = 4;
    options.method = method;
    options.photons = 200000;
    const bool povray = which == "povray", glass = which == "glass" || povray;
    options.povray_light = povray;
    options.caustic_photons = glass ? 200000 : 0;
    if (method == "direct") {
        options.photons = std::size_t(effort);
        if (glass) options.caustic_photons = std::size_t(effort);
    } else if (method == "gather" || method == "cache") {
        options.gather = method == "gather" ? int(effort) : 64;
    } else if (method == "progressive") {
        options.passes = std::size_t(effort);
        options.photons = 50000;
        if (glass) options.caustic_photons = 50000;
        options.render.spp = 1;
    } else if (method == "reference" || method == "bdpt" || method == "vcm" || method == "mask" || method.starts_with("path")) {
        options.render.spp = int(effort);
    }
    if (povray) options.photons = 0; // POV-Ray's model: no global light
    if (argc > 7) options.render.spp = std::atoi(argv[7]); // 1: the pixel's centre, as POV-Ray without anti-aliasing
    const auto run = [&](const auto& scene) {
        // The cache's rays per record are the effort: set through a mapper config the
        // examples' helper does not expose, so render here.
        if (method == "mask") {
            const prism::Film film = prism::render(scenes::cornell_camera<float>(), SeesDiffuseFirst<std::remove_cvref_t<decltype(scene)>>{&scene}, options.render);
            prism::write_pfm(film, out);
            return 0.0;
        }
        if (method == "path" || method == "path_bounces" || method == "path_grid2" || method.starts_with("path_rr") || method.starts_with("path_length")) {
            const auto start = std::chrono::steady_clock::now();
            typename prism::PathTracer<std::remove_cvref_t<decltype(scene)>>::Config config{
                .area_light_grid = method == "path_grid2" ? 2 : 1,
                .area_lights = method == "path_bounces" ? prism::AreaLightStrategy::bounces : prism::AreaLightStrategy::mis};
            if (method.starts_with("path_rr")) config.roulette_depth = std::atoi(method.c_str() + 7);
            if (method.starts_with("path_length")) config.max_length = std::atoi(method.c_str() + 11);
            const prism::PathTracer tracer(scene, config);
            const prism::Film film = prism::render(scenes::cornell_camera<float>(), tracer, options.render);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            prism::write_pfm(film, out);
            return seconds;
        }
        if (method == "cache") {
            using Mapper = prism::PhotonMapper<std::remove_cvref_t<decltype(scene)>>;
            const auto start = std::chrono::steady_clock::now();
            typename Mapper::Config config{.tracing = examples::photon_tracer_config(options), .caustic = examples::caustic_estimator(options), .gather_rays = 64};
            config.irradiance_cache.rays = int(effort);
            Mapper mapper(scene, config);
            mapper.cache_irradiance(scenes::cornell_camera<float>(), options.render);
            const prism::Film film = prism::render(scenes::cornell_camera<float>(), mapper, options.render);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            prism::write_pfm(film, out);
            return seconds;
        }
        return render_one(scene, options, out);
    };
    const double seconds = glass               ? run(scenes::cornell_scene<float>(!povray))
                           : which == "area" ? run(scenes::cornell_diffuse_area_scene<float>())
                                             : run(scenes::cornell_diffuse_scene<float>());
    std::printf("seconds %.4f\n", seconds);
    return 0;
}
