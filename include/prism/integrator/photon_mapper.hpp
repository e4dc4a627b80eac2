// SPDX-License-Identifier: MIT
// PhotonMapper: Whitted's direct and specular light, plus caustics and indirect diffuse
// light from photon maps (Jensen 1996, section 3).
//
// At a diffuse point, with the same convention as Whitted (BRDF albedo kd / pi):
//   direct     shadow rays to the lights (Whitted's term without ambient), with glass
//              opaque: the light through it is the caustic map's. Optionally a shadow
//              ray is skipped where the nearest global photons agree that the point is
//              lit (all direct) or in shadow (all shadow photons; Jensen and
//              Christensen 1995).
//   caustics   the caustic map's density estimate (radius or k nearest, box, cone or
//              Gaussian filter)
//   indirect   final gathering: `gather_rays` cosine-distributed rays, each reading the
//              global map's irradiance where it lands (L = albedo / pi * E there), so the
//              blotchy global estimate is seen only after one more bounce. The global
//              irradiance is precomputed at every 4th photon from its 64 nearest
//              (Christensen 1999), so each gather ray costs one nearest lookup; with
//              gather_rays = 0 the global map is read directly at the point instead,
//              counting only photons that are neither direct nor caustic (those two are
//              computed above), cheaper and blotchier.
// Mirrors and dielectrics recurse as in Whitted.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/parallel.hpp>
#include <prism/core/random.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/integrator/irradiance_cache.hpp>
#include <prism/light/light.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/air.hpp>
#include <prism/medium/nesting.hpp>
#include <prism/optics/refract.hpp>
#include <prism/photon/photon_tracer.hpp>
#include <prism/render/layers.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>
#include <prism/transport/direct.hpp>
#include <prism/transport/equiangular.hpp>
#include <prism/transport/media.hpp>
#include <prism/transport/random_walk.hpp>
#include <prism/transport/travel.hpp>

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace prism {

/// The photon mapper over `scene` with its air (StraightAir, or GradedAir: camera rays,
/// gather rays and photons in the air curve; medium/air.hpp).
template <class SceneT, class Air = StraightAir>
class PhotonMapper {
public:
    /// The scene's precision.
    using scalar_type = typename SceneT::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;

    /// A PhotonMapper's settings: photon tracing, the two maps' estimates, the final gather,
    /// the irradiance cache and the shadow-ray saving.
    struct Config {
        PhotonTracerConfig tracing{}; ///< how many photons, and how they are traced
        Estimator caustic{.radius = 0.1f}; ///< the caustic map's estimate
        /// The global map's estimate where it is read directly (gather_rays = 0); direct
        /// and caustic photons are left out, shadow rays and the caustic map count them.
        Estimator global{.radius = 0.25f, .excluded = Photon::direct | Photon::caustic};
        /// Final-gather rays per diffuse hit, stratified in m x n cells (n about pi m, m n
        /// at most this); 0 reads the global map directly.
        int gather_rays = 32;
        /// An irradiance cache in front of the final gather (cache_irradiance builds it
        /// for a camera): gathers of `rays` rays at records placed where the camera
        /// needs them, interpolated with their gradients in between.
        struct IrradianceCaching {
            int rays = 4096;          ///< gather rays per record (fewer leave the records' noise as blotches)
            float accuracy = 1.0f;    ///< kappa: a record reaches R / kappa (and 10 degrees / kappa of normal)
            float min_pixels = 3.0f;  ///< R at least this many pixel footprints
            float max_pixels = 40.0f; ///< and at most this many
            bool gradients = true; ///< interpolate with the records' rotational and translational gradients
        } irradiance_cache{}; ///< see IrradianceCaching
        /// > 0: look at this many nearest global photons (within global.radius) before a
        /// shadow ray, and skip it when they agree. Scenes with one light only: shadow
        /// photons do not say which light they block.
        std::size_t visibility_k = 0;
        int max_depth = 10; ///< surfaces a camera path may meet
        /// Segments a path may have from the camera to the light, as the path tracer counts
        /// them (docs/guide.md): a camera vertex t segments from the camera reads the photons
        /// of at most max_length - t segments from the light, its shadow rays count where
        /// t + 1 <= max_length, and the photons are traced to max_length - 1 segments. At
        /// most Photon::max_segments + 1 (16: a photon records up to 15) unless unlimited;
        /// the final gather then reads the global map by its `global` estimate, not the
        /// precomputed irradiance, and the irradiance cache is refused.
        int max_length = std::numeric_limits<int>::max();
        T min_weight = T(1e-3); ///< a branch whose weight on the pixel falls below this ends (Hall and Greenberg 1983)
        /// Wavelength bands white camera rays split into at a dispersive interface (as
        /// Whitted's); photons take their own wavelengths (PhotonTracerConfig).
        int dispersion_bands = 8;
        /// Area lights are sampled for direct light on a jittered grid of this many points
        /// per side at each shaded point.
        int area_light_grid = 4;
        /// In a medium that scatters: the radius (in the scene's units) of the beam
        /// radiance estimate along camera rays and of the volume estimate where a gather
        /// ray scatters.
        float volume_radius = 0.05f;
        /// > 0: the beam estimate's radius for the global pass's volume photons (light
        /// scattered more than once, or after a diffuse surface), which is smooth and
        /// sparse: read with a wider kernel, as the global map is on surfaces, it shows no
        /// blotches where a few photons near the camera would each fill a disk of the
        /// image. 0: volume_radius. (Volumetric caustics keep volume_radius.)
        float indirect_volume_radius = 0.0f;
        /// Light of a point or spot light scattered once toward the camera by a medium
        /// (L M E), found along every camera ray by equiangular samples (a spot light's kept
        /// to its cone: transport/equiangular.hpp) and shadow rays, as the path tracer finds
        /// it, in place of the volume photons that carry it (flagged direct), which the
        /// beam estimate then leaves out: a narrow beam in haze comes out clean at a few
        /// samples a pixel. Glass stops the shadow rays: light through glass stays the
        /// caustic photons'. Off: every volume photon counts, as before.
        bool single_scattering = false;
    };

    /// Traces the photon maps (the expensive part), then renders with them.
    explicit PhotonMapper(const SceneT& scene, Config config = {}, Air air = {}) : PhotonMapper(scene, config, std::nullopt, std::move(air)) {}
    PhotonMapper(const SceneT&& scene, Config config = {}, Air air = {}) = delete;

    /// Renders with maps traced already (trace_photons with config.tracing: a pass of
    /// progressive photon mapping).
    PhotonMapper(const SceneT& scene, Config config, PhotonMaps maps, Air air = {})
        : PhotonMapper(scene, config, std::optional<PhotonMaps>(std::move(maps)), std::move(air))
    {
    }
    PhotonMapper(const SceneT&& scene, Config config, PhotonMaps maps, Air air = {}) = delete;

private:
    PhotonMapper(const SceneT& scene, Config config, std::optional<PhotonMaps> maps, Air air)
        : scene_(&scene), config_(config), bands_(config.dispersion_bands), air_(std::move(air))
    {
        scene.validate();
        air_.validate();
        validate(config.caustic, "PhotonMapper caustic");
        validate(config.global, "PhotonMapper global");
        if (config.gather_rays < 0) detail::throw_invalid("PhotonMapper gather_rays must be >= 0, got ", config.gather_rays);
        const auto& cache = config.irradiance_cache;
        if (cache.rays < 1) detail::throw_invalid("PhotonMapper irradiance_cache.rays must be >= 1, got ", cache.rays);
        if (!(cache.accuracy > 0.0f && is_finite(cache.accuracy))) detail::throw_invalid("PhotonMapper irradiance_cache.accuracy must be finite and > 0, got ", cache.accuracy);
        if (!(cache.min_pixels > 0.0f && cache.min_pixels <= cache.max_pixels && is_finite(cache.max_pixels)))
            detail::throw_invalid("PhotonMapper irradiance_cache needs 0 < min_pixels <= max_pixels, finite, got ", cache.min_pixels, " and ", cache.max_pixels);
        if (config.max_depth < 0) detail::throw_invalid("PhotonMapper max_depth must be >= 0, got ", config.max_depth);
        if (config.max_length < 1 || (config.max_length != std::numeric_limits<int>::max() && config.max_length > Photon::max_segments + 1))
            detail::throw_invalid("PhotonMapper max_length must be in [1, ", Photon::max_segments + 1,
                                  "] (a photon records up to 15 segments) or unlimited (std::numeric_limits<int>::max()), got ", config.max_length);
        if (!(config.volume_radius > 0.0f && config.volume_radius * config.volume_radius >= std::numeric_limits<float>::min() &&
              is_finite(config.volume_radius * config.volume_radius)))
            detail::throw_invalid("PhotonMapper volume_radius must be in [1.1e-19, 1.8e19] (its square a finite, normal float), got ", config.volume_radius);
        if (config.indirect_volume_radius != 0.0f &&
            !(config.indirect_volume_radius > 0.0f && config.indirect_volume_radius * config.indirect_volume_radius >= std::numeric_limits<float>::min() &&
              is_finite(config.indirect_volume_radius * config.indirect_volume_radius)))
            detail::throw_invalid("PhotonMapper indirect_volume_radius must be 0 or in [1.1e-19, 1.8e19] (its square a finite, normal float), got ",
                                  config.indirect_volume_radius);
        if (config.area_light_grid < 1 || config.area_light_grid > 64)
            detail::throw_invalid("PhotonMapper area_light_grid must be in [1, 64], got ", config.area_light_grid);
        detail::require_non_negative("PhotonMapper min_weight", config.min_weight);
        if (config.visibility_k > PhotonMap::max_k)
            detail::throw_invalid("PhotonMapper visibility_k must be at most ", PhotonMap::max_k, ", got ", config.visibility_k);
        detail::validate(config.tracing);
        if (config.visibility_k > 0 && SceneT::light_count != 1)
            detail::throw_invalid("PhotonMapper visibility_k needs a scene with exactly one light, got lights: ", SceneT::light_count);
        gather_cells_m_ = std::max(1, int(std::lround(std::sqrt(double(config.gather_rays) / pi<double>))));
        gather_cells_n_ = std::max(1, config.gather_rays / gather_cells_m_);
        maps_ = maps ? std::move(*maps) : trace_photons(scene, tracing_for(config), air_);
        if (config.gather_rays > 0 && !limited() && !maps_.global.has_precomputed_irradiance())
            maps_.global.template precompute_irradiance<precomputed_k>(precomputed_stride, config.tracing.threads);
    }

public:
    /// The photon tracing `config` asks for: its `tracing`, held to max_length - 1
    /// segments where max_length is finite (a camera path reaches a photon by one
    /// segment at least).
    [[nodiscard]] static PhotonTracerConfig tracing_for(const Config& config) noexcept
    {
        PhotonTracerConfig tracing = config.tracing;
        if (config.max_length != std::numeric_limits<int>::max()) tracing.max_length = std::min(tracing.max_length, std::max(config.max_length - 1, 1));
        return tracing;
    }

    /// The final gather reads irradiance precomputed at every precomputed_stride-th global
    /// photon from its precomputed_k nearest (PhotonMap::precompute_irradiance), which the
    /// constructor works out unless the maps it is given have it already.
    static constexpr std::size_t precomputed_k = 64;     ///< photons per precomputed estimate
    static constexpr std::size_t precomputed_stride = 4; ///< every this many global photons gets one

    /// The photon maps.
    [[nodiscard]] const PhotonMaps& maps() const noexcept { return maps_; }
    /// The irradiance cache (empty until cache_irradiance()).
    [[nodiscard]] const IrradianceCache<T>& irradiance_cache() const noexcept { return cache_; }

    /// Build the irradiance cache for what `camera` sees at `render`'s size, before
    /// rendering with it: pixels on grids of halving spacing (the coarsest about a
    /// sixteenth of the image) are visited, and where the first diffuse surface a
    /// pixel's centre sees (through mirrors and glass, along the stronger branch) is not
    /// yet reached by a record, a record is gathered there. Each grid's records are
    /// gathered in parallel, each from its own random stream, and added in pixel order:
    /// the cache is the same for any thread count. Points no record reaches (the weaker
    /// branch of a glass, points inside glass) keep their own gathers.
    void cache_irradiance(const Camera<T>& camera, const RenderConfig& render)
    {
        if (config_.gather_rays == 0) detail::throw_invalid("PhotonMapper cache_irradiance needs gather_rays > 0 (the cache sits in front of the final gather)");
        if (limited()) detail::throw_invalid("PhotonMapper cache_irradiance: a record holds the light of paths of every length, max_length must be unlimited, got ", config_.max_length);
        const CameraRays<T> rays = camera.rays(render.width, render.height);
        const auto& settings = config_.irradiance_cache;
        cache_ = IrradianceCache<T>(T(settings.accuracy), settings.gradients);
        const T pixel = length(rays.pixel_right);
        int stride = 1;
        while (stride * 16 <= std::min(render.width, render.height)) stride *= 2;
        struct Candidate {
            Crossing<T> hit;
            Vec3<T> n;
            T footprint;
            std::size_t stream;
        };
        for (int level = 0; stride >= 1; stride /= 2, ++level) {
            const int columns = (render.width + stride - 1) / stride, rows = (render.height + stride - 1) / stride;
            std::vector<std::optional<Candidate>> found(std::size_t(columns) * std::size_t(rows));
            detail::parallel_for(found.size(), render.threads, [&](std::size_t i) {
                const int x = int(i % std::size_t(columns)) * stride, y = int(i / std::size_t(columns)) * stride;
                const auto seen = first_diffuse_seen(rays.ray(T(x) + T(0.5), T(y) + T(0.5)));
                if (!seen || cache_.covers(seen->first.point, seen->first.facing_shading())) return;
                const std::size_t pixel_index = std::size_t(y) * std::size_t(render.width) + std::size_t(x);
                found[i] = Candidate{seen->first, seen->first.facing_shading(), seen->second * pixel,
                                     pixel_index + std::size_t(level) * std::size_t(render.width) * std::size_t(render.height)};
            });
            std::vector<Candidate> candidates;
            for (const auto& c : found)
                if (c) candidates.push_back(*c);
            std::vector<IrradianceRecord<T>> records(candidates.size());
            detail::parallel_for(candidates.size(), render.threads, [&](std::size_t i) {
                const Candidate& c = candidates[i];
                Random rng(render.seed ^ 0x1cac4eULL, c.stream);
                const int m = std::max(1, int(std::lround(std::sqrt(T(settings.rays) / pi<T>))));
                const int cells_n = std::max(1, settings.rays / m);
                IrradianceRecord<T> r{c.hit.point, c.n, gather<true>(c.hit, c.n, rng, scene_->media_at(c.hit.point), m, cells_n, 1), T(0)};
                if (!translation_holds(c.hit.point)) r.gather.translational = {};
                T radius = r.gather.nearest;
                if (settings.gradients)
                    for (int ch = 0; ch < 3; ++ch) {
                        const T slope = length(Vec3<T>{r.gather.translational[0][ch], r.gather.translational[1][ch], r.gather.translational[2][ch]});
                        if (slope > T(0)) radius = std::min(radius, r.gather.irradiance[ch] / slope);
                    }
                r.radius = std::clamp(radius, T(settings.min_pixels) * c.footprint, T(settings.max_pixels) * c.footprint);
                records[i] = r;
            });
            cache_.add(std::move(records));
        }
    }

    /// The radiance along a camera ray: direct, caustic and indirect light summed.
    [[nodiscard]] Rgb<T> radiance(const Ray<T>& ray, Random& rng) const noexcept { return radiance_parts(ray, rng).sum(); }

    /// The radiance along a camera ray by where its light came from last: the lights by
    /// shadow rays (and the background), the caustic map, the indirect estimate.
    [[nodiscard]] LightParts<T> radiance_parts(const Ray<T>& ray, Random& rng) const noexcept { return trace(ray, 0, 0, Rgb<T>(T(1)), rng, T(0), scene_->media_at(ray.origin)); }

    /// The scene and the air its camera rays start in (render_layers' surface layers).
    [[nodiscard]] const SceneT& scene() const noexcept { return *scene_; }
    /// The air camera rays start in.
    [[nodiscard]] const Air& air() const noexcept { return air_; }

    /// What the nearest global photons say about the light's visibility at p (normal n
    /// facing the viewer): true when the `visibility_k` nearest within global.radius
    /// that arrived on n's side hold direct photons and no shadow photons, false for
    /// the reverse, nothing when they disagree or too few (under a quarter, or under 2) are
    /// either.
    [[nodiscard]] std::optional<bool> visibility_from_photons(const Vec3<T>& p, const Vec3<T>& n) const noexcept
    {
        if (config_.visibility_k == 0) return std::nullopt;
        const auto [direct, shadow] =
            maps_.global.direct_and_shadow(Vec3<float>(p), Vec3<float>(n), config_.visibility_k, config_.global.radius);
        const std::size_t enough = std::max<std::size_t>(config_.visibility_k / 4, 2);
        if (direct >= enough && shadow == 0) return true;
        if (shadow >= enough && direct == 0) return false;
        return std::nullopt;
    }

private:
    static void validate(const Estimator& e, const char* name)
    {
        // The estimates divide by pi r^2: its square must be a finite, normal float.
        if (!(e.radius > 0.0f && e.radius * e.radius >= std::numeric_limits<float>::min() && is_finite(e.radius * e.radius)))
            detail::throw_invalid(name, " radius must be in [1.1e-19, 1.8e19] (its square a finite, normal float), got ", e.radius);
        if (e.k > PhotonMap::max_k) detail::throw_invalid(name, " k must be at most ", PhotonMap::max_k, ", got ", e.k);
        if (!(e.max_height_ratio > 0.0f && e.max_height_ratio <= 1.0f)) detail::throw_invalid(name, " max_height_ratio must be in (0, 1], got ", e.max_height_ratio);
        if (!(e.surface_cos >= 0.0f && e.surface_cos < 1.0f)) detail::throw_invalid(name, " surface_cos must be in [0, 1), got ", e.surface_cos);
        if (e.filter != Filter::box && e.filter != Filter::cone && e.filter != Filter::gaussian)
            detail::throw_invalid(name, " filter must be box, cone or gaussian, got the value ", static_cast<int>(e.filter));
    }

    /// Whether max_length limits the paths.
    [[nodiscard]] bool limited() const noexcept { return config_.max_length != std::numeric_limits<int>::max(); }

    /// `estimator` reading only the photons a camera vertex `length` segments from the
    /// camera may join: at most max_length - length segments from the light.
    [[nodiscard]] Estimator joined_at(Estimator estimator, int length) const noexcept
    {
        if (limited()) estimator.max_segments = config_.max_length - length;
        return estimator;
    }

    /// Whether a photon of `segments` segments may join a camera vertex `length` segments
    /// from the camera.
    [[nodiscard]] bool joins(int segments, int length) const noexcept { return !limited() || segments <= config_.max_length - length; }

    /// Radiance along the ray for light of one wavelength (nanometres), or of all (0), in
    /// the transmissive objects `media` (medium/nesting.hpp); `length` the segments the
    /// path took from the camera to the ray's origin, `depth` the surfaces it met.
    [[nodiscard]] LightParts<T> trace(const Ray<T>& ray, int depth, int length, const Rgb<T>& weight, Random& rng, T wavelength, const MediumStack& media) const noexcept
    {
        if (length >= config_.max_length) return {};
        Ray<T> segment = ray;
        if constexpr (has_media) {
            // Through a medium that scatters: what lies beyond is seen through its
            // transmittance, and the light it scatters toward the camera along the way is
            // the beam radiance estimate of the volume photons (Jarosz et al. 2008): each
            // within volume_radius of a piece of the way (indirect_volume_radius for the
            // global pass's) counts its power times the phase function toward the camera
            // and the transmittance to it, over pi r^2.
            Rgb<T> seen(T(1)); // what the media let through from the camera to the piece
            LightParts<T> scattered{};
            const auto hit = first_hit_through_media(*scene_, air_, media, ray, segment, nullptr, [&](const auto& medium, const Ray<T>& piece, T t0, T t1, T) {
                const Vec3<float> df(piece.direction);
                Rgb<float> caustic(0.0f), other(0.0f);
                const float r_caustic = config_.volume_radius, r_other = indirect_volume_radius();
                const float r2_caustic = r_caustic * r_caustic, r2_other = r_other * r_other;
                maps_.volume.near_beam(Vec3<float>(piece.origin), df, float(t0), float(t1), std::max(r_caustic, r_other), [&](const Photon& photon, float t, float d2) {
                    if (config_.single_scattering && (photon.flags & Photon::direct) != 0) return; // single_scattering's
                    if (!joins(photon.segments(), length + 1)) return;
                    const bool is_caustic = (photon.flags & Photon::caustic) != 0;
                    if (d2 > (is_caustic ? r2_caustic : r2_other)) return;
                    const Rgb<float> light = Rgb<float>(transmittance_along(medium, piece, t0, T(t))) * float(medium.phase.value(T(dot(photon.toward_source(), df)))) * photon.power();
                    (is_caustic ? caustic : other) += light;
                });
                caustic /= pi<float> * r_caustic * r_caustic;
                other /= pi<float> * r_other * r_other;
                scattered.caustic += seen * Rgb<T>(caustic);
                scattered.indirect += seen * Rgb<T>(other);
                if (config_.single_scattering && length + 2 <= config_.max_length) scattered.direct += seen * single_scattering(medium, piece, t0, t1, rng);
                seen *= transmittance_along(medium, piece, t0, t1);
                return true;
            });
            LightParts<T> parts = !hit ? LightParts<T>{.direct = scene_->escaped(segment.direction)}
                                       : scene_->visit_material(*hit, [&](const auto& material) { return shade(material, segment, *hit, depth, length + 1, weight, rng, wavelength, media); });
            parts *= seen;
            parts += scattered;
            return parts;
        } else {
            const auto hit = media.empty() ? first_hit_in_air(*scene_, air_, ray, segment) : first_hit_in_air(*scene_, StraightAir{}, ray, segment);
            if (!hit) return LightParts<T>{.direct = scene_->escaped(segment.direction)};
            return scene_->visit_material(*hit, [&](const auto& material) { return shade(material, segment, *hit, depth, length + 1, weight, rng, wavelength, media); });
        }
    }

    /// Whether a record at p may carry its gather's translational gradient: not in the
    /// air's own fog (FilledAir), where gather rays scatter a short way off and the
    /// gradient, which takes the distances to what the rays met for distances to
    /// surfaces, swings far past the light (there the cache read 1.8 to 5 times the
    /// gather's light: the consistency matrix, tests/matrix.hpp). Its rotational gradient
    /// and its radius from the nearest distance still hold.
    [[nodiscard]] bool translation_holds(const Vec3<T>& p) const noexcept
    {
        if constexpr (air_scatters<Air>) return !air_.bounds().contains(p);
        else return (void)p, true;
    }

    /// Light of the point and spot lights scattered once toward the ray at one equiangular
    /// sample of each along the piece [t0, t1] of a medium (Config::single_scattering):
    /// sigma_s phase T(t0, t) L over the sample's density, the light's shadow ray taking
    /// what the scene and its air let through.
    template <class Md>
    [[nodiscard]] Rgb<T> single_scattering(const Md& medium, const Ray<T>& piece, T t0, T t1, Random& rng) const noexcept
    {
        Rgb<T> out{T(0)};
        scene_->for_each_light([&]<class L>(const L& light) {
            if constexpr (aimed_equiangularly<L>) {
                const std::optional<Interval<T>> span = lit_span(light, piece, t0, t1);
                const T u = rng.uniform<T>(); // (drawn for every light, so that the numbers do not depend on where the ray goes)
                if (!span) return;
                const Equiangular<T> rule(piece, span->min, span->max, light.position);
                const T t = rule.sample(u);
                const T density = rule.pdf(t);
                if (!(t >= span->min && t <= span->max && density > T(0) && density < infinity<T>)) return;
                const Vec3<T> p = piece.at(t);
                for_each_sample_in_medium<ShadowsThroughGlass::blocked>(*scene_, light, p, LightSampling{}, [&](const LightSample<T>& s, const Rgb<T>& v) {
                    const T phase = medium.phase.value(dot(piece.direction, s.wi));
                    out += (phase / density) * transmittance_along(medium, piece, t0, t) * medium.scattering_at(p) * v *
                           air_transmittance<ShadowsThroughGlass::blocked>(*scene_, air_, Ray<T>{p, s.wi}, s.distance) * s.irradiance;
                });
            }
        });
        return out;
    }

    /// The beam estimate's radius for the global pass's volume photons.
    [[nodiscard]] float indirect_volume_radius() const noexcept { return config_.indirect_volume_radius > 0.0f ? config_.indirect_volume_radius : config_.volume_radius; }

    /// Whether the scene or its air holds a medium that scatters: then volume photons, the
    /// beam estimate along camera rays, and the air's transmittance on shadow rays.
    static constexpr bool has_media = SceneT::has_scattering_media || air_scatters<Air>;

    /// What a gather or camera walk finds where it scatters in a medium: its weight (the
    /// medium's sigma_s over the draw's density taken) times the in-scattered radiance the
    /// volume photons within volume_radius give (Jensen and Christensen 1998), their power
    /// weighed by the phase function toward the walk, over the sphere's volume and the
    /// scattering coefficient their stored power carries (those the path may join: the walk
    /// began at a camera vertex `length` segments from the camera).
    template <class Md>
    [[nodiscard]] Rgb<T> volume_radiance(const Md& medium, const WalkMediumVertex<T>& at, int length) const noexcept
    {
        const Vec3<float> toward_viewer(-at.direction);
        const Rgb<float> in = maps_.volume.in_sphere(Vec3<float>(at.point), config_.volume_radius, [&](const Photon& photon) {
            if (!joins(photon.segments(), length + at.length)) return Rgb<float>(0.0f);
            return float(medium.phase.value(T(dot(-photon.toward_source(), toward_viewer)))) * photon.power();
        });
        const Rgb<T> sigma_s = medium.scattering_at(at.point);
        Rgb<T> out{T(0)};
        for (int c = 0; c < 3; ++c)
            if (sigma_s[c] > T(0)) out[c] = at.power[c] * T(in[c]) / sigma_s[c];
        return out;
    }

    template <class M>
    [[nodiscard]] LightParts<T> shade(const M& material, const Ray<T>& ray, const Hit<T>& h, int depth, int length, const Rgb<T>& weight, Random& rng,
                                      T wavelength, const MediumStack& media) const noexcept
    {
        const Crossing<T>& hit = h.crossing;
        const Vec3<T>& d = ray.direction;
        const Vec3<T> n = hit.facing_normal();
        LightParts<T> radiance;
        radiance.direct = emitted(material, hit);
        if constexpr (has_diffuse<M>) {
            const Vec3<float> p(hit.point), nf(n);
            const Rgb<T> brdf = diffuse_response(material, hit).brdf();
            if (length + 1 <= config_.max_length) radiance.direct += brdf * direct(hit, rng);
            radiance.caustic = brdf * Rgb<T>(maps_.caustic.irradiance(p, nf, joined_at(config_.caustic, length)));
            if (config_.gather_rays > 0) {
                // The final gather (and the cache of its results) is over the shading normal's hemisphere.
                const Vec3<T> n_shading = hit.facing_shading();
                const std::optional<Rgb<T>> cached = media.empty() ? cache_.irradiance(hit.point, n_shading) : std::nullopt;
                if (cached) radiance.indirect = brdf * *cached;
                else if (length + 2 <= config_.max_length) radiance.indirect = brdf * gather(hit, n_shading, rng, media, gather_cells_m_, gather_cells_n_, length).irradiance;
            }
            else radiance.indirect = brdf * Rgb<T>(maps_.global.irradiance(p, nf, joined_at(config_.global, length)));
        }
        if constexpr (has_glossy<M> && transmits<M>) {
            // Frosted glass: one draw from its lobe per camera sample, followed with its
            // media as glass is (what it finds, lights with extent included, is counted
            // there), and the delta lights, which no draw finds, by shadow rays from both sides.
            const Interface face = nested_interface(media, {h.slot, h.index, nesting_priority(material)}, hit.entering);
            if (!face.real) {
                radiance = trace(scene_->carry_cone(spawn_ray(hit.point, hit.error, hit.normal, d), ray, hit.t), depth + 1, length - 1, weight, rng, wavelength, face.beyond);
            } else {
                const auto lobe = glossy_at(material, hit, normalize(d), glossy_eta(material, hit, index_of(*scene_, outside_of(media, face, hit.entering), wavelength)));
                scene_->for_each_light([&]<class L>(const L& light) {
                    if constexpr (is_delta_light<L>) {
                        if (length + 1 > config_.max_length) return;
                        for_each_sample_arriving<ShadowsThroughGlass::blocked, Sides::both>(*scene_, light, hit, LightSampling{}, [&](const LightSample<T>& s, const Rgb<T>& v, T cos) {
                            radiance.direct += lobe.f(s.wi, Transport::radiance) * v * s.irradiance * cos;
                        });
                    }
                });
                if (depth < config_.max_depth) {
                    const std::optional<LobeSample<T>> s = lobe.sample(rng, Transport::radiance);
                    if (s && max_component(weight * s->weight) > config_.min_weight) {
                        const bool refracted = dot(s->wi, hit.facing_normal()) < T(0);
                        radiance += s->weight * trace(spawn_ray(hit.point, hit.error, hit.normal, s->wi), depth + 1, length, weight * s->weight, rng, wavelength,
                                                      refracted ? face.beyond : media);
                    }
                }
            }
        } else if constexpr (has_glossy<M>) {
            const auto lobe = glossy_at(material, hit, normalize(d));
            if (!lobe.smooth()) {
                // As for a diffuse lobe, each part weighed by the lobe toward where its light arrives from.
                const Vec3<float> p(hit.point), nf(n);
                if (length + 1 <= config_.max_length) radiance.direct += direct(hit, rng, [&](const Vec3<T>& wi) { return lobe.f(wi, Transport::radiance); });
                radiance.caustic = Rgb<T>(maps_.caustic.radiance(p, nf, joined_at(config_.caustic, length), reflected_by(lobe)));
                if (config_.gather_rays == 0) radiance.indirect = Rgb<T>(maps_.global.radiance(p, nf, joined_at(config_.global, length), reflected_by(lobe)));
                else if (length + 2 <= config_.max_length) radiance.indirect = gather_glossy(lobe, hit, rng, media, length);
            }
            // The lobe's delta part (a mirror, a smooth coat's reflection), followed as a mirror is.
            if (depth < config_.max_depth) {
                const std::optional<LobeSample<T>> s = lobe.delta_part();
                if (s && max_component(weight * s->weight) > config_.min_weight)
                    radiance += s->weight * trace(scene_->carry_cone(spawn_ray(hit.point, hit.error, hit.normal, s->wi), ray, hit.t), depth + 1, length, weight * s->weight, rng,
                                                  wavelength, media);
            }
        }
        if constexpr ((reflects<M> || transmits<M>) && !has_glossy<M>) {
            if (depth < config_.max_depth) {
                const auto follow = [&](const MediumStack& beyond, const Inside* outside) {
                    const auto outside_index = [&](T lambda) { return index_of(*scene_, outside, lambda); };
                    for_each_delta_ray(material, d, hit, wavelength, bands_, outside_index,
                                       [&](const Vec3<T>& direction, const Rgb<T>& k, T lambda, bool transmitted) {
                                           if (max_component(weight * k) > config_.min_weight)
                                               radiance += k * trace(scene_->carry_cone(spawn_ray(hit.point, hit.error, hit.normal, direction), ray, hit.t), depth + 1, length, weight * k,
                                                                     rng, lambda, transmitted ? beyond : media);
                                       });
                };
                if constexpr (transmits<M>) {
                    const Interface face = nested_interface(media, {h.slot, h.index, nesting_priority(material)}, hit.entering);
                    if (face.real)
                        follow(face.beyond, outside_of(media, face, hit.entering));
                    else
                        radiance = trace(scene_->carry_cone(spawn_ray(hit.point, hit.error, hit.normal, d), ray, hit.t), depth + 1, length - 1, weight, rng, wavelength, face.beyond);
                } else {
                    follow(media, nullptr);
                }
            }
        }
        Rgb<T> kept(T(1)); // what the way here keeps of the light (Beer-Lambert), once for the three parts
        attenuate_segment(*scene_, media, material, hit, ray, kept);
        return radiance *= kept;
    }

    /// Irradiance from the lights by shadow rays (glass opaque), or by what the photons
    /// say about visibility where they agree.
    [[nodiscard]] Rgb<T> direct(const Crossing<T>& hit, Random& rng) const noexcept
    {
        return direct(hit, rng, [](const Vec3<T>&) { return Rgb<T>(T(1)); });
    }

    /// The same, each light sample arriving from wi weighed by `weigh(wi)` (a glossy
    /// lobe's BSDF: then the radiance it reflects).
    template <class Weigh>
    [[nodiscard]] Rgb<T> direct(const Crossing<T>& hit, Random& rng, Weigh&& weigh) const noexcept
    {
        Rgb<T> irradiance{T(0)};
        const LightSampling sampling{&rng, config_.area_light_grid};
        if (const std::optional<bool> visible = visibility_from_photons(hit.point, hit.facing_normal())) {
            if (!*visible) return irradiance;
            const Vec3<T> n = hit.facing_normal(), n_shading = hit.facing_shading();
            scene_->for_each_light([&](const auto& light) {
                for_each_light_sample(light, hit.point, sampling, [&](const LightSample<T>& s) {
                    const T cos = shading_cosine(n_shading, n, s.wi);
                    if (cos > T(0)) irradiance += weigh(s.wi) * air_transmittance(air_, Ray<T>{hit.point, s.wi}, s.distance) * s.irradiance * cos;
                });
            });
            return irradiance;
        }
        for_each_light_arriving<ShadowsThroughGlass::blocked>(*scene_, hit, sampling, [&](const LightSample<T>& s, const Rgb<T>& v, T cos) {
            irradiance += weigh(s.wi) * v * air_transmittance<ShadowsThroughGlass::blocked>(*scene_, air_, Ray<T>{hit.point, s.wi}, s.distance) * s.irradiance * cos;
        });
        return irradiance;
    }

    /// The first diffuse surface a camera ray sees in the air, following mirrors and
    /// glass along their stronger branch (reflected or refracted), and the length of
    /// the path to it; nothing when the ray leaves, or ends inside glass.
    [[nodiscard]] std::optional<std::pair<Crossing<T>, T>> first_diffuse_seen(Ray<T> ray) const noexcept
    {
        T travelled = T(0);
        bool inside = false;
        for (int depth = 0; depth <= config_.max_depth; ++depth) {
            Ray<T> segment = ray;
            T path = T(0);
            const auto hit = inside ? first_hit_in_air(*scene_, StraightAir{}, ray, segment, &path) : first_hit_in_air(*scene_, air_, ray, segment, &path);
            if (!hit) return std::nullopt;
            travelled += path;
            const Crossing<T>& c = hit->crossing;
            const Vec3<T> d = normalize(segment.direction);
            std::optional<Vec3<T>> next;
            const bool diffuse = scene_->visit_material(*hit, [&]<class M>(const M& material) {
                if constexpr (has_diffuse<M>) {
                    return true;
                } else if constexpr ((!reflects<M> && !transmits<M>) || has_glossy<M>) {
                    return false; // a lamp, or a glossy surface (which the cache does not hold): nothing goes on from it
                } else {
                    const Vec3<T> n = delta_normal(material, d, c);
                    const SpecularSplit<T> split = delta_split(material, d, n, c.entering, c.point);
                    if (split.refracted && max_component(split.kt) >= max_component(split.kr)) next = *split.refracted;
                    else if (max_component(split.kr) > T(0)) next = reflect(d, n);
                    return false;
                }
            });
            if (diffuse) {
                if (inside) return std::nullopt;
                return std::pair{c, travelled};
            }
            if (!next) return std::nullopt;
            if (dot(*next, c.facing_normal()) < T(0)) inside = !inside; // refracted: through the surface
            ray = spawn_ray(c.point, c.error, c.normal, *next);
        }
        return std::nullopt;
    }

    /// Final gathering over m x cells_n stratified cells (gather_hemisphere). Each ray
    /// walks on through mirrors and glass as a camera path does (random_walk: Fresnel's
    /// choice at glass, a draw from frosted glass's lobe, Russian roulette on its
    /// throughput past WalkLimits' default depth) to the first diffuse surface
    /// (and on through the delta lobes of a surface that also has one),
    /// where L = albedo / pi * E_global (the global map's precomputed irradiance, which
    /// holds every photon there): paths D S+ D carry colour bleeding seen in a mirror or
    /// through glass, and no light is counted twice, since light from a light through
    /// mirrors and glass only (L S+) is the caustic map's and a point light is never hit.
    /// The rays start in the transmissive objects `media` the surface is inside of (so that
    /// they scatter in the fog about it); from a surface in the air, they follow the air's
    /// curve.
    template <bool Gradients = false>
    [[nodiscard]] HemisphereGather<T> gather(const Crossing<T>& hit, const Vec3<T>& n, Random& rng, const MediumStack& media, int m, int cells_n, int length) const
    {
        const WalkLimits limits = gather_limits(length);
        return gather_hemisphere<Gradients, T>(n, m, cells_n, rng, [&](const Vec3<T>& direction) {
            std::pair<Rgb<T>, T> found{Rgb<T>(T(0)), infinity<T>};
            const auto at_diffuse = [&]<class M>(const M& material, const WalkVertex<T>& at) {
                if constexpr (has_glossy<M> && transmits<M>) return Lobes::all; // frosted glass: through it by its lobe
                found.first += global_radiance(material, at, length);
                found.second = std::min(found.second, at.travelled);
                // The diffuse lobe's light is counted; a delta lobe beside it (a coat) still
                // mirrors what lies beyond.
                return reflects<M> || transmits<M> ? Lobes::delta : Lobes::none;
            };
            // (About a shading normal, a direction may lead into the solid: no light.)
            if (!hit.shades_flat() && !(dot(direction, hit.facing_normal()) > T(0))) return found;
            const Ray<T> ray = spawn_ray(hit.point, hit.error, hit.normal, direction);
            const auto at_medium = [&](const auto& medium, const WalkMediumVertex<T>& at) {
                found.first += volume_radiance(medium, at, length);
                found.second = std::min(found.second, at.travelled);
                return false;
            };
            if (media.empty()) random_walk<Transport::radiance>(*scene_, air_, bands_, ray, Rgb<T>(T(1)), rng, limits, WalkHooks{.on_surface = at_diffuse, .on_medium = at_medium});
            else random_walk<Transport::radiance>(*scene_, StraightAir{}, bands_, ray, Rgb<T>(T(1)), rng, limits, WalkHooks{.on_surface = at_diffuse, .on_medium = at_medium}, media);
            return found;
        });
    }

    /// A gather walk's limits from a camera vertex `length` segments from the camera: its
    /// surfaces, and its vertices so that each is joined to a photon within max_length.
    [[nodiscard]] WalkLimits gather_limits(int length) const noexcept
    {
        WalkLimits limits{.max_bounces = config_.max_depth};
        if (limited()) limits.max_length = config_.max_length - length - 1;
        return limits;
    }

    /// What a walk carries back from the global map at a vertex where it ends: its
    /// power times a diffuse lobe's BRDF times the precomputed irradiance (with
    /// max_length, the same estimate, precomputed_k nearest, over the photons the path may
    /// join: the walk began at a camera vertex `length` segments from the camera). A glossy lobe
    /// there, a bounce away from the camera, is read as a diffuse one of its albedo
    /// toward the walk (GlossyAt::albedo): a glossy lobe's own estimate weighs every
    /// photon within the radius by the BSDF, which made a Cornell box's final gather 5
    /// times slower, for a surface the gather blurs anyway.
    template <class M>
    [[nodiscard]] Rgb<T> global_radiance(const M& material, const WalkVertex<T>& at, int length) const noexcept
    {
        const Crossing<T>& c = at.crossing();
        const Vec3<float> p(c.point), n(c.facing_normal());
        const Rgb<T> e(limited() ? maps_.global.irradiance(p, n, joined_at({.k = precomputed_k, .radius = infinity<float>}, length + at.length))
                                 : maps_.global.precomputed_irradiance(p, n));
        if constexpr (has_glossy<M>) return at.power * (glossy_at(material, c, at.direction).albedo() / pi<T>) * e;
        else return at.power * diffuse_response(material, c).brdf() * e;
    }

    /// A photon's power weighed by a glossy lobe between its arrival and the viewer.
    template <class Lobe>
    [[nodiscard]] static auto reflected_by(const GlossyAt<Lobe>& lobe) noexcept
    {
        return [&lobe](const Photon& photon) { return Rgb<float>(lobe.f(Vec3<T>(photon.toward_source()), Transport::radiance)) * photon.power(); };
    }

    /// A glossy lobe's final gather: gather_rays draws from the lobe, each walked on
    /// through mirrors and glass to the first surface with a non-delta lobe, where the
    /// global map gives its radiance (global_radiance). Draws of the lobe's delta part
    /// count nothing here: the caller follows that part.
    template <class Lobe>
    [[nodiscard]] Rgb<T> gather_glossy(const GlossyAt<Lobe>& lobe, const Crossing<T>& hit, Random& rng, const MediumStack& media, int length) const
    {
        Rgb<T> sum{T(0)};
        const WalkLimits limits = gather_limits(length);
        const auto at_vertex = [&]<class M>(const M& material, const WalkVertex<T>& at) {
            if constexpr (has_glossy<M> && transmits<M>) return Lobes::all; // frosted glass: through it by its lobe
            sum += global_radiance(material, at, length);
            return reflects<M> || transmits<M> ? Lobes::delta : Lobes::none;
        };
        const auto at_medium = [&](const auto& medium, const WalkMediumVertex<T>& at) {
            sum += volume_radiance(medium, at, length);
            return false;
        };
        for (int i = 0; i < config_.gather_rays; ++i) {
            const std::optional<LobeSample<T>> s = lobe.sample(rng, Transport::radiance);
            if (!s || s->delta) continue;
            const Ray<T> ray = spawn_ray(hit.point, hit.error, hit.normal, s->wi);
            if (media.empty()) random_walk<Transport::radiance>(*scene_, air_, bands_, ray, s->weight, rng, limits, WalkHooks{.on_surface = at_vertex, .on_medium = at_medium});
            else random_walk<Transport::radiance>(*scene_, StraightAir{}, bands_, ray, s->weight, rng, limits, WalkHooks{.on_surface = at_vertex, .on_medium = at_medium}, media);
        }
        return sum / T(config_.gather_rays);
    }

    const SceneT* scene_;
    Config config_;
    SpectralBands<T> bands_;
    Air air_;
    PhotonMaps maps_;
    IrradianceCache<T> cache_{};
    int gather_cells_m_ = 1, gather_cells_n_ = 1; ///< the final gather's strata: m x n about gather_rays, n about pi m
};

} // namespace prism
