// SPDX-License-Identifier: MIT
// light_trace: the light-tracing half of prism's reference estimator, for the paths a
// path tracer cannot find: those whose vertex next to the light is specular (a point
// light's caustics through glass or off a mirror), L S+ (S|D)* D E.
//
// Light paths are emitted as the caustic map's photons are (aimed at each specular
// object's bounding sphere, stratified by a scrambled Sobol sequence) and walked to
// their end (transport/random_walk.hpp). At every diffuse vertex after a first specular
// bounce, the path is joined to the pinhole by a shadow ray (glass opaque), adding
// to the pixel it lands in
//     power * (albedo / pi) * cos_x / (d^2 * A * cos_c^3)
// where d is the distance to the pinhole, cos_x the cosine at the surface, cos_c the one
// at the camera, and A a pixel's area on the image plane at distance 1: a pixel holds
// the mean radiance over it (Veach 1997, section 10.2; the importance of a pinhole).
// Paths whose first vertex is diffuse are the path tracer's (integrator/path_tracer.hpp),
// so the two add up without counting any path twice.
//
// Deterministic: each thread splats into its own exact sums (render/accumulation.hpp),
// whose addition has no rounding, so the image is the same bits for any thread count,
// and renders of disjoint ranges of the paths (or crops of the image) add up to the
// whole.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/parallel.hpp>
#include <prism/photon/photon_tracer.hpp>
#include <prism/transport/random_walk.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/film.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>
#include <prism/scene/scene.hpp>

#include <algorithm>
#include <array>
#include <cmath>
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
    /// The pixels to splat into; empty (the default): all. Every path is still traced:
    /// a path's end cannot be known before it is walked.
    PixelWindow crop{};
    /// The paths to trace, [first, last) of `paths`; empty (the default): all of them.
    PassRange traced{};
};

/// Add the light tracer's splats of `scene` through `camera` (radiance from the paths
/// L S+ (S|D)* D E), times `scale`, to the R, G, B sums of `sums`, which must hold the
/// config's crop window; weights are left as they are. The reference estimator adds
/// them to a PathTracer's samples (scale: its samples per pixel).
template <class SceneT, class Air = StraightAir>
void light_trace_into(Accumulation& sums, const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera, const LightTracerConfig& config,
                      double scale = 1.0, const Air& air = {})
{
    using T = typename SceneT::scalar_type;
    if (config.max_diffuse_bounces < 0)
        detail::throw_invalid("LightTracerConfig max_diffuse_bounces must be >= 0, got ", config.max_diffuse_bounces);
    if (!(scale > 0.0 && std::isfinite(scale))) detail::throw_invalid("light_trace_into scale must be finite and > 0, got ", scale);
    const CameraRays<T> rays = camera.rays(config.width, config.height);
    const PixelWindow window = detail::render_window({.width = config.width, .height = config.height, .crop = config.crop});
    if (sums.width() != config.width || sums.height() != config.height || !sums.window().contains(window))
        detail::throw_invalid("light_trace_into: the Accumulation does not hold the LightTracerConfig's window");
    const PassRange traced = config.traced == PassRange{} ? PassRange{0, config.paths} : config.traced;
    if (traced.empty() || traced.last > config.paths)
        detail::throw_invalid("LightTracerConfig traced [", traced.first, ", ", traced.last, ") must be a non-empty range of the ", config.paths, " paths");
    const detail::PhotonTracer<SceneT, Air> tracer(scene,
                                                   {.global_photons = 0,
                                                    .caustic_photons = config.paths,
                                                    .max_bounces = config.max_bounces,
                                                    .shadow_photons = false,
                                                    .seed = config.seed,
                                                    .threads = config.threads,
                                                    .dispersion_bands = config.dispersion_bands},
                                                   air);
    const T area = rays.pixel_area();

    // A block of paths splatted into `out`.
    const auto trace_block = [&](std::uint64_t first, std::uint64_t last, Accumulation& out) {
        tracer.walk_aimed(first, last, config.paths, [&]<class M>(const M& material, const WalkVertex<T>& at, const Rgb<T>& power) {
            // A first hit on a diffuse lobe is the path tracer's; where the material also
            // has a delta lobe, the scattering here decides whose the path is.
            if (at.direct) return reflects<M> || transmits<M>;
            if (!at.first_specular) return false;
            const bool go_on = at.diffuse_bounces < config.max_diffuse_bounces;
            const Crossing<T>& c = at.crossing();
            const auto seen = rays.project(c.point);
            if (!seen || !(seen->x >= T(window.x0) && seen->x < T(window.x1) && seen->y >= T(window.y0) && seen->y < T(window.y1))) return go_on;
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
            const Rgb<float> splat(power * diffuse_response(material, c).brdf() * v * importance);
            std::array<ExactSum, 3> add{};
            for (int k = 0; k < 3; ++k) {
                const double value = double(splat[k]) * scale;
                if (value >= 0.0 && ExactSum::takes(value)) add[std::size_t(k)] = ExactSum::of(value);
                else out.reject(1);
            }
            out.add(int(seen->x), int(seen->y), add, 0);
            return go_on;
        });
    };

    // Blocks of paths dealt to threads as they ask; each thread's sums are exact, so
    // which thread took which block changes no bit.
    constexpr std::uint64_t block = 16384;
    const std::uint64_t blocks = (traced.count() + block - 1) / block;
    std::vector<Accumulation> buffers;
    const unsigned workers = detail::workers_for(blocks, config.threads);
    buffers.reserve(workers);
    for (unsigned k = 0; k < workers; ++k) buffers.emplace_back(config.width, config.height, window);
    detail::parallel_blocks(blocks, config.threads, [&](std::size_t b, unsigned worker) {
        trace_block(traced.first + b * block, std::min(traced.last, traced.first + (b + 1) * block), buffers[worker]);
    });
    for (const Accumulation& buffer : buffers) sums += buffer;
}

/// The light tracer's image of `scene` through `camera` (the config's crop window):
/// radiance per pixel from the paths L S+ (S|D)* D E. Add it to a PathTracer render of
/// the same camera and size for the reference.
template <class SceneT, class Air = StraightAir>
[[nodiscard]] Film light_trace(const SceneT& scene, const Camera<typename SceneT::scalar_type>& camera, const LightTracerConfig& config,
                               const Air& air = {})
{
    (void)camera.rays(config.width, config.height); // a bad size is the camera's to name
    Accumulation sums(config.width, config.height, detail::render_window({.width = config.width, .height = config.height, .crop = config.crop}));
    light_trace_into(sums, scene, camera, config, 1.0, air);
    const PixelWindow& w = sums.window();
    const std::array<ExactSum, 3> none{};
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x) sums.add(x, y, none, 1); // the splats are the pixel's value, not a sum of samples
    return sums.image();
}

} // namespace prism
