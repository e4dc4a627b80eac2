// SPDX-License-Identifier: MIT
// AreaLights: a scene's emitting objects, seen by its integrators as one more Light.
//
// An object whose material emits (material/emissive.hpp) is an area light. The scene
// keeps, when it is built, a table of its emitting objects by power (pi L A, twice that
// when two-sided) and, per emitting slot, the surfaces points are drawn on (a mesh's
// triangles by area: MeshSurface). A shading point asks for one sample: an emitter by
// its power, in O(1) (an alias table), then a point of it as the shape draws it seen
// from there (a sphere by its cone of directions, a rectangle by its spherical
// rectangle, the rest by area), with its density per steradian for multiple importance
// sampling, which pdf() gives back for a point a ray found. Photons leave an emitter
// chosen by power from a point uniform over its area, cosine-distributed; aimed at a
// specular object (for the caustic map), uniform over the cone toward it from that point,
// weighted by what the light sends that way.
#pragma once

#include <prism/core/dispatch.hpp>
#include <prism/core/distribution.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>
#include <prism/geometry/shape.hpp>
#include <prism/geometry/surface_point.hpp>
#include <prism/light/light.hpp>
#include <prism/material/bsdf.hpp>
#include <prism/material/texture.hpp>
#include <prism/material/traits.hpp>
#include <prism/scene/hit.hpp>
#include <prism/scene/object.hpp>
#include <prism/scene/object_key.hpp>

#include <tuple>
#include <type_traits>
#include <vector>

namespace prism {

namespace detail {

/// What points are drawn on when a shape of type S emits.
template <class S>
using surface_t = std::remove_cvref_t<decltype(surface_of(std::declval<const S&>()))>;

/// Whether a slot's objects emit.
template <class SlotT>
inline constexpr bool slot_emits = emits<typename SlotT::material_type>;

/// A slot's emitters: the surface of each object and its chance of being picked (empty for
/// a slot that does not emit).
template <class SlotT, bool = slot_emits<SlotT>>
struct SlotEmitters {};

template <class SlotT>
struct SlotEmitters<SlotT, true> {
    static_assert(AreaSampled<surface_t<typename SlotT::shape_type>>,
                  "an emitting material needs a shape with an area to draw light from: a Sphere, Quad, Disk or TriangleMesh");
    static_assert(!reads_coordinates<typename SlotT::material_type>() || HasCoordinates<typename SlotT::shape_type>,
                  "an emitting pattern read by surface coordinates needs a Sphere, Quad or Disk: a mesh's coordinates come only with a ray's crossing");
    std::vector<surface_t<typename SlotT::shape_type>> surfaces; ///< per object of the slot
    std::vector<typename SlotT::scalar_type> probability;       ///< per object: its chance of being picked
};

/// The scene's emitting objects by power.
template <Scalar T>
struct EmitterTable {
    std::vector<ObjectKey> keys;  ///< the emitters, in the order of `pick`
    std::vector<Rgb<T>> powers;   ///< per emitter, pi L A (twice when two-sided)
    AliasTable<T> pick;           ///< by the mean of each power's channels
    Rgb<T> power{T(0)};           ///< all of it
};

/// Where an emitting material is read at a point drawn on its shape: the point, and its
/// surface coordinates where the material reads them.
template <class M, class S, Scalar T>
[[nodiscard]] TexturePoint<T> emission_point(const S& shape, const SurfacePoint<T>& s) noexcept
{
    if constexpr (reads_coordinates<M>()) {
        Crossing<T> c = Crossing<T>::flat(T(0), s.point, Vec3<T>(T(0)), s.normal, true);
        add_coordinates(shape, c);
        return {s.point, c.uv, T(0)};
    } else {
        (void)shape;
        return {s.point, Vec2<T>(T(0)), T(0)};
    }
}

} // namespace detail

/// A scene's area lights as one Light: sampled by power for shading, and emitting
/// photons. Made by Scene::area_lights(); it refers to the scene.
template <class SceneT>
class AreaLights {
public:
    /// The scene's precision.
    using scalar_type = typename SceneT::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;
    /// Not a delta light: drawn point by point.
    static constexpr bool delta = false;

