// SPDX-License-Identifier: MIT
// trace_photons: emit photons from the lights and follow them through a scene into a
// global and a caustic photon map (Jensen 1996, section 2.1).
//
// Global map: each light emits everywhere it shines (Light::emit_photon with no target:
// a point light over its whole sphere, a parallel light through a disk facing it that
// covers every bounded object), and photons are stored at every diffuse hit (flagged
// direct on the first, caustic when only specular bounces came before, or bounces through
// frosted glass, which holds no photons itself). Caustic map:
// each light aims at the bounding sphere of every specular object (POV-Ray's `target`;
// bounding_sphere(shape)), and photons are stored only at the first diffuse hit after
// one or more specular bounces or bounces through frosted glass (L {S | frosted}+ D). Every bounce is scatter_photon's (Russian
// roulette per channel, material/scattering.hpp), and light travelling inside an object
// is attenuated by its medium. Shadow photons mark where the straight continuation of a
// direct photon's path meets further diffuse surfaces (Jensen and Christensen 1995,
// "Efficiently rendering shadows using the photon map"). Where a photon scatters in a
// medium (a Fog) it is stored as a volume photon (Jensen and Christensen 1998): the global
// pass's on every path but a volumetric caustic's, L {S | frosted}+ M, which is the
// caustic pass's. Photon i starts from point i of a scrambled Sobol sequence and draws the
// rest of its path from its own random stream, so the maps are the same bits for any
// thread count. A light without falloff (POV-Ray's `fade_power 0`) has no physical
// power; its photons are scaled by the squared length of the path they travelled, as
// POV-Ray does, so that their estimate gives irradiance that does not fall off with
// distance either.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/parallel.hpp>
#include <prism/core/random.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/geometry/shape.hpp>
#include <prism/light/light.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/air.hpp>
#include <prism/medium/nesting.hpp>
#include <prism/photon/photon_map.hpp>
#include <prism/spectrum/bands.hpp>
#include <prism/transport/random_walk.hpp>
#include <prism/transport/travel.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace prism {

/// How many photons are traced, and how.
struct PhotonTracerConfig {
    std::size_t global_photons = 200000;  ///< emitted for the global map
    std::size_t caustic_photons = 200000; ///< emitted toward specular objects for the caustic map
    int max_bounces = 16;                 ///< bounces at surfaces followed at most
    int max_medium_bounces = 1000;        ///< scatterings in media followed at most (WalkLimits'; in fog that absorbs, roulette ends a photon long before)
    /// Segments a photon's path may take from the light, vertices at surfaces and in media
    /// counted together (WalkLimits::max_length; whichever limit comes first ends it): the
    /// light tracer's paths, joined to the camera by one segment more, are held to its
    /// max_length by this.
    int max_length = std::numeric_limits<int>::max();
    bool shadow_photons = true; ///< store shadow photons in the global map
    std::uint64_t seed = 0; ///< with the light, fixes every photon
    /// The photons' numbers (core/sampler.hpp): photon i of a map is sample i of the
    /// sampler, its choice of light and point (pair 0), its direction (pair 1) and each
    /// bounce (a block of pairs) Owen-scrambled Sobol points, so that the photons of any
    /// 2^m prefix, a pass of progressive photon mapping included, are stratified in each
    /// (zsobol, a layout of the image, draws the same); Halton's points, one sequence over
    /// the photon's first 64 dimensions together; or independent numbers.
    SamplerKind sampler = SamplerKind::sobol;
    unsigned threads = 0; ///< 0 = all hardware threads
    /// A white photon meeting a dispersive interface takes one of this many wavelength
    /// bands at random (1 to 81), its power scaled by the band's photon_weight times
    /// the band count, and keeps that wavelength from then on.
    int dispersion_bands = SpectralBands<float>::max_count;
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
    if (config.max_medium_bounces < 0) throw_invalid("PhotonTracerConfig max_medium_bounces must be >= 0, got ", config.max_medium_bounces);
    if (config.max_length < 1) throw_invalid("PhotonTracerConfig max_length must be >= 1, got ", config.max_length);
    if (config.dispersion_bands < 1 || config.dispersion_bands > SpectralBands<float>::max_count)
        throw_invalid("PhotonTracerConfig dispersion_bands must be in [1, ", SpectralBands<float>::max_count, "], got ", config.dispersion_bands);
}

} // namespace detail

