// SPDX-License-Identifier: MIT
// PathTracer: the unbiased half of prism's reference estimator (the light tracer is the
// other half, integrator/light_tracer.hpp).
//
// A camera path walks the scene as a photon does (transport/random_walk.hpp: Fresnel-
// weighted choice at glass, one wavelength band at a dispersive interface), but ended by
// Russian roulette on its throughput after its first few surfaces, not at each bounce, and, at every diffuse vertex, adds the light arriving from each
// light by a shadow ray: next-event estimation, the only way a path can meet a point or
// parallel light. Glass is opaque to shadow rays, as in the photon mapper (but for an
// index-matched boundary, which bends nothing and is no vertex of a path either: a ball of
// smoke, may_match_index; shadow rays pass it, through its medium): a path whose
// vertex next to the light is specular (L S ...) cannot be found from the camera, and
// is the light tracer's. The two estimators count disjoint sets of paths, so their sum
// is every path either can sample:
//   path tracer   paths whose vertex next to the light is diffuse: E (S|D)* D L
//   light tracer  paths L S+ (S|D)* D E, connected to the camera at a diffuse vertex
// Neither can sample E S+ D S+ L with a point light and a pinhole (a caustic seen in a
// mirror): no unbiased method can, since each of its edges has a delta end.
// With the scene's BRDF albedo / pi and one radiometric convention, a closed diffuse
// room of albedo rho under a light at its centre gives rho / (1 - rho) times E / pi:
// the furnace reads 1.0 where Whitted reads 0.5.
// In a medium that scatters (an object's Fog, or FilledAir around everything) a path
// scatters in the air as at a surface: light samples there are weighed by the phase
// function and the medium's transmittance to the light, shared with the phase
// function's own draw by MIS, and every shadow ray in the air takes the air's
// transmittance. A point or spot light in a uniform medium is also sampled along each
// stretch of medium a path crosses, by equiangular sampling (Kulla and Fajardo 2012:
// density proportional to 1 / d^2 from the light), combined with the light samples taken
// where free flights end by the balance heuristic: thin haze in a narrow beam is found
// by the first, dense fog by the second.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/overload.hpp>
#include <prism/core/random.hpp>
#include <prism/transport/direct.hpp>
#include <prism/transport/equiangular.hpp>
#include <prism/material/scattering.hpp>
#include <prism/medium/air.hpp>
#include <prism/transport/media.hpp>
#include <prism/transport/travel.hpp>
#include <prism/transport/random_walk.hpp>
#include <prism/spectrum/bands.hpp>

#include <limits>

namespace prism {

/// How a path tracer finds the light of area lights at a diffuse vertex.
enum class AreaLightStrategy {
    mis,          ///< light samples and the diffuse bounce, combined by the power heuristic (Veach 1995)
    light_samples, ///< light samples only (a bounce that meets the light counts nothing)
    bounces,      ///< the diffuse bounce only (no shadow ray toward an area light)
};

/// Unbiased path tracing with next-event estimation, in the scene's air.
template <class SceneT, class Air = StraightAir>
class PathTracer {
public:
    /// The scene's precision.
    using scalar_type = typename SceneT::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;

