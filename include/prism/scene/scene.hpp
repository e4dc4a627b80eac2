// SPDX-License-Identifier: MIT
// Scene: lights and object slots fixed at compile time; closest-hit and shadow queries.
// Its lights are scene/lights.hpp's, the order that settles ties scene/object_key.hpp's,
// and how shadow rays cross glass scene/shadow.hpp's.
#pragma once

#include <prism/accel/bvh.hpp>
#include <prism/core/check.hpp>
#include <prism/core/dispatch.hpp>
#include <prism/core/pack.hpp>
#include <prism/core/interval.hpp>
#include <prism/core/offset.hpp>
#include <prism/light/light.hpp>
#include <prism/material/scattering.hpp>
#include <prism/scene/area_lights.hpp>
#include <prism/scene/hit.hpp>
#include <prism/scene/lights.hpp>
#include <prism/scene/object.hpp>
#include <prism/scene/object_key.hpp>
#include <prism/scene/shadow.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace prism {

namespace detail {

template <class X>
struct is_object_array : std::false_type {};
template <class S, class M>
struct is_object_array<ObjectArray<S, M>> : std::true_type {};

/// Nothing: what a scene of several slots keeps in place of its one slot's shapes.
struct NoShapes {};

} // namespace detail

/// A scene: its lights, object slots (one type each), background and ambient radiance.
/// Which shapes and materials exist is part of the type, so integrators compile only
/// the code those materials need.
///
/// Finding what a ray meets: the scene keeps one Bvh over the bounded objects of all its
/// slots (when there are at least tree_from; fewer, the Cornell box's seven, which render
/// 20 % slower through a tree, lie side by side in the lanes of one or two nodes, tested
/// by a ray at once: may_meet), and tests its unbounded ones on every ray. A leaf
/// reaches its object's code through a table with an entry per slot (core/dispatch.hpp),
/// so a ray costs log N in the objects whatever their types, and the code compiled grows
/// linearly with the slots: the traversal is compiled once, only the leaf test once per
/// slot. (A scene of one slot calls its leaf test directly, and keeps its shapes in leaf
/// order beside the tree.) Whatever order the objects are met in, the answer is the same
/// object at the same t: a tie at one t goes to the lower slot, then the lower index, as
/// in a scan of the slots in turn.
// (Slots is checked by a static_assert, not constrained as `Slot... Slots`: clang checks a
// constrained pack as a fold expression, and refuses one of more than 256 terms.)
template <class LightsOfScene, class... Slots>
class Scene {
    static_assert(LightList<LightsOfScene>, "a Scene's first argument must be its lights as Lights{...}, e.g. Scene{Lights{PointLight<float>{...}}, objects...}");
    static_assert(sizeof...(Slots) > 0, "a scene needs at least one object");
    static_assert(detail::all_of({Slot<Slots>...}), "a Scene's objects must each be an Object{shape, material} or an ObjectArray");

    template <std::size_t I>
    using SlotAt = pack_element_t<I, Pack<Slots...>>;

public:
    /// The objects' precision.
    using scalar_type = typename SlotAt<0>::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;
    static_assert(detail::all_of({std::same_as<typename Slots::scalar_type, T>...}), "all objects must share one scalar type");
    static_assert(detail::lights_of_scalar<LightsOfScene, T>, "every light must have the objects' scalar type (a PointLight<float> in a scene of double objects?)");

    /// Whether slot I's objects emit light (area lights).
    template <std::size_t I>
    static constexpr bool slot_emits = detail::slot_emits<SlotAt<I>>;
    /// Some material emits: the scene has area lights (AreaLights, one more light).
    static constexpr bool has_emitters = detail::any_of({detail::slot_emits<Slots>...});
    /// Some light is not a delta light (an area or environment light), or casts a shadow of
    /// its own (POV-Ray's area_light, which may jitter): it is sampled point by point, with
    /// random numbers.
    static constexpr bool has_lights_with_extent = has_emitters || !detail::all_delta<LightsOfScene> || detail::any_own_shadow<LightsOfScene>;
    static_assert(detail::light_count_of<LightsOfScene> > 0 || has_emitters,
                  "a scene needs a light: Lights{...} with at least one (a PointLight, a DirectionalLight, ...), or an object whose material emits (Emissive)");

