// SPDX-License-Identifier: MIT
// Quad: a flat parallelogram, an open surface (an area light's usual shape).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/sampling.hpp>
#include <prism/geometry/plane.hpp>
#include <prism/geometry/shape.hpp>
#include <prism/geometry/surface_point.hpp>

#include <cmath>
#include <limits>

namespace prism {

/// The parallelogram corner + s edge_u + t edge_v, s and t in [0, 1]: an open surface,
/// never inside, which a ray enters where it arrives on the side of its normal,
/// cross(edge_u, edge_v) (the side an area light on it shines to). Its uv is (s, t).
template <Scalar T = float>
class Quad {
public:
    /// The precision of the quad and the crossings.
    using scalar_type = T;
    /// At most one crossing.
    static constexpr std::size_t max_crossings = 1;

    /// The quad at `corner` spanned by two edges; throws std::invalid_argument for a
    /// non-finite corner or edge, or edges whose cross product is zero, not finite or
    /// not normal (a degenerate quad).
    constexpr Quad(const Vec3<T>& corner, const Vec3<T>& edge_u, const Vec3<T>& edge_v) : corner_(corner), u_(edge_u), v_(edge_v)
    {
        detail::require_finite("Quad corner", corner);
        detail::require_nonzero("Quad edge_u", edge_u);
        detail::require_nonzero("Quad edge_v", edge_v);
        const Vec3<T> n = cross(edge_u, edge_v);
        const T area2 = length_squared(n);
        if (!(area2 >= std::numeric_limits<T>::min()) || !is_finite(area2) || !is_finite(corner + edge_u + edge_v))
            detail::throw_invalid("Quad edges ", detail::describe(edge_u), " and ", detail::describe(edge_v),
                                  " must span a parallelogram of finite, non-zero area (|edge_u x edge_v|^2 = ", area2, ")");
        area_ = prism::sqrt(area2);
        normal_ = n / area_;
        offset_ = dot(normal_, corner_);
        // The dual edges: dot(p - corner, dual_u) is s, dot(p - corner, dual_v) is t.
        dual_u_ = cross(edge_v, normal_) / dot(edge_u, cross(edge_v, normal_));
        dual_v_ = cross(normal_, edge_u) / dot(edge_v, cross(normal_, edge_u));
        rectangle_ = std::abs(dot(edge_u, edge_v)) <= T(1e-5) * length(edge_u) * length(edge_v);
        // The rectangle's own frame, for sampling by solid angle: x along edge_u, y along
        // edge_v, z = x cross y (its normal).
        length_u_ = length(u_), length_v_ = length(v_);
        ex_ = u_ / length_u_;
        ey_ = normalize(v_ - dot(v_, ex_) * ex_);
    }

    /// The corner the edges start from.
    [[nodiscard]] constexpr const Vec3<T>& corner() const noexcept { return corner_; }
    /// The first edge (s).
    [[nodiscard]] constexpr const Vec3<T>& edge_u() const noexcept { return u_; }
    /// The second edge (t).
    [[nodiscard]] constexpr const Vec3<T>& edge_v() const noexcept { return v_; }
    /// The unit normal, cross(edge_u, edge_v) normalised: the front.
    [[nodiscard]] constexpr const Vec3<T>& normal() const noexcept { return normal_; }
    /// The area |edge_u x edge_v|.
    [[nodiscard]] constexpr T area() const noexcept { return area_; }
    /// Whether the edges are at right angles (to 10^-5): a rectangle, sampled by solid angle.
    [[nodiscard]] constexpr bool rectangle() const noexcept { return rectangle_; }

    /// The box around the four corners, rounded outward.
    [[nodiscard]] constexpr Aabb<T> bounds() const noexcept
    {
        Aabb<T> box{corner_, corner_};
        for (const Vec3<T>& p : {corner_ + u_, corner_ + v_, corner_ + u_ + v_}) box = {component_min(box.lo, p), component_max(box.hi, p)};
        return box.rounded_out();
    }

    /// Never: a quad has no inside.
    [[nodiscard]] constexpr bool contains(const Vec3<T>&) const noexcept { return false; }