/// The maps one photon tracing gives: the global map (shadow photons in it, flagged) and
/// the caustic map.
struct PhotonMaps {
    PhotonMap global; ///< every photon's diffuse landings (flagged direct, caustic or shadow)
    PhotonMap caustic; ///< landings after specular bounces only (L S+ D)
    PhotonMap volume; ///< where photons scattered in a medium (L ... M; empty in a scene without one), volumetric caustics flagged
};

namespace detail {

/// One light aimed somewhere (everywhere, or at one specular object): a share of a
/// map's photons in proportion to `power`.
template <Scalar T>
struct Emitter {
    std::size_t light = 0;      ///< its number in the scene's Lights{...}
    bool aimed = false;         ///< at `target`; else everywhere
    BoundingSphere<T> target{};
    Rgb<T> power{};             ///< Light::photon_power of this aim
};

template <class SceneT, class Air = StraightAir>
class PhotonTracer {
public:
    using T = typename SceneT::scalar_type;

    PhotonTracer(const SceneT& scene, const PhotonTracerConfig& config, const Air& air = {})
        : scene_(scene), config_((detail::validate(config), config)), bands_(config.dispersion_bands), air_(air)
    {
        air_.validate();
        // A sphere around everything bounded, the air's medium included where it is
        // bounded: parallel photons start outside it.
        Aabb<T> lit = scene.bounds();
        if constexpr (air_scatters<Air>) {
            if (air.bounds().bounded()) lit = lit.merged(air.bounds());
        }
        if (!lit.empty()) {
            scene_sphere_ = lit.bounding_sphere();
            has_sphere_ = true;
        }
        add_emitters(global_, false, {});
        // Every light aimed at each bounded object that may scatter by a delta lobe (a
        // mirror, glass, a glossy lobe's delta part: may_scatter_by_delta), where caustics
        // and a light tracer's paths begin; not at an index-matched boundary, which makes
        // no caustic (may_match_index).
        scene.for_each_object([&]<class Object>(const Object& object) {
            using M = typename Object::material_type;
            if constexpr (reflects<M> || transmits<M> || has_glossy<M>) {
                if (object.bounded && !index_matched(object.material, T(1)) && may_scatter_by_delta(object.material))
                    add_emitters(targets_, true, bounding_sphere(object.shape));
            }
        });
        drop_nested_targets(targets_);
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
        PixelSeeds seeds(config_.seed, 0); // every global photon is a sample of "pixel" 0
        for (std::size_t i = first; i < last; ++i) store(global_, global_power_, config_.global_photons, i, false, seeds, out);
    }

    /// Photons [first, last) of the caustic map, appended to `out`.
    void trace_caustic(std::size_t first, std::size_t last, std::vector<Photon>& out) const
    {
        PixelSeeds seeds(config_.seed, 1); // and every caustic photon of "pixel" 1
        for (std::size_t i = first; i < last; ++i) store(targets_, target_power_, config_.caustic_photons, i, true, seeds, out);
    }