    /// Some material refracts: the integrator needs refraction and Beer-Lambert code.
    static constexpr bool has_transmissive = detail::any_of({transmits<typename Slots::material_type>...});
    /// Some material may be an index-matched boundary (may_match_index): shadow rays that
    /// glass blocks still pass it.
    static constexpr bool has_index_matching = detail::any_of({may_match_index<typename Slots::material_type>...});
    /// Some light casts its own shadow (has_own_shadow: POV-Ray's area_light).
    static constexpr bool has_own_shadow_lights = detail::any_own_shadow<LightsOfScene>;
    /// Some material disperses (its index depends on the wavelength): a white path splits there.
    static constexpr bool has_dispersion = detail::any_of({disperses<typename Slots::material_type>...});
    /// Some material's interior scatters light (a Fog): walks sample where they scatter in it.
    static constexpr bool has_scattering_media = detail::any_of({has_scattering_interior<typename Slots::material_type>...});
    /// Some material reads surface coordinates (a texture, a normal map): its crossings take
    /// them, and rays carry their cones on through mirrors and glass (carry_cone).
    static constexpr bool reads_surface_coordinates = detail::any_of({reads_coordinates<typename Slots::material_type>()...});
    /// Some material has a mirror lobe.
    static constexpr bool has_specular = detail::any_of({reflects<typename Slots::material_type>...}) || has_transmissive;
    /// The number of slots (Object or ObjectArray).
    static constexpr std::size_t slot_count = sizeof...(Slots);
    /// The fewest bounded objects the scene builds its tree over.
    static constexpr std::size_t tree_from = 8;
    /// Whether the scene may need a tree: some slot is an array, or there are tree_from
    /// slots. (A scene of a few single objects compiles no tree code: Whitted's four
    /// compile 1.5 s faster.)
    static constexpr bool may_have_tree = slot_count >= tree_from || detail::any_of({detail::is_object_array<Slots>::value...});

    // Scene Public Members

    LightsOfScene lights; ///< the lights
    Pack<Slots...> slots; ///< get<I>(slots) is slot I
    Rgb<T> background{T(0)}; ///< radiance of rays that hit nothing
    Rgb<T> ambient{T(0)};    ///< the ambient term of Whitted (1980), added where every light is occluded

    /// The scene of `light_list` and the slots `objects`; builds the tree over the bounded objects where there are enough.
    constexpr Scene(LightsOfScene light_list, Slots... objects) : lights(std::move(light_list)), slots(std::move(objects)...)
    {
        // Every object's key, bounded or not, in key order; the transmissive ones again,
        // and one box around every bounded object (a ray that misses it skips them all).
        std::vector<Aabb<T>> boxes;
        for_each_slot([&]<std::size_t I>(Index<I>) {
            const auto list = objects_of(get<I>(slots));
            for (std::uint32_t k = 0; k < list.size(); ++k) {
                const detail::ObjectKey key{std::uint32_t(I), k};
                if (list[k].bounded) {
                    boxes.push_back(list[k].shape.bounds());
                    cluster_ = cluster_.merged(boxes.back());
                    keys_.push_back(key);
                } else {
                    unbounded_.push_back(key);
                }
                if constexpr (transmits<typename SlotAt<I>::material_type>) glass_.push_back(key);
            }
        });
        bounded_objects_ = !cluster_.empty();
        if constexpr (has_emitters) build_emitters();
        if constexpr (may_have_tree) {
            if (keys_.size() >= tree_from) build_tree(boxes);
        }
        if (!has_tree_ && keys_.size() > 1) {
            for (std::size_t k = 0; k < boxes.size(); ++k) side_by_side_[k / side_width].set(int(k % side_width), boxes[k], std::uint32_t(k), 1);
            side_magnitude_ = std::max(max_component(prism::abs(cluster_.lo)), max_component(prism::abs(cluster_.hi)));
        }
    }

    /// The box around every bounded object (empty when there is none): the render's
    /// cull for whole scenes, and the photon tracer's extent.
    [[nodiscard]] constexpr const Aabb<T>& bounds() const noexcept { return cluster_; }

    /// Throws std::invalid_argument, naming the parameter, for a negative or non-finite background or ambient; every integrator calls it.
    constexpr void validate() const
    {
        detail::require_non_negative("Scene background", background);
        detail::require_non_negative("Scene ambient", ambient);
    }

    /// Whether the scene keeps a tree over its bounded objects (at least tree_from).
    [[nodiscard]] constexpr bool has_tree() const noexcept { return has_tree_; }

    // Scene Queries

    /// `next`, the ray a mirror or an interface sends on where `ray` met it at t, carrying
    /// `ray`'s cone on (carrying_cone) where some material reads surface coordinates; as it
    /// is in a scene without textures, which pays nothing for them.
    [[nodiscard]] static Ray<T> carry_cone(const Ray<T>& next, const Ray<T>& ray, T t) noexcept
    {
        if constexpr (reads_surface_coordinates) return carrying_cone(next, ray, t);
        else return next;
    }