    /// The crossing of `ray` within `range`, if it meets the quad there: entering where
    /// it arrives against the normal.
    template <bool Surface = true>
    [[nodiscard]] constexpr Crossings<T, 1> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        Crossings<T, 1> out;
        const T denom = dot(normal_, ray.direction);
        if (denom == T(0)) return out;
        const T t = (offset_ - dot(normal_, ray.origin)) / denom;
        if (!range.surrounds(t)) return out;
        const Vec3<T> point = detail::onto_plane(normal_, offset_, ray.at(t));
        const Vec3<T> local = point - corner_;
        const T s = dot(local, dual_u_), r = dot(local, dual_v_);
        if (!(s >= T(0) && s <= T(1) && r >= T(0) && r <= T(1))) return out;
        const bool entering = denom < T(0);
        if constexpr (!Surface) {
            out.push_back(Crossing<T>::without_surface(t, entering));
        } else {
            // Its coordinates come with it: (s, r) are at hand, and dp/du, dp/dv are its edges.
            out.push_back(Crossing<T>::flat(t, point, detail::plane_point_error(normal_, offset_, point), normal_, entering).with_uv({s, r}, u_, v_));
        }
        return out;
    }

    /// Surface coordinates of a point of the quad (its crossings come with them already;
    /// an area light's sampled point asks here): (s, r) along its edges, in [0, 1]^2, its
    /// edges dp/du and dp/dv.
    void coordinates(Crossing<T>& c) const noexcept
    {
        const Vec3<T> local = c.point - corner_;
        c = c.with_uv({dot(local, dual_u_), dot(local, dual_v_)}, u_, v_);
    }

    /// A point uniform over the quad for u in the unit square, with density 1 / area.
    [[nodiscard]] SurfacePoint<T> sample_area(const Vec2<T>& u) const noexcept
    {
        return {corner_ + u.x * u_ + u.y * v_, normal_, T(1) / area_};
    }

    /// A point of the quad seen from p, by solid angle where it is a rectangle seen
    /// under more than min_solid_angle (Urena, Fajardo and King 2013, "An area-preserving
    /// parametrization for spherical rectangles"), else by area; `pdf` per steradian.
    [[nodiscard]] SurfacePoint<T> sample_from(const Vec3<T>& p, const Vec2<T>& u) const noexcept
    {
        if (rectangle_) {
            const SphericalRectangle r = spherical_rectangle(p);
            if (r.solid_angle > min_solid_angle) return {r.point(u), normal_, T(1) / r.solid_angle};
        }
        SurfacePoint<T> s = sample_area(u);
        s.pdf = area_to_solid_angle(s.pdf, p, s.point, s.normal);
        return s;
    }

    /// The solid-angle density sample_from(p, .) gives the point x of the quad.
    [[nodiscard]] T pdf_from(const Vec3<T>& p, const Vec3<T>& x) const noexcept
    {
        if (rectangle_) {
            const T omega = spherical_rectangle(p).solid_angle;
            if (omega > min_solid_angle) return T(1) / omega;
        }
        return area_to_solid_angle(T(1) / area_, p, x, normal_);
    }

    /// Below this solid angle (steradians) a rectangle is sampled by area: its spherical
    /// parametrization loses its digits as the rectangle shrinks to a point, and area
    /// sampling is as good there (the solid angle is nearly proportional to the area).
    static constexpr T min_solid_angle = T(1e-3);

    /// The solid angle the quad subtends at p (a rectangle's exactly, a parallelogram's
    /// from its two triangles).
    [[nodiscard]] T solid_angle(const Vec3<T>& p) const noexcept
    {
        if (rectangle_) return spherical_rectangle(p).solid_angle;
        return triangle_solid_angle(p, corner_, corner_ + u_, corner_ + u_ + v_) + triangle_solid_angle(p, corner_, corner_ + u_ + v_, corner_ + v_);
    }

private:
    /// The rectangle in a frame at p: x along edge_u, y along edge_v, z against the side p is on.
    struct SphericalRectangle {
        Vec3<T> origin, ex, ey, ez;
        T x0, y0, x1, y1, z0;
        T b0, b1, k, solid_angle;

