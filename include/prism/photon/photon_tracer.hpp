// SPDX-License-Identifier: MIT
// trace_photons: emit photons from the lights and follow them through a scene into a
// global and a caustic photon map (Jensen 1996, section 2.1).
//
// Global map: photons emitted uniformly over the sphere from each point light, stored
// at every diffuse hit (flagged direct on the first, caustic when only specular
// bounces came before). Caustic map: photons aimed at the bounding spheres of specular
// objects (POV-Ray's `target`), their power scaled by the aimed cone's share of the
// sphere, stored only at the first diffuse hit after one or more specular bounces
// (L S+ D). A diffuse hit continues by Russian roulette on the reflectance albedo kd
// with a cosine-distributed direction; a dielectric reflects with probability F and
// refracts otherwise (Beer-Lambert inside); a conductor reflects by roulette on its
// reflectance. Shadow photons mark where the straight continuation of a direct
// photon's path meets further diffuse surfaces (Jensen and Christensen 1995; errata 8).
// Every photon draws from its own random stream, so the maps are the same bits for any
// thread count.
#pragma once

#include <prism/core/offset.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/light/directional_light.hpp>
#include <prism/light/point_light.hpp>
#include <prism/material/traits.hpp>
#include <prism/optics/beer.hpp>
#include <prism/optics/refract.hpp>
#include <prism/photon/photon_map.hpp>
#include <prism/scene/object.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <type_traits>
#include <vector>

namespace prism {

struct PhotonTracerConfig {
    std::size_t global_photons = 200000;  ///< emitted for the global map
    std::size_t caustic_photons = 200000; ///< emitted toward specular objects for the caustic map
    int max_bounces = 16;                 ///< bounces followed at most
    bool shadow_photons = true;
    std::uint64_t seed = 0;
    unsigned threads = 0; ///< 0 = all hardware threads
};

struct PhotonMaps {
    PhotonMap global;
    PhotonMap caustic;
};

namespace detail {

/// Where caustic photons toward one specular object start: a cone of directions from a
/// point light, or (parallel light) a disk facing the light, upstream of the scene.
template <Scalar T>
struct CausticTarget {
    Vec3<T> from{};
    Vec3<T> axis{};
    T cos_half_angle = T(-1); ///< -1: the light is inside the sphere, the cone is everything
    Rgb<T> power{};           ///< the power into this cone (Phi * solid angle / 4 pi) or onto this disk (E pi r^2)
    T disk_radius = T(0);     ///< > 0: parallel light from a disk of this radius centred on `from`
};

/// A point uniform on the disk of radius r centred at c, perpendicular to the unit axis.
template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_disk(const Vec3<T>& c, const Vec3<T>& axis, T r, Pcg32& rng) noexcept
{
    const T rho = r * prism::sqrt(rng.uniform<T>());
    const T phi = T(2) * pi<T> * rng.uniform<T>();
    const auto [s, t] = orthonormal_frame(axis);
    return c + rho * std::cos(phi) * s + rho * std::sin(phi) * t;
}

/// A direction uniform within the cone about `axis` with the given cos(half angle).
template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_cone(const Vec3<T>& axis, T cos_half_angle, Pcg32& rng) noexcept
{
    const T cos_theta = T(1) - rng.uniform<T>() * (T(1) - cos_half_angle);
    const T sin_theta = prism::sqrt(clamp(T(1) - cos_theta * cos_theta, T(0), T(1)));
    const T phi = T(2) * pi<T> * rng.uniform<T>();
    const auto [s, t] = orthonormal_frame(axis);
    return sin_theta * std::cos(phi) * s + sin_theta * std::sin(phi) * t + cos_theta * axis;
}

template <class SceneT>
class PhotonTracer {
public:
    using T = typename SceneT::scalar_type;

    PhotonTracer(const SceneT& scene, const PhotonTracerConfig& config) : scene_(scene), config_(config)
    {
        scene.for_each_light([&](const auto& light) {
            using L = std::remove_cvref_t<decltype(light)>;
            if constexpr (std::is_same_v<L, PointLight<T>>) {
                lights_.push_back(light);
                total_power_ += max_component(light.power());
            } else if constexpr (std::is_same_v<L, DirectionalLight<T>>) {
                suns_.push_back(light);
            }
        });
        collect_targets();
    }

    /// Photons [first, last) of the global map, appended to `out`.
    void trace_global(std::size_t first, std::size_t last, std::vector<Photon>& out) const
    {
        if (lights_.empty() || !(total_power_ > T(0))) return;
        for (std::size_t i = first; i < last; ++i) {
            Pcg32 rng(config_.seed, 2 * i);
            // Choose a light by its share of the power; the photon carries Phi / (N p).
            const PointLight<T>* light = &lights_.back();
            T p = T(1), u = rng.uniform<T>() * total_power_;
            for (const PointLight<T>& l : lights_) {
                const T share = max_component(l.power());
                if (u < share) {
                    light = &l;
                    p = share / total_power_;
                    break;
                }
                u -= share;
            }
            const Rgb<T> power = light->power() / (T(config_.global_photons) * p);
            follow({light->position, uniform_sphere<T>(rng)}, power, rng, false, out);
        }
    }