    /// The closest crossing with t inside `range`. Every object is asked for its
    /// crossings without their surfaces; only the nearest one is then asked again, over
    /// the same range, for its surface.
    [[nodiscard]] std::optional<Hit<T>> closest_hit(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        Nearest nearest{};
        for (const detail::ObjectKey& key : unbounded_) nearest_of(key, no_copy, ray, range, nearest);
        if (has_tree_) {
            if constexpr (may_have_tree)
                tree_.traverse_in_leaf_order(ray, range, [&](std::uint32_t p, Interval<T>& r) {
                    nearest_of(keys_[p], p, ray, r, nearest);
                    return false;
                });
        } else if (const unsigned meets = bounded_objects_ ? may_meet(ray, range) : 0u; meets != 0) {
            // The scan meets objects in key order: with nothing unbounded found before it,
            // no object can win a tie with one found before it.
            const bool in_key_order = !nearest.found;
            visit_bounded(meets, [&]<std::size_t I>(Index<I>, std::uint32_t k) {
                test_nearest<I>(object_at<I>(k).shape, {std::uint32_t(I), k}, no_copy, ray, range, nearest, in_key_order);
                return false;
            });
        }
        if (!nearest.found) return std::nullopt;
        return dispatch<slot_count>(nearest.slot, [&]<std::size_t I>(Index<I>) { return surface_in_slot<I>(ray, nearest); });
    }

    /// Fraction of light passing along the ray from t = 0 to t_max: 0 when an opaque
    /// object is in the way, otherwise what every dielectric crossed lets through
    /// (attenuate_shadow_ray: its medium over the length inside, its tint per boundary;
    /// refraction ignored, the classic Whitted shadow rays through transparent objects).
    /// With ShadowsThroughGlass::blocked dielectrics block the ray like any other
    /// object: a photon mapper brings the light through them by its caustic map instead
    /// (as POV-Ray does for photon targets). All but an index-matched boundary in the air
    /// (may_match_index: a ball of smoke), which bends nothing, so that nothing else could
    /// bring its light: it attenuates the ray either way.
    /// `leaving`: an object the ray leaves on its outer side that is convex (the shading
    /// point's, when convex_object says so), which it cannot cross again and is not asked;
    /// none by default.
    template <ShadowsThroughGlass Glass = ShadowsThroughGlass::attenuated>
    [[nodiscard]] Rgb<T> transmittance(const Ray<T>& ray, T t_max, detail::ObjectKey leaving = detail::no_object) const noexcept
    {
        Rgb<T> tr{T(1)};
        detail::ShadowBoundaries<T> boundaries;
        if (!open_along<Glass>(ray, t_max, tr, boundaries, leaving)) return Rgb<T>{T(0)};
        // Where transmissive objects overlap, the higher priority's medium fills the
        // overlap (medium/nesting.hpp): walk the boundaries in order instead.
        if constexpr (any_pass<Glass>) {
            if (boundaries.sort_and_find_overlap()) return detail::transmittance_by_priority(*this, ray, t_max, boundaries);
        }
        return tr;
    }

    /// Call f(t0, t1) for each stretch of the ray's [0, t_max] outside every object a
    /// shadow ray passes through (transmittance's: with ShadowsThroughGlass::blocked an
    /// index-matched boundary, a ball of smoke; with attenuated, any dielectric): where the
    /// scene's air is, whose own medium (FilledAir) is the caller's. Inside such an object
    /// its interior takes the air's place, and transmittance attenuates by it. One call
    /// f(0, t_max) in a scene with no such object; the same when the ray crosses more
    /// boundaries than ShadowBoundaries holds.
    template <ShadowsThroughGlass Glass = ShadowsThroughGlass::attenuated, class F>
    void for_each_stretch_outside(const Ray<T>& ray, T t_max, F&& f) const noexcept
    {
        if constexpr (any_pass<Glass>) {
            detail::ShadowBoundaries<T> boundaries;
            const Interval<T> range{T(0), t_max};
            for (const detail::ObjectKey& key : glass_)
                dispatch<slot_count>(key.slot, [&]<std::size_t I>(Index<I>) {
                    if constexpr (may_pass<I, Glass>) {
                        const auto& object = object_at<I>(key.index);
                        if (!passes<Glass>(object.material)) return;
                        const auto crossings = object.shape.template crossings<false>(ray, range);
                        if (crossings.inside_at_start) boundaries.add({T(0), key.slot, key.index, true, true});
                        for (const Crossing<T>& c : crossings) boundaries.add({c.t, key.slot, key.index, c.entering, false});
                    }
                });
            if (boundaries.overflow) {
                f(T(0), t_max);
                return;
            }
            (void)boundaries.sort_and_find_overlap(); // sorts by t
            int depth = 0;
            T from = T(0);
            for (std::size_t i = 0; i < boundaries.count; ++i) {
                const auto& b = boundaries.items[i];
                if (b.entering || b.at_start) {
                    if (depth == 0 && b.t > from) f(from, b.t);
                    ++depth;
                } else if (depth > 0 && --depth == 0) {
                    from = b.t;
                }
            }
            if (depth == 0 && t_max > from) f(from, t_max);
        } else {
            f(T(0), t_max);
        }
    }

