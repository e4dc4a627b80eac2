// SPDX-License-Identifier: MIT
// Camera: a pinhole camera as a plain struct, and the rays it shoots.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/ray.hpp>

#include <cmath>
#include <optional>

namespace prism {

/// Where the camera shoots rays through a width x height image.
template <Scalar T>
struct CameraRays {
    Vec3<T> origin{}; ///< the pinhole (a thin lens's centre)
    Vec3<T> top_left{};    ///< direction through the top-left image corner
    Vec3<T> pixel_right{}; ///< step of one pixel to the right
    Vec3<T> pixel_down{};  ///< step of one pixel down
    T lens_radius = T(0);  ///< a thin lens's radius (0: a pinhole)
    T focus = T(1);        ///< the distance along the view direction of the plane in focus
    Vec3<T> lens_right{};  ///< unit, along the lens's first axis (the image's right)
    Vec3<T> lens_up{};     ///< unit, along its second (the image's up)

    /// The ray through image position (x, y), in pixels from the top-left corner, from the
    /// pinhole (a thin lens's centre), with the spread of a pixel's footprint (Ray::spread).
    [[nodiscard]] constexpr Ray<T> ray(T x, T y) const noexcept
    {
        const Vec3<T> through = top_left + x * pixel_right + y * pixel_down; // one unit along the view direction
        return {origin, normalize(through), T(0), length(pixel_right) / length(through)};
    }

    /// Whether the camera has a lens of some size (then rays start across it).
    [[nodiscard]] constexpr bool thin_lens() const noexcept { return lens_radius > T(0); }

    /// The point of the lens that the unit square's (u, v) maps onto, uniformly by area
    /// (the pinhole for a pinhole camera).
    [[nodiscard]] Vec3<T> lens_point(T u, T v) const noexcept
    {
        if (!thin_lens()) return origin;
        const T r = lens_radius * std::sqrt(u), phi = T(2) * pi<T> * v;
        return origin + (r * std::cos(phi)) * lens_right + (r * std::sin(phi)) * lens_up;
    }

    /// The ray through image position (x, y) from the lens point of (u, v): aimed at
    /// where the pinhole ray through (x, y) meets the plane in focus, so every ray
    /// through one image position meets there (a point in focus images to a point).
    [[nodiscard]] Ray<T> ray(T x, T y, T u, T v) const noexcept
    {
        if (!thin_lens()) return ray(x, y);
        const Vec3<T> through = top_left + x * pixel_right + y * pixel_down; // one unit along the view direction
        const Vec3<T> from = lens_point(u, v);
        return {from, normalize(origin + focus * through - from), T(0), length(pixel_right) / length(through)};
    }

    /// Where a point is seen: image position (x, y) in pixels from the top-left corner
    /// (inside the image when 0 <= x < width, 0 <= y < height), its distance from the
    /// pinhole and the cosine between the view direction and the ray to it.
    struct Projection {
        T x;        ///< column, in pixels from the left
        T y;        ///< row, in pixels from the top
        T distance; ///< from the pinhole
        T cos;      ///< between the view direction and the ray to the point
    };

    /// The point's projection, or nothing when it is not in front of the camera.
    [[nodiscard]] std::optional<Projection> project(const Vec3<T>& p) const noexcept
    {
        const Vec3<T> forward = normalize(cross(pixel_right, pixel_down));
        const Vec3<T> v = p - origin;
        const T depth = dot(v, forward), distance = length(v);
        if (!(depth > T(0)) || !(distance > T(0))) return std::nullopt;
        const Vec3<T> on_plane = v / depth - top_left; // the image plane lies at distance 1
        return Projection{dot(on_plane, pixel_right) / length_squared(pixel_right), dot(on_plane, pixel_down) / length_squared(pixel_down),
                          distance, depth / distance};
    }

    /// Where a point is seen through the lens point `from`: the image position of the
    /// point where the ray from `from` through p meets the plane in focus, its distance
    /// from `from` and the cosine between the view direction and that ray. (A light
    /// path joined to a thin lens's point drawn uniformly weighs what it brings as it
    /// would at a pinhole there.)
    [[nodiscard]] std::optional<Projection> project(const Vec3<T>& p, const Vec3<T>& from) const noexcept
    {
        const Vec3<T> forward = normalize(cross(pixel_right, pixel_down));
        const Vec3<T> v = p - from;
        const T depth = dot(v, forward), distance = length(v);
        if (!(depth > T(0)) || !(distance > T(0))) return std::nullopt;
        const Vec3<T> on_plane = (from - origin + v * (focus / depth)) / focus - top_left;
        return Projection{dot(on_plane, pixel_right) / length_squared(pixel_right), dot(on_plane, pixel_down) / length_squared(pixel_down),
                          distance, depth / distance};
    }

