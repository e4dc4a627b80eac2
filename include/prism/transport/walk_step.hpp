// SPDX-License-Identifier: MIT
// walk_step: one step of a path through a scene, from where it last scattered (or
// started) to where it scatters next. Every walk is a loop of these steps: random_walk's
// (the photon tracer, light tracer and path tracer) and Bidirectional's subpaths; what
// a walk does at a vertex (the hooks) is its own.
//
// A step goes along its ray (in the air along the air's curve, inside objects straight)
// to the first surface. On the way, in a medium that scatters (an object's Fog, or
// FilledAir), it draws where the path scatters, piece by piece of its way (the medium's
// free flight, whose weight the path's power takes), and stops there if it does. At the
// surface, the medium it crossed attenuates the power; a false interface (inside a medium
// of higher priority) and an index-matched one (may_match_index: no bend, so no vertex)
// are passed, the path going on straight in the media beyond. At any other surface, and
// where it scatters in a medium, the caller's hook says the direction the path leaves by
// (it scatters there) or that it ends; a path that refracts goes on in the media beyond.
#pragma once

#include <prism/core/offset.hpp>
#include <prism/core/random.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/air.hpp>
#include <prism/medium/nesting.hpp>
#include <prism/scene/hit.hpp>
#include <prism/transport/media.hpp>
#include <prism/transport/travel.hpp>

#include <cstdint>
#include <optional>
#include <type_traits>
#include <variant>

