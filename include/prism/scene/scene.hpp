// SPDX-License-Identifier: MIT
// Scene: lights and object slots fixed at compile time; closest-hit and shadow queries.
#pragma once

#include <prism/accel/bvh.hpp>
#include <prism/core/check.hpp>
#include <prism/core/interval.hpp>
#include <prism/core/offset.hpp>
#include <prism/light/light.hpp>
#include <prism/material/scattering.hpp>
#include <prism/medium/nesting.hpp>
#include <prism/scene/hit.hpp>
#include <prism/scene/object.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace prism {

/// The lights of a scene, each of its own type, at least one.
template <Light... Ls>
struct Lights {
    static_assert(sizeof...(Ls) > 0, "Lights{} holds no light: a scene needs at least one (a PointLight, a DirectionalLight, ...)");

    std::tuple<Ls...> items;

    constexpr explicit Lights(Ls... lights) : items(std::move(lights)...)
    {
        std::apply([](const auto&... light) { (light.validate(), ...); }, items);
    }
};

namespace detail {

template <class X>
struct is_light_list : std::false_type {};
template <class... Ls>
struct is_light_list<Lights<Ls...>> : std::true_type {};

/// Whether every light of the list has scalar type T (true for what is no list: that
/// has its own error).
template <class List, class T>
inline constexpr bool lights_of_scalar = true;
template <class... Ls, class T>
inline constexpr bool lights_of_scalar<Lights<Ls...>, T> = (std::same_as<typename Ls::scalar_type, T> && ...);

} // namespace detail

/// A scene's first argument: Lights{...}.
template <class X>
concept LightList = detail::is_light_list<X>::value;

/// How shadow rays treat dielectrics.
enum class ShadowsThroughGlass : bool {
    attenuated, ///< light passes, attenuated by the medium and the transmission tint (Whitted)
    blocked,    ///< glass casts a full shadow: its light arrives by a caustic map instead
};

namespace detail {

/// Where a shadow ray meets a transmissive object's boundary (or starts inside it), kept
/// to resolve overlapping objects by priority; a fixed number, no allocation.
template <Scalar T>
struct ShadowBoundaries {
    struct Boundary {
        T t;
        std::uint32_t slot;
        std::uint32_t index;
        bool entering;
        bool at_start; ///< the ray starts inside the object (no boundary crossed)
    };
    static constexpr std::size_t capacity = 32;
    std::array<Boundary, capacity> items;
    std::size_t count = 0;
    bool overflow = false;

    constexpr void add(const Boundary& b) noexcept
    {
        if (count == capacity) overflow = true;
        else items[count++] = b;
    }

    /// Sort by t; whether two objects' insides overlap anywhere along the ray.
    constexpr bool sort_and_find_overlap() noexcept
    {
        if (overflow) return false;
        for (std::size_t i = 1; i < count; ++i)
            for (std::size_t j = i; j > 0 && items[j].t < items[j - 1].t; --j) std::swap(items[j], items[j - 1]);
        int depth = 0;
        for (std::size_t i = 0; i < count; ++i) {
            depth += items[i].entering || items[i].at_start ? 1 : -1;
            if (depth >= 2) return true;
        }
        return false;
    }
};

/// What a slot keeps to find its objects: nothing for one object; for an ObjectArray of
/// at least tree_from objects, a Bvh over its bounded ones and the list of its unbounded
/// ones (tested on every ray). Fewer are scanned: the Cornell box's five walls render 20 %
/// slower through a tree.
template <class SlotT>
struct SlotIndex {
    static constexpr bool accelerated = false;
    constexpr explicit SlotIndex(const SlotT&) noexcept {}
};

template <class S, class M>
struct SlotIndex<ObjectArray<S, M>> {
    using T = typename S::scalar_type;
    static constexpr bool accelerated = true;
    static constexpr std::size_t tree_from = 8;
    bool tree = false;                   ///< false: the array is scanned
    Bvh<T> bvh;                          ///< over the bounded objects
    std::vector<S> shapes;               ///< the bounded objects' shapes, in the Bvh's leaf order
    std::vector<std::uint32_t> object;   ///< the object behind each of them
    std::vector<std::uint32_t> unbounded;

