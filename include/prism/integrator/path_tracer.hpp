// SPDX-License-Identifier: MIT
// PathTracer: the unbiased half of prism's reference estimator (the light tracer is the
// other half, integrator/light_tracer.hpp).
//
// A camera path walks the scene as a photon does (transport/random_walk.hpp: Russian
// roulette by reflectance, Fresnel-weighted choice at glass, one wavelength band at a
// dispersive interface) and, at every diffuse vertex, adds the light arriving from each
// light by a shadow ray: next-event estimation, the only way a path can meet a point or
// parallel light. Glass is opaque to shadow rays, as in the photon mapper: a path whose
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
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/rng.hpp>
#include <prism/transport/direct.hpp>
#include <prism/material/scattering.hpp>
#include <prism/medium/air.hpp>
#include <prism/transport/travel.hpp>
#include <prism/transport/random_walk.hpp>
#include <prism/spectrum/bands.hpp>

namespace prism {

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
        int max_depth = 256; ///< surfaces a path may meet; Russian roulette ends it long before
        /// Diffuse bounces a path may take: 0 lights each pixel's first diffuse surface by
        /// shadow rays and goes no further (direct light, seen directly or through
        /// mirrors and glass), as POV-Ray without radiosity; 1 adds one bounce, and so on.
        int max_diffuse_bounces = 256;
        /// A white path meeting a dispersive interface takes one of this many wavelength
        /// bands at random (1 to 81), as a photon does.
        int dispersion_bands = SpectralBands<float>::max_count;
    };

    /// A path tracer of `scene` (which must outlive it) in `air`; throws std::invalid_argument, naming the parameter, for a bad scene, air or setting.
    explicit PathTracer(const SceneT& scene, Config config = {}, Air air = {})
        : scene_(&scene), config_(config), bands_(checked_bands(config.dispersion_bands)), air_(std::move(air))
    {
        scene.validate();
        air_.validate();
        if (config.max_depth < 0) detail::throw_invalid("PathTracer max_depth must be >= 0, got ", config.max_depth);
        if (config.max_diffuse_bounces < 0) detail::throw_invalid("PathTracer max_diffuse_bounces must be >= 0, got ", config.max_diffuse_bounces);
    }
    PathTracer(const SceneT&& scene, Config config = {}, Air air = {}) = delete;

    /// The radiance along a camera ray: light at every diffuse vertex by shadow rays, and
    /// the background where a path of specular bounces only leaves the scene (the
    /// background is seen, as in Whitted, but lights nothing).
    [[nodiscard]] Rgb<T> radiance(const Ray<T>& ray, Pcg32& rng) const noexcept
    {
        Rgb<T> sum{T(0)};
        random_walk<Transport::radiance>(*scene_, air_, bands_, ray, Rgb<T>(T(1)), rng, config_.max_depth,
                    [&]<class M>(const M& material, const WalkVertex<T>& at) {
                        const Crossing<T>& c = at.crossing();
                        Rgb<T> irradiance{T(0)};
                        for_each_light_arriving<ShadowsThroughGlass::blocked>(
                            *scene_, c, [&](const LightSample<T>& s, const Rgb<T>& v, T cos) { irradiance += v * s.irradiance * cos; });
                        sum += at.power * diffuse_response(material, c).brdf() * irradiance;
                        return at.diffuse_bounces < config_.max_diffuse_bounces;
                    },
                    [&](const Ray<T>&, const Rgb<T>& weight, bool specular_only) {
                        if (specular_only) sum += weight * scene_->background;
                    });
        return sum;
    }

    /// The scene and the air its camera rays start in (render_layers' surface layers).
    [[nodiscard]] const SceneT& scene() const noexcept { return *scene_; }
    /// The air camera rays start in.
    [[nodiscard]] const Air& air() const noexcept { return air_; }

private:
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
