// SPDX-License-Identifier: MIT
// Mirror reflection and Snell refraction of directions.
//
// Conventions: d is the incident direction (travelling toward the surface), n is the
// unit normal on the side d comes from (dot(d, n) < 0), so cos(theta_i) = -dot(d, n)
// (as in Pharr, Jakob and Humphreys 2023, "Physically Based Rendering", 4th edition,
// section 4.5), and eta = n_t / n_i, the index of the far side over the near side.
#pragma once

#include <prism/core/math.hpp>

#include <optional>

namespace prism {

/// Mirror reflection of d about n: d - 2 (d . n) n.
template <Scalar T>
[[nodiscard]] constexpr Vec3<T> reflect(const Vec3<T>& d, const Vec3<T>& n) noexcept
{
    return d - (T(2) * dot(d, n)) * n;
}

/// A refracted direction and the cosine of its angle with the normal (on the far side).
template <Scalar T>
struct Refraction {
    Vec3<T> direction; ///< unit refracted direction
    T cos_t; ///< cosine between it and the normal, on the far side
};

/// Snell refraction of the unit direction d through a surface with unit normal n
/// facing d, into a medium of relative index eta = n_t / n_i, with cos_t for the Fresnel
/// equations (computed once, here). Returns nothing under total internal reflection.
/// The direction is unit length:
///   t = d / eta + (cos_i / eta - cos_t) n,  cos_t = sqrt(1 - (1 - cos_i^2) / eta^2).
template <Scalar T>
[[nodiscard]] constexpr std::optional<Refraction<T>> refraction(const Vec3<T>& d, const Vec3<T>& n, T eta) noexcept
{
    const T cos_i = -dot(d, n);
    const T sin2_i = T(1) - cos_i * cos_i > T(0) ? T(1) - cos_i * cos_i : T(0);
    const T sin2_t = sin2_i / (eta * eta);
    // Handle total internal reflection
    if (sin2_t >= T(1)) return std::nullopt;
    const T cos_t = prism::sqrt(T(1) - sin2_t);
    return Refraction<T>{d / eta + (cos_i / eta - cos_t) * n, cos_t};
}

/// The refracted direction alone (see refraction).
template <Scalar T>
[[nodiscard]] constexpr std::optional<Vec3<T>> refract(const Vec3<T>& d, const Vec3<T>& n, T eta) noexcept
{
    if (const auto r = refraction(d, n, eta)) return r->direction;
    return std::nullopt;
}

} // namespace prism