    /// Light paths [first, last) of `count` aimed where the caustic map's photons are,
    /// each walked to its end: visit(material, vertex, power) at every
    /// diffuse surface and visit_medium(medium, vertex, power) where it scatters in a
    /// medium return whether the walk goes on (the light tracer's paths).
    template <class Visit, class VisitMedium = IgnoreMedia>
    void walk_aimed(std::size_t first, std::size_t last, std::size_t count, Visit&& visit, VisitMedium&& visit_medium = {}) const
    {
        PixelSeeds seeds(config_.seed, 1);
        for (std::size_t i = first; i < last; ++i) emit(targets_, target_power_, count, i, true, seeds, visit, visit_medium);
    }

private:
    /// Photon i of a map of `count`: choose an emitter by its share of the power (the
    /// photon carries its power / (count p)), let its light place the photon, and walk
    /// it (random_walk), calling visit(material, vertex, stored power) at each diffuse
    /// surface. Its numbers are sample i of config.sampler: with Sobol points the choice
    /// and the point on the light (pair 0), the direction (pair 1) and each bounce are
    /// stratified over the photons as on a jittered grid, but for any count.
    template <class Visit, class VisitMedium = IgnoreMedia>
    void emit(const std::vector<Emitter<T>>& emitters, T total_power, std::size_t count, std::size_t i, bool caustic_pass, PixelSeeds& seeds, Visit&& visit,
              VisitMedium&& visit_medium = {}) const
    {
        if (emitters.empty() || !(total_power > T(0))) return;
        // Photon i's numbers: sample i of the map's sampler, Sampler(kind, seed, caustic_pass,
        // i), its seeds kept in `seeds` (photon indices stay below 2^32: check_photon_passes),
        // then the photon's own PCG stream.
        Random rng(Sampler(config_.sampler, seeds, static_cast<std::uint32_t>(i)), Pcg32(config_.seed, 2 * i + (caustic_pass ? 1 : 0)));
        auto [u, v] = rng.uniform2<double>();
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
        const EmittedPhoton<T> photon =
            scene_.visit_light(e->light, [&](const auto& light) { return prism::emit_photon(light, aim(*e), T(u), T(v), rng); });
        // Where two targets' cones overlap, a direction is the first target's to carry:
        // counted by both, the light sent that way would be counted twice.
        if (e->aimed && aimed_at_earlier_target(emitters, *e, photon.ray)) return;
        // A light without falloff: the power a photon stores grows with its path squared.
        const bool without_falloff = photon.without_falloff;
        const auto stored = [&](const auto& at) { return without_falloff ? at.power * (at.travelled * at.travelled) : at.power; };
        random_walk(scene_, air_, bands_, photon.ray, e->power / T(double(count) * p) * photon.weight, rng,
                    WalkLimits{.max_bounces = config_.max_bounces, .max_medium_bounces = config_.max_medium_bounces, .max_length = config_.max_length},
                    WalkHooks{.on_surface = [&]<class M>(const M& material, const WalkVertex<T>& at) { return visit(material, at, stored(at)); },
                              .on_medium = [&]<class Md>(const Md& medium, const WalkMediumVertex<T>& at) { return visit_medium(medium, at, stored(at)); }});
    }

    /// Store photon i: in the caustic pass only L S+ D, going on past it only by delta lobes.
    void store(const std::vector<Emitter<T>>& emitters, T total_power, std::size_t count, std::size_t i, bool caustic_pass, PixelSeeds& seeds,
               std::vector<Photon>& out) const
    {
        emit(emitters, total_power, count, i, caustic_pass, seeds, [&]<class M>(const M& material, const WalkVertex<T>& at, const Rgb<T>& power) {
            (void)material;
            const Crossing<T>& c = at.crossing();
            // Frosted glass holds no photons (no estimate reads them there: a camera or
            // gather ray goes through it by its lobe), and light through it on to a surface
            // is a caustic, as through clear glass.
            if constexpr (has_glossy<M> && transmits<M>) return caustic_pass && !at.caustic_path() ? Lobes::none : Lobes::all;
            if (caustic_pass) {
                if (!at.direct && at.caustic_path()) out.push_back(photon(c, power, at.direction, Photon::caustic | Photon::segments_bits(at.length)));
                // What a diffuse lobe sends on is the global map's; a delta lobe (a coat
                // over the diffuse one) may still send a caustic on, and so may a glossy
                // lobe's delta part (a mix's mirror, a smooth coat), by the lobe's own draw.
                if constexpr (has_glossy<M>) {
                    if (at.caustic_path() && glossy_at(material, c, at.direction, glossy_eta(material, c, at.outside_index)).delta_part()) return Lobes::all;
                }
                return (reflects<M> || transmits<M>) && at.caustic_path() ? Lobes::delta : Lobes::none;
            }
            std::uint8_t flags = std::uint8_t((at.direct ? Photon::direct : 0) | Photon::segments_bits(at.length));
            if (!at.direct && at.caustic_path()) flags |= Photon::caustic;
            out.push_back(photon(c, power, at.direction, flags));
            if (at.direct && config_.shadow_photons) store_shadow_photons(c, at.direction, out);
            return Lobes::all;
        }, [&](const auto&, const WalkMediumVertex<T>& at, const Rgb<T>& power) {
            // Where a photon scatters in a medium: a volume photon (split from the surface
            // ones afterwards). A volumetric caustic (L {S | frosted}+ M) is the caustic
            // pass's, and its walk ends there; every other path's the global pass's.
            const bool caustic = !at.direct && at.caustic_path();
            if (caustic != caustic_pass) return !caustic_pass;
            const Vec3<float> travelling(at.direction);
            out.push_back({Vec3<float>(at.point), Rgb<float>(power), -travelling, -travelling,
                           std::uint8_t(Photon::volume | (caustic ? Photon::caustic : 0) | (at.direct ? Photon::direct : 0) | Photon::segments_bits(at.length))});
            return !caustic_pass;
        });
    }

