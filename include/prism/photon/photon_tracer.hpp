// SPDX-License-Identifier: MIT
// trace_photons: emit photons from the lights and follow them through a scene into a
// global and a caustic photon map (Jensen 1996, section 2.1).
//
// Global map: photons emitted uniformly over the sphere from each point light, and from
// each parallel light through a disk facing it that covers every bounded object (the
// projection disk), stored at every diffuse hit (flagged direct on the first, caustic
// when only specular bounces came before). Caustic map: photons aimed at the bounding
// spheres of specular objects (POV-Ray's `target`), their power scaled by the aimed
// cone's share of the sphere, stored only at the first diffuse hit after one or more
// specular bounces (L S+ D). A diffuse hit continues by Russian roulette on the
// reflectance albedo kd with a cosine-distributed direction; a dielectric reflects with
// probability F and refracts otherwise (Beer-Lambert inside); a conductor reflects by
// roulette on its reflectance. Shadow photons mark where the straight continuation of a
// direct photon's path meets further diffuse surfaces (Jensen and Christensen 1995;
// errata 8). Photon i starts from point i of a scrambled Sobol sequence and draws the
// rest of its path from its own random stream, so the maps are the same bits for any
// thread count. A point light with Falloff::none (POV-Ray's `fade_power 0`) has no
// physical power; its photons are scaled by the squared length of the path they
// travelled, as POV-Ray does, so that their estimate gives irradiance that does not
// fall off with distance either.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/rng.hpp>
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
#include <limits>
#include <thread>
#include <string>
#include <type_traits>
#include <utility>
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

namespace detail {

/// The photons a map may be asked for: its KdTree indexes them in 32 bits.
inline constexpr std::size_t max_photons = std::numeric_limits<std::uint32_t>::max() - 1;

inline void validate(const PhotonTracerConfig& config)
{
    for (const auto& [name, count] : {std::pair{"global_photons", config.global_photons}, std::pair{"caustic_photons", config.caustic_photons}}) {
        const double bytes = double(count) * sizeof(Photon);
        if (count > max_photons)
            throw_invalid("PhotonTracerConfig ", name, " must be at most ", max_photons, " (a map indexes its photons in 32 bits), got ", count,
                          " (their records alone would need ", describe_bytes(bytes), ")");
        require_memory("PhotonTracerConfig " + std::string(name) + " = " + std::to_string(count) + " (its photon records alone)", bytes);
    }
    if (config.max_bounces < 0) throw_invalid("PhotonTracerConfig max_bounces must be >= 0, got ", config.max_bounces);
}

} // namespace detail

struct PhotonMaps {
    PhotonMap global;
    PhotonMap caustic;
};

namespace detail {

/// Where a map's photons start: a point light's whole sphere of directions or a cone of
/// them toward one specular object, or a disk facing a parallel light, upstream of the
/// scene.
template <Scalar T>
struct Emitter {
    Vec3<T> from{};
    Vec3<T> axis{};
    T cos_half_angle = T(-1); ///< -1: every direction
    Rgb<T> power{};           ///< the power into this cone (Phi * solid angle / 4 pi) or onto this disk (E pi r^2)
    T disk_radius = T(0);     ///< > 0: parallel light from a disk of this radius centred on `from`
    bool distance_squared = false; ///< Falloff::none: scale by the squared path length when stored
};

/// The point (u, v) of the unit square mapped uniformly onto the disk of radius r centred
/// at c, perpendicular to the unit axis.
template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_disk(const Vec3<T>& c, const Vec3<T>& axis, T r, T u, T v) noexcept
{
    const T rho = r * prism::sqrt(u);
    const T phi = T(2) * pi<T> * v;
    const auto [s, t] = orthonormal_frame(axis);
    return c + rho * std::cos(phi) * s + rho * std::sin(phi) * t;
}

/// (u, v) mapped uniformly onto the directions within the cone about `axis` with the
/// given cos(half angle).
template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_cone(const Vec3<T>& axis, T cos_half_angle, T u, T v) noexcept
{
    const T cos_theta = T(1) - u * (T(1) - cos_half_angle);
    const T sin_theta = prism::sqrt(clamp(T(1) - cos_theta * cos_theta, T(0), T(1)));
    const T phi = T(2) * pi<T> * v;
    const auto [s, t] = orthonormal_frame(axis);
    return sin_theta * std::cos(phi) * s + sin_theta * std::sin(phi) * t + cos_theta * axis;
}

template <class SceneT>
class PhotonTracer {
public:
    using T = typename SceneT::scalar_type;