    /// A PathTracer's settings.
    struct Config {
        /// Segments a path may have from the camera to the light (1: lights seen directly;
        /// 2: direct light; ...), vertices in media counted as those on surfaces: every
        /// prism estimator counts its depth so (docs/guide.md). Russian roulette ends a
        /// path long before the default.
        int max_length = 1024;
        /// Surfaces a path scatters at before Russian roulette on its throughput may end it
        /// (path_roulette; pbrt's depth 1, Mitsuba's rr_depth 5). Roulette at the first
        /// bounces cuts short the paths a caustic is found by, on their way to the light;
        /// later it saves the long tails of dim paths. 3 was the most efficient on the
        /// area-lit Cornell box with Sobol samples (1 to 8 tried: docs/benchmarks.md).
        int roulette_depth = 3;
        /// Diffuse bounces a path may take: 0 lights each pixel's first diffuse surface by
        /// shadow rays and goes no further (direct light, seen directly or through
        /// mirrors and glass), as POV-Ray without radiosity; 1 adds one bounce, and so on.
        int max_diffuse_bounces = 256;
        /// A white path meeting a dispersive interface takes one of this many wavelength
        /// bands at random (1 to 81), as a photon does.
        int dispersion_bands = SpectralBands<float>::max_count;
        /// Area lights sampled per diffuse vertex, on a jittered grid of this many points
        /// per side (each combined with the diffuse bounce by the power heuristic).
        int area_light_grid = 1;
        /// How light samples and diffuse bounces share the area lights' light.
        AreaLightStrategy area_lights = AreaLightStrategy::mis;
        /// Whether a path that meets an area or environment light through mirrors and glass
        /// after a diffuse bounce (... D S+ L: a caustic of the light) counts it. The path
        /// tracer alone does; Reference leaves those paths to its light tracer, but for
        /// the ones the camera sees through mirrors and glass first (E S+ D ... S+ L), which
        /// a light tracer cannot join to the camera: those the path tracer always counts.
        bool caustics_of_area_lights = true;
        /// Whether point and spot lights in a uniform medium are also sampled along each
        /// stretch of medium by equiangular sampling, MIS'd with the light samples where
        /// free flights end (false: those alone).
        bool equiangular = true;
    };

    /// A path tracer of `scene` (which must outlive it) in `air`; throws std::invalid_argument, naming the parameter, for a bad scene, air or setting.
    explicit PathTracer(const SceneT& scene, Config config = {}, Air air = {})
        : scene_(&scene), config_(config), bands_(checked_bands(config.dispersion_bands)), air_(std::move(air))
    {
        scene.validate();
        air_.validate();
        if (config.max_length < 1) detail::throw_invalid("PathTracer max_length must be >= 1, got ", config.max_length);
        if (config.roulette_depth < 0) detail::throw_invalid("PathTracer roulette_depth must be >= 0, got ", config.roulette_depth);
        if (config.max_diffuse_bounces < 0) detail::throw_invalid("PathTracer max_diffuse_bounces must be >= 0, got ", config.max_diffuse_bounces);
        if (config.area_light_grid < 1 || config.area_light_grid > 64)
            detail::throw_invalid("PathTracer area_light_grid must be in [1, 64], got ", config.area_light_grid);
    }
    PathTracer(const SceneT&& scene, Config config = {}, Air air = {}) = delete;

    /// The radiance along a camera ray: light at every diffuse vertex by shadow rays, and
    /// the background where a path of specular bounces only leaves the scene (the
    /// background is seen, as in Whitted, but lights nothing).
    [[nodiscard]] Rgb<T> radiance(const Ray<T>& ray, Random& rng) const noexcept
    {
        Path path{.sampling = {&rng, config_.area_light_grid}};
        random_walk<Transport::radiance>(
            *scene_, air_, bands_, ray, Rgb<T>(T(1)), rng, walk_limits(),
            WalkHooks{.on_surface = [&]<class M>(const M& material, const WalkVertex<T>& at) { return at_surface(material, at, path); },
                      .on_escape = [&](const WalkEscape<T>& out) { escaped(out, path); },
                      .on_emitter = [&]<class M>(const M& material, const WalkVertex<T>& at) { met_emitter(material, at, path); },
                      .on_medium = Overload{[&]<class Md>(const Md& medium, const WalkMediumVertex<T>& at) { return in_medium(medium, at, path); },
                                            [&]<class Md>(const Md& medium, const WalkMediumStretch<T>& stretch) { return along_medium(medium, stretch, path); }}},
            scene_->media_at(ray.origin));
        return path.sum;
    }

    /// The scene and the air its camera rays start in (render_layers' surface layers).
    [[nodiscard]] const SceneT& scene() const noexcept { return *scene_; }
    /// The air camera rays start in.
    [[nodiscard]] const Air& air() const noexcept { return air_; }

