// SPDX-License-Identifier: MIT
// random_walk: the path a photon takes through a scene, shared by the photon tracer, the
// light tracer and the path tracer (a camera path carries importance by the same rules).
//
// From a ray carrying `power`, step by step (transport/walk_step.hpp: the media on the
// way attenuate it or scatter it, false and index-matched interfaces are passed, in the
// air it follows the air's curve, inside objects straight lines): at a diffuse or glossy
// surface the caller's `on_surface` sees the vertex (and may stop the walk); a white path
// meeting a dispersive interface takes one wavelength band at random; then scatter_photon
// picks the next direction (material/scattering.hpp): a photon by Russian roulette at
// every bounce, which keeps its power bounded; a camera path by its lobes alone, ended by
// roulette on its throughput once it has met WalkLimits::roulette_depth surfaces, so a
// path on its way to a bright, hard-to-find light (a caustic) is not cut short by the dim
// surfaces it left. Where it scatters in a medium (an object's Fog, or FilledAir) the
// caller's `on_medium` sees the vertex, and the walk goes on in a direction drawn from
// the medium's phase function.
#pragma once

#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/air.hpp>
#include <prism/medium/nesting.hpp>
#include <prism/medium/phase.hpp>
#include <prism/scene/hit.hpp>
#include <prism/spectrum/bands.hpp>
#include <prism/transport/walk_step.hpp>

#include <algorithm>
#include <concepts>
#include <limits>
#include <optional>
#include <type_traits>

namespace prism {

/// A walk at a surface with a non-delta lobe (diffuse, or glossy and not a mirror),
/// before it scatters there.
template <Scalar T>
struct WalkVertex {
    const Hit<T>& hit; ///< the surface the walk met
    const Vec3<T>& direction; ///< unit, arriving
    const Rgb<T>& power;      ///< what the path carries here, after the medium it crossed
    bool direct;              ///< nothing scattered it yet (a photon's first hit)
    int diffuse_bounces;      ///< non-delta (diffuse or glossy) scatterings so far (0: every scattering so far was specular)
    bool first_specular;      ///< the first scattering was specular (the vertex next to the path's start: L S ...)
    T travelled;              ///< the path's length so far
    T wavelength;             ///< 0 while white
    const MediumStack& media; ///< the transmissive objects the path is inside of
    const Vec3<T>& last_point; ///< where the path last scattered (or started)
    T last_pdf;               ///< the solid-angle density of the last scattering's non-delta lobe (a diffuse one's cos / pi); 0 after a delta one or at the start
    bool last;                ///< the walk ends after this surface (its depth limit): nothing it scatters is followed
    Random& rng;               ///< the walk's stream, for a caller that draws at the vertex (a thin lens's point)
    T outside_index;          ///< the index of refraction on a transmissive material's outer side (1 for others; glossy_eta)
    int surface_bounces;      ///< the non-delta scatterings other than through frosted glass (a glossy interface)
    int length;               ///< segments from the walk's start to here: the vertices so far, this one included (surfaces and media alike)

    /// Where the walk met the surface, with its normal and side.
    [[nodiscard]] const Crossing<T>& crossing() const noexcept { return hit.crossing; }
    /// Whether every scattering so far was specular.
    [[nodiscard]] bool specular_only() const noexcept { return diffuse_bounces == 0; }
    /// Whether every scattering so far was specular or through frosted glass: the path
    /// of a caustic, L {S | frosted}+ (the photon maps' classification).
    [[nodiscard]] bool caustic_path() const noexcept { return surface_bounces == 0; }
};

/// A walk leaving the scene: the segment it left along, and what it carries.
template <Scalar T>
struct WalkEscape {
    const Ray<T>& ray;        ///< the segment that left the scene, its direction the way it went
    const Rgb<T>& power;      ///< what the path carries
    int diffuse_bounces;      ///< non-delta (diffuse or glossy) scatterings on the way (0: every scattering was specular)
    bool first_specular;      ///< the first scattering was specular (the vertex next to the path's start)
    T last_pdf;               ///< as WalkVertex's: the last scattering's diffuse density, 0 after a delta one

