// SPDX-License-Identifier: MIT
// Sphere: the solid ball |p - center| <= radius.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/sampling.hpp>
#include <prism/geometry/shape.hpp>
#include <prism/geometry/surface_point.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

/// The solid sphere: a Shape with at most two crossings per ray.
template <Scalar T = float>
class Sphere {
public:
    /// The precision of the sphere and the crossings.
    using scalar_type = T;
    /// At most two crossings: in and out.
    static constexpr std::size_t max_crossings = 2;

    // Sphere Public Methods

    /// A sphere; throws std::invalid_argument for a non-finite center or a radius outside
    /// [detail::smallest_length, detail::largest_length] (float: 1.7e-18 to 1.2e18, so
    /// that r^2 neither underflows nor overflows).
    constexpr Sphere(const Vec3<T>& center, T radius) : center_(center), radius_(radius)
    {
        detail::require_finite("Sphere center", center);
        detail::require_length("Sphere radius", radius);
    }

    /// The centre.
    [[nodiscard]] constexpr const Vec3<T>& center() const noexcept { return center_; }
    /// The radius.
    [[nodiscard]] constexpr T radius() const noexcept { return radius_; }

    /// Its own sphere, the radius grown by 16 epsilon for rounding: tighter than the
    /// sphere around its box, which a caustic photon aimed at it would mostly miss.
    [[nodiscard]] constexpr BoundingSphere<T> bounding_sphere() const noexcept
    {
        return {center_, radius_ * (T(1) + T(16) * std::numeric_limits<T>::epsilon())};
    }

    /// A ball is convex.
    [[nodiscard]] static constexpr bool convex() noexcept { return true; }

    /// The box around the sphere, rounded outward.
    [[nodiscard]] constexpr Aabb<T> bounds() const noexcept
    {
        return Aabb<T>{center_ - Vec3<T>(radius_), center_ + Vec3<T>(radius_)}.rounded_out();
    }

    /// Whether p is strictly inside.
    [[nodiscard]] constexpr bool contains(const Vec3<T>& p) const noexcept
    {
        return length_squared(p - center_) < radius_ * radius_;
    }

    /// Every crossing of `ray` within `range` (at most two), sorted, the roots taken from the ray's closest approach to the centre (Haines et al. 2019, "Precision improvements for ray/sphere intersection").
    template <bool Surface = true>
    [[nodiscard]] constexpr Crossings<T, 2> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        Crossings<T, 2> out;
        const Roots r = roots(ray);
        if (!r.real) return out;
        // The ray is inside between the roots: it enters at t0 and leaves at t1, as
        // the gradient 2(p - center) points against d at t0 and along it at t1. The
        // surface points are taken from the closest approach l, at -+sqrt(disc) / a along
        // the ray from it: exact to the sphere's own scale however far the origin is,
        // where o + t d would carry the rounding of t (an ulp of the distance).
        out.inside_at_start = r.t0 < range.min && range.min < r.t1;
        if (range.surrounds(r.t0)) out.push_back(Surface ? crossing_at(r.closest - r.half_chord * ray.direction, r.t0, true) : Crossing<T>::without_surface(r.t0, true));
        if (range.surrounds(r.t1)) out.push_back(Surface ? crossing_at(r.closest + r.half_chord * ray.direction, r.t1, false) : Crossing<T>::without_surface(r.t1, false));
        return out;
    }

    /// crossings<false>(ray, range).front().t (infinity if none), without the list.
    [[nodiscard]] constexpr T first_crossing(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        const Roots r = roots(ray);
        if (!r.real) return infinity<T>;
        return range.surrounds(r.t0) ? r.t0 : (range.surrounds(r.t1) ? r.t1 : infinity<T>);
    }

    /// Whether the ray crosses the sphere within `range` (a shadow ray's query).
    [[nodiscard]] constexpr bool any_crossing(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        return first_crossing(ray, range) < infinity<T>;
    }

    /// The area 4 pi r^2.
    [[nodiscard]] constexpr T area() const noexcept { return T(4) * pi<T> * radius_ * radius_; }

    /// A point uniform over the sphere for u in the unit square, with density 1 / area.
    [[nodiscard]] SurfacePoint<T> sample_area(const Vec2<T>& u) const noexcept
    {
        const Vec3<T> n = uniform_sphere(u.x, u.y);
        return {center_ + radius_ * n, n, T(1) / area()};
    }

    /// A point of the sphere seen from p: from outside, uniform over the cone of directions
    /// that meet it (density 1 / (2 pi (1 - cos theta_max)) per steradian), the point
    /// where the direction first meets it; from inside (or on it), by area.
    [[nodiscard]] SurfacePoint<T> sample_from(const Vec3<T>& p, const Vec2<T>& u) const noexcept
    {
        const Cone cone = cone_from(p);
        if (!cone.outside) {
            SurfacePoint<T> s = sample_area(u);
            s.pdf = area_to_solid_angle(s.pdf, p, s.point, s.normal);
            return s;
        }
        // cos theta uniform in [cos theta_max, 1]; 1 - cos theta and sin^2 theta kept
        // without cancellation for the small cones of far lights.
        const T one_minus_cos = u.x * cone.one_minus_cos;
        const T cos_theta = T(1) - one_minus_cos;
        const T sin2_theta = one_minus_cos * (T(2) - one_minus_cos);
        const T phi = T(2) * pi<T> * u.y;
        const auto [s, t] = orthonormal_frame(cone.axis);
        const T sin_theta = prism::sqrt(sin2_theta);
        const Vec3<T> w = sin_theta * std::cos(phi) * s + sin_theta * std::sin(phi) * t + cos_theta * cone.axis;
        // The nearer crossing of the line p + d w with the sphere: d = dc cos - sqrt(r^2 - dc^2 sin^2).
        const T dc = cone.distance;
        const T d = dc * cos_theta - prism::sqrt(std::max(T(0), radius_ * radius_ - dc * dc * sin2_theta));
        const Vec3<T> n = normalize(p + d * w - center_);
        return {center_ + radius_ * n, n, T(1) / (T(2) * pi<T> * cone.one_minus_cos)};
    }

    /// The solid-angle density sample_from(p, .) gives the point x of the sphere.
    [[nodiscard]] T pdf_from(const Vec3<T>& p, const Vec3<T>& x) const noexcept
    {
        const Cone cone = cone_from(p);
        if (!cone.outside) return area_to_solid_angle(T(1) / area(), p, x, normalize(x - center_));
        return T(1) / (T(2) * pi<T> * cone.one_minus_cos);
    }

    /// Surface coordinates (docs/guide.md) of a crossing of this sphere, from its normal:
    /// u = 1/2 + atan2(-n.x, -n.z) / 2 pi round the vertical axis (0 at +z, 1/4 at +x, 1/2
    /// at -z, 3/4 at -x), v = 1 - theta / pi from the bottom (-y) to the top (+y), theta
    /// the angle from +y. Seen from outside (dp/du, dp/dv, n) is right-handed, so a picture
    /// reads the right way round.
    void coordinates(Crossing<T>& c) const noexcept
    {
        const Vec3<T>& n = c.normal;
        const T rho = prism::sqrt(n.x * n.x + n.z * n.z);
        c.uv = {T(0.5) + std::atan2(-n.x, -n.z) / (T(2) * pi<T>), T(1) - std::atan2(rho, n.y) / pi<T>};
        c.dpdu = (T(2) * pi<T> * radius_) * Vec3<T>(n.z, T(0), -n.x);
        // At a pole u's direction is undefined; there atan2(-0, -0) = 0 picks the meridian through -z.
        const T sx = rho > T(0) ? n.x / rho : T(0), sz = rho > T(0) ? n.z / rho : T(-1);
        c.dpdv = (pi<T> * radius_) * Vec3<T>(-n.y * sx, rho, -n.y * sz);
    }