    /// The area lights of `scene`.
    explicit AreaLights(const SceneT& scene) noexcept : scene_(&scene) {}

    /// One point of one emitter, for the shading point p: the emitter by power with u.x
    /// (what is left of it places the point, with u.y). Its estimate is L / pdf where the
    /// front faces p (or the emitter is two-sided), else 0.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p, const Vec2<T>& u) const noexcept { return sample_point(p, u).sample; }

    /// A light sample and the emitter's point it was drawn at.
    struct PointSample {
        LightSample<T> sample; ///< as sample() gives it
        Hit<T> at;             ///< the emitter's point, its outward normal the crossing's (slot and index the emitter's)
    };

    /// sample(p, u), with the point it drew (for a bidirectional estimator's weights).
    [[nodiscard]] PointSample sample_point(const Vec3<T>& p, const Vec2<T>& u) const noexcept
    {
        const auto& table = scene_->emitter_table_;
        if (table.keys.empty()) return {{{T(0), T(0), T(1)}, T(0), Rgb<T>(T(0)), T(1)}, {}};
        const AliasPick<T> pick = table.pick.pick(u.x);
        const detail::ObjectKey key = table.keys[pick.index];
        return dispatch<SceneT::slot_count>(key.slot, [&]<std::size_t I>(Index<I>) -> PointSample {
            if constexpr (SceneT::template slot_emits<I>) {
                const auto& object = scene_->template object_at<I>(key.index);
                const auto& material = object.material;
                const auto& surface = std::get<I>(scene_->slot_emitters_).surfaces[key.index];
                const SurfacePoint<T> s = sample_toward(surface, p, Vec2<T>(pick.rest, u.y));
                Hit<T> at;
                at.crossing = Crossing<T>::flat(T(0), s.point, Vec3<T>(T(0)), s.normal, true);
                at.slot = std::uint32_t(I);
                at.index = key.index;
                Vec3<T> wi = s.point - p;
                const T distance = length(wi);
                wi /= distance;
                const T pdf = s.pdf * pick.probability;
                const bool front = material.two_sided || dot(s.normal, wi) < T(0);
                if (!(pdf > T(0)) || !is_finite(pdf) || !(distance > T(0))) return {{wi, distance, Rgb<T>(T(0)), T(1)}, at};
                if (!front) return {{wi, distance, Rgb<T>(T(0)), pdf}, at};
                using M = std::remove_cvref_t<decltype(material)>;
                return {{wi, distance, material.emitted_radiance(detail::emission_point<M>(object.shape, s)) / pdf, pdf}, at};
            } else {
                return {};
            }
        });
    }

    /// The density per steradian with which sample(from, .) draws the point of `hit` (an
    /// emitter a ray from `from` met): multiple importance sampling's other strategy.
    [[nodiscard]] T pdf(const Hit<T>& hit, const Vec3<T>& from) const noexcept
    {
        return dispatch<SceneT::slot_count>(hit.slot, [&]<std::size_t I>(Index<I>) -> T {
            if constexpr (SceneT::template slot_emits<I>) {
                const auto& emitters = std::get<I>(scene_->slot_emitters_);
                const T q = emitters.probability[hit.index];
                if (!(q > T(0))) return T(0);
                return q * pdf_toward(emitters.surfaces[hit.index], from, hit.crossing.point, hit.crossing.normal);
            } else {
                return T(0);
            }
        });
    }

    /// Everywhere: every emitter's power. Toward a target sphere: the light each emitter
    /// sends into the cone toward it from its own bounding sphere's centre (L A times
    /// that cone's solid angle, at most a hemisphere's per side), an estimate the photons'
    /// weights correct.
    [[nodiscard]] Rgb<T> photon_power(const PhotonAim<T>& aim) const noexcept
    {
        const auto& table = scene_->emitter_table_;
        if (!aim.target) return table.power;
        Rgb<T> sum{T(0)};
        for (std::size_t e = 0; e < table.keys.size(); ++e) {
            const detail::ObjectKey key = table.keys[e];
            dispatch<SceneT::slot_count>(key.slot, [&]<std::size_t I>(Index<I>) {
                if constexpr (SceneT::template slot_emits<I>) {
                    const auto& object = scene_->template object_at<I>(key.index);
                    const T sides = object.material.two_sided ? T(2) : T(1);
                    const T omega = std::min(ConeToward<T>::of(bounding_sphere(object.shape).center, *aim.target).solid_angle(), T(2) * pi<T> * sides);
                    sum += table.powers[e] / (pi<T> * sides) * omega; // L A omega
                }
            });
        }
        return sum;
    }