    PhotonTracer(const SceneT& scene, const PhotonTracerConfig& config) : scene_(scene), config_(config)
    {
        validate(config);
        Pcg32 scrambles(config.seed, 0xfeed5eedULL);
        for (std::uint32_t& word : global_scramble_) word = scrambles.next_u32();
        for (std::uint32_t& word : caustic_scramble_) word = scrambles.next_u32();
        scene.for_each_light([&](const auto& light) {
            using L = std::remove_cvref_t<decltype(light)>;
            if constexpr (std::is_same_v<L, PointLight<T>>) lights_.push_back(light);
            else if constexpr (std::is_same_v<L, DirectionalLight<T>>) suns_.push_back(light);
        });
        // A sphere around everything bounded: parallel photons start outside it.
        std::apply([&](const auto&... slot) { (add_to_extent(slot), ...); }, scene_.slots);
        for (const PointLight<T>& light : lights_)
            global_.push_back({light.position, {T(0), T(1), T(0)}, T(-1), light.power(), T(0), light.falloff == Falloff::none});
        if (!extent_.empty())
            for (const DirectionalLight<T>& sun : suns_)
                global_.push_back(sun_disk(sun, T(0.5) * (extent_.lo + extent_.hi), T(0.5) * length(extent_.hi - extent_.lo)));
        std::apply([&](const auto&... slot) { (add_targets(slot), ...); }, scene_.slots);
        for (const auto& e : global_) global_power_ += max_component(e.power);
        for (const auto& e : targets_) target_power_ += max_component(e.power);
        // A light whose power is finite can still overflow here: a parallel light's
        // irradiance times the scene's cross-section, or the sum over many lights.
        if (!is_finite(global_power_) || !is_finite(target_power_))
            throw_invalid("photon emission: the lights' total power overflows (", global_power_, ", ", target_power_,
                          "); a DirectionalLight's irradiance times the scene's cross-section pi r^2 must be finite");
    }

    /// Photons [first, last) of the global map, appended to `out`.
    void trace_global(std::size_t first, std::size_t last, std::vector<Photon>& out) const
    {
        for (std::size_t i = first; i < last; ++i) emit(global_, global_power_, config_.global_photons, i, false, out);
    }

    /// Photons [first, last) of the caustic map, appended to `out`.
    void trace_caustic(std::size_t first, std::size_t last, std::vector<Photon>& out) const
    {
        for (std::size_t i = first; i < last; ++i) emit(targets_, target_power_, config_.caustic_photons, i, true, out);
    }

private:
    /// Photon i of a map of `count`: choose an emitter by its share of the power (the
    /// photon carries its power / (count p)), draw where it starts, and follow it. The
    /// choice and the two numbers that place the photon come from point i of a scrambled
    /// Sobol (0,2)-sequence, so the photons of each emitter are stratified over its
    /// directions (or its disk) as on a jittered grid, but for any count; everything after
    /// the first hit is random.
    void emit(const std::vector<Emitter<T>>& emitters, T total_power, std::size_t count, std::size_t i, bool caustic_pass,
              std::vector<Photon>& out) const
    {
        if (emitters.empty() || !(total_power > T(0))) return;
        Pcg32 rng(config_.seed, 2 * i + (caustic_pass ? 1 : 0));
        const std::uint32_t* scramble = caustic_pass ? caustic_scramble_ : global_scramble_;
        auto [u, v] = sobol02<double>(static_cast<std::uint32_t>(i), scramble[0], scramble[1]);
        // The emitter whose share of [0, 1) holds u; u rescaled within that share.
        const Emitter<T>* e = &emitters.back();
        double p = 1, start = 0;
        for (const Emitter<T>& candidate : emitters) {
            const double share = double(max_component(candidate.power)) / double(total_power);
            if (u < start + share || &candidate == &emitters.back()) {
                e = &candidate;
                p = share;
                break;
            }
            start += share;
        }
        u = std::clamp((u - start) / p, 0.0, std::nextafter(1.0, 0.0));
        const Rgb<T> power = e->power / T(double(count) * p);
        if (e->disk_radius > T(0)) {
            follow({uniform_disk(e->from, e->axis, e->disk_radius, T(u), T(v)), e->axis}, power, false, rng, caustic_pass, out);
            return;
        }
        const Vec3<T> direction = e->cos_half_angle <= T(-1) ? uniform_sphere(T(u), T(v)) : uniform_cone(e->axis, e->cos_half_angle, T(u), T(v));
        follow({e->from, direction}, power, e->distance_squared, rng, caustic_pass, out);
    }