    explicit SlotIndex(const ObjectArray<S, M>& array) : tree(array.items.size() >= tree_from)
    {
        if (!tree) return;
        std::vector<Aabb<T>> boxes;
        std::vector<std::uint32_t> bounded;
        for (std::uint32_t k = 0; k < array.items.size(); ++k) {
            if (array.items[k].bounded) {
                bounded.push_back(k);
                boxes.push_back(array.items[k].shape.bounds());
            } else
                unbounded.push_back(k);
        }
        bvh = Bvh<T>(boxes);
        // The shapes a traversal tests, side by side as it meets them (a copy: the
        // objects' materials stay out of the cache's way), and the surface pass takes
        // the nearest from here too.
        for (const std::uint32_t p : bvh.primitives()) {
            object.push_back(bounded[p]);
            shapes.push_back(array.items[bounded[p]].shape);
        }
    }
};

} // namespace detail

/// A scene: its lights, object slots (one type each), background and ambient radiance.
/// Which shapes and materials exist is part of the type, so integrators compile only
/// the code those materials need.
template <class LightsOfScene, Slot... Slots>
class Scene {
    static_assert(LightList<LightsOfScene>, "a Scene's first argument must be its lights as Lights{...}, e.g. Scene{Lights{PointLight<float>{...}}, objects...}");
    static_assert(sizeof...(Slots) > 0, "a scene needs at least one object");

public:
    using scalar_type = typename std::tuple_element_t<0, std::tuple<Slots...>>::scalar_type;
    using T = scalar_type;
    static_assert((std::same_as<typename Slots::scalar_type, T> && ...), "all objects must share one scalar type");
    static_assert(detail::lights_of_scalar<LightsOfScene, T>, "every light must have the objects' scalar type (a PointLight<float> in a scene of double objects?)");

    /// Some material refracts: the integrator needs refraction and Beer-Lambert code.
    static constexpr bool has_transmissive = (transmits<typename Slots::material_type> || ...);
    /// Some material has a mirror lobe.
    static constexpr bool has_specular = (reflects<typename Slots::material_type> || ...) || has_transmissive;
    static constexpr std::size_t slot_count = sizeof...(Slots);

    // Scene Public Members

    LightsOfScene lights;
    std::tuple<Slots...> slots;
    Rgb<T> background{T(0)}; ///< radiance of rays that hit nothing
    Rgb<T> ambient{T(0)};    ///< the notes' ambient term, added where every light is occluded

