// SPDX-License-Identifier: MIT
// Transformed: any shape moved by an affine transform (rotate, scale, translate, shear).
#pragma once

#include <prism/core/transform.hpp>
#include <prism/geometry/shape.hpp>

#include <utility>

namespace prism {

/// A shape under an affine transform from its own coordinates to the world's. The ray
/// is carried into the shape's coordinates without renormalising its direction, so t
/// means the same in both; normals map by the inverse transpose, so they stay right
/// under non-uniform scale; hit-point error bounds are carried through the matrix.
template <Shape S>
class Transformed {
public:
    using scalar_type = typename S::scalar_type;
    using T = scalar_type;
    static constexpr std::size_t max_crossings = S::max_crossings;

    // Transformed Public Methods

    Transformed(S shape, const Transform<T>& to_world) : shape_(std::move(shape)), to_world_(to_world), bounds_(world_bounds()) {}

    [[nodiscard]] const S& shape() const noexcept { return shape_; }
    [[nodiscard]] const Transform<T>& transform() const noexcept { return to_world_; }
    [[nodiscard]] Aabb<T> bounds() const noexcept { return bounds_; }

    [[nodiscard]] bool contains(const Vec3<T>& p) const noexcept
    {
        return shape_.contains(Vec3<T>(to_world_.inverse_matrix() * glm::vec<4, T>(p, T(1))));
    }

    [[nodiscard]] Crossings<T, max_crossings> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        const Mat4<T>& inv = to_world_.inverse_matrix();
        const Ray<T> local{Vec3<T>(inv * glm::vec<4, T>(ray.origin, T(1))), Vec3<T>(inv * glm::vec<4, T>(ray.direction, T(0)))};
        Crossings<T, max_crossings> out = shape_.crossings(local, range);
        for (std::size_t k = 0; k < out.count; ++k) {
            Crossing<T>& c = out.items[k];
            c.error = to_world_.point_error(c.point, c.error);
            c.point = to_world_.point(c.point);
            c.normal = normalize(to_world_.normal(c.normal));
        }
        return out;
    }

private:
    /// The box around the eight transformed corners of the shape's box.
    [[nodiscard]] Aabb<T> world_bounds() const noexcept
    {
        const Aabb<T> local = shape_.bounds();
        if (local.empty()) return local;
        if (!is_finite(local.lo) || !is_finite(local.hi)) return Aabb<T>::universe();
        Aabb<T> out;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3<T> p{corner & 1 ? local.hi.x : local.lo.x, corner & 2 ? local.hi.y : local.lo.y, corner & 4 ? local.hi.z : local.lo.z};
            const Vec3<T> w = to_world_.point(p);
            out.lo = component_min(out.lo, w);
            out.hi = component_max(out.hi, w);
        }
        // Widen by the rounding of the corner transform.
        const Vec3<T> pad = gamma<T>(4) * (abs(out.lo) + abs(out.hi));
        return {out.lo - pad, out.hi + pad};
    }

    S shape_;
    Transform<T> to_world_;
    Aabb<T> bounds_;
};

} // namespace prism