    /// One pixel's area on the image plane at distance 1: a pixel's value is the mean
    /// radiance over it, so light arriving at the pinhole from a point seen at cosine
    /// cos adds E / (pixel_area cos^3) (pixel area to solid angle: cos^3 / distance^2).
    [[nodiscard]] T pixel_area() const noexcept { return length(pixel_right) * length(pixel_down); }
};

/// A pinhole camera, or a thin lens (depth of field). `fov` is the horizontal field of
/// view in degrees, as POV-Ray's `angle`. With an `aperture_radius` above 0, rays start
/// across a lens of that radius about `position`, perpendicular to the view direction,
/// and meet again on the plane `focus_distance` ahead (pbrt's thin lens; POV-Ray's
/// `aperture` is its diameter and `focal_point` a point on that plane): points on the
/// plane are sharp, and a point at distance z blurs over a circle of diameter
/// 2 aperture_radius |1 / focus_distance - 1 / z| on the image plane one unit ahead.
template <Scalar T = float>
struct Camera {
    Vec3<T> position{T(0), T(0), T(0)}; ///< the pinhole, or the lens's centre
    Vec3<T> look_at{T(0), T(0), T(-1)}; ///< the point seen at the image's centre
    Vec3<T> up{T(0), T(1), T(0)}; ///< the direction that is up in the image
    T fov = T(40); ///< horizontal field of view in degrees
    T aperture_radius = T(0); ///< the lens's radius (0: a pinhole, everything sharp)
    /// The distance along the view direction of the plane in focus; none: look_at's.
    std::optional<T> focus_distance{};

    /// Throws std::invalid_argument for non-finite fields, position == look_at, an up
    /// vector parallel to the view direction, or a field of view outside (0, 180).
    void validate() const
    {
        detail::require_finite("Camera position", position);
        detail::require_finite("Camera look_at", look_at);
        detail::require_nonzero("Camera up", up);
        detail::require_finite("Camera fov", fov);
        if (position == look_at) detail::throw_invalid("Camera position and look_at must differ, both are ", detail::describe(position));
        if (!(fov > T(0) && fov < T(180))) detail::throw_invalid("Camera fov must be in (0, 180) degrees, got ", fov);
        const Vec3<T> side = cross(forward(), unit(up));
        if (!(length(side) > T(1e-6))) detail::throw_invalid("Camera up ", detail::describe(up), " is parallel to the view direction");
        if (!(aperture_radius >= T(0) && aperture_radius < infinity<T>)) detail::throw_invalid("Camera aperture_radius must be finite and >= 0, got ", aperture_radius);
        if (focus_distance && !(*focus_distance > T(0) && *focus_distance < infinity<T>))
            detail::throw_invalid("Camera focus_distance must be finite and > 0, got ", *focus_distance);
        if (aperture_radius > T(0) && !focus_distance && !(dot(look_at - position, forward()) < infinity<T>))
            detail::throw_invalid("Camera focus_distance: look_at's distance ", detail::describe(look_at - position), " is not finite");
    }

    /// The unit view direction, from position to look_at. Found without overflow or
    /// underflow for points 3e38 or 1e-44 apart: the difference is halved where it would
    /// overflow and scaled by its largest component before normalising.
    [[nodiscard]] Vec3<T> forward() const noexcept
    {
        Vec3<T> d = look_at - position;
        if (!is_finite(d)) d = T(0.5) * look_at - T(0.5) * position;
        return unit(d);
    }

    /// v / |v| for any non-zero finite v, however small or large.
    [[nodiscard]] static Vec3<T> unit(const Vec3<T>& v) noexcept { return normalize(v / max_component(abs(v))); }

    /// The rays for a width x height image; validates the camera and the size.
    [[nodiscard]] CameraRays<T> rays(int width, int height) const
    {
        validate();
        if (width <= 0 || height <= 0) detail::throw_invalid("image size must be positive, got ", width, " x ", height);
        const Vec3<T> forward = this->forward();
        const Vec3<T> right = normalize(cross(forward, unit(up)));
        const Vec3<T> true_up = cross(right, forward);
        const T half_width = std::tan(T(0.5) * fov * pi<T> / T(180));
        const T half_height = half_width * T(height) / T(width);
        CameraRays<T> out;
        out.origin = position;
        out.top_left = forward - half_width * right + half_height * true_up;
        out.pixel_right = (T(2) * half_width / T(width)) * right;
        out.pixel_down = (-T(2) * half_height / T(height)) * true_up;
        if (aperture_radius > T(0)) {
            out.lens_radius = aperture_radius;
            out.focus = focus_distance ? *focus_distance : dot(look_at - position, forward);
            out.lens_right = right;
            out.lens_up = true_up;
        }
        return out;
    }
};

} // namespace prism