    /// The photon stored where `travelling` met the surface of crossing c.
    [[nodiscard]] static Photon photon(const Crossing<T>& c, const Rgb<T>& power, const Vec3<T>& travelling, std::uint8_t flags) noexcept
    {
        return {Vec3<float>(c.point), Rgb<float>(power), Vec3<float>(-travelling), Vec3<float>(c.facing_normal()), flags};
    }

    /// Shadow photons along the straight line on from a direct photon's first hit.
    void store_shadow_photons(const Crossing<T>& first, const Vec3<T>& d, std::vector<Photon>& out) const
    {
        Ray<T> through = spawn_ray(first.point, first.error, first.normal, d);
        for (int surfaces = 0; surfaces < 8; ++surfaces) {
            const auto hit = scene_.closest_hit(through, {T(0), infinity<T>});
            if (!hit) return;
            const Crossing<T>& c = hit->crossing;
            const bool diffuse = scene_.visit_material(*hit, [&]<class M>(const M& material) { return scatters_smoothly(material, c, d); });
            if (diffuse) out.push_back(photon(c, Rgb<T>(T(0)), d, Photon::shadow));
            through = spawn_ray(c.point, c.error, c.normal, d);
        }
    }

    [[nodiscard]] PhotonAim<T> aim(const Emitter<T>& e) const noexcept
    {
        return {e.aimed ? &e.target : nullptr, has_sphere_ ? &scene_sphere_ : nullptr, e.power};
    }

    /// Every light aimed at `target` (or everywhere when not `aimed`), where it sends any power.
    void add_emitters(std::vector<Emitter<T>>& emitters, bool aimed, const BoundingSphere<T>& target)
    {
        for (std::size_t i = 0; i < SceneT::light_count; ++i) {
            Emitter<T> e{i, aimed, target, {}};
            e.power = scene_.visit_light(i, [&](const auto& light) { return light.photon_power(aim(e)); });
            if (max_component(e.power) > T(0)) emitters.push_back(e);
        }
    }

    /// Whether a photon of emitter e leaving along `ray` also heads for the target of an
    /// earlier emitter of the same light (its ray meets that target's sphere).
    [[nodiscard]] static bool aimed_at_earlier_target(const std::vector<Emitter<T>>& emitters, const Emitter<T>& e, const Ray<T>& ray) noexcept
    {
        const Vec3<T> d = normalize(ray.direction);
        for (const Emitter<T>& other : emitters) {
            if (&other == &e) return false;
            if (!other.aimed || other.light != e.light) continue;
            const Vec3<T> oc = other.target.center - ray.origin;
            const T along = dot(oc, d), off2 = length_squared(oc) - along * along, r2 = other.target.radius * other.target.radius;
            if (off2 <= r2 && (along > T(0) || length_squared(oc) <= r2)) return true;
        }
        return false;
    }