    /// A photon: an emitter by power with u (what is left of u, with v, places it uniformly
    /// over its area), leaving cosine-distributed about its normal (either side of a
    /// two-sided one), or, aimed at a target, uniform over the cone toward it, weighted by
    /// L cos A solid angle / (chance of the emitter * aim.power). `rng` gives the direction.
    [[nodiscard]] EmittedPhoton<T> emit_photon(const PhotonAim<T>& aim, T u, T v, Random& rng) const noexcept
    {
        const auto& table = scene_->emitter_table_;
        if (table.keys.empty()) return {{Vec3<T>(T(0)), Vec3<T>(T(0), T(0), T(1))}, Rgb<T>(T(0))};
        const AliasPick<T> pick = table.pick.pick(u);
        const detail::ObjectKey key = table.keys[pick.index];
        return dispatch<SceneT::slot_count>(key.slot, [&]<std::size_t I>(Index<I>) -> EmittedPhoton<T> {
            if constexpr (SceneT::template slot_emits<I>) {
                const auto& object = scene_->template object_at<I>(key.index);
                const auto& surface = std::get<I>(scene_->slot_emitters_).surfaces[key.index];
                const SurfacePoint<T> s = surface.sample_area(Vec2<T>(pick.rest, v));
                const bool two_sided = object.material.two_sided;
                // The point's rounding: a few operations on coordinates of the emitter's size.
                const BoundingSphere<T> own = bounding_sphere(object.shape);
                const Vec3<T> error = Vec3<T>(gamma<T>(32) * (max_component(abs(s.point)) + own.radius));
                if (!aim.target) {
                    Vec3<T> n = s.normal;
                    if (two_sided && rng.uniform<T>() < T(0.5)) n = -n;
                    const Vec3<T> w = cosine_hemisphere(n, rng);
                    // power_e / (q_e power): 1 where the table's weights are the powers' own.
                    // Where the radiance varies, the point's own: pi L(x) A / (q_e power),
                    // whose mean over the area is the emitter's power however its mean
                    // radiance was estimated.
                    using M = std::remove_cvref_t<decltype(object.material)>;
                    if constexpr (emission_varies<M>()) {
                        const T sides = two_sided ? T(2) : T(1);
                        const Rgb<T> radiance = object.material.emitted_radiance(detail::emission_point<M>(object.shape, s));
                        return {spawn_ray(s.point, error, s.normal, w), safe(radiance * (pi<T> * surface.area() * sides / pick.probability) / table.power)};
                    }
                    const Rgb<T> weight = table.powers[pick.index] / (pick.probability * table.power);
                    return {spawn_ray(s.point, error, s.normal, w), safe(weight)};
                }
                // Uniform over the cone toward the target from this point (every direction
                // from inside it), weighted by the radiance the emitter sends along it.
                const ConeToward<T> cone = ConeToward<T>::of(s.point, *aim.target);
                const T omega = cone.solid_angle();
                const auto [u1, u2] = rng.uniform2<T>();
                const Vec3<T> w = cone.cos_half_angle <= T(-1) ? uniform_sphere(u1, u2) : uniform_cone(cone.axis, cone.cos_half_angle, u1, u2);
                const T cos = dot(w, s.normal);
                const T emitting = two_sided ? std::abs(cos) : std::max(cos, T(0));
                using M = std::remove_cvref_t<decltype(object.material)>;
                const Rgb<T> weight = object.material.emitted_radiance(detail::emission_point<M>(object.shape, s)) * (emitting * omega / (s.pdf * pick.probability)) / aim.power;
                return {spawn_ray(s.point, error, s.normal, w), safe(weight)};
            } else {
                return {};
            }
        });
    }