    /// The weight of one of a vertex's samples of a light with extent, drawn with solid-angle
    /// density `light_pdf`, where the diffuse bounce from there would draw its direction with
    /// `bounce_pdf` (cos / pi): the power heuristic, counting every sample the vertex takes of
    /// the light (area_light_grid^2), with AreaLightStrategy::mis; 1 or 0 for the strategies
    /// alone (the caller skips light samples for `bounces`). With met_light_weight of the same
    /// path it sums to 1 (tests/integrator/path_tracer.cpp).
    [[nodiscard]] T light_sample_weight(T light_pdf, T bounce_pdf) const noexcept
    {
        return config_.area_lights == AreaLightStrategy::mis ? power_heuristic(light_samples() * light_pdf, bounce_pdf) : T(1);
    }

    /// The weight of a light with extent (an area or environment light) that a path meets
    /// after a diffuse bounce: with a diffuse bounce just before it (its density last_pdf,
    /// cos / pi), the power heuristic against sampling the light from there (n samples of
    /// density light_pdf(): n times it), or 1 or 0 for the strategies alone; through mirrors
    /// and glass after a diffuse bounce (no light sample can find it there), 1 where the path
    /// tracer counts such paths, else 0, but 1 always when the camera's own first scattering
    /// was specular (`first_specular`): a light tracer joins its paths to the camera from a
    /// diffuse surface the camera sees directly, so it cannot have them. (Seen from the
    /// camera through mirrors and glass only, a light counts whole: the caller's.)
    template <class LightPdf>
    [[nodiscard]] T met_light_weight(T last_pdf, bool first_specular, LightPdf&& light_pdf) const noexcept
    {
        if (last_pdf > T(0)) {
            if (config_.area_lights != AreaLightStrategy::mis) return config_.area_lights == AreaLightStrategy::bounces ? T(1) : T(0);
            return power_heuristic(last_pdf, light_samples() * light_pdf());
        }
        return config_.caustics_of_area_lights || first_specular ? T(1) : T(0);
    }

private:
    /// A camera path's light so far, and how its vertices sample the lights.
    struct Path {
        Rgb<T> sum{T(0)};
        LightSampling sampling;
    };

    /// At a diffuse or glossy surface: every light's samples there. Whether the walk goes on.
    template <class M>
    [[nodiscard]] bool at_surface(const M& material, const WalkVertex<T>& at, Path& path) const noexcept
    {
        if (at.last) return false; // (a light sample from here would make one segment too many)
        const Crossing<T>& c = at.crossing();
        const bool go_on = at.diffuse_bounces < config_.max_diffuse_bounces;
        // Each light sample: an area light's shares its path with the bounce that finds it
        // where the walk goes on (the diffuse lobe's cos / pi, a glossy lobe's own density
        // there). A diffuse lobe sums irradiance and takes its BRDF once; a glossy one weighs
        // each sample by f toward it, from both sides for a glossy interface (its lobe refracts).
        constexpr Sides sides = has_glossy<M> && transmits<M> ? Sides::both : Sides::near;
        const auto lobe = [&] {
            if constexpr (has_glossy<M>) return glossy_at(material, c, at.direction, glossy_eta(material, c, at.outside_index));
            else return diffuse_response(material, c);
        }();
        Rgb<T> gathered{T(0)};
        scene_->for_each_light([&]<class L>(const L& light) {
            if constexpr (!is_delta_light<L>) {
                if (config_.area_lights == AreaLightStrategy::bounces && go_on) return;
            }
            for_each_sample_arriving<ShadowsThroughGlass::blocked, sides>(*scene_, light, c, path.sampling, [&](const LightSample<T>& s, const Rgb<T>& v, T cos) {
                const bool shared = !s.delta() && go_on;
                if constexpr (has_glossy<M>) {
                    const Rgb<T> f = lobe.f(s.wi, Transport::radiance);
                    if (!(max_component(f) > T(0))) return;
                    const T w = shared ? light_sample_weight(s.pdf, lobe.pdf(s.wi)) : T(1);
                    gathered += (w * cos) * f * v * air_transmittance<ShadowsThroughGlass::blocked>(*scene_, air_, Ray<T>{c.point, s.wi}, s.distance) * s.irradiance;
                } else {
                    const T w = shared ? light_sample_weight(s.pdf, cos / pi<T>) : T(1);
                    gathered += w * v * air_transmittance<ShadowsThroughGlass::blocked>(*scene_, air_, Ray<T>{c.point, s.wi}, s.distance) * s.irradiance * cos;
                }
            });
        });
        if constexpr (has_glossy<M>) path.sum += at.power * gathered;
        else path.sum += at.power * lobe.brdf() * gathered;
        return go_on;
    }

