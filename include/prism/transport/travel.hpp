// SPDX-License-Identifier: MIT
// How a ray travels through the scene's air to the first surface it meets
// (first_hit_in_air): straight in StraightAir; in GradedAir it follows the ray equation
// by AdaptiveStepper's steps, and each step's chord is tested against the scene: the
// first surface a chord meets is where the ray lands (a chord is within the stepper's
// tolerance of the true path). Surfaces shade as usual; the rays they send on (any ray
// back in the air) curve again. Shadow rays stay straight: over the few metres to
// kilometres a scene spans, air bends light by well under a degree, enough to move an
// image (the mirage) and too little to move a shadow's edge visibly; tracing the curved
// path that reaches a light is a boundary-value problem left for later.
//
// A caller may watch the path piece by piece (on_piece): every straight piece it takes
// through the air, in order, up to the surface it lands on; a caller that returns false
// stops the path there (a walker that scatters in fog filling the air).
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/core/ray.hpp>
#include <prism/medium/air.hpp>
#include <prism/medium/graded_index.hpp>
#include <prism/scene/hit.hpp>

#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

namespace prism {

namespace detail {

/// A straight piece of a path, tested against the scene a hair past its end: a surface
/// exactly where one piece ends and the next begins (a floor on a layer boundary) is
/// otherwise missed by both, the first ending just short of it by rounding, the second
/// starting on it.
template <class SceneT>
[[nodiscard]] std::optional<Hit<typename SceneT::scalar_type>> hit_on_piece(const SceneT& scene, const Ray<typename SceneT::scalar_type>& piece,
                                                                           typename SceneT::scalar_type piece_length) noexcept
{
    using T = typename SceneT::scalar_type;
    const T slack = T(64) * std::numeric_limits<T>::epsilon() * (piece_length + max_component(abs(piece.origin)));
    return scene.closest_hit(piece, {T(0), piece_length + slack});
}

/// What a path shows a caller that does not watch its pieces: nothing, and it goes on.
struct AnyPiece {
    template <Scalar T>
    constexpr bool operator()(const Ray<T>&, T, T) const noexcept
    {
        return true;
    }
};

/// The length of a path up to its current piece, told where the path lands.
template <Scalar T>
struct PathLength {
    T travelled = T(0);
    T* out = nullptr;

