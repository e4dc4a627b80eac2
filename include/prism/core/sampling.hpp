// SPDX-License-Identifier: MIT
// Sampling: directions and points drawn from the unit square, for lights, photons and
// diffuse bounces; Russian roulette.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/random.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace prism {

/// A direction uniform on the unit sphere: z = 1 - 2u, phi = 2 pi v (no
/// rejection sampling of a cube, whose accepted points were never normalised).
template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_sphere(T u, T v) noexcept
{
    const T z = T(1) - T(2) * u;
    const T r = prism::sqrt(clamp(T(1) - z * z, T(0), T(1)));
    const T phi = T(2) * pi<T> * v;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_sphere(Random& rng) noexcept
{
    const auto [u, v] = rng.uniform2<T>();
    return uniform_sphere(u, v);
}

/// Two unit vectors that make an orthonormal frame with the unit vector n (Duff et al.
/// 2017, "Building an Orthonormal Basis, Revisited").
template <Scalar T>
[[nodiscard]] inline std::pair<Vec3<T>, Vec3<T>> orthonormal_frame(const Vec3<T>& n) noexcept
{
    const T sign = std::copysign(T(1), n.z);
    const T a = T(-1) / (sign + n.z);
    const T b = n.x * n.y * a;
    return {{T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}};
}

/// A cosine-distributed direction about the unit normal n (Malley's method: a uniform
/// point on the disk, lifted onto the hemisphere): the diffuse bounce of a photon.
template <Scalar T>
[[nodiscard]] inline Vec3<T> cosine_hemisphere(const Vec3<T>& n, Random& rng) noexcept
{
    const auto [u, v] = rng.uniform2<T>();
    const T r = prism::sqrt(u);
    const T phi = T(2) * pi<T> * v;
    const T x = r * std::cos(phi), y = r * std::sin(phi);
    const T z = prism::sqrt(clamp(T(1) - x * x - y * y, T(0), T(1)));
    const auto [s, t] = orthonormal_frame(n);
    return x * s + y * t + z * n;
}

/// Russian roulette (Arvo and Kirk 1990, "Particle transport and image synthesis"): the photon survives with probability p = the largest
/// channel of its reflectance (at most 1), and a survivor's power is scaled per channel
/// by reflectance / p, so the expected power leaving is reflectance times the power
/// arriving, in every channel. Returns false when the photon is absorbed.
template <Scalar T>
[[nodiscard]] inline bool russian_roulette(Rgb<T>& power, const Rgb<T>& reflectance, Random& rng) noexcept
{
    const T p = clamp(max_component(reflectance), T(0), T(1));
    if (!(p > T(0)) || rng.uniform<T>() >= p) return false;
    power *= reflectance / p;
    return true;
}

/// Russian roulette by a camera path's throughput (Arvo and Kirk 1990): the path goes on with
/// probability p = the square root of the largest channel of `throughput` (at most 1) and a
/// survivor's throughput is divided by p, so its expectation is unchanged. A path whose
/// throughput has fallen is likely ended; one still carrying much is not, however many lobes
/// it was drawn through. The square root keeps dim paths longer than pbrt's and Mitsuba's p =
/// the throughput itself: on the area-lit Cornell box (walls of albedo 0.6) it gave 1.4 times
/// the efficiency (1 / (error^2 time)) in the display range, the same in linear radiance
/// (docs/benchmarks.md). Returns false when the path ends.
template <Scalar T>
[[nodiscard]] inline bool path_roulette(Rgb<T>& throughput, Random& rng) noexcept
{
    const T p = std::min(T(1), prism::sqrt(max_component(throughput)));
    if (!(p > T(0)) || !(rng.uniform<T>() < p)) return false;
    throughput /= p;
    return true;
}

/// The point (u, v) of the unit square mapped uniformly onto the disk of radius r centred
/// at c, perpendicular to the unit axis.
template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_disk(const Vec3<T>& c, const Vec3<T>& axis, T r, T u, T v) noexcept
{
    const T rho = r * prism::sqrt(u);
    const T phi = T(2) * pi<T> * v;
    const auto [s, t] = orthonormal_frame(axis);
    return c + rho * std::cos(phi) * s + rho * std::sin(phi) * t;
}

/// (u, v) mapped uniformly onto the directions within the cone about `axis` with the
/// given cos(half angle).
template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_cone(const Vec3<T>& axis, T cos_half_angle, T u, T v) noexcept
{
    const T cos_theta = T(1) - u * (T(1) - cos_half_angle);
    const T sin_theta = prism::sqrt(clamp(T(1) - cos_theta * cos_theta, T(0), T(1)));
    const T phi = T(2) * pi<T> * v;
    const auto [s, t] = orthonormal_frame(axis);
    return sin_theta * std::cos(phi) * s + sin_theta * std::sin(phi) * t + cos_theta * axis;
}

} // namespace prism