    /// Leaving the scene: the background, or an environment light's light.
    void escaped(const WalkEscape<T>& out, Path& path) const noexcept
    {
        if (out.specular_only()) {
            path.sum += out.power * scene_->escaped(out.ray.direction);
            return;
        }
        // After a diffuse bounce the background lights nothing; an environment light does,
        // shared with its samples as an area light's.
        scene_->for_each_light([&]<class L>(const L& light) {
            if constexpr (is_at_infinity<L>) {
                const Vec3<T> d = normalize(out.ray.direction);
                path.sum += out.power * light.arriving_from(d) * met_light_weight(out.last_pdf, out.first_specular, [&] { return light.pdf(d); });
            }
        });
    }

    /// Meeting an area light: its light, shared with the light samples that find it.
    template <class M>
    void met_emitter(const M& material, const WalkVertex<T>& at, Path& path) const noexcept
    {
        if constexpr (SceneT::has_emitters) {
            if (at.specular_only()) path.sum += at.power * emitted(material, at.crossing());
            else path.sum += at.power * emitted(material, at.crossing()) *
                             met_light_weight(at.last_pdf, at.first_specular, [&] { return scene_->area_lights().pdf(at.hit, at.last_point); });
        }
    }

    /// Scattering in a medium: the light samples there. Whether the walk goes on.
    template <class Md>
    [[nodiscard]] bool in_medium(const Md& medium, const WalkMediumVertex<T>& at, Path& path) const noexcept
    {
        // Each light's samples weighed by the phase function toward them (the bounce's
        // density there, for MIS), no cosine; a point or spot light's shared with its
        // equiangular samples.
        if (at.last) return false;
        const bool go_on = at.diffuse_bounces < config_.max_diffuse_bounces;
        Rgb<T> gathered{T(0)};
        scene_->for_each_light([&]<class L>(const L& light) {
            if constexpr (!is_delta_light<L>) {
                if (config_.area_lights == AreaLightStrategy::bounces && go_on) return;
            }
            T shared = T(1);
            // (Tested on the medium first, outside the light's condition: clang checks a
            // branch that depends on the light alone against the medium at hand.)
            if constexpr (uniform_medium<Md>) {
                if constexpr (has_equiangular<L, Md>) {
                    if (config_.equiangular) {
                        const T t = dot(at.point - at.stretch.origin, at.stretch.direction);
                        const T flight = medium.flight_pdf(at.entering, t);
                        shared = flight / (flight + Equiangular(at.stretch, at.stretch_length, light.position).pdf(t));
                    }
                }
            }
            for_each_sample_in_medium<ShadowsThroughGlass::blocked>(*scene_, light, at.point, path.sampling, [&](const LightSample<T>& s, const Rgb<T>& v) {
                const T phase = medium.phase.value(dot(at.direction, s.wi));
                const T w = !s.delta() && go_on ? light_sample_weight(s.pdf, phase) : shared;
                gathered += (w * phase) * v * through_air(at.point, s) * s.irradiance;
            });
        });
        path.sum += at.power * gathered;
        return go_on;
    }

    /// Entering a stretch of a medium: a point or spot light's equiangular samples along it.
    template <class Md>
    [[nodiscard]] bool along_medium(const Md& medium, const WalkMediumStretch<T>& stretch, Path& path) const noexcept
    {
        // (Each sample is a vertex on the stretch, and a segment from there to the light.)
        if constexpr (uniform_medium<Md>) {
            if (!config_.equiangular || stretch.vertices + 2 > config_.max_length) return true;
            scene_->for_each_light([&]<class L>(const L& light) {
                if constexpr (has_equiangular<L, Md>) path.sum += equiangular_sample(medium, light, stretch, path.sampling);
            });
        }
        return true;
    }