        [[nodiscard]] Vec3<T> point(const Vec2<T>& u) const noexcept
        {
            // u.x picks the solid angle swept from the x0 edge: a great-circle arc through the
            // rectangle at x = xu; u.y the point along it, uniform in the sine of its elevation.
            const T au = u.x * solid_angle + k;
            const T fu = (std::cos(au) * b0 - b1) / std::sin(au);
            T cu = std::copysign(T(1) / prism::sqrt(fu * fu + b0 * b0), fu);
            cu = clamp(cu, T(-1) + std::numeric_limits<T>::epsilon(), T(1) - std::numeric_limits<T>::epsilon());
            T xu = -(cu * z0) / prism::sqrt(std::max(T(0), T(1) - cu * cu));
            xu = clamp(xu, x0, x1);
            const T d = prism::sqrt(xu * xu + z0 * z0);
            const T h0 = y0 / prism::sqrt(d * d + y0 * y0), h1 = y1 / prism::sqrt(d * d + y1 * y1);
            const T hv = h0 + u.y * (h1 - h0), hv2 = hv * hv;
            const T yv = hv2 < T(1) - T(1e-6) ? hv * d / prism::sqrt(T(1) - hv2) : y1;
            return origin + xu * ex + clamp(yv, y0, y1) * ey + z0 * ez;
        }
    };

    [[nodiscard]] SphericalRectangle spherical_rectangle(const Vec3<T>& p) const noexcept
    {
        SphericalRectangle r{};
        r.origin = p;
        r.ex = ex_, r.ey = ey_, r.ez = cross(ex_, ey_);
        const Vec3<T> d = corner_ - p;
        r.x0 = dot(d, r.ex), r.y0 = dot(d, r.ey), r.z0 = dot(d, r.ez);
        if (r.z0 > T(0)) r.z0 = -r.z0, r.ez = -r.ez;
        r.x1 = r.x0 + length_u_, r.y1 = r.y0 + length_v_;
        if (!(r.z0 < T(0))) return r; // p in the rectangle's plane: it subtends nothing
        // The interior angle of the spherical rectangle at a corner (x, y, z0) is that
        // between the planes through p and the two edges meeting there: its sine is
        // |z0| |(x, y, z0)| / (N N'), its cosine -+x y / (N N'), N and N' the lengths of
        // those planes' normals (0, z0, -y) and (-z0, 0, x) (Urena et al.'s n0 to n3).
        // The angles are summed in pairs along the edges x = x1 and x = x0 (sin and cos of
        // a sum, the common N N' left out), each pair by one atan2: exact near 0 and pi
        // alike, and a sum in (0, 2 pi) taken back from atan2's (-pi, pi].
        const T z = -r.z0, z2 = z * z;
        const auto pair = [&](T x, T ya, T yb) {
            const T sa = z * prism::sqrt(x * x + ya * ya + z2), ca = x * ya;  // at (x, ya)
            const T sb = z * prism::sqrt(x * x + yb * yb + z2), cb = -x * yb; // at (x, yb)
            const T sum = std::atan2(sa * cb + ca * sb, ca * cb - sa * sb);
            return sum < T(0) ? sum + T(2) * pi<T> : sum;
        };
        const T g01 = pair(r.x1, r.y0, r.y1);                // angles at (x1, y0) and (x1, y1)
        const T g23 = pair(r.x0, r.y1, r.y0);                // at (x0, y1) and (x0, y0)
        r.b0 = -r.y0 / prism::sqrt(z2 + r.y0 * r.y0), r.b1 = r.y1 / prism::sqrt(z2 + r.y1 * r.y1); // n0.z and n2.z
        r.k = -g23;
        r.solid_angle = std::max(T(0), g01 + g23 - T(2) * pi<T>);
        return r;
    }

    Vec3<T> corner_, u_, v_;
    Vec3<T> normal_{};
    T offset_ = T(0), area_ = T(0);
    Vec3<T> dual_u_{}, dual_v_{};
    Vec3<T> ex_{}, ey_{};
    T length_u_ = T(0), length_v_ = T(0);
    bool rectangle_ = false;
};

static_assert(Shape<Quad<float>>);
static_assert(Shape<Quad<double>>);

} // namespace prism