    constexpr Scene(LightsOfScene light_list, Slots... objects)
        : lights(std::move(light_list)), slots(std::move(objects)...),
          indices_(std::apply([](const auto&... slot) { return std::tuple<detail::SlotIndex<Slots>...>(detail::SlotIndex<Slots>(slot)...); }, slots))
    {
        // Each slot's own box, for visiting the slots nearest first, which pays where a
        // slot has a tree to cull by the range the nearer slots have shrunk; and one box
        // around them all: a ray that misses it skips every bounded object.
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((slot_reach_[I] = reach_of(std::get<I>(slots))), ...);
            nearest_first_ = sizeof...(Slots) > 1 && (has_tree<I>() || ...);
        }(std::index_sequence_for<Slots...>{});
        for (const SlotReach& reach : slot_reach_) cluster_ = cluster_.merged(reach.box);
        bounded_objects_ = !cluster_.empty();
    }

    /// The box around every bounded object (empty when there is none): the render's
    /// cull for whole scenes, and the photon tracer's extent.
    [[nodiscard]] constexpr const Aabb<T>& bounds() const noexcept { return cluster_; }

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
        if (nearest_first_ && near_cluster) {
            // The slots in the order the ray enters their boxes: a nearer slot's hit
            // shrinks the range before a farther slot's tree is walked. Which object wins
            // does not depend on the order (a tie at one t goes to the lower slot, then
            // the lower index, as in a scan of the slots in turn).
            std::array<std::pair<T, std::uint32_t>, sizeof...(Slots)> order;
            for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = {slot_reach_[k].entry(ray, range), k};
            for (std::size_t i = 1; i < order.size(); ++i)
                for (std::size_t j = i; j > 0 && order[j].first < order[j - 1].first; --j) std::swap(order[j], order[j - 1]);
            // (A slot whose box the ray misses comes last and is still asked: rounding may
            // report a crossing just outside a shape's box, and each slot culls with a
            // box widened for that.)
            for (const auto& entry : order) {
                [&]<std::size_t... I>(std::index_sequence<I...>) {
                    ((entry.second == I ? nearest_in_slot<I>(ray, range, nearest, true) : void()), ...);
                }(std::index_sequence_for<Slots...>{});
            }
        } else {
            [&]<std::size_t... I>(std::index_sequence<I...>) {
                (nearest_in_slot<I>(ray, range, nearest, near_cluster), ...);
            }(std::index_sequence_for<Slots...>{});
        }
        if (!nearest.found) return std::nullopt;
        return surface_in_slot<0>(ray, nearest);
    }

    /// Fraction of light passing along the ray from t = 0 to t_max: 0 when an opaque
    /// object is in the way, otherwise what every dielectric crossed lets through
    /// (attenuate_shadow_ray: its medium over the length inside, its tint per boundary;
    /// refraction ignored, the lecture notes' shadow rays through transparent objects).
    /// With ShadowsThroughGlass::blocked dielectrics block the ray like any other
    /// object: a photon mapper brings the light through them by its caustic map instead
    /// (as POV-Ray does for photon targets).
    template <ShadowsThroughGlass Glass = ShadowsThroughGlass::attenuated>
    [[nodiscard]] Rgb<T> transmittance(const Ray<T>& ray, T t_max) const noexcept
    {
        Rgb<T> tr{T(1)};
        // Unwidened: a shadow ray needs no spurious crossing a far-off shape might report
        // (culling it can only let light through where rounding alone would block it).
        const bool near_cluster = bounded_objects_ && (cluster_.contains(ray.origin) || !cluster_.clip(ray, {T(0), t_max}).empty());
        detail::ShadowBoundaries<T> boundaries;
        const bool open = [&]<std::size_t... I>(std::index_sequence<I...>) {
            return (transmittance_of_slot<I, Glass>(ray, t_max, tr, near_cluster, boundaries) && ...);
        }(std::index_sequence_for<Slots...>{});
        if (!open) return Rgb<T>{T(0)};
        // Where transmissive objects overlap, the higher priority's medium fills the
        // overlap (medium/nesting.hpp): walk the boundaries in order instead.
        if constexpr (has_transmissive && Glass == ShadowsThroughGlass::attenuated) {
            if (boundaries.sort_and_find_overlap()) return transmittance_by_priority(ray, t_max, boundaries);
        }
        return tr;
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

    static constexpr std::size_t light_count = std::tuple_size_v<decltype(LightsOfScene::items)>;

    /// Call f(light) with light number i (in the order of Lights{...}), with its static type.
    template <class F>
    decltype(auto) visit_light(std::size_t i, F&& f) const
    {
        return visit_light_at<0>(i, std::forward<F>(f));
    }

private:
    Aabb<T> cluster_{}; ///< around every bounded object (empty when there are none)
    bool bounded_objects_ = false;
    /// Each slot's index (a Bvh for an ObjectArray), built with the scene: the slots are
    /// not to be changed after it.
    std::tuple<detail::SlotIndex<Slots>...> indices_;

    /// Where a ray may first meet a slot's objects, for ordering the slots (never for
    /// skipping one: each culls its own objects by the range).
    struct SlotReach {
        Aabb<T> box{};          ///< around its bounded objects
        bool unbounded = false; ///< it has an unbounded object: met from the range's start
        /// Where the ray enters the box within the range (the range's start for an
        /// unbounded object; infinity where it misses the box, or the slot is empty):
        /// only the order of the slots, so no widening.
        [[nodiscard]] constexpr T entry(const Ray<T>& ray, Interval<T> range) const noexcept
        {
            if (unbounded) return range.min;
            const Interval<T> inside = box.empty() ? Interval<T>{} : box.clip(ray, range);
            return inside.empty() ? infinity<T> : inside.min;
        }
    };
    std::array<SlotReach, sizeof...(Slots)> slot_reach_{};
    bool nearest_first_ = false; ///< two slots or more, one with a tree: visit them nearest first

    // Scene Private Methods

    /// The nearest object so far: where its first crossing is, and the range over
    /// which it was found.
    struct Nearest {
        bool found = false;
        std::uint32_t slot = 0, index = 0;
        Interval<T> range{};
        SurfaceHint<T> hint{}; ///< the shape's own (a mesh's triangle), for surface_crossing
        /// Where a slot's tree keeps its copy of the shape (else none): the surface pass
        /// reads that copy, which the test has just brought into the cache.
        std::uint32_t copy = no_copy;
    };
    static constexpr std::uint32_t no_copy = ~std::uint32_t(0);

    template <class S>
    [[nodiscard]] static constexpr SlotReach reach_of(const S& slot) noexcept
    {
        SlotReach reach;
        for (const auto& object : objects_of(slot)) {
            if (object.bounded) reach.box = reach.box.merged(object.shape.bounds());
            else reach.unbounded = true;
        }
        return reach;
    }

    template <std::size_t I>
    [[nodiscard]] constexpr bool has_tree() const noexcept
    {
        if constexpr (detail::SlotIndex<std::tuple_element_t<I, std::tuple<Slots...>>>::accelerated) return std::get<I>(indices_).tree;
        return false;
    }

    template <std::size_t I, class F>
    decltype(auto) visit_light_at(std::size_t i, F&& f) const
    {
        if constexpr (I + 1 < light_count) {
            if (i != I) return visit_light_at<I + 1>(i, std::forward<F>(f));
        }
        PRISM_ASSERT(i == I);
        return f(std::get<I>(lights.items));
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
        if constexpr (detail::SlotIndex<std::tuple_element_t<I, std::tuple<Slots...>>>::accelerated) {
            if (std::get<I>(indices_).tree) return nearest_in_tree<I>(ray, range, nearest, near_cluster);
        }
        const auto objects = objects_of(std::get<I>(slots));
        for (std::size_t k = 0; k < objects.size(); ++k) {
            if (!worth_testing(objects[k], near_cluster)) continue;
            SurfaceHint<T> hint;
            // Visited after a later slot's find (nearest first): a crossing at its t
            // wins too, as it would have in a scan of the slots in turn.
            const bool wins_tie = nearest.found && nearest.slot > I;
            const T t = first_crossing(objects[k].shape, ray, wins_tie ? Interval<T>{range.min, next_float_up(range.max)} : range, hint);
            if (!(t < infinity<T>)) continue;
            // Ending the range just past the crossing keeps every crossing before it, and
            // so the same first one, while the surface pass refines nothing beyond it:
            // no shape's answer up to a t depends on where its range ends (shapes cull by
            // Aabb::reached_after, which ignores the end).
            nearest = {true, static_cast<std::uint32_t>(I), static_cast<std::uint32_t>(k), {range.min, next_float_up(t)}, hint};
            range.max = t;
        }
    }

    /// nearest_in_slot through the slot's Bvh: the same object at the same t.
    template <std::size_t I>
    void nearest_in_tree(const Ray<T>& ray, Interval<T>& range, Nearest& nearest, bool near_cluster) const noexcept
    {
        const auto objects = objects_of(std::get<I>(slots));
        const auto& index = std::get<I>(indices_);
        PRISM_ASSERT(index.shapes.size() + index.unbounded.size() == objects.size());
        // Crossings lie strictly inside the range, so in a scan in index order the first
        // object at a t wins a tie. The tree visits objects in another order: once an
        // object is found, each is asked up to just past its t, and one at exactly that t
        // wins only if it comes before it (as it would have in the scan). Which object
        // that is, is looked up only for a crossing, not for every test.
        const auto test = [&](const auto& shape, const auto& object_index, std::uint32_t copy, Interval<T>& r) {
            SurfaceHint<T> hint;
            const T t = first_crossing(shape, ray, nearest.found ? Interval<T>{r.min, next_float_up(r.max)} : r, hint);
            if (!(t < infinity<T>)) return;
            const std::uint32_t k = object_index();
            if (!(t < r.max) && !(nearest.slot > I || (nearest.slot == I && k < nearest.index))) return;
            nearest = {true, static_cast<std::uint32_t>(I), k, {r.min, next_float_up(t)}, hint, copy};
            r.max = t;
        };
        for (const std::uint32_t k : index.unbounded) test(objects[k].shape, [k] { return k; }, no_copy, range);
        if (near_cluster)
            index.bvh.traverse_in_leaf_order(ray, range, [&](std::uint32_t p, Interval<T>& r) {
                test(index.shapes[p], [&] { return index.object[p]; }, p, r);
                return false;
            });
    }

    /// The nearest object's first crossing with its surface: the same computation as
    /// before over a range that holds the same crossings up to it, so the same t.
    template <std::size_t I>
    std::optional<Hit<T>> surface_in_slot(const Ray<T>& ray, const Nearest& nearest) const noexcept
    {
        if constexpr (I + 1 < sizeof...(Slots)) {
            if (nearest.slot != I) return surface_in_slot<I + 1>(ray, nearest);
        }
        const auto& shape = [&]() -> const auto& {
            if constexpr (detail::SlotIndex<std::tuple_element_t<I, std::tuple<Slots...>>>::accelerated)
                if (nearest.copy != no_copy) return std::get<I>(indices_).shapes[nearest.copy]; // the same shape, bit for bit
            return objects_of(std::get<I>(slots))[nearest.index].shape;
        }();
        const auto crossing = surface_crossing(shape, ray, nearest.range, nearest.hint);
        PRISM_ASSERT(crossing.has_value());
        if (!crossing) return std::nullopt;
        return Hit<T>{*crossing, nearest.slot, nearest.index};
    }

    template <std::size_t I, ShadowsThroughGlass Glass>
    bool transmittance_of_slot(const Ray<T>& ray, T t_max, Rgb<T>& tr, bool near_cluster, detail::ShadowBoundaries<T>& boundaries) const noexcept
    {
        using Slot = std::tuple_element_t<I, std::tuple<Slots...>>;
        using M = typename Slot::material_type;
        const Interval<T> range{T(0), t_max};
        if constexpr (detail::SlotIndex<Slot>::accelerated && (!transmits<M> || Glass == ShadowsThroughGlass::blocked)) {
            // Opaque: any crossing blocks the ray, in whatever order the tree finds it.
            // (Transmissive objects multiply their attenuations in index order below,
            // so that the product is the same bits.)
            if (std::get<I>(indices_).tree) return !blocked_in_tree<I>(ray, range, near_cluster);
        }
        std::uint32_t index = 0;
        for (const auto& object : objects_of(std::get<I>(slots))) {
            const std::uint32_t this_index = index++;
            if (!worth_testing(object, near_cluster)) continue;
            if constexpr (!transmits<M> || Glass == ShadowsThroughGlass::blocked) {
                if (any_crossing(object.shape, ray, range)) return false;
            } else {
                const auto crossings = object.shape.template crossings<false>(ray, range);
                attenuate_shadow_ray(object.material, crossings, ray, t_max, tr);
                if (max_component(tr) <= T(0)) return false;
                if (crossings.inside_at_start) boundaries.add({T(0), std::uint32_t(I), this_index, true, true});
                for (const Crossing<T>& c : crossings) boundaries.add({c.t, std::uint32_t(I), this_index, c.entering, false});
            }
        }
        return true;
    }

    /// Whether an object of the slot's Bvh (or an unbounded one) crosses the ray in range.
    template <std::size_t I>
    bool blocked_in_tree(const Ray<T>& ray, Interval<T> range, bool near_cluster) const noexcept
    {
        const auto objects = objects_of(std::get<I>(slots));
        const auto& index = std::get<I>(indices_);
        for (const std::uint32_t k : index.unbounded)
            if (any_crossing(objects[k].shape, ray, range)) return true;
        Interval<T> r = range;
        return near_cluster && index.bvh.any_in_leaf_order(ray, r, [&](std::uint32_t p, Interval<T>&) { return any_crossing(index.shapes[p], ray, range); });
    }

    /// A shadow ray through overlapping transmissive objects: each stretch attenuated by
    /// the medium of the object it is in (the highest priority, medium/nesting.hpp), a
    /// transmission tint at each real interface, none at a false one.
    [[nodiscard]] Rgb<T> transmittance_by_priority(const Ray<T>& ray, T t_max, const detail::ShadowBoundaries<T>& boundaries) const noexcept
    {
        Rgb<T> tr{T(1)};
        const T speed = length(ray.direction);
        MediumStack media;
        T previous = T(0);
        const auto attenuate_to = [&](T t) {
            if (const Inside* in = media.top()) {
                visit_material(Hit<T>{{}, in->slot, in->index}, [&]<class N>(const N& material) {
                    if constexpr (transmits<N>) tr *= material.medium().transmittance((t - previous) * speed);
                });
            }
            previous = t;
        };
        for (std::size_t i = 0; i < boundaries.count; ++i) {
            const auto& b = boundaries.items[i];
            attenuate_to(b.t);
            visit_material(Hit<T>{{}, b.slot, b.index}, [&]<class N>(const N& material) {
                if constexpr (transmits<N>) {
                    const Inside object{b.slot, b.index, nesting_priority(material)};
                    if (b.at_start) {
                        media = media.entered(object);
                        return;
                    }
                    const Interface face = nested_interface(media, object, b.entering);
                    if (face.real) tr *= material.transmission_tint();
                    media = face.beyond;
                }
            });
        }
        attenuate_to(t_max);
        return tr;
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

template <class L, class... Slots>
Scene(L, Slots...) -> Scene<L, Slots...>;

} // namespace prism
