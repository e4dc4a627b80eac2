// SPDX-License-Identifier: MIT
// Whitted: recursive ray tracing (Whitted 1980, "An improved illumination model for
// shaded display", Communications of the ACM 23(6)).
//
// At each hit:
//   L = L_emitted + albedo (kd L_diffuse + ka L_ambient prod_lights (1 - V_light)) + kr L_reflect + kt L_transmit
// with L_diffuse = sum_lights V E cos / pi (a Lambertian BRDF albedo / pi lit by shadow
// rays; V is the shadow ray's transmittance, so a light seen through glass counts
// partly; an area light is the mean over a jittered grid of its points, its V the mean
// of theirs: soft shadows), kr and kt weighted by Fresnel on dielectrics, Beer-Lambert absorption along
// every segment travelled inside a dielectric, a depth limit and an adaptive cut-off
// when a path's weight becomes negligible (Hall and Greenberg 1983). Through a medium
// that scatters, a ray sees what lies beyond through the medium's transmittance, plus the
// light of every light scattered once toward it, by marching along the ray with a shadow
// ray to each light at every step (no multiple scattering: the photon mapper and the
// path tracer have it), or, for point and spot lights in the scene's air, as the airlight:
// the same integral with no shadow rays, summed by Gauss-Legendre in the angle seen from
// the light, where it is smooth (InScattering::airlight). Every branch is
// chosen by the material's compile-time traits, so a scene without dielectrics
// contains no refraction code; the physics of each branch is material/scattering.hpp's.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/quadrature.hpp>
#include <prism/core/random.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/light/light.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/air.hpp>
#include <prism/medium/nesting.hpp>
#include <prism/optics/refract.hpp>
#include <prism/scene/hit.hpp>
#include <prism/spectrum/bands.hpp>
#include <prism/transport/direct.hpp>
#include <prism/transport/media.hpp>
#include <prism/transport/travel.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>

namespace prism {

/// How Whitted sums the light of point and spot lights scattered once in the scene's air.
enum class InScattering {
    march,    ///< march_steps points along each segment, each lit by shadow rays: shafts and volumetric shadows
    airlight, ///< the airlight: no shadow rays, airlight_nodes Gauss-Legendre nodes in the angle seen from the light
};

/// Whitted over `scene` with its air: StraightAir (the default), or GradedAir, through
/// which rays outside every object curve (medium/air.hpp).
template <class SceneT, class Air = StraightAir>
class Whitted {
public:
    /// The scene's precision.
    using scalar_type = typename SceneT::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;

    /// Whether it draws no random number: no light with extent to sample, no medium to
    /// march (render() then skips the sampler's work at one sample per pixel).
    static constexpr bool draws_nothing = !SceneT::has_lights_with_extent && !(SceneT::has_scattering_media || air_scatters<Air>);

    /// A Whitted integrator's settings.
    struct Config {
        int max_depth = 10;          ///< reflection/refraction bounces followed at most
        T min_weight = T(1e-3);      ///< stop a branch whose weight on the pixel is below this
        /// Wavelength bands white light splits into where it refracts through a dispersive
        /// interface (1 to 81; POV-Ray's dispersion_samples, 7 by default there).
        int dispersion_bands = 8;
        /// An area light is sampled on a grid of this many points per side, each jittered
        /// in its cell (POV-Ray's area_light with jitter): soft shadows.
        int area_light_grid = 4;
        /// In a medium that scatters (FilledAir, a Fog interior): the points each ray
        /// segment through it is sampled at for single scattering (stratified, each
        /// jittered in its stratum), each lit by a shadow ray to every light.
        int march_steps = 32;
        /// How the light of point and spot lights scattered once in the scene's air is
        /// summed along a ray: by marching (shadow rays: shafts and volumetric shadows),
        /// or as the airlight (no shadow rays, far faster; other lights are marched).
        InScattering in_scattering = InScattering::march;
        /// The airlight's Gauss-Legendre nodes per light and segment (1 to 64).
        int airlight_nodes = 16;
    };