    /// The walk's limits: max_length alone (no count of surfaces or of scatterings in media
    /// apart), and roulette_depth.
    [[nodiscard]] WalkLimits walk_limits() const noexcept
    {
        constexpr int none = std::numeric_limits<int>::max();
        return {.max_bounces = none, .max_medium_bounces = none, .roulette_depth = config_.roulette_depth, .max_length = config_.max_length};
    }

    /// Whether a light is sampled along stretches of medium Md: a delta light at a point,
    /// in a uniform medium.
    template <class L, class Md>
    static constexpr bool has_equiangular = uniform_medium<Md> && aimed_equiangularly<L> && requires(const Md& medium, const Rgb<T>& power) {
        medium.flight_pdf(power, T(0));
    };

    /// One equiangular sample of `light` along a stretch of uniform `medium`: its light
    /// scattered once toward the path there, through the medium's transmittance back to
    /// the stretch's start, over the sample's density, weighed against the free flight's
    /// light sample by the balance heuristic.
    template <class Md, class L>
    [[nodiscard]] Rgb<T> equiangular_sample(const Md& medium, const L& light, const WalkMediumStretch<T>& stretch, const LightSampling& sampling) const noexcept
    {
        const Equiangular rule(stretch.ray, stretch.length, light.position);
        const T t = rule.sample(stretch.rng.template uniform<T>());
        const T density = rule.pdf(t);
        if (!(t >= T(0) && t < stretch.length && density > T(0) && density < infinity<T>)) return Rgb<T>(T(0));
        const Vec3<T> p = stretch.ray.at(t);
        const T w = density / (density + medium.flight_pdf(stretch.power, t));
        Rgb<T> out{T(0)};
        for_each_sample_in_medium<ShadowsThroughGlass::blocked>(*scene_, light, p, sampling, [&](const LightSample<T>& s, const Rgb<T>& v) {
            const T phase = medium.phase.value(dot(stretch.ray.direction, s.wi));
            out += (w * phase / density) * v * through_air(p, s) * s.irradiance;
        });
        return stretch.power * medium.transmittance(t) * medium.scattering_at(p) * out;
    }

    /// What the scene's air lets through along a light sample's shadow ray from `p` in a
    /// medium: its medium's transmittance over the stretches outside the objects the shadow
    /// ray passes (FilledAir; from inside a ball of smoke, the air beyond it), 1 in clear
    /// air. (From inside glass the scene's transmittance is 0: the ray stops at the glass.)
    [[nodiscard]] Rgb<T> through_air(const Vec3<T>& p, const LightSample<T>& s) const noexcept
    {
        return air_transmittance<ShadowsThroughGlass::blocked>(*scene_, air_, Ray<T>{p, s.wi}, s.distance);
    }

    /// The samples each area light takes at a diffuse vertex (the heuristic counts them all).
    [[nodiscard]] T light_samples() const noexcept { return T(config_.area_light_grid * config_.area_light_grid); }

    /// Veach's power heuristic (beta = 2) for a sample drawn with density `mine` where the
    /// other strategy has density `other`: mine^2 / (mine^2 + other^2).
    [[nodiscard]] static T power_heuristic(T mine, T other) noexcept
    {
        const T a = mine * mine, b = other * other;
        return a + b > T(0) ? a / (a + b) : T(0);
    }

    static SpectralBands<T> checked_bands(int count)
    {
        if (count < 1 || count > SpectralBands<float>::max_count)
            detail::throw_invalid("PathTracer dispersion_bands must be in [1, ", SpectralBands<float>::max_count, "], got ", count);
        return SpectralBands<T>(count);
    }

    const SceneT* scene_;
    Config config_;
    SpectralBands<T> bands_;
    Air air_;
};

} // namespace prism
