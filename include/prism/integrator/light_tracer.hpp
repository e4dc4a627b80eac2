// SPDX-License-Identifier: MIT
// light_trace: the light-tracing half of prism's reference estimator, for the paths a
// path tracer cannot find: those whose vertex next to the light is specular (a point
// light's caustics through glass or off a mirror), L S+ (S|D)* D E.
//
// Light paths are emitted as the caustic map's photons are (aimed at each specular
// object's bounding sphere, stratified by a scrambled Sobol sequence) and walked to
// their end (photon/random_walk.hpp). At every diffuse vertex after a first specular
// bounce, the path is joined to the pinhole by a shadow ray (glass opaque), adding
// to the pixel it lands in
//     power * (albedo / pi) * cos_x / (d^2 * A * cos_c^3)
// where d is the distance to the pinhole, cos_x the cosine at the surface, cos_c the one
// at the camera, and A a pixel's area on the image plane at distance 1: a pixel holds
// the mean radiance over it (Veach 1997, section 10.2; the importance of a pinhole).
// Paths whose first vertex is diffuse are the path tracer's (integrator/path_tracer.hpp),
// so the two add up without counting any path twice.
//
// Deterministic: paths are taken in fixed blocks, each block splats into its own
// buffer, and the buffers are added in block order, so the image is the same bits for
// any thread count.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/parallel.hpp>
#include <prism/photon/photon_tracer.hpp>
#include <prism/photon/random_walk.hpp>
#include <prism/render/film.hpp>
#include <prism/scene/camera.hpp>
#include <prism/scene/scene.hpp>

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

namespace prism {

struct LightTracerConfig {
    int width = 512;
    int height = 512;
    std::size_t paths = 1000000; ///< light paths aimed at the specular objects
    int max_bounces = 256;       ///< surfaces a path may meet; Russian roulette ends it long before
    int max_diffuse_bounces = 256; ///< as PathTracer's: 0 joins a path to the camera at its first diffuse surface only
    std::uint64_t seed = 0;
    unsigned threads = 0;        ///< 0 = all hardware threads
    int dispersion_bands = SpectralBands<float>::max_count; ///< as PhotonTracerConfig's
};

/// The light tracer's image of `scene` through `camera`: radiance per pixel from the
/// paths L S+ (S|D)* D E. Add it to a PathTracer render of the same camera and size for
/// the reference.
template <class SceneT, class Air = StraightAir>
[[nodiscard]] Film light_trace(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera, const LightTracerConfig& config,
                               const Air& air = {})
{
    using T = typename SceneT::scalar_type;
    if (config.max_diffuse_bounces < 0)
        detail::throw_invalid("LightTracerConfig max_diffuse_bounces must be >= 0, got ", config.max_diffuse_bounces);
    const CameraRays<T> rays = camera.rays(config.width, config.height);
    const detail::PhotonTracer<SceneT, Air> tracer(scene,
                                                   {.global_photons = 0,
                                                    .caustic_photons = config.paths,
                                                    .max_bounces = config.max_bounces,
                                                    .shadow_photons = false,
                                                    .seed = config.seed,
                                                    .threads = config.threads,
                                                    .dispersion_bands = config.dispersion_bands},
                                                   air);
    const std::size_t width = std::size_t(config.width), pixels = width * std::size_t(config.height);
    const T area = rays.pixel_area();

    // One block of paths splatted into `out` (zeroed first).
    const auto trace_block = [&](std::size_t first, std::size_t last, std::vector<Rgb<float>>& out) {
        std::fill(out.begin(), out.end(), Rgb<float>(0.0f));
        tracer.walk_aimed(first, last, config.paths, [&]<class M>(const M& material, const WalkVertex<T>& at, const Rgb<T>& power) {
            // A first hit on a diffuse lobe is the path tracer's; where the material also
            // has a delta lobe, the scattering here decides whose the path is.
            if (at.direct) return reflects<M> || transmits<M>;
            if (!at.first_specular) return false;
            const bool go_on = at.diffuse_bounces < config.max_diffuse_bounces;
            const Crossing<T>& c = at.crossing();
            const auto seen = rays.project(c.point);
            if (!seen || !(seen->x >= T(0) && seen->x < T(config.width) && seen->y >= T(0) && seen->y < T(config.height))) return go_on;
            const Vec3<T> to_camera = (rays.origin - c.point) / seen->distance;
            const T cos_x = dot(c.facing_normal(), to_camera);
            if (!(cos_x > T(0))) return go_on; // the camera sees the other side
            const Rgb<T> v = scene.template transmittance<ShadowsThroughGlass::blocked>(spawn_ray(c.point, c.error, c.normal, to_camera),
                                                                                         seen->distance);
            if (!(max_component(v) > T(0))) return go_on;
            T importance = cos_x / (seen->distance * seen->distance * area * seen->cos * seen->cos * seen->cos);
            // A shading normal weighs the light arriving here by its own cosine over the
            // true one (scattering.hpp).
            if (!c.shades_flat()) {
                importance *= shading_cosine(c.facing_shading(), c.facing_normal(), -at.direction) / -dot(at.direction, c.facing_normal());
                if (!(importance < infinity<T>)) return go_on;
            }
            const std::size_t pixel = std::size_t(seen->y) * width + std::size_t(seen->x);
            out[pixel] += Rgb<float>(power * diffuse_response(material, c).brdf() * v * importance);
            return go_on;
        });
    };

    constexpr std::size_t block = 16384;
    const std::size_t blocks = (config.paths + block - 1) / block;
    unsigned threads = detail::worker_count(config.threads);
    threads = unsigned(std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(blocks, 1)));
    std::vector<std::vector<Rgb<float>>> buffers(threads, std::vector<Rgb<float>>(pixels));
    std::vector<Rgb<double>> sum(pixels, Rgb<double>(0.0));
    for (std::size_t wave = 0; wave < blocks; wave += threads) {
        const std::size_t count = std::min<std::size_t>(threads, blocks - wave);
        const auto run = [&](std::size_t k) { trace_block((wave + k) * block, std::min(config.paths, (wave + k + 1) * block), buffers[k]); };
        std::vector<std::thread> workers;
        for (std::size_t k = 1; k < count; ++k) workers.emplace_back(run, k);
        run(0);
        for (auto& worker : workers) worker.join();
        for (std::size_t k = 0; k < count; ++k) // in block order, whatever the thread count
            for (std::size_t i = 0; i < pixels; ++i) sum[i] += Rgb<double>(buffers[k][i]);
    }
    Film film(config.width, config.height);
    for (std::size_t i = 0; i < pixels; ++i) film.set(int(i % width), int(i / width), sum[i]);
    return film;
}

} // namespace prism