    /// A Whitted integrator of `scene` (which must outlive it) in `air`; throws std::invalid_argument, naming the parameter, for a bad scene, air or setting.
    explicit Whitted(const SceneT& scene, Config config = {}, Air air = {})
        : scene_(&scene), config_(config), bands_(config.dispersion_bands), air_(std::move(air)), airlight_rule_(checked_nodes(config.airlight_nodes))
    {
        scene.validate();
        air_.validate();
        if (config.max_depth < 0) detail::throw_invalid("Whitted max_depth must be >= 0, got ", config.max_depth);
        if (config.area_light_grid < 1 || config.area_light_grid > 64)
            detail::throw_invalid("Whitted area_light_grid must be in [1, 64], got ", config.area_light_grid);
        if (config.march_steps < 1 || config.march_steps > 65536) detail::throw_invalid("Whitted march_steps must be in [1, 65536], got ", config.march_steps);
        detail::require_non_negative("Whitted min_weight", config.min_weight);
    }

    /// The integrator keeps a reference to its scene: a temporary scene would dangle.
    Whitted(const SceneT&& scene, Config config = {}, Air air = {}) = delete;

    /// Radiance arriving along the ray (its direction must be unit length); `rng` jitters
    /// the samples of area lights and the points single scattering is marched at
    /// (nothing else is random).
    [[nodiscard]] Rgb<T> radiance(const Ray<T>& ray, Random& rng) const noexcept
    {
        if constexpr (SceneT::has_lights_with_extent || has_media) return trace(ray, 0, Rgb<T>(T(1)), T(0), scene_->media_at(ray.origin), false, &rng);
        else return (void)rng, trace(ray, 0, Rgb<T>(T(1)), T(0), {}, false);
    }
    /// Radiance arriving along the ray, with area lights sampled from a fixed stream.
    [[nodiscard]] Rgb<T> radiance(const Ray<T>& ray) const noexcept
    {
        Random rng(0, 0);
        return radiance(ray, rng);
    }

    /// The scene and the air its camera rays start in (render_layers' surface layers).
    [[nodiscard]] const SceneT& scene() const noexcept { return *scene_; }
    /// The air camera rays start in.
    [[nodiscard]] const Air& air() const noexcept { return air_; }

    /// The settings.
    [[nodiscard]] const Config& config() const noexcept { return config_; }

private:
    // Whitted Private Methods

    /// The stream a recursion carries (none: no light with extent to jitter).
    [[nodiscard]] static Random* stream_of() noexcept { return nullptr; }
    [[nodiscard]] static Random* stream_of(Random* rng) noexcept { return rng; }

    // The recursion carries the stream that jitters area lights' samples (`jitter`: a
    // Random*) only where the scene has lights with extent (area, environment): GCC optimises a recursion that
    // carries none to less code, 7 % faster to compile.

    /// Whether the scene or its air holds a medium that scatters.
    static constexpr bool has_media = SceneT::has_scattering_media || air_scatters<Air>;

    /// Radiance along the ray for light of one wavelength (nanometres), or of all (0):
    /// a ray carries one once it has refracted through a dispersive interface. `media`:
    /// the transmissive objects the ray is inside of (medium/nesting.hpp). `lights_counted`:
    /// the ray stands in for a glossy lobe whose light samples counted the lights with a
    /// surface, so an emitting surface it meets is not counted again.
    template <class... Jitter>
    [[nodiscard]] Rgb<T> trace(const Ray<T>& ray, int depth, const Rgb<T>& weight, T wavelength, const MediumStack& media, bool lights_counted,
                               Jitter... jitter) const noexcept
    {
        // In the air (inside no object) the ray follows the air's curve, landing on a
        // chord; inside objects it is straight. Through a medium that scatters, what lies
        // beyond is seen through its transmittance, plus single scattering of every light
        // along each piece of the way.
        Ray<T> segment = ray;
        [[maybe_unused]] Rgb<T> seen(T(1)), scattered(T(0)); // what the media let through from the ray's origin to the piece; what they scatter toward it
        const std::optional<Hit<T>> hit = [&] {
            if constexpr (has_media) {
                return first_hit_through_media(*scene_, air_, media, ray, segment, nullptr, [&](const auto& medium, const Ray<T>& piece, T t0, T t1, T) {
                    scattered += seen * single_scattering(medium, piece, t0, t1, media, jitter...);
                    seen *= transmittance_along(medium, piece, t0, t1);
                    return true;
                });
            } else {
                return media.empty() ? first_hit_in_air(*scene_, air_, ray, segment) : first_hit_in_air(*scene_, StraightAir{}, ray, segment);
            }
        }();
        const Rgb<T> beyond = !hit ? scene_->escaped(segment.direction) : scene_->visit_material(*hit, [&](const auto& material) {
            return shade(material, segment, *hit, depth, weight, wavelength, media, lights_counted, jitter...);
        });
        if constexpr (has_media) return beyond * seen + scattered;
        else return beyond;
    }