    [[nodiscard]] std::optional<Hit<T>> landed(std::optional<Hit<T>> hit) const noexcept
    {
        if (hit && out != nullptr) *out = travelled + hit->crossing.t;
        return hit;
    }
};

/// The straight start of a path toward a slab or box of air: the surface it meets before
/// reaching the box (`hit`), or whether it reaches the box at all and how far away.
template <Scalar T>
struct Approach {
    std::optional<Hit<T>> hit;
    bool reaches = false;
    T distance = T(0);
};

template <class SceneT>
[[nodiscard]] Approach<typename SceneT::scalar_type> approach(const SceneT& scene, const Aabb<typename SceneT::scalar_type>& box,
                                                            const Ray<typename SceneT::scalar_type>& segment) noexcept
{
    using T = typename SceneT::scalar_type;
    const Interval<T> inside = box.clip(segment, {T(0), infinity<T>});
    if (inside.empty()) return {scene.closest_hit(segment, {T(0), infinity<T>}), false, T(0)};
    if (inside.min > T(0)) return {scene.closest_hit(segment, {T(0), inside.min}), true, inside.min};
    return {std::nullopt, true, T(0)};
}

} // namespace detail

/// Where a ray through layered air first meets a surface (see first_hit_through below).
template <class SceneT, IndexField F, class OnPiece = detail::AnyPiece>
[[nodiscard]] std::optional<Hit<typename SceneT::scalar_type>> first_hit_through(const SceneT& scene, const LayeredAir<F>& air,
                                                                                const Ray<typename SceneT::scalar_type>& ray,
                                                                                Ray<typename SceneT::scalar_type>& segment,
                                                                                typename SceneT::scalar_type* path = nullptr, OnPiece&& on_piece = {}) noexcept
{
    using T = typename SceneT::scalar_type;
    static_assert(std::same_as<T, typename F::scalar_type>, "LayeredAir's field must have the scene's scalar type");
    const LayeredMedium<F> medium(air.field, air.bottom, air.top, air.layers);
    segment = {ray.origin, normalize(ray.direction)};
    detail::PathLength<T> length_so_far{T(0), path};
    // The last straight piece, to the surface it meets or on forever.
    const auto last_piece = [&](std::optional<Hit<T>> hit) -> std::optional<Hit<T>> {
        if (!on_piece(std::as_const(segment), hit ? hit->crossing.t : infinity<T>, length_so_far.travelled)) return std::nullopt;
        return length_so_far.landed(hit);
    };
    const auto to_box = detail::approach(scene, Aabb<T>{{-infinity<T>, air.bottom, -infinity<T>}, {infinity<T>, air.top, infinity<T>}}, segment);
    if (to_box.hit || !to_box.reaches) return last_piece(to_box.hit);
    if (to_box.distance > T(0) && !on_piece(std::as_const(segment), to_box.distance, T(0))) return std::nullopt;
    length_so_far.travelled = to_box.distance;
    Vec3<T> origin = segment.at(to_box.distance), direction = segment.direction;
    // Entering through the top or bottom face, the ray starts in the layer it enters.
    int layer = medium.layer_of(origin.y + (direction.y > T(0) ? T(0.5) : T(-0.5)) * (air.top - air.bottom) / T(air.layers));
    for (int i = 0; i < 4 * air.layers + 4; ++i) {
        const Vec3<T> start = origin, heading = direction;
        const bool inside_layers = medium.step(origin, direction, layer);
        const T length_now = length(origin - start);
        segment = {start, heading};
        if (length_now > T(0)) {
            if (auto hit = detail::hit_on_piece(scene, segment, length_now)) return last_piece(hit);
            if (!on_piece(std::as_const(segment), length_now, length_so_far.travelled)) return std::nullopt;
        }
        length_so_far.travelled += length_now;
        if (!inside_layers) {
            if (heading.y == T(0)) return last_piece(scene.closest_hit(segment, {T(0), infinity<T>})); // level: straight on
            segment = {origin, direction};
            return last_piece(scene.closest_hit(segment, {T(0), infinity<T>}));
        }
    }
    return std::nullopt;
}

/// Where a ray through curved air first meets a surface of the scene, or nothing; on a
/// hit, `segment` is the straight piece (unit direction) on which it lies, the ray to
/// shade with, and `path` (if given) receives the length of the whole curved path.
/// on_piece(piece, length, before) is shown each straight piece of the path in order
/// (unit direction; its length, infinite for the last if it meets nothing; the path's
/// length before it), and returns false to stop the path there (then nothing is met).
template <class SceneT, IndexField F, class OnPiece = detail::AnyPiece>
[[nodiscard]] std::optional<Hit<typename SceneT::scalar_type>> first_hit_through(const SceneT& scene, const GradedAir<F>& air,
                                                                                const Ray<typename SceneT::scalar_type>& ray,
                                                                                Ray<typename SceneT::scalar_type>& segment,
                                                                                typename SceneT::scalar_type* path = nullptr, OnPiece&& on_piece = {}) noexcept
{
    using T = typename SceneT::scalar_type;
    static_assert(std::same_as<T, typename F::scalar_type>, "GradedAir's field must have the scene's scalar type");
    segment = {ray.origin, normalize(ray.direction)};
    detail::PathLength<T> length_so_far{T(0), path}; // along the path, up to `segment`'s origin
    // The last straight piece, to the surface it meets or on forever.
    const auto last_piece = [&](std::optional<Hit<T>> hit) -> std::optional<Hit<T>> {
        if (!on_piece(std::as_const(segment), hit ? hit->crossing.t : infinity<T>, length_so_far.travelled)) return std::nullopt;
        return length_so_far.landed(hit);
    };
    const auto to_box = detail::approach(scene, air.region, segment);
    if (to_box.hit || !to_box.reaches) return last_piece(to_box.hit);
    if (to_box.distance > T(0) && !on_piece(std::as_const(segment), to_box.distance, T(0))) return std::nullopt;
    length_so_far.travelled = to_box.distance;
    CurvedRay<T> curved = curved_ray(air.field, Ray<T>{segment.at(to_box.distance), segment.direction});
    const AdaptiveStepper<F> stepper(air.field, air.stepping);
    T dt = T(0);
    for (int i = 0; i < air.max_steps; ++i) {
        const CurvedRay<T> start = curved;
        T taken = T(0);
        stepper.step(curved, dt, &taken);
        const Vec3<T> chord = curved.position - start.position;
        const T chord_length = length(chord);
        if (!(chord_length > T(0))) continue;
        segment = {start.position, chord / chord_length};
        if (auto hit = detail::hit_on_piece(scene, segment, chord_length)) {
            // Home in on the landing point along the curve: halve the step while its
            // chord is long, keeping the half whose chord meets the surface.
            CurvedRay<T> from = start;
            T h = taken;
            T length_now = chord_length;
            while (length_now > air.landing_chord && h > T(0)) {
                h /= T(2);
                const CurvedRay<T> middle = sharma_step(air.field, from, h);
                const Vec3<T> first = middle.position - from.position;
                const T first_length = length(first);
                if (!(first_length > T(0))) break;
                const Ray<T> first_segment{from.position, first / first_length};
                if (auto near = detail::hit_on_piece(scene, first_segment, first_length)) {
                    segment = first_segment;
                    hit = near;
                    length_now = first_length;
                    continue;
                }
                const CurvedRay<T> end = sharma_step(air.field, middle, h);
                const Vec3<T> second = end.position - middle.position;
                const T second_length = length(second);
                if (!(second_length > T(0))) break;
                const Ray<T> second_segment{middle.position, second / second_length};
                auto far = detail::hit_on_piece(scene, second_segment, second_length);
                if (!far) break; // the curve grazes past where the chord met it: keep the chord's hit
                if (!on_piece(first_segment, first_length, length_so_far.travelled)) return std::nullopt; // passed
                segment = second_segment;
                hit = far;
                from = middle;
                length_so_far.travelled += first_length;
                length_now = second_length;
            }
            return last_piece(hit);
        }
        if (!on_piece(std::as_const(segment), chord_length, length_so_far.travelled)) return std::nullopt;
        length_so_far.travelled += chord_length;
        if (!air.region.contains(curved.position)) {
            // Out of the box: straight from here on.
            segment = {curved.position, curved.direction()};
            return last_piece(scene.closest_hit(segment, {T(0), infinity<T>}));
        }
    }
    return std::nullopt;
}

/// The air through which rays curve: the air itself (GradedAir, LayeredAir), or the air a
/// medium fills (FilledAir's base).
template <class Air>
[[nodiscard]] constexpr const auto& bending_air(const Air& air) noexcept
{
    if constexpr (requires { air.base; }) return air.base;
    else return air;
}

/// The first surface a ray in the air meets: along the curve in GradedAir or LayeredAir
/// (or fog filling them), straight in StraightAir (where `segment` is the ray itself).
/// `path`, if given, receives the length travelled to it. on_piece, if given, is shown
/// each straight piece of the path (first_hit_through's; in straight air the one piece,
/// the ray with its direction made unit) and may stop the path (then nothing is met).
template <class SceneT, class Air, class OnPiece = detail::AnyPiece>
[[nodiscard]] std::optional<Hit<typename SceneT::scalar_type>> first_hit_in_air(const SceneT& scene, const Air& air,
                                                                               const Ray<typename SceneT::scalar_type>& ray,
                                                                               Ray<typename SceneT::scalar_type>& segment,
                                                                               typename SceneT::scalar_type* path = nullptr, OnPiece&& on_piece = {}) noexcept
{
    using T = typename SceneT::scalar_type;
    if constexpr (Air::curved) {
        return first_hit_through(scene, bending_air(air), ray, segment, path, on_piece);
    } else {
        segment = ray;
        auto hit = scene.closest_hit(ray, {T(0), infinity<T>});
        if constexpr (!std::is_same_v<std::remove_cvref_t<OnPiece>, detail::AnyPiece>) {
            const T scale = length(ray.direction);
            if (!on_piece(Ray<T>{ray.origin, normalize(ray.direction)}, hit ? hit->crossing.t * scale : infinity<T>, T(0))) return std::nullopt;
        }
        if (hit && path != nullptr) *path = hit->crossing.t * length(ray.direction);
        return hit;
    }
}

} // namespace prism
