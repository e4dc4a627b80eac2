// SPDX-License-Identifier: MIT
// Fresnel reflectance: exact dielectric, Schlick's approximation, complex conductor.
//
// cos_i is the cosine of the incident angle (>= 0, measured on the incident side) and
// eta = n_t / n_i. Formulas from Born and Wolf (1999, "Principles of Optics", 7th
// edition, section 1.5.2):
//   R_s = ((n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t))^2
//   R_p = ((n_i cos_t - n_t cos_i) / (n_i cos_t + n_t cos_i))^2
#pragma once

#include <prism/core/math.hpp>

#include <complex>

namespace prism {

/// Reflectance for s- (perpendicular) and p- (parallel) polarised light.
template <Scalar T>
struct PolarisedReflectance {
    T s; ///< reflectance of s-polarised light
    T p; ///< reflectance of p-polarised light
};

/// Exact dielectric reflectance by polarisation, given the refracted cosine cos_t (as
/// refraction() computes it, so it is computed once per interaction).
template <Scalar T>
[[nodiscard]] constexpr PolarisedReflectance<T> fresnel_dielectric_polarised(T cos_i, T cos_t, T eta) noexcept
{
    cos_i = clamp(cos_i, T(0), T(1));
    // Divided through by n_i, so n_i -> 1 and n_t -> eta.
    const T r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const T r_p = (cos_t - eta * cos_i) / (cos_t + eta * cos_i);
    return {r_s * r_s, r_p * r_p};
}

/// Exact dielectric reflectance by polarisation; both are 1 under total internal reflection.
template <Scalar T>
[[nodiscard]] constexpr PolarisedReflectance<T> fresnel_dielectric_polarised(T cos_i, T eta) noexcept
{
    cos_i = clamp(cos_i, T(0), T(1));
    // Compute cos_t with Snell's law
    const T sin2_t = (T(1) - cos_i * cos_i) / (eta * eta);
    // Handle total internal reflection
    if (sin2_t >= T(1)) return {T(1), T(1)};
    return fresnel_dielectric_polarised(cos_i, prism::sqrt(T(1) - sin2_t), eta);
}

/// Exact dielectric reflectance for unpolarised light, (R_s + R_p) / 2; 1 under total
/// internal reflection. Transmittance is 1 minus it.
template <Scalar T>
[[nodiscard]] constexpr T fresnel_dielectric(T cos_i, T eta) noexcept
{
    const PolarisedReflectance<T> r = fresnel_dielectric_polarised(cos_i, eta);
    return T(0.5) * (r.s + r.p);
}

/// The same, given the refracted cosine cos_t (no total internal reflection).
template <Scalar T>
[[nodiscard]] constexpr T fresnel_dielectric(T cos_i, T cos_t, T eta) noexcept
{
    const PolarisedReflectance<T> r = fresnel_dielectric_polarised(cos_i, cos_t, eta);
    return T(0.5) * (r.s + r.p);
}

/// Schlick's approximation (Schlick 1994, "An Inexpensive BRDF Model for Physically-based
/// Rendering"): R0 + (1 - R0)(1 - cos)^5 with R0 = ((eta - 1)/(eta + 1))^2. The cosine
/// must be the one on the optically less dense side: going from dense to less dense
/// (eta < 1) that is cos_t, and the answer is 1 under total internal reflection (with
/// cos_i there the error reaches 0.9 near the critical angle; tests/optics/fresnel.cpp).
template <Scalar T>
[[nodiscard]] constexpr T fresnel_schlick(T cos_i, T cos_t, T eta) noexcept
{
    const T cos = eta < T(1) ? cos_t : clamp(cos_i, T(0), T(1));
    const T r0 = ((eta - T(1)) / (eta + T(1))) * ((eta - T(1)) / (eta + T(1)));
    const T m = T(1) - cos;
    const T m2 = m * m;
    return r0 + (T(1) - r0) * m2 * m2 * m;
}

/// Schlick's approximation from cos_i alone: cos_t found here (1 under total internal
/// reflection).
template <Scalar T>
[[nodiscard]] constexpr T fresnel_schlick(T cos_i, T eta) noexcept
{
    cos_i = clamp(cos_i, T(0), T(1));
    const T sin2_t = (T(1) - cos_i * cos_i) / (eta * eta);
    if (eta < T(1) && sin2_t >= T(1)) return T(1);
    return fresnel_schlick(cos_i, eta < T(1) ? prism::sqrt(T(1) - sin2_t) : T(0), eta);
}

/// Reflectance of a conductor with complex index eta = n + i k relative to the outside
/// medium, unpolarised (pbrt-v4 FrComplex; Born & Wolf 14.2). Metals brighten toward
/// grazing incidence, unlike a constant kr.
template <Scalar T>
[[nodiscard]] inline T fresnel_conductor(T cos_i, std::complex<T> eta) noexcept
{
    using C = std::complex<T>;
    cos_i = clamp(cos_i, T(0), T(1));
    const T sin2_i = T(1) - cos_i * cos_i;
    const C sin2_t = C(sin2_i) / (eta * eta);
    const C cos_t = std::sqrt(C(1) - sin2_t);
    const C r_s = (C(cos_i) - eta * cos_t) / (C(cos_i) + eta * cos_t);
    const C r_p = (eta * C(cos_i) - cos_t) / (eta * C(cos_i) + cos_t);
    return T(0.5) * (std::norm(r_s) + std::norm(r_p));
}

// Fresnel policies for Dielectric<T, Policy>

/// The exact dielectric Fresnel equations.
struct ExactFresnel {
    /// The exact reflectance at incidence cosine cos_i and eta = n_t / n_i (1 under total internal reflection).
    template <Scalar T>
    [[nodiscard]] static constexpr T reflectance(T cos_i, T eta) noexcept
    {
        return fresnel_dielectric(cos_i, eta);
    }
    /// The exact reflectance given cos_t as well (from Snell, computed once for direction and Fresnel).
    template <Scalar T>
    [[nodiscard]] static constexpr T reflectance(T cos_i, T cos_t, T eta) noexcept
    {
        return fresnel_dielectric(cos_i, cos_t, eta);
    }
};

/// Schlick's approximation, evaluated on the less dense side.
struct SchlickFresnel {
    /// Schlick's reflectance at incidence cosine cos_i and eta = n_t / n_i, on the less dense side.
    template <Scalar T>
    [[nodiscard]] static constexpr T reflectance(T cos_i, T eta) noexcept
    {
        return fresnel_schlick(cos_i, eta);
    }
    /// Schlick's reflectance given cos_t as well.
    template <Scalar T>
    [[nodiscard]] static constexpr T reflectance(T cos_i, T cos_t, T eta) noexcept
    {
        return fresnel_schlick(cos_i, cos_t, eta);
    }
};

/// A Fresnel policy: reflectance(cos_i, eta) in [0, 1] (1 under total internal
/// reflection), and reflectance(cos_i, cos_t, eta) given the refracted cosine.
template <class P, class T>
concept FresnelPolicy = Scalar<T> && requires(T cos_i, T eta) {
    { P::reflectance(cos_i, eta) } -> std::same_as<T>;
    { P::reflectance(cos_i, cos_i, eta) } -> std::same_as<T>;
};

static_assert(FresnelPolicy<ExactFresnel, float> && FresnelPolicy<SchlickFresnel, double>);

} // namespace prism