    /// Whether every scattering on the way was specular.
    [[nodiscard]] bool specular_only() const noexcept { return diffuse_bounces == 0; }
};

/// A walk where it scatters in a medium, before it scatters there.
template <Scalar T>
struct WalkMediumVertex {
    const Vec3<T>& point;     ///< where it scatters
    const Vec3<T>& direction; ///< unit, arriving
    const Rgb<T>& power;      ///< what the path carries here, the medium's scattering coefficient and the draw's weight taken
    bool direct;              ///< nothing scattered it yet
    int diffuse_bounces;      ///< non-delta scatterings so far, at surfaces or in media
    bool first_specular;      ///< the first scattering was specular
    T travelled;              ///< the path's length so far
    T wavelength;             ///< 0 while white
    const MediumStack& media; ///< the transmissive objects the path is inside of
    const Vec3<T>& last_point; ///< where the path last scattered (or started)
    T last_pdf;               ///< as WalkVertex's
    bool last;                ///< the walk ends after this vertex (its depth limit)
    Random& rng;               ///< the walk's stream
    int surface_bounces;      ///< as WalkVertex's: non-delta scatterings but through frosted glass
    const Ray<T>& stretch;    ///< the stretch of medium the flight was drawn over: from where it starts, unit direction
    T stretch_length;         ///< its length (may be infinite)
    const Rgb<T>& entering;   ///< what the path carried as it entered the stretch (the flight's draw was weighed by it)
    int length;               ///< segments from the walk's start to here, as WalkVertex's

