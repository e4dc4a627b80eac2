// SPDX-License-Identifier: MIT
// LightTracer: the light-tracing half of prism's reference estimator, for the paths a
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
// In a medium that scatters, a path is joined to the camera where it scatters as at a
// diffuse surface, the phase function toward the camera in place of the BRDF and no
// cosine there: power * p(cos) * T / (d^2 * A * cos_c^3), T what the air lets through on
// the way (the shadow ray's own stop at glass as ever). A path that scatters in the air
// before any specular bounce (L M ...) is the path tracer's, which samples the light from
// there.
//
// An integrator of passes (render/render.hpp's PassEstimator): pass s traces paths
// [s P, (s + 1) P) of one sequence, P = LightTracerConfig::paths, and the image is the mean
// of the passes'. Deterministic: each thread splats into its own exact sums
// (render/accumulation.hpp), whose addition has no rounding, so the image is the same
// bits for any thread count, and renders of disjoint ranges of the passes (or crops of
// the image) add up to the whole.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/parallel.hpp>
#include <prism/medium/air.hpp>
#include <prism/photon/photon_tracer.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/film.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>
#include <prism/scene/scene.hpp>
#include <prism/transport/media.hpp>
#include <prism/transport/random_walk.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace prism {

/// A LightTracer's settings: paths a pass, bounces, wavelength bands.
struct LightTracerConfig {
    std::size_t paths = 1000000;   ///< light paths per pass, aimed at the specular objects
    /// Segments a path may have from the light to the camera, vertices in media counted
    /// as those on surfaces (as PathTracer's: docs/guide.md); below 3 there are none
    /// (L S D E is the shortest). Russian roulette ends a path long before the default.
    int max_length = 1024;
    int max_diffuse_bounces = 256; ///< as PathTracer's: 0 joins a path to the camera at its first diffuse surface only
    int dispersion_bands = SpectralBands<float>::max_count; ///< as PhotonTracerConfig's
};

/// Light tracing of `scene` in its air: radiance from the paths L S+ (S|D)* D E. Add it to a
/// PathTracer render of the same camera and size for the reference (integrator/reference.hpp).
template <class SceneT, class Air = StraightAir>
class LightTracer {
public:
    /// The scene's precision.
    using scalar_type = typename SceneT::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;

    /// A light tracer of `scene` (which must outlive it) in `air`; throws std::invalid_argument, naming the parameter, for a bad scene, air or setting.
    explicit LightTracer(const SceneT& scene, LightTracerConfig config = {}, Air air = {}) : scene_(&scene), config_(config), air_(std::move(air))
    {
        scene.validate();
        air_.validate();
        if (config.paths == 0) detail::throw_invalid("LightTracerConfig paths must be >= 1, got 0");
        if (config.max_length < 1) detail::throw_invalid("LightTracerConfig max_length must be >= 1, got ", config.max_length);
        if (config.max_diffuse_bounces < 0)
            detail::throw_invalid("LightTracerConfig max_diffuse_bounces must be >= 0, got ", config.max_diffuse_bounces);
        detail::validate(tracer_config(1, 0, 1));
    }
    LightTracer(const SceneT&& scene, LightTracerConfig config = {}, Air air = {}) = delete;

    /// The settings.
    [[nodiscard]] const LightTracerConfig& config() const noexcept { return config_; }

    /// Passes config.passes of config.spp (render/render.hpp's PassEstimator).
    void add_passes(Accumulation& sums, const Camera<T>& camera, const RenderConfig& config) const
    {
        add_splats(sums, camera, config);
        const PassRange passes = detail::render_passes(config);
        const PixelWindow window = detail::render_window(config);
        const std::array<ExactSum, 3> none{};
        for (int y = window.y0; y < window.y1; ++y)
            for (int x = window.x0; x < window.x1; ++x) sums.add(x, y, none, passes.count());
    }

