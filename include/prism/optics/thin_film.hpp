// SPDX-License-Identifier: MIT
// Thin-film interference: the exact reflectance and transmittance of one film between
// two media, by Airy's sum of the multiply reflected amplitudes (Born & Wolf,
// "Principles of Optics", section 7.6.1; Heavens, "Optical Properties of Thin Solid
// Films"), per polarisation and per wavelength.
//
// Medium 0 (incident, real index n0) | film 1 (index n1, thickness d) | substrate 2
// (complex index n2 = n + i k: a dielectric, or a metal). With the cosines c_j of the
// angles in each medium (n0 sin0 = n_j sin_j, the branch with Im(n_j c_j) >= 0: a wave
// that decays as it goes in) and the interface amplitudes
//   r_ij^s = (n_i c_i - n_j c_j) / (n_i c_i + n_j c_j)   t_ij^s = 2 n_i c_i / (n_i c_i + n_j c_j)
//   r_ij^p = (n_j c_i - n_i c_j) / (n_j c_i + n_i c_j)   t_ij^p = 2 n_i c_i / (n_j c_i + n_i c_j)
// the film's phase thickness beta = 2 pi n1 c1 d / lambda sums the geometric series of
// its internal reflections to
//   r = (r01 + r12 e^{2 i beta}) / (1 + r01 r12 e^{2 i beta})
//   t = t01 t12 e^{i beta} / (1 + r01 r12 e^{2 i beta})
// and R = |r|^2, T = Re(n2 c2) / (n0 c0) |t|^2 (s; p likewise in the magnetic field).
#pragma once

#include <prism/core/math.hpp>
#include <prism/optics/fresnel.hpp>

#include <complex>

namespace prism {

/// One film over a substrate, seen from an incident medium; thickness in nanometres.
template <Scalar T>
struct FilmStack {
    T incident = T(1);                   ///< n0, real
    std::complex<T> film{T(1.33)};       ///< n1 (a non-absorbing film has k = 0)
    T thickness_nm = T(0);               ///< d
    std::complex<T> substrate{T(1)};     ///< n2
};

/// Reflectance and transmittance by polarisation; the unpolarised values are their means.
template <Scalar T>
struct FilmResponse {
    PolarisedReflectance<T> reflectance; ///< reflectance of s- and p-polarised light
    PolarisedReflectance<T> transmittance; ///< transmittance of s- and p-polarised light

    /// The unpolarised reflectance.
    [[nodiscard]] constexpr T reflected() const noexcept { return T(0.5) * (reflectance.s + reflectance.p); }
    /// The unpolarised transmittance.
    [[nodiscard]] constexpr T transmitted() const noexcept { return T(0.5) * (transmittance.s + transmittance.p); }
};

namespace detail {

/// n_j c_j in medium j for the invariant n0 sin0, on the branch whose wave decays
/// going in (Im >= 0); c_j itself is n_j c_j / n_j.
template <Scalar T>
[[nodiscard]] std::complex<T> normal_wavenumber(std::complex<T> n, T n0_sin0) noexcept
{
    std::complex<T> nc = std::sqrt(n * n - std::complex<T>(n0_sin0 * n0_sin0));
    if (nc.imag() < T(0) || (nc.imag() == T(0) && nc.real() < T(0))) nc = -nc;
    return nc;
}

} // namespace detail

/// The film's response at the incident cosine cos0 (in medium 0) and wavelength
/// lambda_nm (in vacuum, nanometres): Airy's formula above.
template <Scalar T>
[[nodiscard]] FilmResponse<T> thin_film(const FilmStack<T>& stack, T cos0, T lambda_nm) noexcept
{
    using C = std::complex<T>;
    cos0 = clamp(cos0, T(0), T(1));
    const C n0(stack.incident), n1 = stack.film, n2 = stack.substrate;
    const T invariant = stack.incident * std::sqrt(T(1) - cos0 * cos0);
    // q_j = n_j c_j, the normal component of each medium's wave vector over k0.
    const C q0(stack.incident * cos0), q1 = detail::normal_wavenumber(n1, invariant), q2 = detail::normal_wavenumber(n2, invariant);
    // s: r = (q_i - q_j) / (q_i + q_j); p, in the magnetic field with u_j = q_j / n_j^2 = c_j / n_j:
    // r = (u_i - u_j) / (u_i + u_j), which is (n_j c_i - n_i c_j) / (n_j c_i + n_i c_j).
    const auto interface = [](C a, C b) { return (a - b) / (a + b); };
    const auto transmit = [](C a, C b) { return T(2) * a / (a + b); };
    const C u0 = q0 / (n0 * n0), u1 = q1 / (n1 * n1), u2 = q2 / (n2 * n2);
    const C phase = std::exp(C(0, T(2) * pi<T> * stack.thickness_nm / lambda_nm) * q1); // e^{i beta}
    const C phase2 = phase * phase;

    const C r01s = interface(q0, q1), r12s = interface(q1, q2);
    const C r01p = interface(u0, u1), r12p = interface(u1, u2);
    const C den_s = C(1) + r01s * r12s * phase2, den_p = C(1) + r01p * r12p * phase2;
    const C rs = (r01s + r12s * phase2) / den_s, rp = (r01p + r12p * phase2) / den_p;

    FilmResponse<T> out{{std::norm(rs), std::norm(rp)}, {T(0), T(0)}};
    if (q0.real() > T(0)) {
        // The normal energy flux is Re(q) |E|^2 for s and Re(u) |H|^2 for p, whose
        // interfaces match (E, q E) and (H, u H) alike: t = 2 a / (a + b) per interface.
        const C ts = transmit(q0, q1) * transmit(q1, q2) * phase / den_s;
        const C tp = transmit(u0, u1) * transmit(u1, u2) * phase / den_p;
        out.transmittance.s = q2.real() / q0.real() * std::norm(ts);
        out.transmittance.p = u2.real() / u0.real() * std::norm(tp);
    }
    return out;
}

} // namespace prism