    /// Drop the targets whose sphere lies inside another target's (an object nested in a
    /// glass): every photon aimed at them would be the outer target's to carry.
    static void drop_nested_targets(std::vector<Emitter<T>>& targets)
    {
        std::vector<Emitter<T>> kept;
        for (std::size_t i = 0; i < targets.size(); ++i) {
            const BoundingSphere<T>& a = targets[i].target;
            bool nested = false;
            for (std::size_t j = 0; j < targets.size() && !nested; ++j) {
                if (j == i || targets[j].light != targets[i].light) continue;
                const BoundingSphere<T>& b = targets[j].target;
                const bool inside = length(a.center - b.center) + a.radius <= b.radius;
                const bool same = a.center == b.center && a.radius == b.radius;
                nested = inside && (!same || j < i); // of two equal spheres, keep the first
            }
            if (!nested) kept.push_back(targets[i]);
        }
        targets = std::move(kept);
    }

    const SceneT& scene_;
    PhotonTracerConfig config_;
    SpectralBands<T> bands_; ///< for photons meeting a dispersive interface
    Air air_;                ///< the scene's air: photons in it curve in GradedAir
    BoundingSphere<T> scene_sphere_{}; ///< around everything bounded (when anything is)
    bool has_sphere_ = false;           ///< whether anything is
    std::vector<Emitter<T>> global_;  ///< every light aimed everywhere, for the global map
    T global_power_ = T(0);
    std::vector<Emitter<T>> targets_; ///< every light aimed at each object that may scatter by a delta lobe: the caustic map's and a light tracer's
    T target_power_ = T(0);
};

/// Run `trace(first, last, out)` over [0, count) in fixed blocks on worker threads and
/// concatenate the blocks in order: the result does not depend on the thread count.
/// Each worker appends to a vector of its own (no allocation per block: many threads
/// allocating and first touching large blocks at once wait on each other in the
/// kernel) and notes where each of its blocks lies.
template <class Trace>
std::vector<Photon> trace_in_fixed_blocks(std::size_t count, unsigned threads, Trace&& trace)
{
    constexpr std::size_t block = 4096;
    const std::size_t blocks = (count + block - 1) / block;
    struct Part {
        unsigned worker = 0;
        std::size_t begin = 0, end = 0;
    };
    std::vector<Part> parts(blocks);
    std::vector<std::vector<Photon>> local(workers_for(blocks, threads));
    parallel_blocks(blocks, threads, [&](std::size_t b, unsigned worker) {
        std::vector<Photon>& out = local[worker];
        const std::size_t begin = out.size();
        trace(b * block, std::min(count, (b + 1) * block), out);
        parts[b] = {worker, begin, out.size()};
    });
    std::size_t total = 0;
    for (const Part& part : parts) total += part.end - part.begin;
    std::vector<Photon> all;
    all.reserve(total);
    for (const Part& part : parts) {
        const auto first = local[part.worker].begin();
        all.insert(all.end(), first + std::ptrdiff_t(part.begin), first + std::ptrdiff_t(part.end));
    }
    return all;
}

} // namespace detail

namespace detail {

[[nodiscard]] inline allocation_error photons_out_of_memory(const PhotonTracerConfig& config)
{
    return allocation_error("prism: tracing " + std::to_string(config.global_photons) + " global and " + std::to_string(config.caustic_photons) +
                            " caustic photons ran out of memory (each stored photon takes " + std::to_string(sizeof(Photon)) +
                            " bytes, and a photon may be stored at every diffuse bounce)");
}

} // namespace detail

/// The photons one process of `parts` traces of a pass (a distributed trace's share):
/// of each map, photon indices [count part / parts, count (part + 1) / parts) of pass
/// `pass`, in index order and not yet in a tree. Each photon's Sobol point and random
/// stream come from its index, so the shares of parts 0 to parts - 1, put end to end,
/// are the photons trace_photons finds, bit for bit.
struct PhotonShare {
    std::vector<Photon> global;  ///< this share of the global map's photons
    std::vector<Photon> caustic; ///< this share of the caustic map's photons
    std::vector<Photon> volume;  ///< this share of the volume map's photons (the global pass's, then the caustic pass's)
};

