// SPDX-License-Identifier: MIT
// Transformed: any shape moved by an affine transform (rotate, scale, translate, shear).
#pragma once

#include <prism/core/transform.hpp>
#include <prism/geometry/shape.hpp>

#include <cstdint>
#include <optional>
#include <utility>

namespace prism {

/// A shape that knows its box under a transform better than the box around its own
/// box's transformed corners: `bounds_under(transform)` (a CSG node, from its children's).
template <class S>
concept HasBoundsUnder = Shape<S> && requires(const S& shape, const Transform<typename S::scalar_type>& transform) {
    { shape.bounds_under(transform) } -> std::same_as<Aabb<typename S::scalar_type>>;
};

/// The box around `shape` carried by `transform`: its own (HasBoundsUnder), else the box
/// around its box's transformed corners, cut down where it has a sphere of its own to
/// that sphere's ellipsoid's box (a turned ball's box is its own size; its box's turned
/// corners' is up to sqrt(3) times as wide on an axis).
template <Shape S>
[[nodiscard]] Aabb<typename S::scalar_type> bounds_under(const S& shape, const Transform<typename S::scalar_type>& transform) noexcept
{
    if constexpr (HasBoundsUnder<S>) {
        return shape.bounds_under(transform);
    } else {
        const Aabb<typename S::scalar_type> box = transform.box(shape.bounds());
        if constexpr (HasBoundingSphere<S>) {
            const auto ball = shape.bounding_sphere();
            const auto own = transform.sphere_box(ball.center, ball.radius);
            return {component_max(box.lo, own.lo), component_min(box.hi, own.hi)};
        }
        return box;
    }
}

/// A shape under an affine transform from its own coordinates to the world's. The ray
/// is carried into the shape's coordinates without renormalising its direction, so t
/// means the same in both; normals map by the inverse transpose, so they stay right
/// under non-uniform scale; hit-point error bounds are carried through the matrix.
template <Shape S>
class Transformed {
public:
    /// The shape's precision.
    using scalar_type = typename S::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;
    /// As many crossings as the shape has.
    static constexpr std::size_t max_crossings = S::max_crossings;
    /// The shape's CSG depth (Crossing::path passes through).
    static constexpr std::size_t csg_depth = detail::csg_depth<S>();

    // Transformed Public Methods

    /// `shape` moved into the world by `to_world`.
    Transformed(S shape, const Transform<T>& to_world) : shape_(std::move(shape)), to_world_(to_world), bounds_(world_bounds())
    {
        bounded_ = bounds_.bounded();
        if (bounded_) near_ = NearBox<T>(bounds_);
    }

    /// The shape, in its own frame.
    [[nodiscard]] const S& shape() const noexcept { return shape_; }
    /// The transform from the shape's frame to the world.
    [[nodiscard]] const Transform<T>& transform() const noexcept { return to_world_; }
    /// The world box around the shape's transformed box, rounded outward.
    [[nodiscard]] Aabb<T> bounds() const noexcept { return bounds_; }

    /// Convex where the shape is (an affine map keeps a convex set convex).
    [[nodiscard]] bool convex() const noexcept { return prism::convex(shape_); }

    /// Whether world point p is inside the shape.
    [[nodiscard]] bool contains(const Vec3<T>& p) const noexcept
    {
        return shape_.contains(to_world_.inverse_point(p));
    }

    /// Every crossing of the world `ray` within `range`: the shape's, in the shape's frame, carried back with normals by the inverse transpose and error bounds through the matrix.
    template <bool Surface = true>
    [[nodiscard]] Crossings<T, max_crossings> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        // A ray that cannot come near the bounds cannot cross the shape.
        if (bounded_ && !bounds_.reached_after(ray, range.min)) return {};
        const LocalRay local = to_local(ray);
        const T dt = local.dt;
        // The end of the range is carried over two float steps wide and applied again to
        // the world t: the result keeps every crossing before range.max however the
        // subtraction rounds, so a query over a shorter range finds the same first one.
        Crossings<T, max_crossings> out = shape_.template crossings<Surface>(local.ray, local.range(range));
        std::size_t kept = 0;
        for (std::size_t k = 0; k < out.count; ++k) {
            out.items[k].t += dt;
            if (out.items[k].t < range.max) out.items[kept++] = out.items[k];
        }
        out.count = kept;
        if constexpr (!Surface) return out;
        for (std::size_t k = 0; k < out.count; ++k) to_world(out.items[k]);
        return out;
    }

    /// crossings<false>(ray, range).front().t (infinity if none): the shape's own lean
    /// query, when it has one, in its coordinates.
    [[nodiscard]] T first_crossing(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        SurfaceHint<T> unused;
        return first_crossing_with(ray, range, unused);
    }

    /// Whether the ray crosses the shape within `range` (a shadow ray's query).
    [[nodiscard]] bool any_crossing(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        return first_crossing(ray, range) < infinity<T>;
    }