    /// The objects whose interior scatters light (a Fog's, a VaryingFog's) that hold `p`,
    /// entered in key order by their priorities: the media a camera at p starts in. Empty
    /// in a scene without such objects, at no cost. (A camera inside glass that only
    /// absorbs needs none: its ray's first crossing leaves the glass, and is attenuated so.)
    [[nodiscard]] MediumStack media_at(const Vec3<T>& p) const noexcept
    {
        MediumStack media;
        if constexpr (has_scattering_media) {
            const Ray<T> probe{p, normalize(Vec3<T>(T(0.5377), T(0.7631), T(-0.3584)))}; // any direction
            for (const detail::ObjectKey& key : glass_)
                dispatch<slot_count>(key.slot, [&]<std::size_t I>(Index<I>) {
                    if constexpr (has_scattering_interior<typename SlotAt<I>::material_type>) {
                        const auto& object = object_at<I>(key.index);
                        if (object.shape.template crossings<false>(probe, {T(0), infinity<T>}).inside_at_start)
                            media = media.entered({key.slot, key.index, nesting_priority(object.material)});
                    }
                });
        } else {
            (void)p;
        }
        return media;
    }

    /// Whether object `index` of slot `slot` is convex (prism::convex of its shape): a
    /// shadow ray leaving it on its outer side need not ask it (transmittance's `leaving`).
    [[nodiscard]] bool convex_object(std::uint32_t slot, std::uint32_t index) const noexcept
    {
        return dispatch<slot_count>(slot, [&]<std::size_t I>(Index<I>) { return prism::convex(object_at<I>(index).shape); });
    }

    /// Call f(material) with the material of object `index` of slot `slot`, with its
    /// static type.
    template <class F>
    decltype(auto) visit_material(std::uint32_t slot, std::uint32_t index, F&& f) const
    {
        return dispatch<slot_count>(slot, [&]<std::size_t I>(Index<I>) -> decltype(auto) {
            PRISM_ASSERT(index < objects_of(get<I>(slots)).size());
            return f(objects_of(get<I>(slots))[index].material);
        });
    }

    /// Call f(material) with the material of the hit object, with its static type.
    template <class F>
    decltype(auto) visit_material(const Hit<T>& hit, F&& f) const
    {
        return visit_material(hit.slot, hit.index, std::forward<F>(f));
    }

    /// Call f(object) for every object (its shape, material and whether it is bounded),
    /// with its static type, slot by slot and in each slot in order.
    template <class F>
    void for_each_object(F&& f) const
    {
        for_each_slot([&]<std::size_t I>(Index<I>) {
            for (const auto& object : objects_of(get<I>(slots))) f(object);
        });
    }

    /// The scene's emitting objects as one light (a scene without any has none to give).
    [[nodiscard]] AreaLights<Scene> area_lights() const noexcept
    {
        static_assert(has_emitters, "this scene has no emitting object (an Emissive material), so no area lights");
        return AreaLights<Scene>(*this);
    }

    /// Call f(light) for every light: those of Lights{...}, then the area lights.
    template <class F>
    void for_each_light(F&& f) const
    {
        std::apply([&](const auto&... light) { (f(light), ...); }, lights.items);
        if constexpr (has_emitters) f(area_lights());
    }

    /// The radiance a ray that leaves the scene along `direction` sees: the background,
    /// and every environment light's.
    [[nodiscard]] Rgb<T> escaped(const Vec3<T>& direction) const noexcept
    {
        Rgb<T> seen = background;
        std::apply([&](const auto&... light) { ((seen += arriving(light, direction)), ...); }, lights.items);
        return seen;
    }

    /// The number of lights: those of Lights{...}, and one more for the area lights.
    static constexpr std::size_t light_count = detail::light_count_of<LightsOfScene> + (has_emitters ? 1 : 0);