    /// The splats of passes config.passes of config.spp over the config's crop window,
    /// without their weights, each pass's counted as one sample's: added to the sums of
    /// another estimator's config.spp samples per pixel, their mean is the sum of both
    /// estimates (the reference).
    void add_splats(Accumulation& sums, const Camera<T>& camera, const RenderConfig& config) const
    {
        const CameraRays<T> rays = camera.rays(config.width, config.height);
        const PixelWindow window = detail::render_window(config);
        const PassRange passes = detail::render_passes(config);
        if (sums.width() != config.width || sums.height() != config.height || !sums.window().contains(window))
            detail::throw_invalid("LightTracer: the Accumulation does not hold the RenderConfig's window");
        const std::uint64_t per_pass = config_.paths;
        if (std::uint64_t(config.spp) > std::numeric_limits<std::uint64_t>::max() / per_pass)
            detail::throw_invalid("LightTracer: ", config.spp, " passes of ", per_pass, " paths overflow a 64-bit path index");
        const std::uint64_t count = std::uint64_t(config.spp) * per_pass;
        if (config_.max_length < 3) return; // no path it finds is that short
        const PassRange traced{passes.first * per_pass, passes.last * per_pass};
        const detail::PhotonTracer<SceneT, Air> tracer(*scene_, tracer_config(count, config.seed, config.threads), air_);
        const View view{rays, window, rays.pixel_area(), double(config.spp)};
        // A block of paths splatted into `out`.
        const auto trace_block = [&](std::uint64_t first, std::uint64_t last, Accumulation& out) {
            tracer.walk_aimed(
                first, last, count, [&]<class M>(const M& material, const WalkVertex<T>& at, const Rgb<T>& power) { return at_surface(material, at, power, view, out); },
                [&]<class Md>(const Md& medium, const WalkMediumVertex<T>& at, const Rgb<T>& power) { return in_medium(medium, at, power, view, out); });
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

private:
    /// What the camera sees: its rays, the window splats land in, a pixel's area on the
    /// image plane, and what each splat is scaled by (the passes).
    struct View {
        const CameraRays<T>& rays; ///< the camera's rays
        PixelWindow window;        ///< the pixels splats land in
        T area;                    ///< a pixel's area on the image plane
        double scale;              ///< each splat's scale: the passes

        /// Where the camera sees point p, in the window (or nothing), and the unit direction
        /// from p to the eye: for a thin lens, a point of the lens drawn uniformly, seen as a
        /// pinhole there sees.
        struct Seen {
            typename CameraRays<T>::Projection at; ///< where on the image, and how far
            Vec3<T> to_camera;                     ///< unit, from the point to the eye
        };
        [[nodiscard]] std::optional<Seen> look_from(const Vec3<T>& p, Random& rng) const noexcept
        {
            Vec3<T> eye = rays.origin;
            if (rays.thin_lens()) {
                const auto [u, v] = rng.template uniform2<T>();
                eye = rays.lens_point(u, v);
            }
            const auto seen = rays.thin_lens() ? rays.project(p, eye) : rays.project(p);
            if (!seen || !(seen->x >= T(window.x0) && seen->x < T(window.x1) && seen->y >= T(window.y0) && seen->y < T(window.y1))) return std::nullopt;
            return Seen{*seen, (eye - p) / seen->distance};
        }
    };

    /// A path at a surface: joined to the camera where it is the light tracer's (L S+ D ... E:
    /// the camera's own first scattering specular), its splat added to `out`. Whether the
    /// walk goes on.
    template <class M>
    [[nodiscard]] bool at_surface(const M& material, const WalkVertex<T>& at, const Rgb<T>& power, const View& view, Accumulation& out) const noexcept
    {
        // A first hit on a diffuse lobe is the path tracer's; where the material also
        // has a delta lobe (a mirror beside it, or a glossy lobe's delta part: a
        // mix's mirror, a smooth coat), the scattering here decides whose the path is.
        if (at.direct) {
            if constexpr (has_glossy<M>) {
                if (glossy_at(material, at.crossing(), at.direction, glossy_eta(material, at.crossing(), at.outside_index)).delta_part()) return true;
            }
            return reflects<M> || (transmits<M> && !has_glossy<M>);
        }
        if (!at.first_specular) return false;
        const bool go_on = at.diffuse_bounces < config_.max_diffuse_bounces;
        const Crossing<T>& c = at.crossing();
        const auto look = view.look_from(c.point, at.rng);
        if (!look) return go_on;
        const auto& seen = look->at;
        const Vec3<T>& to_camera = look->to_camera;
        // The camera sees the other side: only through a glossy interface (frosted glass).
        const T cos_x = transmits<M> && has_glossy<M> ? std::abs(dot(c.facing_normal(), to_camera)) : dot(c.facing_normal(), to_camera);
        if (!(cos_x > T(0))) return go_on;
        const Rgb<T> v = scene_->template transmittance<ShadowsThroughGlass::blocked>(spawn_ray(c.point, c.error, c.normal, to_camera),
                                                                                       seen.distance) *
                         air_transmittance<ShadowsThroughGlass::blocked>(*scene_, air_, Ray<T>{c.point, to_camera}, seen.distance);
        if (!(max_component(v) > T(0))) return go_on;
        T importance = cos_x / (seen.distance * seen.distance * view.area * seen.cos * seen.cos * seen.cos);
        // A shading normal weighs the light arriving here by its own cosine over the
        // true one (scattering.hpp).
        if (!c.shades_flat()) {
            importance *= shading_cosine(c.facing_shading(), c.facing_normal(), -at.direction) / -dot(at.direction, c.facing_normal());
            if (!(importance < infinity<T>)) return go_on;
        }
        Rgb<T> f;
        if constexpr (has_glossy<M>) f = glossy_at(material, c, at.direction, glossy_eta(material, c, at.outside_index)).f(to_camera, Transport::importance);
        else f = diffuse_response(material, c).brdf();
        splat(out, seen, power * f * v * importance, view.scale);
        return go_on;
    }

    /// A path scattering in a medium: joined to the camera where it is the light tracer's.
    /// Whether the walk goes on.
    template <class Md>
    [[nodiscard]] bool in_medium(const Md& medium, const WalkMediumVertex<T>& at, const Rgb<T>& power, const View& view, Accumulation& out) const noexcept
    {
        // Scattered in the air before any specular bounce: the path tracer's.
        if (at.direct || !at.first_specular) return false;
        const bool go_on = at.diffuse_bounces < config_.max_diffuse_bounces;
        const auto look = view.look_from(at.point, at.rng);
        if (!look) return go_on;
        const auto& seen = look->at;
        const Vec3<T>& to_camera = look->to_camera;
        const Rgb<T> v = scene_->template transmittance<ShadowsThroughGlass::blocked>(Ray<T>{at.point, to_camera}, seen.distance) *
                         through_air(at.point, to_camera, seen.distance);
        if (!(max_component(v) > T(0))) return go_on;
        const T importance = T(medium.phase.value(dot(at.direction, to_camera))) / (seen.distance * seen.distance * view.area * seen.cos * seen.cos * seen.cos);
        splat(out, seen, power * v * importance, view.scale);
        return go_on;
    }

    /// What the scene's air lets through from `p` in a medium to the camera, `distance`
    /// along `to_camera`: its medium's transmittance over the stretches outside the
    /// objects the ray passes (FilledAir; from inside a ball of smoke, the air beyond it),
    /// 1 in clear air. (From inside glass the scene's transmittance is 0.)
    [[nodiscard]] Rgb<T> through_air(const Vec3<T>& p, const Vec3<T>& to_camera, T distance) const noexcept
    {
        return air_transmittance<ShadowsThroughGlass::blocked>(*scene_, air_, Ray<T>{p, to_camera}, distance);
    }

    /// Adds `value` (one path's radiance on the pixel, times `scale`) to the pixel `seen`
    /// lands in; a part that is negative, not finite or too large for exact sums is rejected.
    template <class Seen>
    static void splat(Accumulation& out, const Seen& seen, const Rgb<T>& value, double scale) noexcept
    {
        const Rgb<float> radiance(value);
        std::array<ExactSum, 3> add{};
        for (int k = 0; k < 3; ++k) {
            const double v = double(radiance[k]) * scale;
            if (v >= 0.0 && ExactSum::takes(v)) add[std::size_t(k)] = ExactSum::of(v);
            else out.reject(1);
        }
        out.add(int(seen.x), int(seen.y), add, 0);
    }

    /// The photon tracer's settings for `count` paths in all.
    [[nodiscard]] PhotonTracerConfig tracer_config(std::uint64_t count, std::uint64_t seed, unsigned threads) const noexcept
    {
        return {.global_photons = 0,
                .caustic_photons = count,
                .max_bounces = std::numeric_limits<int>::max(),
                .max_medium_bounces = std::numeric_limits<int>::max(),
                .max_length = std::max(config_.max_length - 1, 1), // a vertex joined to the camera by one segment more
                .shadow_photons = false,
                .seed = seed,
                .threads = threads,
                .dispersion_bands = config_.dispersion_bands};
    }

    const SceneT* scene_;
    LightTracerConfig config_;
    Air air_;
};

} // namespace prism