    /// Whether every scattering so far was specular.
    [[nodiscard]] bool specular_only() const noexcept { return diffuse_bounces == 0; }
    /// Whether every scattering so far was specular or through frosted glass (a
    /// volumetric caustic's path when one came before: L {S | frosted}+ M).
    [[nodiscard]] bool caustic_path() const noexcept { return surface_bounces == 0; }
};

/// A walk entering a stretch of a medium that scatters, before its flight there is drawn:
/// shown to a caller's on_medium that takes it (the path tracer's equiangular samples).
template <Scalar T>
struct WalkMediumStretch {
    const Ray<T>& ray;        ///< from where the stretch starts, unit direction
    T length;                 ///< its length (may be infinite)
    const Rgb<T>& power;      ///< what the path carries entering it
    int diffuse_bounces;      ///< non-delta scatterings so far
    const MediumStack& media; ///< the transmissive objects the path is inside of
    Random& rng;               ///< the walk's stream
    int vertices;             ///< the vertices so far (the stretch starts at the last, or at the walk's start): segments to its start
};

/// What a walk does where it scatters in a medium when its caller says nothing: it goes on.
struct IgnoreMedia {
    /// Goes on (whatever it is shown: the medium, the vertex, a photon's power).
    template <class... Seen>
    constexpr bool operator()(const Seen&...) const noexcept
    {
        return true;
    }
};

/// What a walk does where it leaves the scene when its caller says nothing: nothing.
struct IgnoreEscape {
    /// Does nothing.
    template <class E>
    constexpr void operator()(const E&) const noexcept
    {
    }
};

/// What a walk does where it meets an emitting surface when its caller says nothing: nothing.
struct IgnoreEmitters {
    /// Does nothing.
    template <class M, class V>
    constexpr void operator()(const M&, const V&) const noexcept
    {
    }
};

/// What a walk calls where things happen to it, by name (each but on_surface may be left
/// out): `WalkHooks{.on_surface = ..., .on_escape = ...}`.
///   on_surface(material, WalkVertex)   at every surface with a non-delta lobe (diffuse, or
///                                      glossy and not a mirror: scatters_smoothly), before the
///                                      walk scatters there; returns the lobes it may scatter by
///                                      (Lobes; or true for all, false to end the walk)
///   on_escape(WalkEscape)              where the path leaves the scene
///   on_emitter(material, WalkVertex)   where it meets a surface that emits (an area light;
///                                      it scatters there only by the lobes the material also has)
///   on_medium(medium, WalkMediumVertex) where it scatters in a medium; returns whether the walk
///                                      goes on. A caller whose on_medium also takes
///                                      (medium, WalkMediumStretch) is shown each stretch of a
///                                      medium that scatters before the flight there is drawn.
template <class OnSurface, class OnEscape = IgnoreEscape, class OnEmitter = IgnoreEmitters, class OnMedium = IgnoreMedia>
struct WalkHooks {
    OnSurface on_surface;   ///< at a surface with a non-delta lobe
    OnEscape on_escape{};   ///< where the path leaves the scene
    OnEmitter on_emitter{}; ///< where the path meets an emitting surface
    OnMedium on_medium{};   ///< where the path scatters in a medium
};

/// How far a walk may go.
struct WalkLimits {
    int max_bounces = 256; ///< surfaces past the first the walk may scatter at (it meets at most max_bounces + 1)
    /// Scatterings in media past the first the walk may follow, counted apart from the
    /// surfaces: in dense fog that does not absorb a path scatters hundreds of times
    /// between two surfaces (16 in all lost 7 % of the light of a fog of optical depth 8).
    int max_medium_bounces = 1000;
    /// Surfaces a camera path (Transport::radiance) scatters at before Russian roulette on
    /// its throughput may end it (path_roulette); a photon's roulette is per bounce.
    int roulette_depth = 2;
    /// Segments the walk may take: it reaches at most this many vertices (scatterings at
    /// surfaces and in media alike; an interface it passes is none) and scatters at none
    /// past the one before, so that a camera path's light met at its last vertex, or a
    /// light sample taken at the one before, makes a path of at most max_length segments
    /// (the depth every prism estimator counts: docs/guide.md).
    int max_length = std::numeric_limits<int>::max();
};

/// Walk from `ray` carrying `power` through at most limits.max_bounces + 1 surfaces,
/// limits.max_medium_bounces + 1 scatterings in media and limits.max_length vertices of
/// either kind (whichever comes first), calling `hooks` (WalkHooks) where
/// things happen. `Mode`: whether the path is a photon's or a camera's (scatter_photon); a
/// camera path is ended by path_roulette after limits.roulette_depth surfaces. Scatterings
/// in media count toward their own limit, and toward roulette_depth with the surfaces (a
/// scene or air with no medium never compiles them). `start`: the transmissive objects the
/// ray starts inside (a camera's: Scene::media_at).
template <Transport Mode = Transport::importance, class SceneT, class Air, class Hooks>
void random_walk(const SceneT& scene, const Air& air, const SpectralBands<typename SceneT::scalar_type>& bands, Ray<typename SceneT::scalar_type> ray,
                 Rgb<typename SceneT::scalar_type> power, Random& rng, WalkLimits limits, const Hooks& hooks, MediumStack start = {})
{
    using T = typename SceneT::scalar_type;
    bool direct = true, first_specular = false;
    int diffuse_bounces = 0, surface_bounces = 0;
    T travelled = T(0);
    T wavelength = T(0); // white until a dispersive interface splits it
    MediumStack media = start; // the transmissive objects the path is inside of
    Vec3<T> last_point = ray.origin;
    T last_pdf = T(0);
    int medium_bounces = 0; // of the bounces, those in media
    int length = 0;         // vertices so far, at surfaces and in media
    for (int bounce = 0; bounce - medium_bounces <= limits.max_bounces; ++bounce) {
        rng.bounce(bounce); // each bounce its own block of the sampler's dimensions
        // At a surface: the hooks see it, then the path scatters by the lobes they leave it.
        const auto at_surface = [&]<class M>(const M& material, const SurfaceArrival<T>& at) -> std::optional<Vec3<T>> {
            const Crossing<T>& c = at.hit.crossing;
            const bool last = bounce - medium_bounces == limits.max_bounces || length + 1 >= limits.max_length;
            // The walk at this surface, as the hooks see it (outside_index: 1 until known).
            const auto vertex = [&](T outside_index) {
                return WalkVertex<T>{.hit = at.hit,
                                     .direction = at.direction,
                                     .power = power,
                                     .direct = direct,
                                     .diffuse_bounces = diffuse_bounces,
                                     .first_specular = first_specular,
                                     .travelled = travelled + at.path,
                                     .wavelength = wavelength,
                                     .media = media,
                                     .last_point = last_point,
                                     .last_pdf = last_pdf,
                                     .last = last,
                                     .rng = rng,
                                     .outside_index = outside_index,
                                     .surface_bounces = surface_bounces,
                                     .length = length + 1};
            };
            if constexpr (emits<M>) hooks.on_emitter(material, vertex(T(1)));
            if constexpr (!has_diffuse<M> && !has_glossy<M> && !reflects<M> && !transmits<M>) {
                return std::nullopt; // a lamp that only emits
            } else {
                Lobes lobes = Lobes::all;
                // (A glossy lobe that is a mirror has no vertex of its own.)
                if constexpr (has_diffuse<M> || has_glossy<M>) if (scatters_smoothly(material, c, at.direction)) {
                    const auto go_on = hooks.on_surface(material, vertex(at.outside_index));
                    if constexpr (std::same_as<std::remove_const_t<decltype(go_on)>, bool>) lobes = go_on ? Lobes::all : Lobes::none;
                    else lobes = go_on;
                    if (lobes == Lobes::none) return std::nullopt;
                }
                if constexpr (disperses<M>) {
                    if (wavelength == T(0)) {
                        // One band at random: its (non-negative) share of white, over its probability 1 / count.
                        const int count = bands.size();
                        const WavelengthBand<T>& band = bands[std::min(int(rng.uniform<T>() * T(count)), count - 1)];
                        power *= band.photon_weight * T(count);
                        wavelength = band.wavelength_nm;
                    }
                }
                const auto next = scatter_photon<Mode>(material, c, at.direction, power, rng, wavelength, at.outside_index, lobes);
                if (!next) return std::nullopt;
                if constexpr (Mode == Transport::radiance) {
                    if (bounce >= limits.roulette_depth && !path_roulette(power, rng)) return std::nullopt;
                }
                last_point = c.point;
                if constexpr (has_glossy<M>) last_pdf = next->pdf;
                else last_pdf = next->diffuse ? std::max(dot(next->direction, c.facing_shading()), T(0)) / pi<T> : T(0);
                if (next->diffuse) ++diffuse_bounces;
                if (next->diffuse && !(has_glossy<M> && transmits<M>)) ++surface_bounces;
                if (direct) first_specular = !next->diffuse;
                ++length;
                return next->direction;
            }
        };
        // Where it scatters in a medium: the hooks see it, then a photon plays roulette by
        // the flight's weight (a camera path by its throughput) and the medium's phase
        // function draws the way on.
        const auto in_medium = [&]<class Md>(const Md& medium, const MediumArrival<T>& at) -> std::optional<Vec3<T>> {
            const bool last = medium_bounces == limits.max_medium_bounces || length + 1 >= limits.max_length;
            if (!hooks.on_medium(medium, WalkMediumVertex<T>{.point = at.point,
                                                             .direction = at.direction,
                                                             .power = power,
                                                             .direct = direct,
                                                             .diffuse_bounces = diffuse_bounces,
                                                             .first_specular = first_specular,
                                                             .travelled = travelled + at.path,
                                                             .wavelength = wavelength,
                                                             .media = media,
                                                             .last_point = last_point,
                                                             .last_pdf = last_pdf,
                                                             .last = last,
                                                             .rng = rng,
                                                             .surface_bounces = surface_bounces,
                                                             .stretch = at.stretch,
                                                             .stretch_length = at.stretch_length,
                                                             .entering = at.entering,
                                                             .length = length + 1}))
                return std::nullopt;
            if constexpr (Mode == Transport::importance) {
                // A photon keeps its power: it goes on with the chance of the draw's
                // largest weight (the albedo in a grey medium), divided out.
                const T keep = std::min(T(1), max_component(at.weight));
                if (!(keep > T(0)) || !(rng.uniform<T>() < keep)) return std::nullopt;
                power /= keep;
            } else {
                if (bounce >= limits.roulette_depth && !path_roulette(power, rng)) return std::nullopt;
            }
            const auto [u1, u2] = rng.uniform2<T>();
            const PhaseSample<T> next = medium.phase.sample(at.direction, u1, u2);
            last_point = at.point;
            last_pdf = next.pdf;
            ++diffuse_bounces;
            ++surface_bounces;
            ++length;
            if (direct) first_specular = false;
            return next.direction;
        };
        const Step<T> step = walk_step(scene, air, ray, media, power, rng,
                                       StepHooks{.on_surface = at_surface,
                                                 .on_medium = in_medium,
                                                 .on_escape =
                                                     [&](const Ray<T>& segment) {
                                                         hooks.on_escape(WalkEscape<T>{.ray = segment,
                                                                                       .power = power,
                                                                                       .diffuse_bounces = diffuse_bounces,
                                                                                       .first_specular = first_specular,
                                                                                       .last_pdf = last_pdf});
                                                     },
                                                 .through_matched =
                                                     [&](const Rgb<T>& tint) {
                                                         if constexpr (Mode == Transport::radiance) {
                                                             power *= tint;
                                                             return true;
                                                         } else {
                                                             return russian_roulette(power, tint, rng);
                                                         }
                                                     },
                                                 .at_interface = [&](const auto&) { return wavelength; },
                                                 .on_stretch =
                                                     [&]<class Md>(const Md& medium, const Ray<T>& stretch, T stretch_length) {
                                                         // (A caller's on_medium that takes a stretch is shown it: the path tracer's equiangular samples.)
                                                         if constexpr (std::is_invocable_v<decltype(hooks.on_medium)&, const Md&, const WalkMediumStretch<T>&>)
                                                             hooks.on_medium(medium, WalkMediumStretch<T>{.ray = stretch,
                                                                                                          .length = stretch_length,
                                                                                                          .power = power,
                                                                                                          .diffuse_bounces = diffuse_bounces,
                                                                                                          .media = media,
                                                                                                          .rng = rng,
                                                                                                          .vertices = length});
                                                     }});
        travelled += step.path;
        switch (step.end) {
        case StepEnd::escaped:
        case StepEnd::ended: return;
        case StepEnd::passed: break;
        case StepEnd::medium:
            if (++medium_bounces > limits.max_medium_bounces || length >= limits.max_length) return;
            direct = false;
            break;
        case StepEnd::surface:
            if (length >= limits.max_length) return;
            direct = false;
            break;
        }
    }
}

} // namespace prism