    /// Call f(light) with light number i (in the order of Lights{...}, the area lights
    /// last), with its static type.
    template <class F>
    decltype(auto) visit_light(std::size_t i, F&& f) const
    {
        return dispatch<light_count>(i, [&]<std::size_t I>(Index<I>) -> decltype(auto) { return f(light_at<I>()); });
    }

private:
    template <class>
    friend class AreaLights;

    Aabb<T> cluster_{}; ///< around every bounded object (empty when there are none)
    /// The emitting objects by power, and per slot its emitters' surfaces and chances
    /// (nothing in a scene without area lights, which compiles none of their code).
    [[no_unique_address]] std::conditional_t<has_emitters, detail::EmitterTable<T>, detail::NoShapes> emitter_table_;
    [[no_unique_address]] std::conditional_t<has_emitters, std::tuple<detail::SlotEmitters<Slots>...>, detail::NoShapes> slot_emitters_;
    bool bounded_objects_ = false;
    /// The lanes of the nodes side_by_side_ fills: one per node of the tree.
    static constexpr int side_width = BvhNode<T>::width;
    /// A scene without a tree and with two or more bounded objects keeps their boxes side
    /// by side here, in key order (box k in lane k % side_width of node k / side_width),
    /// and a ray tests them all at once, widened as a tree's nodes are (may_meet). One
    /// object's box is the cluster, and a shape tests its own box or is cheaper than the
    /// test (a mesh's Bvh starts with its root's children; a sphere is one quadratic).
    std::array<BvhNode<T>, (tree_from - 2) / side_width + 1> side_by_side_{};
    T side_magnitude_ = T(0); ///< the largest coordinate magnitude of those boxes (SlabRay's `magnitude`)
    bool has_tree_ = false;
    Bvh<T> tree_; ///< over the bounded objects (when there are at least tree_from)
    /// The object behind each of the tree's primitives, in its leaf order; without a tree
    /// the bounded objects in key order. Built with the scene: the slots are not to be
    /// changed after it.
    std::vector<detail::ObjectKey> keys_;
    std::vector<detail::ObjectKey> unbounded_; ///< in key order
    std::vector<detail::ObjectKey> glass_;     ///< the transmissive objects, in key order
    /// A scene of one slot: its bounded shapes in the tree's leaf order.
    [[no_unique_address]] std::conditional_t<slot_count == 1, std::vector<typename SlotAt<0>::shape_type>, detail::NoShapes> shapes_;

    // Scene Private Methods

    /// What `light` sends along -direction if it is at infinity, else nothing.
    template <class L>
    [[nodiscard]] static Rgb<T> arriving(const L& light, const Vec3<T>& direction) noexcept
    {
        if constexpr (is_at_infinity<L>) return light.arriving_from(direction);
        else return (void)light, (void)direction, Rgb<T>(T(0));
    }

    /// Light I: of Lights{...}, or past them the area lights (a template of I, so that a
    /// scene without area lights never names them: clang checks what an index does not
    /// depend on when the lambda that asks is instantiated).
    template <std::size_t I>
    [[nodiscard]] decltype(auto) light_at() const noexcept
    {
        if constexpr (I < detail::light_count_of<LightsOfScene>) return (std::get<I>(lights.items));
        else return area_lights();
    }

