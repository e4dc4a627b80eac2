// SPDX-License-Identifier: MIT
// Scene: lights and object slots fixed at compile time; closest-hit and shadow queries.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/interval.hpp>
#include <prism/core/offset.hpp>
#include <prism/light/light.hpp>
#include <prism/optics/beer.hpp>
#include <prism/scene/hit.hpp>
#include <prism/scene/object.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>
#include <utility>

namespace prism {

/// The lights of a scene, each of its own type.
template <Light... Ls>
struct Lights {
    std::tuple<Ls...> items;

    constexpr explicit Lights(Ls... lights) : items(std::move(lights)...)
    {
        std::apply([](const auto&... light) { (light.validate(), ...); }, items);
    }
};

/// A scene: its lights, object slots (one type each), background and ambient radiance.
/// Which shapes and materials exist is part of the type, so integrators compile only
/// the code those materials need.
template <class LightList, Slot... Slots>
class Scene {
    static_assert(sizeof...(Slots) > 0, "a scene needs at least one object");

public:
    using scalar_type = typename std::tuple_element_t<0, std::tuple<Slots...>>::scalar_type;
    using T = scalar_type;
    static_assert((std::same_as<typename Slots::scalar_type, T> && ...), "all objects must share one scalar type");

    /// Some material refracts: the integrator needs refraction and Beer-Lambert code.
    static constexpr bool has_transmissive = (transmits<typename Slots::material_type> || ...);
    /// Some material has a mirror lobe.
    static constexpr bool has_specular = (reflects<typename Slots::material_type> || ...) || has_transmissive;
    static constexpr std::size_t slot_count = sizeof...(Slots);

    // Scene Public Members

    LightList lights;
    std::tuple<Slots...> slots;
    Rgb<T> background{T(0)}; ///< radiance of rays that hit nothing
    Rgb<T> ambient{T(0)};    ///< the notes' ambient term, added where every light is occluded

    constexpr Scene(LightList light_list, Slots... objects) : lights(std::move(light_list)), slots(std::move(objects)...)
    {
        // One box around every bounded object: a ray that misses it skips them all.
        std::apply([this](const auto&... slot) { (add_to_cluster(slot), ...); }, slots);
        bounded_objects_ = !cluster_.empty();
    }

    constexpr void validate() const
    {
        detail::require_non_negative("Scene background", background);
        detail::require_non_negative("Scene ambient", ambient);
    }

    // Scene Queries

    /// The closest crossing with t inside `range`. Every object is asked for its
    /// crossings without their surfaces; only the nearest one is then asked again, over
    /// the same range, for its surface.
    [[nodiscard]] std::optional<Hit<T>> closest_hit(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        Nearest nearest{};
        const bool near_cluster = reaches_cluster(ray, range);
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (nearest_in_slot<I>(ray, range, nearest, near_cluster), ...);
        }(std::index_sequence_for<Slots...>{});
        if (!nearest.found) return std::nullopt;
        return surface_in_slot<0>(ray, nearest);
    }

    /// Fraction of light passing along the ray from t = 0 to t_max: 0 when an opaque
    /// object is in the way, otherwise Beer-Lambert absorption (times kt per boundary)
    /// through every dielectric crossed, refraction ignored (the lecture notes' shadow
    /// rays through transparent objects). With GlassTransmits = false dielectrics block
    /// the ray like any other object: a photon mapper brings the light through them by
    /// its caustic map instead (as POV-Ray does for photon targets).
    template <bool GlassTransmits = true>
    [[nodiscard]] Rgb<T> transmittance(const Ray<T>& ray, T t_max) const noexcept
    {
        Rgb<T> tr{T(1)};
        // Unwidened: a shadow ray needs no spurious crossing a far-off shape might report
        // (culling it can only let light through where rounding alone would block it).
        const bool near_cluster = bounded_objects_ && (cluster_.contains(ray.origin) || !cluster_.clip(ray, {T(0), t_max}).empty());
        const bool open = [&]<std::size_t... I>(std::index_sequence<I...>) {
            return (transmittance_of_slot<I, GlassTransmits>(ray, t_max, tr, near_cluster) && ...);
        }(std::index_sequence_for<Slots...>{});
        return open ? tr : Rgb<T>{T(0)};
    }

    /// Call f(material) with the material of the hit object, with its static type.
    template <class F>
    decltype(auto) visit_material(const Hit<T>& hit, F&& f) const
    {
        return visit_slot<0>(hit, std::forward<F>(f));
    }

    /// Call f(light) for every light.
    template <class F>
    void for_each_light(F&& f) const
    {
        std::apply([&](const auto&... light) { (f(light), ...); }, lights.items);
    }

private:
    Aabb<T> cluster_{}; ///< around every bounded object (empty when there are none)
    bool bounded_objects_ = false;