private:
    // Sphere Private Methods

    /// Where the ray's line crosses the sphere: t0 < t1, or no real pair (a miss or a
    /// tangent); the closest approach to the center and the half chord over a, from
    /// which the crossing points are taken.
    struct Roots {
        bool real = false;
        T t0 = 0, t1 = 0;
        Vec3<T> closest{};
        T half_chord = 0;
    };

    /// The cone of directions from p that meet the sphere: its axis, 1 - cos of its
    /// half-angle (r^2 / dc^2 = sin^2, over 1 + cos), and whether p is outside at all.
    struct Cone {
        bool outside = false;
        Vec3<T> axis{};
        T distance = T(0), one_minus_cos = T(0);
    };

    [[nodiscard]] Cone cone_from(const Vec3<T>& p) const noexcept
    {
        const Vec3<T> to = center_ - p;
        const T dc2 = length_squared(to);
        const T r2 = radius_ * radius_;
        // Just outside, the cone is nearly a hemisphere and a point by area is as good.
        if (!(dc2 > r2 * T(1.0001))) return {};
        const T dc = prism::sqrt(dc2);
        const T sin2_max = r2 / dc2;
        const T cos_max = prism::sqrt(std::max(T(0), T(1) - sin2_max));
        return {true, to / dc, dc, sin2_max / (T(1) + cos_max)};
    }

    [[nodiscard]] constexpr Roots roots(const Ray<T>& ray) const noexcept
    {
        // Compute quadratic coefficients: a t^2 + 2 h t + c = 0 with f = o - center
        const Vec3<T> f = ray.origin - center_;
        const Vec3<T>& d = ray.direction;
        const T a = length_squared(d);
        const T h = dot(f, d);
        const T c = length_squared(f) - radius_ * radius_;

        // Compute the discriminant without cancellation (Haines et al., "Precision
        // Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019, ch. 7):
        // h^2 - a c = a (r^2 - |f - (h/a) d|^2), where the vector is the ray's closest
        // approach to the center.
        const Vec3<T> l = f - (h / a) * d;
        const T ll2 = length_squared(l);
        if constexpr (sizeof(T) < sizeof(double)) {
            // In float, l is off the line by the rounding of f and of the product (h/a) d,
            // and off the closest approach along it by the rounding of h/a, which |l|^2
            // counts squared: each of order eps |f|, 10^-3 when the ray starts 10^4 away.
            // With e bounding a component's error (16 eps |f|), |l|^2 is off by at most
            // 2 |l| e + e^2 and its own rounding, 4 eps (|l|^2 + r^2): within
            // 4 r e + e^2 + 20 eps r^2 where |l| <= 2r, and never enough to cross r^2
            // beyond that while e <= r / 4. Where |l|^2 is that near r^2 (or the sphere
            // that small for its distance), the side is decided in double. First, cheaply:
            // from within 1000 r (|f|^2 = c + r^2), e < 0.002 r and all of that is below
            // r^2 / 100, so a gap wider than that is decided as it is: most misses leave
            // on one well-predicted branch, as they did before.
            constexpr T eps = std::numeric_limits<T>::epsilon();
            const T r2 = radius_ * radius_, gap = ll2 - r2;
            const bool near = c < T(1e6) * r2;
            if (near & (gap > T(0.01) * r2)) return {};
            if (!(near & (gap < T(-0.01) * r2))) {
                // (|x| as max(x, -x), which compiles to maxss: x < 0 ? -x : x became a
                // branch on the sign, mispredicted half the time.)
                const auto magnitude = [](T x) { return x > -x ? x : -x; };
                const T e = T(16) * eps * max_component(Vec3<T>(magnitude(f.x), magnitude(f.y), magnitude(f.z)));
                if ((e > T(0.25) * radius_) | !(magnitude(gap) > (T(4) * radius_ + e) * e + T(20) * eps * r2)) return roots_in_double(ray, a, h, c);
                if (gap > T(0)) return {};
            }
        } else {
            // A clear miss, decided before any square root: |l|^2 is computed to within a
            // few ulps, so beyond r^2 (1 + 8 eps) the ray passes outside the sphere.
            if (ll2 > radius_ * radius_ * (T(1) + T(8) * std::numeric_limits<T>::epsilon())) return {};
        }
        const T ll = prism::sqrt(ll2);
        const T disc = a * (radius_ - ll) * (radius_ + ll);

        // A miss, or a tangent (a double root: the ray touches but does not cross).
        if (!(disc > T(0))) return {};

        return solved(disc, a, h, c, l);
    }

    /// The roots where the ray crosses (disc > 0, or a float's double decision), stable:
    /// q = -(h + sign(h) sqrt(disc)), t = q / a and c / q.
    [[nodiscard]] static constexpr Roots solved(T disc, T a, T h, T c, const Vec3<T>& l) noexcept
    {
        const T root = prism::sqrt(disc);
        const T q = -(h >= T(0) ? h + root : h - root);
        T t0 = q / a;
        T t1 = q != T(0) ? c / q : -t0;
        if (t0 > t1) std::swap(t0, t1);
        return {true, t0, t1, l, root / a};
    }

    /// roots() for a float sphere whose rim the ray passes within float's rounding of:
    /// the closest approach and the discriminant's sign in double, where a float's
    /// differences and products are exact; the roots as roots() takes them.
    [[gnu::noinline]] Roots roots_in_double(const Ray<T>& ray, T a, T h, T c) const noexcept
    {
        const Vec3<double> f = Vec3<double>(ray.origin) - Vec3<double>(center_), d(ray.direction);
        const Vec3<double> l = f - (dot(f, d) / dot(d, d)) * d;
        const double ll2 = length_squared(l), r2 = double(radius_) * double(radius_);
        if (!(ll2 < r2)) return {};
        return solved(T(double(a) * (r2 - ll2)), a, h, c, Vec3<T>(l));
    }

    [[nodiscard]] constexpr Crossing<T> crossing_at(const Vec3<T>& radial, T t, bool entering) const noexcept
    {
        // Refine the hit point by reprojecting it onto the surface; the remaining error
        // is that of the reprojection (pbrt-v4, Sphere::InteractionFromIntersection).
        T radial_length = length(radial);
        Vec3<T> unit_radial = radial;
        // A radial so short that its square lost bits (below 2^24 of the smallest normal:
        // a sphere far smaller than its distance to the ray, as the fuzzer builds) is scaled
        // up first, or its normal would not be of unit length; others keep their bits.
        if (!(length_squared(radial) >= std::numeric_limits<T>::min() * T(16777216))) {
            const T largest = std::max({std::abs(radial.x), std::abs(radial.y), std::abs(radial.z)});
            if (largest > T(0)) {
                unit_radial = radial / largest;
                radial_length = length(unit_radial);
            }
        }
        const Vec3<T> normal = radial_length > T(0) ? unit_radial * (T(1) / radial_length) : Vec3<T>(T(0), T(0), T(1));
        const Vec3<T> offset = normal * radius_;
        const Vec3<T> point = center_ + offset;
        const Vec3<T> error = gamma<T>(5) * abs(offset) + gamma<T>(1) * abs(point);
        return Crossing<T>::flat(t, point, error, normal, entering);
    }

    Vec3<T> center_;
    T radius_;
};

static_assert(Shape<Sphere<float>>);
static_assert(Shape<Sphere<double>>);

} // namespace prism