    /// An emitter's radiance over its surface: its own where it is the same everywhere,
    /// else the mean of 64 x 64 points, one in each cell of a grid over the unit square
    /// its surface maps uniformly onto its area (a point's radiance costs a texture read:
    /// 4096 of them once, when the scene is built).
    template <class M, class S, class Surface>
    [[nodiscard]] static Rgb<T> mean_emitted_radiance(const M& material, const S& shape, const Surface& surface) noexcept
    {
        if constexpr (!emission_varies<M>()) {
            return (void)shape, (void)surface, material.emitted_radiance(TexturePoint<T>{});
        } else {
            constexpr int n = 64;
            Rgb<double> sum(0.0);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const SurfacePoint<T> s = surface.sample_area(Vec2<T>((T(i) + T(0.5)) / T(n), (T(j) + T(0.5)) / T(n)));
                    sum += Rgb<double>(material.emitted_radiance(detail::emission_point<M>(shape, s)));
                }
            return Rgb<T>(sum / double(n * n));
        }
    }

    /// The table of emitting objects by power, and each emitting slot's surfaces.
    void build_emitters()
    {
        std::vector<double> weights;
        for_each_slot([&]<std::size_t I>(Index<I>) {
            if constexpr (slot_emits<I>) {
                auto& mine = std::get<I>(slot_emitters_);
                const auto list = objects_of(get<I>(slots));
                for (std::uint32_t k = 0; k < list.size(); ++k) {
                    if (!list[k].bounded)
                        detail::throw_invalid("an emitting object must be bounded: object ", k, " of slot ", I, " has no finite bounds");
                    mine.surfaces.push_back(surface_of(list[k].shape));
                    const T sides = list[k].material.two_sided ? T(2) : T(1);
                    const Rgb<T> radiance = mean_emitted_radiance(list[k].material, list[k].shape, mine.surfaces.back());
                    const Rgb<T> power = radiance * (pi<T> * mine.surfaces.back().area() * sides);
                    if (!is_finite(power))
                        detail::throw_invalid("the power pi L A of emitting object ", k, " of slot ", I, " overflows: radiance ",
                                              detail::describe(radiance), ", area ", mine.surfaces.back().area());
                    emitter_table_.keys.push_back({std::uint32_t(I), k});
                    emitter_table_.powers.push_back(power);
                    emitter_table_.power += power;
                    weights.push_back((double(power.x) + double(power.y) + double(power.z)) / 3);
                }
                mine.probability.assign(list.size(), T(0));
            }
        });
        double sum = 0;
        for (const double w : weights) sum += w;
        // Emitters that are all black light nothing: an empty table.
        if (!(sum > 0)) {
            emitter_table_.keys.clear();
            return;
        }
        emitter_table_.pick = AliasTable<T>(weights, "emitter power");
        for (std::size_t e = 0; e < emitter_table_.keys.size(); ++e) {
            const detail::ObjectKey key = emitter_table_.keys[e];
            dispatch<slot_count>(key.slot, [&]<std::size_t I>(Index<I>) {
                if constexpr (slot_emits<I>) std::get<I>(slot_emitters_).probability[key.index] = emitter_table_.pick.probability(e);
            });
        }
    }

    /// The tree over the bounded objects' boxes (in key order), and the keys in its leaf order.
    void build_tree(const std::vector<Aabb<T>>& boxes)
    {
        tree_ = Bvh<T>(boxes);
        const std::vector<detail::ObjectKey> in_key_order = std::move(keys_);
        keys_.clear();
        for (const std::uint32_t p : tree_.primitives()) {
            keys_.push_back(in_key_order[p]);
            // One slot: its shapes side by side as a traversal meets them (a copy: the
            // objects' materials stay out of the cache's way), and the surface pass
            // takes the nearest from here too.
            if constexpr (slot_count == 1) shapes_.push_back(objects_of(get<0>(slots))[in_key_order[p].index].shape);
        }
        has_tree_ = true;
    }

    /// The nearest object so far: where its first crossing is, and the range over
    /// which it was found.
    struct Nearest {
        bool found = false;
        std::uint32_t slot = 0, index = 0;
        Interval<T> range{};
        SurfaceHint<T> hint{}; ///< the shape's own (a mesh's triangle), for surface_crossing
        /// Where shapes_ keeps a copy of the shape (else none): the surface pass reads
        /// that copy, which the test has just brought into the cache.
        std::uint32_t copy = no_copy;
    };
    static constexpr std::uint32_t no_copy = ~std::uint32_t(0);

    /// f(Index<I>{}) for every slot I, in order (a braced list, not a fold: clang nests a
    /// fold's terms, and refuses more than 256).
    template <class F>
    static constexpr void for_each_slot(F&& f)
    {
        [&]<std::size_t... I>(std::index_sequence<I...>) { [[maybe_unused]] const int in_order[] = {(f(Index<I>{}), 0)...}; }(std::index_sequence_for<Slots...>{});
    }

    template <std::size_t I>
    [[nodiscard]] const auto& object_at(std::uint32_t k) const noexcept
    {
        return objects_of(get<I>(slots))[k];
    }

    /// The object behind the key (at position `copy` of shapes_, if it is there) asked for
    /// the nearest, through the slot table. In whatever order the objects come, once one
    /// is found each is asked up to just past its t, and one at exactly that t wins only
    /// if its key comes first (as it would have in a scan of the slots in turn).
    void nearest_of(const detail::ObjectKey& key, std::uint32_t copy, const Ray<T>& ray, Interval<T>& r, Nearest& nearest) const noexcept
    {
        dispatch<slot_count>(key.slot, [&]<std::size_t I>(Index<I>) {
            if constexpr (slot_count == 1)
                if (copy != no_copy) return test_nearest<I>(shapes_[copy], key, copy, ray, r, nearest);
            test_nearest<I>(object_at<I>(key.index).shape, key, no_copy, ray, r, nearest);
        });
    }

    /// in_key_order: every object found so far came before this one in key order (a scan
    /// with nothing found before it), so this one cannot win a tie at the nearest t, and
    /// its range need not reach past it.
    template <std::size_t I, class S>
    void test_nearest(const S& shape, const detail::ObjectKey& key, std::uint32_t copy, const Ray<T>& ray, Interval<T>& r, Nearest& nearest,
                      bool in_key_order = false) const noexcept
    {
        SurfaceHint<T> hint;
        const bool may_tie = nearest.found && !in_key_order;
        const T t = first_crossing(shape, ray, may_tie ? Interval<T>{r.min, next_float_up(r.max)} : r, hint);
        if (!(t < infinity<T>)) return;
        if (may_tie && !(t < r.max) && !key.before({nearest.slot, nearest.index})) return;
        // Ending the range just past the crossing keeps every crossing before it, and so
        // the same first one, while the surface pass refines nothing beyond it: no shape's
        // answer up to a t depends on where its range ends (shapes cull by
        // Aabb::reached_after, which ignores the end).
        nearest = {true, key.slot, key.index, {r.min, next_float_up(t)}, hint, copy};
        r.max = t;
    }

    /// A bit per bounded object of a scene without a tree (bit k for the k-th in key
    /// order) that a shape inside its box may report crossing within `range`: one test of
    /// every box at once, each widened per ray as a tree's (Bvh), so that it culls no
    /// object Aabb::may_cross keeps. Every object's bit for one bounded object, and for a
    /// ray with a NaN or an infinity in it (which a pad made of it cannot bound).
    [[nodiscard]] unsigned may_meet(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        static_assert(tree_from <= 32);
        const std::size_t n = keys_.size();
        const unsigned all = (1u << n) - 1u;
        if (n < 2 || !is_finite(ray.origin + ray.direction * T(0))) return all; // (a NaN or an infinity anywhere makes a NaN)
#if PRISM_VECTOR_EXTENSIONS
        const detail::SlabLanes<T, side_width> slab(ray, side_magnitude_);
#else
        const detail::SlabRay<T> slab(ray, side_magnitude_);
#endif
        std::array<T, side_width> near;
        unsigned meets = slab.may_cross(side_by_side_[0], range, near);
        for (std::size_t node = 1; node * side_width < n; ++node) meets |= slab.may_cross(side_by_side_[node], range, near) << (node * side_width);
        return meets & all;
    }

    /// visit(Index<I>{}, k) for each bounded object of a scene without a tree whose bit is
    /// set in `meets` (may_meet's: bit b for keys_[b]), in key order, until one returns
    /// true (whether one did). Only those objects are visited, each through the slot
    /// chain (core/dispatch.hpp: for a few slots, inlined calls).
    template <class Visit>
    bool visit_bounded(unsigned meets, Visit&& visit) const noexcept
    {
        for (; meets != 0; meets &= meets - 1) {
            const detail::ObjectKey key = keys_[std::size_t(std::countr_zero(meets))];
            if (dispatch<slot_count>(key.slot, [&]<std::size_t I>(Index<I>) { return visit(Index<I>{}, key.index); })) return true;
        }
        return false;
    }

    /// The nearest object's first crossing with its surface: the same computation as
    /// before over a range that holds the same crossings up to it, so the same t.
    template <std::size_t I>
    std::optional<Hit<T>> surface_in_slot(const Ray<T>& ray, const Nearest& nearest) const noexcept
    {
        const auto& shape = [&]() -> const auto& {
            if constexpr (slot_count == 1)
                if (nearest.copy != no_copy) return shapes_[nearest.copy]; // the same shape, bit for bit
            return object_at<I>(nearest.index).shape;
        }();
        const auto crossing = surface_crossing(shape, ray, nearest.range, nearest.hint);
        PRISM_ASSERT(crossing.has_value());
        if (!crossing) return std::nullopt;
        Hit<T> hit{*crossing, nearest.slot, nearest.index};
        using M = typename std::remove_cvref_t<decltype(object_at<I>(nearest.index))>::material_type;
        if constexpr (reads_coordinates<M>()) {
            // Surface coordinates, and the footprint of the ray's cone across the surface:
            // stretched by 1 / cos along its slant, taken as the isotropic width of the same
            // area. Only for materials that read them: other scenes never compute them.
            add_coordinates(shape, hit.crossing);
            if (ray.width > T(0) || ray.spread > T(0)) {
                const T cos = std::abs(dot(hit.crossing.normal, ray.direction)) / length(ray.direction);
                hit.crossing.footprint = ray.footprint_at(hit.crossing.t) / prism::sqrt(std::max(cos, T(1e-3)));
            }
            // A material that sets its own shading normal (a normal or bump map) sets it here.
            if constexpr (requires { object_at<I>(nearest.index).material.shade(hit.crossing); })
                object_at<I>(nearest.index).material.shade(hit.crossing);
        }
        return hit;
    }

    /// Whether the slot's material may let a shadow ray through (attenuated) rather than
    /// block it: glass, where shadows pass it; else an index-matched boundary (passes).
    template <std::size_t I, ShadowsThroughGlass Glass>
    static constexpr bool may_pass =
        transmits<typename SlotAt<I>::material_type> && (Glass == ShadowsThroughGlass::attenuated || may_match_index<typename SlotAt<I>::material_type>);
    /// Whether some slot's material may.
    template <ShadowsThroughGlass Glass>
    static constexpr bool any_pass = has_transmissive && (Glass == ShadowsThroughGlass::attenuated || has_index_matching);

    /// Whether a shadow ray passes `material` (may_pass), in the air (index 1).
    template <ShadowsThroughGlass Glass, class M>
    [[nodiscard]] static constexpr bool passes(const M& material) noexcept
    {
        return Glass == ShadowsThroughGlass::attenuated || index_matched(material, T(1));
    }

    /// transmittance's first pass: whether the ray is open. Opaque objects end it at their
    /// first crossing, in whatever order they are met; the transmissive ones met are
    /// gathered, then attenuate it in key order (a product is the same bits only in the
    /// same order), where they cross it, marked in `boundaries`.
    template <ShadowsThroughGlass Glass>
    bool open_along(const Ray<T>& ray, T t_max, Rgb<T>& tr, detail::ShadowBoundaries<T>& boundaries, detail::ObjectKey leaving) const noexcept
    {
        const Interval<T> range{T(0), t_max};
        detail::ShadowKeys met;
        const auto blocks_in = [&]<std::size_t I>(Index<I>, std::uint32_t k, std::uint32_t copy) {
            if (I == leaving.slot && k == leaving.index) return false; // (convex, and left on its outer side)
            if constexpr (may_pass<I, Glass>) {
                if (passes<Glass>(object_at<I>(k).material)) {
                    met.add({std::uint32_t(I), k});
                    return false;
                }
            }
            if constexpr (slot_count == 1)
                if (copy != no_copy) return any_crossing(shapes_[copy], ray, range);
            return any_crossing(object_at<I>(k).shape, ray, range);
        };
        const auto blocks = [&](const detail::ObjectKey& key, std::uint32_t copy) {
            return dispatch<slot_count>(key.slot, [&]<std::size_t I>(Index<I>) { return blocks_in(Index<I>{}, key.index, copy); });
        };
        for (const detail::ObjectKey& key : unbounded_)
            if (blocks(key, no_copy)) return false;
        if (has_tree_) {
            if constexpr (may_have_tree) {
                Interval<T> r = range;
                if (tree_.any_in_leaf_order(ray, r, [&](std::uint32_t p, Interval<T>&) { return blocks(keys_[p], p); })) return false;
            }
        } else if (bounded_objects_ && (cluster_.contains(ray.origin) || cluster_.crosses(ray, range))) {
            // (Unwidened: a shadow ray needs no spurious crossing a far-off shape might
            // report; culling it can only let light through where rounding alone would
            // block it. The objects' own boxes are then widened, as closest_hit's: they
            // cull only what could not block.)
            if (visit_bounded(may_meet(ray, range), [&]<std::size_t I>(Index<I>, std::uint32_t k) { return blocks_in(Index<I>{}, k, no_copy); })) return false;
        }
        if constexpr (any_pass<Glass>) {
            // More met than the list holds: every transmissive object, in key order (one
            // the ray misses changes nothing).
            const std::span<const detail::ObjectKey> in_order = met.overflow ? std::span<const detail::ObjectKey>(glass_) : met.sorted();
            for (const detail::ObjectKey& key : in_order) {
                dispatch<slot_count>(key.slot, [&]<std::size_t I>(Index<I>) {
                    if constexpr (may_pass<I, Glass>) {
                        const auto& object = object_at<I>(key.index);
                        if (!passes<Glass>(object.material)) return;
                        const auto crossings = object.shape.template crossings<false>(ray, range);
                        attenuate_shadow_ray(object.material, crossings, ray, t_max, tr);
                        if (crossings.inside_at_start) boundaries.add({T(0), key.slot, key.index, true, true});
                        for (const Crossing<T>& c : crossings) boundaries.add({c.t, key.slot, key.index, c.entering, false});
                    }
                });
                if (max_component(tr) <= T(0)) return false;
            }
        }
        return true;
    }
};

template <class L, class... Slots>
Scene(L, Slots...) -> Scene<L, Slots...>;

} // namespace prism