    // Scene Private Methods

    /// The nearest object so far: where its first crossing is, and the range over
    /// which it was found.
    struct Nearest {
        bool found = false;
        std::uint32_t slot = 0, index = 0;
        Interval<T> range{};
    };

    template <class S>
    void add_to_cluster(const S& slot) noexcept
    {
        for (const auto& object : objects_of(slot))
            if (object.bounded) cluster_ = {component_min(cluster_.lo, object.shape.bounds().lo), component_max(cluster_.hi, object.shape.bounds().hi)};
    }

    /// Whether the ray may come near the cluster's box within the range (conservatively:
    /// Aabb::may_cross). Only the first pass of a query culls by it, so it may use the
    /// range's end.
    [[nodiscard]] bool reaches_cluster(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        return bounded_objects_ && cluster_.may_cross(ray, range);
    }

    /// Whether the object needs testing: it is unbounded, or the ray comes near the cluster.
    template <class O>
    [[nodiscard]] static bool worth_testing(const O& object, bool near_cluster) noexcept
    {
        return near_cluster || !object.bounded;
    }

    template <std::size_t I>
    void nearest_in_slot(const Ray<T>& ray, Interval<T>& range, Nearest& nearest, bool near_cluster) const noexcept
    {
        const auto objects = objects_of(std::get<I>(slots));
        for (std::size_t k = 0; k < objects.size(); ++k) {
            if (!worth_testing(objects[k], near_cluster)) continue;
            const auto crossings = objects[k].shape.template crossings<false>(ray, range);
            if (crossings.empty()) continue;
            // Ending the range just past the crossing keeps every crossing before it, and
            // so the same first one, while the surface pass refines nothing beyond it:
            // no shape's answer up to a t depends on where its range ends (shapes cull by
            // Aabb::reached_after, which ignores the end).
            nearest = {true, static_cast<std::uint32_t>(I), static_cast<std::uint32_t>(k), {range.min, next_float_up(crossings.front().t)}};
            range.max = crossings.front().t;
        }
    }

    /// The nearest object's first crossing with its surface: the same computation as
    /// before over a range that holds the same crossings up to it, so the same t.
    template <std::size_t I>
    std::optional<Hit<T>> surface_in_slot(const Ray<T>& ray, const Nearest& nearest) const noexcept
    {
        if constexpr (I + 1 < sizeof...(Slots)) {
            if (nearest.slot != I) return surface_in_slot<I + 1>(ray, nearest);
        }
        const auto crossings = objects_of(std::get<I>(slots))[nearest.index].shape.crossings(ray, nearest.range);
        PRISM_ASSERT(!crossings.empty());
        if (crossings.empty()) return std::nullopt;
        return Hit<T>{crossings.front(), nearest.slot, nearest.index};
    }

    template <std::size_t I, bool GlassTransmits>
    bool transmittance_of_slot(const Ray<T>& ray, T t_max, Rgb<T>& tr, bool near_cluster) const noexcept
    {
        using Slot = std::tuple_element_t<I, std::tuple<Slots...>>;
        using M = typename Slot::material_type;
        const Interval<T> range{T(0), t_max};
        for (const auto& object : objects_of(std::get<I>(slots))) {
            if (!worth_testing(object, near_cluster)) continue;
            const auto crossings = object.shape.template crossings<false>(ray, range);
            if constexpr (!transmits<M> || !GlassTransmits) {
                if (!crossings.empty()) return false;
            } else {
                // Length of the ray inside the solid within [0, t_max].
                bool inside = crossings.inside_at_start;
                T previous = T(0), inside_length = T(0);
                for (const Crossing<T>& c : crossings) {
                    if (inside) inside_length += c.t - previous;
                    inside = c.entering;
                    previous = c.t;
                }
                if (inside) inside_length += t_max - previous;
                if (inside_length > T(0))
                    tr *= beer_lambert(object.material.absorption, inside_length * length(ray.direction));
                for (std::size_t k = 0; k < crossings.size(); ++k) tr *= object.material.kt;
                if (max_component(tr) <= T(0)) return false;
            }
        }
        return true;
    }

    template <std::size_t I, class F>
    decltype(auto) visit_slot(const Hit<T>& hit, F&& f) const
    {
        if constexpr (I + 1 < sizeof...(Slots)) {
            if (hit.slot != I) return visit_slot<I + 1>(hit, std::forward<F>(f));
        }
        PRISM_ASSERT(hit.slot == I);
        return f(objects_of(std::get<I>(slots))[hit.index].material);
    }
};

template <class LightList, class... Slots>
Scene(LightList, Slots...) -> Scene<LightList, Slots...>;

} // namespace prism
