// SPDX-License-Identifier: MIT
// Disk: a flat round surface, open (a round area light, a lamp's opening).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/sampling.hpp>
#include <prism/geometry/plane.hpp>
#include <prism/geometry/shape.hpp>
#include <prism/geometry/surface_point.hpp>

#include <cmath>

namespace prism {

/// The disk of `radius` about `center`, perpendicular to `normal`: an open surface, never
/// inside, which a ray enters where it arrives on the normal's side (the side an area light
/// on it shines to). Its uv is (distance from the centre / radius, angle / 2 pi).
template <Scalar T = float>
class Disk {
public:
    /// The precision of the disk and the crossings.
    using scalar_type = T;
    /// At most one crossing.
    static constexpr std::size_t max_crossings = 1;

    /// The disk; throws std::invalid_argument for a non-finite center, a zero or
    /// non-finite normal, or a radius outside [detail::smallest_length, detail::largest_length].
    constexpr Disk(const Vec3<T>& center, const Vec3<T>& normal, T radius) : center_(center), radius_(radius)
    {
        detail::require_finite("Disk center", center);
        detail::require_nonzero("Disk normal", normal);
        detail::require_length("Disk radius", radius);
        normal_ = normalize(normal / max_component(abs(normal)));
        offset_ = dot(normal_, center_);
        const auto [s, t] = orthonormal_frame(normal_);
        s_ = s, t_ = t;
    }

    /// The centre.
    [[nodiscard]] constexpr const Vec3<T>& center() const noexcept { return center_; }
    /// The unit normal: the front.
    [[nodiscard]] constexpr const Vec3<T>& normal() const noexcept { return normal_; }
    /// The radius.
    [[nodiscard]] constexpr T radius() const noexcept { return radius_; }
    /// The area pi r^2.
    [[nodiscard]] constexpr T area() const noexcept { return pi<T> * radius_ * radius_; }

    /// The box around the disk (its extent along each axis, r sqrt(1 - n_i^2)), rounded outward.
    [[nodiscard]] constexpr Aabb<T> bounds() const noexcept
    {
        Vec3<T> half;
        for (int i = 0; i < 3; ++i) half[i] = radius_ * prism::sqrt(std::max(T(0), T(1) - normal_[i] * normal_[i]));
        // The square root rounds: a relative margin keeps the box around the rim.
        half *= T(1) + T(4) * std::numeric_limits<T>::epsilon();
        return Aabb<T>{center_ - half, center_ + half}.rounded_out();
    }

    /// Never: a disk has no inside.
    [[nodiscard]] constexpr bool contains(const Vec3<T>&) const noexcept { return false; }

    /// The crossing of `ray` within `range`, if it meets the disk there: entering where it
    /// arrives against the normal.
    template <bool Surface = true>
    [[nodiscard]] constexpr Crossings<T, 1> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        Crossings<T, 1> out;
        const T denom = dot(normal_, ray.direction);
        if (denom == T(0)) return out;
        const T t = (offset_ - dot(normal_, ray.origin)) / denom;
        if (!range.surrounds(t)) return out;
        const Vec3<T> point = detail::onto_plane(normal_, offset_, ray.at(t));
        const Vec3<T> local = point - center_;
        const T r2 = length_squared(local);
        if (!(r2 <= radius_ * radius_)) return out;
        const bool entering = denom < T(0);
        if constexpr (!Surface) {
            out.push_back(Crossing<T>::without_surface(t, entering));
        } else {
            out.push_back(Crossing<T>::flat(t, point, detail::plane_point_error(normal_, offset_, point), normal_, entering));
        }
        return out;
    }

    /// Surface coordinates of a crossing of this disk: polar, u the distance from the
    /// centre over the radius, v the angle over 2 pi.
    void coordinates(Crossing<T>& c) const noexcept
    {
        const Vec3<T> local = c.point - center_;
        T angle = std::atan2(dot(local, t_), dot(local, s_));
        if (angle < T(0)) angle += T(2) * pi<T>;
        const T rho = length(local);
        const Vec3<T> radial = rho > T(0) ? local * (radius_ / rho) : s_ * radius_;
        c = c.with_uv({rho / radius_, angle / (T(2) * pi<T>)}, radial, (T(2) * pi<T>) * cross(normal_, local));
    }

    /// A point uniform over the disk for u in the unit square, with density 1 / area.
    [[nodiscard]] SurfacePoint<T> sample_area(const Vec2<T>& u) const noexcept
    {
        return {uniform_disk(center_, normal_, radius_, u.x, u.y), normal_, T(1) / area()};
    }

private:
    Vec3<T> center_;
    T radius_;
    Vec3<T> normal_{}, s_{}, t_{};
    T offset_ = T(0);
};

static_assert(Shape<Disk<float>>);
static_assert(Shape<Disk<double>>);

} // namespace prism
