// SPDX-License-Identifier: MIT
// Light arriving from each light at a surface point, by shadow rays: shared by the integrators.
#pragma once

#include <prism/core/offset.hpp>
#include <prism/core/random.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/light/light.hpp>
#include <prism/material/scattering.hpp>
#include <prism/scene/scene.hpp>

#include <array>
#include <utility>

namespace prism {

/// Shadow rays stop this fraction short of a point light, so a light placed on a
/// surface is not shadowed by that surface (pbrt's ShadowEpsilon).
template <Scalar T>
inline constexpr T shadow_epsilon = T(1e-4);

/// How a shading point samples a light with extent (a delta light is asked once):
/// `grid` x `grid` stratified samples, each jittered within its stratum by `rng` (at the
/// strata's centres without one), each carrying 1 / grid^2 of the estimate.
struct LightSampling {
    Random* rng = nullptr; ///< jitters each sample in its stratum; null: stratum centres
    int grid = 1;         ///< samples per side of the unit square
};

/// The samples one light is asked for: 1 for a delta light, grid^2 for the others.
template <Light L>
[[nodiscard]] constexpr int samples_of(const LightSampling& sampling) noexcept
{
    return is_delta_light<L> ? 1 : sampling.grid * sampling.grid;
}

/// g(sample) for each sample `sampling` asks of `light` at p: its one sample for a delta
/// light; else one per stratum of the grid, its irradiance that stratum's share.
template <Light L, Scalar T, class G>
void for_each_light_sample(const L& light, const Vec3<T>& p, const LightSampling& sampling, G&& g)
{
    if constexpr (is_delta_light<L>) {
        g(light.sample(p, Vec2<T>(T(0.5))));
    } else {
        const int n_side = sampling.grid;
        const T side = T(1) / T(n_side), share = side * side;
        for (int i = 0; i < n_side; ++i)
            for (int j = 0; j < n_side; ++j) {
                const auto [ju, jv] = sampling.rng ? sampling.rng->template uniform2<T>() : std::array<T, 2>{T(0.5), T(0.5)};
                LightSample<T> s = light.sample(p, Vec2<T>((T(i) + ju) * side, (T(j) + jv) * side));
                s.irradiance *= share;
                g(s);
            }
    }
}

/// The sides of a surface light is gathered from: the one a ray arrived from (a surface
/// that reflects), or both (an interface whose lobe also refracts: frosted glass).
enum class Sides { near, both };

namespace detail {

/// for_each_sample_arriving's work: `convex_key` is the object the shading point lies on
/// when that object is convex (else no_object), which a shadow ray leaving it on its outer
/// side skips.
template <ShadowsThroughGlass Glass, Sides Gathered, class SceneT, Light L, Scalar T, class F>
void samples_arriving(const SceneT& scene, const L& light, const Crossing<T>& hit, ObjectKey convex_key, const LightSampling& sampling, F&& f)
{
    const Vec3<T> n = hit.facing_normal(), n_shading = hit.facing_shading();
    const auto leaving = [&](const Vec3<T>& direction) { return dot(direction, hit.normal) > T(0) ? convex_key : no_object; };
    for_each_light_sample(light, hit.point, sampling, [&](const LightSample<T>& s) {
        T cos = shading_cosine(n_shading, n, s.wi);
        if constexpr (Gathered == Sides::both) {
            if (!(cos > T(0))) cos = shading_cosine(-n_shading, -n, s.wi);
        }
        if (!(cos > T(0)) || !(max_component(s.irradiance) > T(0))) return;
        if constexpr (has_own_shadow<L>) {
            const auto through = [&](const Vec3<T>& point) {
                const Vec3<T> to = point - hit.point;
                const T distance = length(to);
                if (!(distance > T(0))) return Rgb<T>(T(1));
                const Vec3<T> direction = to / distance;
                return scene.template transmittance<Glass>(spawn_ray(hit.point, hit.error, hit.normal, direction), distance * (T(1) - shadow_epsilon<T>),
                                                           leaving(direction));
            };
            f(s, light.shadow(through, s.irradiance / pi<T>, sampling.rng), cos);
        } else {
            const Ray<T> shadow = spawn_ray(hit.point, hit.error, hit.normal, s.wi);
            f(s, scene.template transmittance<Glass>(shadow, s.distance * (T(1) - shadow_epsilon<T>), leaving(s.wi)), cos);
        }
    });
}

} // namespace detail

/// For each sample of `light` arriving at the surface on the side the ray arrived from
/// (or on either side, with Sides::both), call f(sample, v, cos): the sample (its
/// irradiance already the sample's share of the light's), the shadow ray's transmittance v
/// (0 when occluded, Beer-Lambert through glass) and the cosine at the surface (the
/// shading normal's: shading_cosine; its absolute value from the far side, where the
/// shading and the true normal agree on the side). Samples behind the surface, or carrying
/// nothing, are not visited: they count as occluded. How dielectrics shadow: see
/// Scene::transmittance. A light that casts its own shadow (has_own_shadow: POV-Ray's
/// area_light) gives v itself, from shadow rays to its points.
template <ShadowsThroughGlass Glass = ShadowsThroughGlass::attenuated, Sides Gathered = Sides::near, class SceneT, Light L, Scalar T, class F>
void for_each_sample_arriving(const SceneT& scene, const L& light, const Crossing<T>& hit, const LightSampling& sampling, F&& f)
{
    detail::samples_arriving<Glass, Gathered>(scene, light, hit, detail::no_object, sampling, std::forward<F>(f));
}

/// The same at a scene's hit: a shadow ray leaving a convex object (Scene::convex_object)
/// on its outer side does not ask that object, which it cannot cross again (a floor's own
/// plane, for every shadow ray from the floor).
template <ShadowsThroughGlass Glass = ShadowsThroughGlass::attenuated, Sides Gathered = Sides::near, class SceneT, Light L, Scalar T, class F>
void for_each_sample_arriving(const SceneT& scene, const L& light, const Hit<T>& hit, const LightSampling& sampling, F&& f)
{
    const detail::ObjectKey key = scene.convex_object(hit.slot, hit.index) ? detail::ObjectKey{hit.slot, hit.index} : detail::no_object;
    detail::samples_arriving<Glass, Gathered>(scene, light, hit.crossing, key, sampling, std::forward<F>(f));
}

/// For each sample of `light` at a point `p` in a medium (no surface: every direction
/// counts), call f(sample, v): the sample, its irradiance already its share of the
/// light's, and v the scene's transmittance along the shadow ray (0 when occluded; the
/// air's own medium is the caller's, transport/media.hpp's air_transmittance).
template <ShadowsThroughGlass Glass = ShadowsThroughGlass::attenuated, class SceneT, Light L, Scalar T, class F>
void for_each_sample_in_medium(const SceneT& scene, const L& light, const Vec3<T>& p, const LightSampling& sampling, F&& f)
{
    for_each_light_sample(light, p, sampling, [&](const LightSample<T>& s) {
        if (!(max_component(s.irradiance) > T(0))) return;
        if constexpr (has_own_shadow<L>) {
            const auto through = [&](const Vec3<T>& point) {
                const Vec3<T> to = point - p;
                const T distance = length(to);
                if (!(distance > T(0))) return Rgb<T>(T(1));
                return scene.template transmittance<Glass>(Ray<T>{p, to / distance}, distance * (T(1) - shadow_epsilon<T>));
            };
            f(s, light.shadow(through, s.irradiance / pi<T>, sampling.rng));
        } else {
            f(s, scene.template transmittance<Glass>(Ray<T>{p, s.wi}, s.distance * (T(1) - shadow_epsilon<T>)));
        }
    });
}

/// for_each_sample_arriving over every light of the scene, its area lights last.
template <ShadowsThroughGlass Glass = ShadowsThroughGlass::attenuated, class SceneT, Scalar T, class F>
void for_each_light_arriving(const SceneT& scene, const Crossing<T>& hit, const LightSampling& sampling, F&& f)
{
    scene.for_each_light([&](const auto& light) { for_each_sample_arriving<Glass>(scene, light, hit, sampling, f); });
}

/// The same, one sample per light at its strata's centre (delta lights only are exact).
template <ShadowsThroughGlass Glass = ShadowsThroughGlass::attenuated, class SceneT, Scalar T, class F>
void for_each_light_arriving(const SceneT& scene, const Crossing<T>& hit, F&& f)
{
    for_each_light_arriving<Glass>(scene, hit, LightSampling{}, std::forward<F>(f));
}

} // namespace prism