    /// Follow one photon; in the caustic pass store only L S+ D and stop there.
    void follow(Ray<T> ray, Rgb<T> power, bool distance_squared, Pcg32& rng, bool caustic_pass, std::vector<Photon>& out) const
    {
        bool direct = true, specular_only = true;
        T travelled = T(0);
        for (int bounce = 0; bounce <= config_.max_bounces; ++bounce) {
            const auto hit = scene_.closest_hit(ray, {T(0), infinity<T>});
            if (!hit) return;
            const Crossing<T>& c = hit->crossing;
            const Vec3<T> d = normalize(ray.direction);
            travelled += c.t * length(ray.direction);
            const auto stored = [&] { return distance_squared ? power * (travelled * travelled) : power; };
            const Vec3<T> n = c.entering ? c.normal : -c.normal; // facing the photon
            const bool go_on = scene_.visit_material(*hit, [&]<class M>(const M& material) -> bool {
                if constexpr (has_diffuse<M>) {
                    if (caustic_pass) {
                        if (!direct && specular_only) out.push_back(photon(c.point, stored(), d, Photon::caustic));
                        return false;
                    }
                    std::uint8_t flags = direct ? std::uint8_t(Photon::direct) : std::uint8_t(0);
                    if (!direct && specular_only) flags |= Photon::caustic;
                    out.push_back(photon(c.point, stored(), d, flags));
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
                // The sphere around the object: its own for a sphere, else around its box.
                const Aabb<T> b = object.shape.bounds();
                Vec3<T> centre = T(0.5) * (b.lo + b.hi);
                T radius = T(0.5) * length(b.hi - b.lo);
                if constexpr (requires { object.shape.center(); object.shape.radius(); }) {
                    centre = object.shape.center();
                    radius = object.shape.radius() * (T(1) + T(16) * std::numeric_limits<T>::epsilon());
                }
                for (const PointLight<T>& light : lights_) {
                    const Vec3<T> to = centre - light.position;
                    const T distance = length(to);
                    Emitter<T> target{light.position, to / distance, T(-1), light.power(), T(0), light.falloff == Falloff::none};
                    if (distance > radius) {
                        const T sin_half = radius / distance;
                        target.cos_half_angle = prism::sqrt(T(1) - sin_half * sin_half);
                        target.power = light.power() * (T(0.5) * (T(1) - target.cos_half_angle)); // solid angle / 4 pi
                    }
                    targets_.push_back(target);
                }
                for (const DirectionalLight<T>& sun : suns_) targets_.push_back(sun_disk(sun, centre, radius));
            }
        }
    }

    /// Parallel light onto the sphere (centre, radius): from the disk of that radius facing
    /// the light, just upstream of everything bounded, carrying E pi r^2.
    [[nodiscard]] Emitter<T> sun_disk(const DirectionalLight<T>& sun, const Vec3<T>& centre, T radius) const
    {
        const Vec3<T> axis = normalize(sun.direction);
        const Vec3<T> middle = T(0.5) * (extent_.lo + extent_.hi);
        const T upstream = length(centre - middle) + T(0.5) * length(extent_.hi - extent_.lo) + radius;
        return {centre - upstream * axis, axis, T(-1), sun.irradiance * (pi<T> * radius * radius), radius};
    }

    const SceneT& scene_;
    PhotonTracerConfig config_;
    std::vector<PointLight<T>> lights_;
    std::vector<DirectionalLight<T>> suns_;
    Aabb<T> extent_{};
    std::vector<Emitter<T>> global_;  ///< every light's emission for the global map
    T global_power_ = T(0);
    std::vector<Emitter<T>> targets_; ///< cones and disks toward specular objects, for the caustic map
    T target_power_ = T(0);
    std::uint32_t global_scramble_[2]{}, caustic_scramble_[2]{}; ///< the Sobol points' scrambling, per map
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

/// Trace the global and caustic photon maps of a scene, from its point and directional
/// lights.
template <class SceneT>
[[nodiscard]] PhotonMaps trace_photons(const SceneT& scene, const PhotonTracerConfig& config)
{
    const detail::PhotonTracer<SceneT> tracer(scene, config);
    PhotonMaps maps;
    try {
        maps.global = PhotonMap(detail::in_blocks(config.global_photons, config.threads, [&](std::size_t a, std::size_t b, std::vector<Photon>& out) {
            tracer.trace_global(a, b, out);
        }));
        maps.caustic = PhotonMap(detail::in_blocks(config.caustic_photons, config.threads, [&](std::size_t a, std::size_t b, std::vector<Photon>& out) {
            tracer.trace_caustic(a, b, out);
        }));
    } catch (const std::bad_alloc&) {
        throw allocation_error("prism: tracing " + std::to_string(config.global_photons) + " global and " + std::to_string(config.caustic_photons) +
                               " caustic photons ran out of memory (each stored photon takes " + std::to_string(sizeof(Photon)) +
                               " bytes, and a photon may be stored at every diffuse bounce)");
    }
    return maps;
}

} // namespace prism