    template <class M, class... Jitter>
    [[nodiscard]] Rgb<T> shade(const M& material, const Ray<T>& ray, const Hit<T>& h, int depth, const Rgb<T>& weight,
                               T wavelength, const MediumStack& media, bool lights_counted, Jitter... jitter) const noexcept
    {
        const Crossing<T>& hit = h.crossing;
        const Vec3<T>& d = ray.direction;
        // (An emitting surface is an area light: a glossy lobe's light samples counted it.)
        Rgb<T> radiance = lights_counted ? Rgb<T>(T(0)) : emitted(material, hit);

        if constexpr (has_diffuse<M>) radiance += diffuse_and_ambient(material, h, d, jitter...);

        // Whether a glossy lobe's light samples counted the lights with a surface (it is not
        // smooth): the rays that stand in for it then count no emitting surface they meet.
        [[maybe_unused]] bool lobe_counted_lights = false;
        if constexpr (has_glossy<M>) {
            // A glossy lobe: each light with a surface or none (point, spot, area) by its BSDF
            // toward the light, and what lies about the mirror direction by one mirror ray
            // carrying the albedo of the lobe's part there (the lobe's spread is left out;
            // for frosted glass that ray is the clean glass's split, below). Each light is
            // counted once: a sky or an environment map by the mirror ray, which meets it
            // everywhere (by light samples it would be noise about a narrow lobe), and an
            // emitting surface the mirror ray meets not again.
            const auto lobe = glossy_at(material, hit, normalize(d), glossy_eta(material, hit));
            const LightSampling sampling{stream_of(jitter...), config_.area_light_grid};
            scene_->for_each_light([&]<class L>(const L& light) {
                if constexpr (!is_at_infinity<L>)
                    for_each_sample_arriving(*scene_, light, h, sampling, [&](const LightSample<T>& s, const Rgb<T>& v, T cos) {
                        radiance += lobe.f(s.wi, Transport::radiance) * v * s.irradiance * cos;
                    });
            });
            lobe_counted_lights = !lobe.smooth();
            // (A delta part, a mirror's or a smooth coat's, is that mirror ray exactly.)
            if constexpr (!transmits<M>) {
            const std::optional<LobeSample<T>> delta = lobe.delta_part();
            const Rgb<T> k = delta ? delta->weight : lobe.mirror_albedo();
            if (depth < config_.max_depth && max_component(weight * k) > config_.min_weight)
                radiance += k * trace(scene_->carry_cone(spawn_ray(hit.point, hit.error, hit.normal, delta ? delta->wi : lobe.mirror()), ray, hit.t), depth + 1,
                                      weight * k, wavelength, media, !delta.has_value(), jitter...);
            }
        }

        if constexpr (reflects<M> || transmits<M>) {
            // Frosted glass refracts and reflects here as the clean glass of its index (its
            // lights' highlights are counted above; the blur of its roughness is left out).
            const auto split_with = [&](const auto& delta_material) {
                if (depth >= config_.max_depth) return;
                // Reflected rays stay in the ray's media; refracted ones go on in `beyond`,
                // and the medium of `outside` lies on the surface's far side.
                const auto follow = [&](const MediumStack& beyond, const Inside* outside) {
                    const auto outside_index = [&](T lambda) { return index_of(*scene_, outside, lambda); };
                    for_each_delta_ray(delta_material, d, hit, wavelength, bands_, outside_index,
                                       [&](const Vec3<T>& direction, const Rgb<T>& k, T lambda, bool transmitted) {
                                           const Rgb<T> next_weight = weight * k;
                                           if (max_component(next_weight) > config_.min_weight)
                                               radiance += k * trace(scene_->carry_cone(spawn_ray(hit.point, hit.error, hit.normal, direction), ray, hit.t),
                                                                     depth + 1, next_weight, lambda, transmitted ? beyond : media, lobe_counted_lights, jitter...);
                                       });
                };
                if constexpr (transmits<M>) {
                    const Interface face = nested_interface(media, {h.slot, h.index, nesting_priority(material)}, hit.entering);
                    if (face.real)
                        follow(face.beyond, outside_of(media, face, hit.entering));
                    else // a surface inside a medium of higher priority: the ray passes on
                        radiance = trace(scene_->carry_cone(spawn_ray(hit.point, hit.error, hit.normal, d), ray, hit.t), depth + 1, weight, wavelength,
                                         face.beyond, lights_counted, jitter...);
                } else {
                    follow(media, nullptr);
                }
            };
            if constexpr (has_glossy<M>) split_with(material.clean());
            else split_with(material);
        }

        // The light arriving here travelled in the ray's medium from its origin.
        attenuate_segment(*scene_, media, material, hit, ray, radiance);
        return radiance;
    }