    /// first_crossing, with the shape's hint for surface_crossing (a mesh's triangle).
    [[nodiscard]] T first_crossing(const Ray<T>& ray, Interval<T> range, SurfaceHint<T>& hint) const noexcept
        requires HasHintedSurface<S>
    {
        return first_crossing_with(ray, range, hint);
    }

    /// crossings(ray, range).front(), from the shape's hint.
    [[nodiscard]] std::optional<Crossing<T>> surface_crossing(const Ray<T>& ray, Interval<T> range, const SurfaceHint<T>& hint) const noexcept
        requires HasHintedSurface<S>
    {
        if (bounded_ && !bounds_.reached_after(ray, range.min)) return std::nullopt;
        const LocalRay local = to_local(ray);
        std::optional<Crossing<T>> c = shape_.surface_crossing(local.ray, local.range(range), hint);
        if (!c) return c;
        c->t += local.dt;
        if (!(c->t < range.max)) return std::nullopt;
        to_world(*c);
        return c;
    }

    /// Surface coordinates: the shape's own at the crossing carried back into its frame,
    /// their derivatives carried out to the world's.
    void coordinates(Crossing<T>& c) const noexcept
        requires HasCoordinates<S>
    {
        Crossing<T> local = c;
        local.point = to_world_.inverse_point(c.point);
        local.normal = normalize(to_world_.inverse_normal(c.normal));
        shape_.coordinates(local);
        c.uv = local.uv;
        c.dpdu = to_world_.vector(local.dpdu);
        c.dpdv = to_world_.vector(local.dpdv);
    }

private:
    /// The shape's first crossing (and its hint, where it gives one), in world t.
    [[nodiscard]] T first_crossing_with(const Ray<T>& ray, Interval<T> range, SurfaceHint<T>& hint) const noexcept
    {
        if (bounded_ && !bounds_.reached_after(ray, range.min)) return infinity<T>;
        const LocalRay local = to_local(ray);
        const T t = prism::first_crossing(shape_, local.ray, local.range(range), hint) + local.dt;
        return t < range.max ? t : infinity<T>;
    }

    struct LocalRay {
        Ray<T> ray;
        T dt;       ///< local t + dt = world t
        T moved{0}; ///< how far along the world ray its origin was brought before the transform

        /// The world range in the shape's coordinates. (Its start not moved by the
        /// transform's own step past its rounding: no crossing of the shape lies there.)
        [[nodiscard]] Interval<T> range(const Interval<T>& world) const noexcept
        {
            return {world.min - moved, next_float_up(next_float_up(world.max - dt))};
        }
    };

    /// The ray in the shape's coordinates. The new origin is off by the rounding of that
    /// transform, which can be more than a spawned ray's offset from the surface it
    /// leaves: it is moved forward along the ray past that error, and t measured from
    /// there (pbrt-v4, Transform::ApplyInverse(Ray)).
    [[nodiscard]] LocalRay to_local(const Ray<T>& world) const noexcept
    {
        // A float ray from far off is first brought near the shape's box (core/aabb.hpp):
        // the transform's rounding of a far origin is as large as the shape.
        const NearRay<T> near = bounded_ ? brought_near(world, near_) : NearRay<T>{world};
        const Ray<T>& ray = near.ray;
        Ray<T> local{to_world_.inverse_point(ray.origin), to_world_.inverse_vector(ray.direction)};
        const T length2 = length_squared(local.direction);
        T dt = length2 > T(0) ? dot(abs(local.direction), to_world_.inverse_point_error(ray.origin)) / length2 : T(0);
        if (!is_finite(dt)) dt = T(0);
        local.origin += dt * local.direction;
        return {local, T(near.shift + double(dt)), T(near.shift)};
    }

    /// A crossing found in the shape's coordinates, carried to the world's.
    void to_world(Crossing<T>& c) const noexcept
    {
        // The bound also covers the rounding with which a ray spawned here is carried
        // back into the shape's coordinates, so that it starts on the side it leaves by
        // there too (moving its origin forward along the ray, above, does not cover that
        // for a ray leaving at a grazing angle).
        const Vec3<T> world = to_world_.point(c.point);
        c.error = to_world_.point_error(c.point, c.error + to_world_.inverse_point_error(world));
        c.point = world;
        const bool flat = c.shades_flat();
        c.normal = normalize(to_world_.normal(c.normal));
        c.shading = flat ? c.normal : normalize(to_world_.normal(c.shading));
        // A mesh's coordinates come with its crossing.
        c.dpdu = to_world_.vector(c.dpdu);
        c.dpdv = to_world_.vector(c.dpdv);
    }

    /// The world box around the shape: its own under the transform where it has one (a
    /// sphere's ellipsoid, a CSG node's from its children's), else the box around its
    /// box's transformed corners (bounds_under).
    [[nodiscard]] Aabb<T> world_bounds() const noexcept { return bounds_under(shape_, to_world_); }

    S shape_;
    Transform<T> to_world_;
    Aabb<T> bounds_;
    NearBox<T> near_; ///< the bounds as brought_near asks them, worked out once
    bool bounded_ = false;
};

} // namespace prism