    /// Photons [first, last) of the caustic map, appended to `out`.
    void trace_caustic(std::size_t first, std::size_t last, std::vector<Photon>& out) const
    {
        if (targets_.empty()) return;
        for (std::size_t i = first; i < last; ++i) {
            Pcg32 rng(config_.seed, 2 * i + 1);
            // Choose a cone by its share of the power aimed at specular objects.
            const CausticTarget<T>* target = &targets_.back();
            T p = T(1), u = rng.uniform<T>() * target_power_;
            for (const CausticTarget<T>& c : targets_) {
                const T share = max_component(c.power);
                if (u < share) {
                    target = &c;
                    p = share / target_power_;
                    break;
                }
                u -= share;
            }
            const Rgb<T> power = target->power / (T(config_.caustic_photons) * p);
            if (target->disk_radius > T(0)) {
                follow({uniform_disk(target->from, target->axis, target->disk_radius, rng), target->axis}, power, rng, true, out);
                continue;
            }
            const Vec3<T> direction =
                target->cos_half_angle <= T(-1) ? uniform_sphere<T>(rng) : uniform_cone(target->axis, target->cos_half_angle, rng);
            follow({target->from, direction}, power, rng, true, out);
        }
    }

private:
    /// Follow one photon; in the caustic pass store only L S+ D and stop there.
    void follow(Ray<T> ray, Rgb<T> power, Pcg32& rng, bool caustic_pass, std::vector<Photon>& out) const
    {
        bool direct = true, specular_only = true;
        for (int bounce = 0; bounce <= config_.max_bounces; ++bounce) {
            const auto hit = scene_.closest_hit(ray, {T(0), infinity<T>});
            if (!hit) return;
            const Crossing<T>& c = hit->crossing;
            const Vec3<T> d = normalize(ray.direction);
            const Vec3<T> n = c.entering ? c.normal : -c.normal; // facing the photon
            const bool go_on = scene_.visit_material(*hit, [&]<class M>(const M& material) -> bool {
                if constexpr (has_diffuse<M>) {
                    if (caustic_pass) {
                        if (!direct && specular_only) out.push_back(photon(c.point, power, d, Photon::caustic));
                        return false;
                    }
                    std::uint8_t flags = direct ? std::uint8_t(Photon::direct) : std::uint8_t(0);
                    if (!direct && specular_only) flags |= Photon::caustic;
                    out.push_back(photon(c.point, power, d, flags));
                    if (direct && config_.shadow_photons) store_shadow_photons(c, d, out);
                    const Rgb<T> reflectance = component_min(material.albedo.albedo(c.point) * material.kd, Rgb<T>(T(1)));
                    if (!russian_roulette(power, reflectance, rng)) return false;
                    ray = spawn_ray(c.point, c.error, c.normal, cosine_hemisphere(n, rng));
                    specular_only = false;
                } else if constexpr (transmits<M>) {
                    if (!c.entering) power *= beer_lambert(material.absorption, c.t * length(ray.direction));
                    const T eta = c.entering ? material.ior : T(1) / material.ior;
                    const T cos_i = clamp(-dot(d, n), T(0), T(1));
                    const auto refracted = refract(d, n, eta);
                    const T fresnel = refracted ? material.fresnel(cos_i, eta) : T(1);
                    const bool reflect_it = rng.uniform<T>() < fresnel;
                    if (!russian_roulette(power, Rgb<T>(reflect_it ? material.kr : material.kt), rng)) return false;
                    ray = spawn_ray(c.point, c.error, c.normal, reflect_it ? reflect(d, n) : *refracted);
                } else if constexpr (reflects<M>) {
                    const T cos_i = clamp(-dot(d, n), T(0), T(1));
                    if (!russian_roulette(power, material.reflectance(cos_i), rng)) return false;
                    ray = spawn_ray(c.point, c.error, c.normal, reflect(d, n));
                }
                return true;
            });
            if (!go_on) return;
            direct = false;
        }
    }

    [[nodiscard]] static Photon photon(const Vec3<T>& at, const Rgb<T>& power, const Vec3<T>& travelling, std::uint8_t flags) noexcept
    {
        return {Vec3<float>(at), Rgb<float>(power), Vec3<float>(-travelling), flags};
    }

