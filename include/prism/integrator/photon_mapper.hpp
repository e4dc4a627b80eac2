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
#include <prism/core/rng.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/integrator/direct.hpp>
#include <prism/light/light.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/nesting.hpp>
#include <prism/optics/refract.hpp>
#include <prism/photon/photon_tracer.hpp>

#include <algorithm>
#include <optional>

namespace prism {

/// The photon mapper over `scene` with its air (StraightAir, or GradedAir: camera rays,
/// gather rays and photons in the air curve; medium/air.hpp).
template <class SceneT, class Air = StraightAir>
class PhotonMapper {
public:
    using scalar_type = typename SceneT::scalar_type;
    using T = scalar_type;

    struct Config {
        PhotonTracerConfig tracing{}; ///< how many photons, and how they are traced
        Estimator caustic{.radius = 0.1f}; ///< the caustic map's estimate
        /// The global map's estimate where it is read directly (gather_rays = 0); direct
        /// and caustic photons are left out, shadow rays and the caustic map count them.
        Estimator global{.radius = 0.25f, .excluded = Photon::direct | Photon::caustic};
        int gather_rays = 32; ///< final-gather rays per diffuse hit; 0 reads the global map directly
        /// > 0: look at this many nearest global photons (within global.radius) before a
        /// shadow ray, and skip it when they agree. Scenes with one light only: shadow
        /// photons do not say which light they block.
        std::size_t visibility_k = 0;
        int max_depth = 10;
        T min_weight = T(1e-3);
        /// Wavelength bands white camera rays split into at a dispersive interface (as
        /// Whitted's); photons take their own wavelengths (PhotonTracerConfig).
        int dispersion_bands = 8;
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
        if (config.max_depth < 0) detail::throw_invalid("PhotonMapper max_depth must be >= 0, got ", config.max_depth);
        detail::require_non_negative("PhotonMapper min_weight", config.min_weight);
        if (config.visibility_k > PhotonMap::max_k)
            detail::throw_invalid("PhotonMapper visibility_k must be at most ", PhotonMap::max_k, ", got ", config.visibility_k);
        detail::validate(config.tracing);
        if (config.visibility_k > 0 && SceneT::light_count != 1)
            detail::throw_invalid("PhotonMapper visibility_k needs a scene with exactly one light, got lights: ", SceneT::light_count);
        maps_ = maps ? std::move(*maps) : trace_photons(scene, config.tracing, air_);
        if (config.gather_rays > 0) maps_.global.precompute_irradiance<64>(4, config.tracing.threads);
    }

public:

    [[nodiscard]] const PhotonMaps& maps() const noexcept { return maps_; }

    [[nodiscard]] Rgb<T> radiance(const Ray<T>& ray, Pcg32& rng) const noexcept { return trace(ray, 0, Rgb<T>(T(1)), rng, T(0), {}); }

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
        if (!(e.radius > 0.0f && is_finite(e.radius))) detail::throw_invalid(name, " radius must be finite and > 0, got ", e.radius);
        if (e.k > PhotonMap::max_k) detail::throw_invalid(name, " k must be at most ", PhotonMap::max_k, ", got ", e.k);
        if (!(e.max_height_ratio > 0.0f && e.max_height_ratio <= 1.0f)) detail::throw_invalid(name, " max_height_ratio must be in (0, 1], got ", e.max_height_ratio);
        if (!(e.surface_cos >= 0.0f && e.surface_cos < 1.0f)) detail::throw_invalid(name, " surface_cos must be in [0, 1), got ", e.surface_cos);
        if (e.filter != Filter::box && e.filter != Filter::cone && e.filter != Filter::gaussian)
            detail::throw_invalid(name, " filter must be box, cone or gaussian, got the value ", static_cast<int>(e.filter));
    }

    /// Radiance along the ray for light of one wavelength (nanometres), or of all (0), in
    /// the transmissive objects `media` (medium/nesting.hpp).
    [[nodiscard]] Rgb<T> trace(const Ray<T>& ray, int depth, const Rgb<T>& weight, Pcg32& rng, T wavelength, const MediumStack& media) const noexcept
    {
        Ray<T> segment = ray;
        const auto hit = media.empty() ? first_hit_in_air(*scene_, air_, ray, segment) : first_hit_in_air(*scene_, StraightAir{}, ray, segment);
        if (!hit) return scene_->background;
        return scene_->visit_material(*hit, [&](const auto& material) { return shade(material, segment, *hit, depth, weight, rng, wavelength, media); });
    }