    /// A ray of the area lights' emission (their photons' distribution, everywhere): an
    /// emitter by power with u_pick, a point uniform over its area (u_position), a direction
    /// cosine-distributed about its normal (u_direction; either side of a two-sided one,
    /// chosen by u_pick's remainder), with the point as a Hit (for pdf() and emission_pdf()).
    struct Emitted {
        EmissionSample<T> emission; ///< the ray and its densities
        Hit<T> at;            ///< where it leaves, the emitter's outward normal as the crossing's (nothing when there is no emitter: a zero pdf_area)
    };

    /// See Emitted.
    [[nodiscard]] Emitted emission(T u_pick, const Vec2<T>& u_position, const Vec2<T>& u_direction) const noexcept
    {
        const auto& table = scene_->emitter_table_;
        if (table.keys.empty()) return {};
        const AliasPick<T> pick = table.pick.pick(u_pick);
        const detail::ObjectKey key = table.keys[pick.index];
        return dispatch<SceneT::slot_count>(key.slot, [&]<std::size_t I>(Index<I>) -> Emitted {
            if constexpr (SceneT::template slot_emits<I>) {
                const auto& object = scene_->template object_at<I>(key.index);
                const auto& surface = std::get<I>(scene_->slot_emitters_).surfaces[key.index];
                const SurfacePoint<T> s = surface.sample_area(u_position);
                const BoundingSphere<T> own = bounding_sphere(object.shape);
                const Vec3<T> error = Vec3<T>(gamma<T>(32) * (max_component(abs(s.point)) + own.radius));
                const bool two_sided = object.material.two_sided;
                const bool back = two_sided && pick.rest < T(0.5);
                const Vec3<T> n = back ? -s.normal : s.normal;
                const Vec3<T> w = LocalFrame<T>::about(n).to_world(cosine_direction(u_direction.x, u_direction.y));
                const T cos = dot(w, n);
                using M = std::remove_cvref_t<decltype(object.material)>;
                Emitted out;
                out.emission = {spawn_ray(s.point, error, s.normal, w), object.material.emitted_radiance(detail::emission_point<M>(object.shape, s)),
                                pick.probability / surface.area(), cos / pi<T> * (two_sided ? T(0.5) : T(1)), cos};
                out.at.crossing = Crossing<T>::flat(T(0), s.point, error, s.normal, true);
                out.at.slot = std::uint32_t(I);
                out.at.index = key.index;
                return out;
            } else {
                return {};
            }
        });
    }

    /// The densities emission() draws a ray leaving `at` (an emitter's point, its outward
    /// normal the crossing's) along the unit direction `leaving` with.
    [[nodiscard]] EmissionPdf<T> emission_pdf(const Hit<T>& at, const Vec3<T>& leaving) const noexcept
    {
        return dispatch<SceneT::slot_count>(at.slot, [&]<std::size_t I>(Index<I>) -> EmissionPdf<T> {
            if constexpr (SceneT::template slot_emits<I>) {
                const auto& emitters = std::get<I>(scene_->slot_emitters_);
                const bool two_sided = scene_->template object_at<I>(at.index).material.two_sided;
                const T cos = dot(leaving, at.crossing.normal);
                const T emitting = two_sided ? std::abs(cos) * T(0.5) : std::max(cos, T(0));
                return {emitters.probability[at.index] / emitters.surfaces[at.index].area(), emitting / pi<T>};
            } else {
                return {};
            }
        });
    }

    /// Nothing to check: the objects checked their materials.
    constexpr void validate() const noexcept {}

private:
    /// 0 where a channel's ratio is not finite (a channel with no power at all).
    [[nodiscard]] static Rgb<T> safe(Rgb<T> w) noexcept
    {
        for (int c = 0; c < 3; ++c)
            if (!is_finite(w[c])) w[c] = T(0);
        return w;
    }

    const SceneT* scene_;
};

} // namespace prism