    /// Shadow photons along the straight line on from a direct photon's first hit.
    void store_shadow_photons(const Crossing<T>& first, const Vec3<T>& d, std::vector<Photon>& out) const
    {
        Ray<T> through = spawn_ray(first.point, first.error, first.normal, d);
        for (int surfaces = 0; surfaces < 8; ++surfaces) {
            const auto hit = scene_.closest_hit(through, {T(0), infinity<T>});
            if (!hit) return;
            const Crossing<T>& c = hit->crossing;
            const bool diffuse = scene_.visit_material(*hit, []<class M>(const M&) { return has_diffuse<M>; });
            if (diffuse) out.push_back(photon(c.point, Rgb<T>(T(0)), d, Photon::shadow));
            through = spawn_ray(c.point, c.error, c.normal, d);
        }
    }

    /// A cone from every point light, and a disk for every parallel light, to every
    /// bounded specular object.
    void collect_targets()
    {
        // A sphere around everything bounded: parallel photons start outside it.
        std::apply([&](const auto&... slot) { (add_to_extent(slot), ...); }, scene_.slots);
        std::apply([&](const auto&... slot) { (add_targets(slot), ...); }, scene_.slots);
        for (const auto& t : targets_) target_power_ += max_component(t.power);
    }

    template <class Slot>
    void add_to_extent(const Slot& slot)
    {
        for (const auto& object : objects_of(slot))
            if (object.bounded) extent_ = {component_min(extent_.lo, object.shape.bounds().lo), component_max(extent_.hi, object.shape.bounds().hi)};
    }

    template <class Slot>
    void add_targets(const Slot& slot)
    {
        using M = typename Slot::material_type;
        if constexpr (reflects<M> || transmits<M>) {
            for (const auto& object : objects_of(slot)) {
                if (!object.bounded) continue;
                const Aabb<T> b = object.shape.bounds();
                const Vec3<T> centre = T(0.5) * (b.lo + b.hi);
                const T radius = T(0.5) * length(b.hi - b.lo);
                for (const PointLight<T>& light : lights_) {
                    const Vec3<T> to = centre - light.position;
                    const T distance = length(to);
                    CausticTarget<T> target{light.position, to / distance, T(-1), light.power()};
                    if (distance > radius) {
                        const T sin_half = radius / distance;
                        target.cos_half_angle = prism::sqrt(T(1) - sin_half * sin_half);
                        target.power = light.power() * (T(0.5) * (T(1) - target.cos_half_angle)); // solid angle / 4 pi
                    }
                    targets_.push_back(target);
                }
                for (const DirectionalLight<T>& sun : suns_) {
                    // The disk facing the light, just upstream of everything bounded.
                    const Vec3<T> axis = normalize(sun.direction);
                    const Vec3<T> middle = T(0.5) * (extent_.lo + extent_.hi);
                    const T upstream = length(centre - middle) + T(0.5) * length(extent_.hi - extent_.lo) + radius;
                    targets_.push_back({centre - upstream * axis, axis, T(-1), sun.irradiance * (pi<T> * radius * radius), radius});
                }
            }
        }
    }

    const SceneT& scene_;
    PhotonTracerConfig config_;
    std::vector<PointLight<T>> lights_;
    std::vector<DirectionalLight<T>> suns_; ///< parallel lights: caustic photons only, for now
    Aabb<T> extent_{};
    T total_power_ = T(0);
    std::vector<CausticTarget<T>> targets_;
    T target_power_ = T(0);
};

/// Run `trace(first, last, out)` over [0, count) in fixed blocks on worker threads and
/// concatenate the blocks in order: the result does not depend on the thread count.
template <class Trace>
std::vector<Photon> in_blocks(std::size_t count, unsigned threads, Trace&& trace)
{
    constexpr std::size_t block = 4096;
    const std::size_t blocks = (count + block - 1) / block;
    std::vector<std::vector<Photon>> parts(blocks);
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t b = next++; b < blocks; b = next++) trace(b * block, std::min(count, (b + 1) * block), parts[b]);
    };
    threads = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(blocks, 1)));
    std::vector<std::thread> workers;
    for (unsigned i = 1; i < threads; ++i) workers.emplace_back(work);
    work();
    for (auto& worker : workers) worker.join();
    std::vector<Photon> all;
    for (auto& part : parts) all.insert(all.end(), part.begin(), part.end());
    return all;
}

} // namespace detail

/// Trace the global and caustic photon maps of a scene. Point lights emit into both;
/// directional lights, for now, only caustic photons (aimed at specular objects).
template <class SceneT>
[[nodiscard]] PhotonMaps trace_photons(const SceneT& scene, const PhotonTracerConfig& config)
{
    const detail::PhotonTracer<SceneT> tracer(scene, config);
    PhotonMaps maps;
    maps.global = PhotonMap(detail::in_blocks(config.global_photons, config.threads, [&](std::size_t a, std::size_t b, std::vector<Photon>& out) {
        tracer.trace_global(a, b, out);
    }));
    maps.caustic = PhotonMap(detail::in_blocks(config.caustic_photons, config.threads, [&](std::size_t a, std::size_t b, std::vector<Photon>& out) {
        tracer.trace_caustic(a, b, out);
    }));
    return maps;
}

} // namespace prism