namespace detail {

/// Move the volume photons of `surface` (in order) to the end of `volume`.
inline void split_volume_photons(std::vector<Photon>& surface, std::vector<Photon>& volume)
{
    std::size_t kept = 0;
    for (const Photon& photon : surface) {
        if ((photon.flags & Photon::volume) != 0) volume.push_back(photon);
        else surface[kept++] = photon;
    }
    surface.resize(kept);
}

} // namespace detail

/// Throws std::invalid_argument when passes 0 to `passes` - 1 of `config`'s photons would
/// reach past photon index 2^32 (photon indices are Sobol indices, 32 bits), naming the
/// first pass that does: a render of many passes checks its last before it traces its first.
inline void check_photon_passes(const PhotonTracerConfig& config, std::uint64_t passes)
{
    for (const std::size_t count : {config.global_photons, config.caustic_photons})
        if (count > 0 && passes > 0 && passes - 1 >= (std::uint64_t(1) << 32) / count)
            detail::throw_invalid("trace_photons pass ", (std::uint64_t(1) << 32) / count, " of ", count,
                                  " photons reaches past photon index 2^32 (the Sobol sequence's length): at most ", (std::uint64_t(1) << 32) / count,
                                  " passes of this many photons, asked for ", passes);
}

template <class SceneT, class Air = StraightAir>
[[nodiscard]] PhotonShare trace_photon_share(const SceneT& scene, const PhotonTracerConfig& config, const Air& air, std::size_t pass, std::size_t part,
                                             std::size_t parts)
{
    if (parts < 1 || parts >= (std::size_t(1) << 31) || part >= parts)
        detail::throw_invalid("trace_photon_share part ", part, " of ", parts, ": expected 0 <= part < parts < 2^31");
    const detail::PhotonTracer<SceneT, Air> tracer(scene, config, air);
    check_photon_passes(config, pass + 1);
    // floor(count k / parts) without overflow (parts < 2^31): with count = q parts + r,
    // it is q k + floor(r k / parts).
    const auto share_first = [&](std::size_t count, std::size_t k) { return count / parts * k + count % parts * k / parts; };
    PhotonShare share;
    try {
        for (const bool caustic : {false, true}) {
            const std::size_t count = caustic ? config.caustic_photons : config.global_photons;
            const std::size_t first = pass * count + share_first(count, part), last = pass * count + share_first(count, part + 1);
            (caustic ? share.caustic : share.global) =
                detail::trace_in_fixed_blocks(last - first, config.threads, [&](std::size_t a, std::size_t b, std::vector<Photon>& out) {
                    if (caustic) tracer.trace_caustic(first + a, first + b, out);
                    else tracer.trace_global(first + a, first + b, out);
                });
        }
        if constexpr (SceneT::has_scattering_media || air_scatters<Air>) {
            detail::split_volume_photons(share.global, share.volume);
            detail::split_volume_photons(share.caustic, share.volume);
        }
    } catch (const std::bad_alloc&) {
        throw detail::photons_out_of_memory(config);
    }
    return share;
}

/// Trace the global and caustic photon maps of a scene, from its lights: photons
/// [pass N, (pass + 1) N) of each map's sequence, N its count in `config`. Pass 0 is the
/// maps; every pass is an independent set of the same size and power (progressive photon
/// mapping's), since each photon's Sobol point and random stream come from its index.
/// The trees are built on config.threads threads, the same for any count.
template <class SceneT, class Air = StraightAir>
[[nodiscard]] PhotonMaps trace_photons(const SceneT& scene, const PhotonTracerConfig& config = {}, const Air& air = {}, std::size_t pass = 0)
{
    PhotonShare all = trace_photon_share(scene, config, air, pass, 0, 1);
    PhotonMaps maps;
    try {
        maps.global = PhotonMap(std::move(all.global), config.threads);
        maps.caustic = PhotonMap(std::move(all.caustic), config.threads);
        if (!all.volume.empty()) maps.volume = PhotonMap(std::move(all.volume), config.threads);
    } catch (const std::bad_alloc&) {
        throw detail::photons_out_of_memory(config);
    }
    return maps;
}

} // namespace prism