    template <class M>
    [[nodiscard]] Rgb<T> shade(const M& material, const Ray<T>& ray, const Hit<T>& h, int depth, const Rgb<T>& weight, Pcg32& rng,
                               T wavelength, const MediumStack& media) const noexcept
    {
        const Crossing<T>& hit = h.crossing;
        const Vec3<T>& d = ray.direction;
        const Vec3<T> n = hit.facing_normal();
        Rgb<T> radiance{T(0)};
        if constexpr (has_diffuse<M>) {
            const Vec3<float> p(hit.point), nf(n);
            Rgb<T> irradiance = direct(hit, n) + Rgb<T>(maps_.caustic.irradiance(p, nf, config_.caustic));
            if (config_.gather_rays > 0) irradiance += gather(hit, n, rng, media.empty());
            else irradiance += Rgb<T>(maps_.global.irradiance(p, nf, config_.global));
            radiance += diffuse_response(material, hit.point).brdf() * irradiance;
        }
        if constexpr (reflects<M> || transmits<M>) {
            if (depth < config_.max_depth) {
                const auto follow = [&](const MediumStack& beyond, const Inside* outside) {
                    const auto outside_index = [&](T lambda) { return index_of(*scene_, outside, lambda); };
                    for_each_delta_ray(material, d, n, hit, wavelength, bands_, outside_index,
                                       [&](const Vec3<T>& direction, const Rgb<T>& k, T lambda, bool transmitted) {
                                           if (max_component(weight * k) > config_.min_weight)
                                               radiance += k * trace(spawn_ray(hit.point, hit.error, hit.normal, direction), depth + 1, weight * k,
                                                                     rng, lambda, transmitted ? beyond : media);
                                       });
                };
                if constexpr (transmits<M>) {
                    const Interface face = nested_interface(media, {h.slot, h.index, nesting_priority(material)}, hit.entering);
                    if (face.real)
                        follow(face.beyond, outside_of(media, face, hit.entering));
                    else
                        radiance = trace(spawn_ray(hit.point, hit.error, hit.normal, d), depth + 1, weight, rng, wavelength, face.beyond);
                } else {
                    follow(media, nullptr);
                }
            }
        }
        attenuate_segment(*scene_, media, material, hit, ray, radiance);
        return radiance;
    }

    /// Irradiance from the lights by shadow rays (glass opaque), or by what the photons
    /// say about visibility where they agree.
    [[nodiscard]] Rgb<T> direct(const Crossing<T>& hit, const Vec3<T>& n) const noexcept
    {
        Rgb<T> irradiance{T(0)};
        if (const std::optional<bool> visible = visibility_from_photons(hit.point, n)) {
            if (!*visible) return irradiance;
            scene_->for_each_light([&](const auto& light) {
                const LightSample<T> s = light.sample(hit.point);
                irradiance += s.irradiance * std::max(dot(n, s.wi), T(0));
            });
            return irradiance;
        }
        for_each_light_arriving<ShadowsThroughGlass::blocked>(*scene_, hit, n, [&](const LightSample<T>& s, const Rgb<T>& v, T cos) { irradiance += v * s.irradiance * cos; });
        return irradiance;
    }

    /// Final gathering: E = pi / M sum L_i for cosine-distributed directions, with
    /// L_i = albedo / pi * E_global where the ray lands on a diffuse surface; from a
    /// surface in the air (`in_air`), the gather rays follow the air's curve.
    [[nodiscard]] Rgb<T> gather(const Crossing<T>& hit, const Vec3<T>& n, Pcg32& rng, bool in_air) const noexcept
    {
        Rgb<T> sum{T(0)};
        for (int i = 0; i < config_.gather_rays; ++i) {
            const Ray<T> ray = spawn_ray(hit.point, hit.error, hit.normal, cosine_hemisphere(n, rng));
            Ray<T> segment = ray;
            const auto next = in_air ? first_hit_in_air(*scene_, air_, ray, segment) : first_hit_in_air(*scene_, StraightAir{}, ray, segment);
            if (!next) continue;
            const Crossing<T>& c = next->crossing;
            sum += scene_->visit_material(*next, [&]<class M>(const M& material) -> Rgb<T> {
                if constexpr (has_diffuse<M>) {
                    const Rgb<T> e(maps_.global.precomputed_irradiance(Vec3<float>(c.point), Vec3<float>(c.facing_normal())));
                    return diffuse_response(material, c.point).brdf() * e;
                } else {
                    return Rgb<T>(T(0)); // light seen through mirrors and glass arrives by the caustic map
                }
            });
        }
        return sum * (pi<T> / T(config_.gather_rays));
    }

    const SceneT* scene_;
    Config config_;
    SpectralBands<T> bands_;
    Air air_;
    PhotonMaps maps_;
};

} // namespace prism