    /// The light of every light scattered once toward the ray's origin along [t0, t1] of
    /// `ray` (unit direction) in `medium`: march_steps stratified points, each jittered in
    /// its stratum (at its middle without a stream), each lit by shadow rays through the
    /// scene (glass attenuating) and the air, weighed by sigma_s, the phase function and
    /// the transmittance back to t0. An unbounded segment is marched to where the medium
    /// lets through less than e^-10 in every channel.
    template <class Md, class... Jitter>
    [[nodiscard]] Rgb<T> single_scattering(const Md& medium, const Ray<T>& ray, T t0, T t1, const MediumStack& media, Jitter... jitter) const noexcept
    {
        // The airlight of the lights at a point, in the air; the rest marched.
        // (A medium that varies is marched.)
        const bool airlight = uniform_medium<Md> && config_.in_scattering == InScattering::airlight && media.empty();
        Rgb<T> sum{T(0)};
        if constexpr (uniform_medium<Md>) {
            if (airlight) {
                bool all = true;
                scene_->for_each_light([&]<class L>(const L& light) {
                    if constexpr (has_airlight<L>) sum += airlight_of(light, medium, ray, t0, t1);
                    else all = false;
                });
                if (all) return sum;
            }
            if (!(t1 < infinity<T>)) {
                // (A clear channel scatters nothing: only the channels that scatter count.)
                const Rgb<T> sigma_t = medium.extinction();
                T thinnest = infinity<T>;
                for (int c = 0; c < 3; ++c)
                    if (sigma_t[c] > T(0)) thinnest = std::min(thinnest, sigma_t[c]);
                if (!(thinnest < infinity<T>)) return Rgb<T>(T(0));
                t1 = t0 + T(10) / thinnest;
            }
        } else {
            // Only where the medium is.
            const Interval<T> inside = medium.bounds().clip(ray, {t0, t1});
            if (inside.empty()) return Rgb<T>(T(0));
            t0 = inside.min, t1 = inside.max;
        }
        Random* rng = stream_of(jitter...);
        const LightSampling sampling{rng, config_.area_light_grid};
        const T step = (t1 - t0) / T(config_.march_steps);
        Rgb<T> marched{T(0)};
        // In a medium that varies, the transmittance to each point is marched too, by the
        // midpoint rule from the point before: one density lookup a step, no tracking.
        [[maybe_unused]] Rgb<T> depth{T(0)}; // the optical depth from t0 to `last`
        [[maybe_unused]] T last = t0;
        for (int i = 0; i < config_.march_steps; ++i) {
            const T s = t0 + (T(i) + (rng ? rng->template uniform<T>() : T(0.5))) * step;
            const Vec3<T> p = ray.at(s);
            Rgb<T> arriving{T(0)};
            scene_->for_each_light([&]<class L>(const L& light) {
                if constexpr (has_airlight<L>) {
                    if (airlight) return;
                }
                for_each_sample_in_medium(*scene_, light, p, sampling, [&](const LightSample<T>& sample, const Rgb<T>& v) {
                    const Rgb<T> air = air_transmittance<ShadowsThroughGlass::attenuated>(*scene_, air_, Ray<T>{p, sample.wi}, sample.distance);
                    arriving += T(medium.phase.value(dot(ray.direction, sample.wi))) * v * air * sample.irradiance;
                });
            });
            if constexpr (uniform_medium<Md>) {
                marched += transmittance_along(medium, ray, t0, s) * medium.scattering_at(p) * arriving;
            } else {
                depth += medium.extinction_at(ray.at(T(0.5) * (last + s))) * (s - last);
                last = s;
                const Rgb<T> seen{std::exp(-depth.x), std::exp(-depth.y), std::exp(-depth.z)};
                marched += seen * medium.scattering_at(p) * arriving;
            }
        }
        return sum + marched * step;
    }