namespace prism {

/// How a step of a walk ended.
enum class StepEnd : std::uint8_t {
    escaped, ///< it left the scene (the caller's on_escape was shown its last segment)
    passed,  ///< it crossed an interface that makes no vertex: the next step goes on straight
    surface, ///< it scattered at a surface: the next step leaves from there
    medium,  ///< it scattered in a medium: the next step leaves from there
    ended,   ///< it was absorbed, or its caller ended it
};

/// How a step ended, and how far it went.
template <Scalar T>
struct Step {
    StepEnd end; ///< where it ended
    T path; ///< the length of its way, from its start to where it ended (0 where it escaped)
};

/// A step at a surface where the path makes a vertex, before it scatters there.
template <Scalar T>
struct SurfaceArrival {
    const Hit<T>& hit;        ///< the surface
    const Vec3<T>& direction; ///< unit, arriving
    T path;                   ///< the length of the step's way to here
    T outside_index;          ///< the index of refraction on a transmissive material's outer side (1 for others)
};

/// A step where the path scatters in a medium, before it does.
template <Scalar T>
struct MediumArrival {
    const Vec3<T>& point;     ///< where
    const Vec3<T>& direction; ///< unit, arriving
    T path;                   ///< the length of the step's way to here
    const Ray<T>& stretch;    ///< the stretch of medium the flight was drawn over: where it starts, unit direction
    T stretch_length;         ///< its length (may be infinite)
    const Rgb<T>& entering;   ///< the path's power as it entered the stretch
    const Rgb<T>& weight;     ///< the flight's weight, which the power took
    const MediumStack& media; ///< the transmissive objects the path is inside of (the medium is the top one's, or the air's)
};

/// What a step does on a stretch of medium before its flight there is drawn when its
/// caller says nothing: nothing.
struct IgnoreStretch {
    /// Does nothing.
    template <class Md, class R, class L>
    constexpr void operator()(const Md&, const R&, const L&) const noexcept
    {
    }
};

/// What a step calls, by name (on_stretch may be left out):
///   on_surface(material, SurfaceArrival) -> std::optional<Vec3>
///       at a surface that makes a vertex: the unit direction the path leaves by, or
///       nothing to end it
///   on_medium(medium, MediumArrival) -> std::optional<Vec3>
///       where it scatters in a medium: the same
///   on_escape(segment)                 where it leaves the scene, along `segment`
///   through_matched(tint) -> bool      at an index-matched boundary: takes the tint into
///                                      the path's power (or plays roulette by it), and
///                                      says whether the path goes on
///   at_interface(material) -> T        at a real interface of a transmissive material,
///                                      before the index on its outer side is looked up:
///                                      the wavelength the path crosses it at (0: white)
///   on_stretch(medium, stretch, length) on each stretch of a medium that scatters, before
///                                      the flight there is drawn
template <class OnSurface, class OnMedium, class OnEscape, class ThroughMatched, class AtInterface, class OnStretch = IgnoreStretch>
struct StepHooks {
    OnSurface on_surface;           ///< at a surface that makes a vertex
    OnMedium on_medium;             ///< where the path scatters in a medium
    OnEscape on_escape;             ///< where it leaves the scene
    ThroughMatched through_matched; ///< at an index-matched boundary
    AtInterface at_interface;       ///< at a real interface, its wavelength
    OnStretch on_stretch{};         ///< before a flight in a medium
};

/// One step of a walk from `ray` (which it leaves where the next step starts) inside
/// `media` (which it leaves as the media there), the path carrying `power`: see the file's
/// comment. The walk's sampler block (Random::bounce) is the caller's to choose.
template <class SceneT, class Air, class Hooks>
[[nodiscard]] Step<typename SceneT::scalar_type> walk_step(const SceneT& scene, const Air& air, Ray<typename SceneT::scalar_type>& ray, MediumStack& media,
                                                           Rgb<typename SceneT::scalar_type>& power, Random& rng, const Hooks& hooks)
{
    using T = typename SceneT::scalar_type;
    Ray<T> segment = ray;
    T path = T(0);
    std::optional<Hit<T>> hit;
    if constexpr (!SceneT::has_scattering_media && !air_scatters<Air>) {
        hit = media.empty() ? first_hit_in_air(scene, air, ray, segment, &path) : first_hit_in_air(scene, StraightAir{}, ray, segment, &path);
    } else {
        std::optional<Step<T>> scattered; // where the path scattered, or ended, in a medium
        hit = first_hit_through_media(scene, air, media, ray, segment, &path, [&]<class Md>(const Md& medium, const Ray<T>& piece, T t0, T t1, T before) {
            const Ray<T> stretch{piece.at(t0), piece.direction};
            const Rgb<T> entering = power;
            hooks.on_stretch(medium, stretch, t1 - t0);
            const FreeFlight<T> flight = medium.sample_flight(stretch, t1 - t0, power, rng);
            power *= flight.weight;
            if (!flight.scattered) return true;
            const T s = t0 + flight.distance;
            const Vec3<T>& d = piece.direction;
            const Vec3<T> p = piece.origin + s * d;
            const std::optional<Vec3<T>> next = hooks.on_medium(medium, MediumArrival<T>{.point = p,
                                                                                         .direction = d,
                                                                                         .path = before + s,
                                                                                         .stretch = stretch,
                                                                                         .stretch_length = t1 - t0,
                                                                                         .entering = entering,
                                                                                         .weight = flight.weight,
                                                                                         .media = media});
            scattered = Step<T>{next ? StepEnd::medium : StepEnd::ended, before + s};
            if (next) ray = {p, *next};
            return false;
        });
        if (scattered) return *scattered;
    }
    if (!hit) {
        hooks.on_escape(segment);
        return {StepEnd::escaped, T(0)};
    }
    const Crossing<T>& c = hit->crossing;
    const Vec3<T> d = normalize(segment.direction);
    const StepEnd end = scene.visit_material(*hit, [&]<class M>(const M& material) -> StepEnd {
        // What the medium it travelled in let through, before anything else.
        attenuate_segment(scene, media, material, c, segment, power);
        // The media beyond the surface, and false interfaces passed. (Only transmissive
        // materials keep an interface: no copy of the media for the diffuse and mirror
        // hits that make most of a path's vertices.)
        [[maybe_unused]] std::conditional_t<transmits<M>, Interface, std::monostate> face{};
        T outside_index = T(1);
        if constexpr (transmits<M>) {
            face = nested_interface(media, {hit->slot, hit->index, nesting_priority(material)}, c.entering);
            if (!face.real) {
                ray = spawn_ray(c.point, c.error, c.normal, d);
                media = face.beyond;
                return StepEnd::passed;
            }
            outside_index = T(index_of(scene, outside_of(media, face, c.entering), hooks.at_interface(material)));
        }
        if constexpr (may_match_index<M>) {
            // An index-matched boundary is no vertex: the path goes on straight, its tint
            // taken, as a shadow ray passes it (Scene::transmittance).
            if (material.index_matched(outside_index)) {
                if (!hooks.through_matched(material.transmission_tint())) return StepEnd::ended;
                ray = spawn_ray(c.point, c.error, c.normal, d);
                media = face.beyond;
                return StepEnd::passed;
            }
        }
        const std::optional<Vec3<T>> next = hooks.on_surface(material, SurfaceArrival<T>{.hit = *hit, .direction = d, .path = path, .outside_index = outside_index});
        if (!next) return StepEnd::ended;
        if constexpr (transmits<M>) {
            if (dot(*next, c.facing_normal()) < T(0)) media = face.beyond; // refracted
        }
        ray = spawn_ray(c.point, c.error, c.normal, *next);
        return StepEnd::surface;
    });
    return {end, path};
}

} // namespace prism