    /// n, the airlight's node count; throws std::invalid_argument, naming the setting, for n outside [1, 64].
    static int checked_nodes(int n)
    {
        if (n < 1 || n > GaussLegendre::max_count) detail::throw_invalid("Whitted airlight_nodes must be in [1, ", GaussLegendre::max_count, "], got ", n);
        return n;
    }

    /// A scene and air without a scattering medium hold no airlight rule (nor compile its construction).
    struct NoRule {
        explicit constexpr NoRule(int) noexcept {}
    };

    /// Whether a light is summed by the airlight: a delta light at a point.
    template <class L>
    static constexpr bool has_airlight = is_delta_light<L> && requires(const L& light) { light.position; };

    /// The airlight: the light of `light` (at a point) scattered once toward the ray's
    /// origin along [t0, t1] of `ray` (unit direction) in the air's `medium`, with no
    /// shadow ray. A point at s on the ray lies at d = h / cos(theta) from the light, where
    /// h is the light's distance from the ray's line and tan(theta) = (s - s_light) / h,
    /// and ds / d^2 = dtheta / h: in theta the integrand of sigma_s T p I / d^2 is smooth
    /// and bounded, and [t0, infinity) a finite interval, which Gauss-Legendre's nodes sum
    /// to the precision of the float arithmetic (Sun et al. 2005 tabulate the same
    /// integral for an isotropic phase function; Kulla and Fajardo 2012 sample it).
    template <class L, class Md>
    [[nodiscard]] Rgb<T> airlight_of(const L& light, const Md& medium, const Ray<T>& ray, T t0, T t1) const noexcept
    {
        const Vec3<T> to_light = light.position - ray.origin;
        const T along = dot(to_light, ray.direction);
        // (A light on the ray's line would be seen as infinitely bright haze: kept off it.)
        const T h = std::max(length(to_light - along * ray.direction), T(1e-6) * (T(1) + std::abs(along)));
        const T theta0 = std::atan((t0 - along) / h), theta1 = t1 < infinity<T> ? std::atan((t1 - along) / h) : pi<T> / T(2);
        return airlight_rule_.integrate(theta0, theta1, [&](T theta) {
            const T s = along + h * std::tan(theta);
            const Vec3<T> p = ray.at(s);
            const LightSample<T> sample = light.sample(p, Vec2<T>(T(0.5)));
            const T intensity_scale = sample.distance * sample.distance / h; // I / d^2 ds = I dtheta / h
            return Rgb<T>(medium.transmittance(s - t0) * medium.scattering_at(p) * air_transmittance(air_, Ray<T>{p, sample.wi}, sample.distance) *
                          sample.irradiance * (T(medium.phase.value(dot(ray.direction, sample.wi))) * intensity_scale));
        });
    }

    template <class M, class... Jitter>
    [[nodiscard]] Rgb<T> diffuse_and_ambient(const M& material, const Hit<T>& h, const Vec3<T>& d, Jitter... jitter) const noexcept
    {
        const Crossing<T>& hit = h.crossing;
        Rgb<T> irradiance{T(0)}; // sum of V E cos over the lights' samples
        Rgb<T> unlit{T(1)};      // prod of (1 - V) over the lights, V a light's mean over its samples
        Rgb<T> highlights{T(0)}; // POV-Ray's Phong term, for materials that have one
        const Vec3<T> mirror = reflect(d, hit.facing_shading());
        const LightSampling sampling{stream_of(jitter...), config_.area_light_grid};
        scene_->for_each_light([&]<class L>(const L& light) {
            const T share = T(1) / T(samples_of<L>(sampling));
            Rgb<T> seen{T(0)};
            for_each_sample_arriving(*scene_, light, h, sampling, [&](const LightSample<T>& s, const Rgb<T>& v_scene, T cos) {
                const Rgb<T> v = v_scene * air_transmittance<ShadowsThroughGlass::attenuated>(*scene_, air_, Ray<T>{hit.point, s.wi}, s.distance);
                irradiance += v * s.irradiance * cos;
                seen += share * v;
                const T shine = highlight(material, mirror, s.wi);
                if (shine > T(0)) highlights += shine * v * s.irradiance;
            });
            unlit *= Rgb<T>(T(1)) - seen;
        });
        return diffuse_response(material, hit).reflected(irradiance, scene_->ambient, unlit) + highlights;
    }

    const SceneT* scene_;
    Config config_;
    SpectralBands<T> bands_;
    Air air_;
    [[no_unique_address]] std::conditional_t<has_media, GaussLegendre, NoRule> airlight_rule_;
};

} // namespace prism
