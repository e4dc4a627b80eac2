// SPDX-License-Identifier: MIT
// Dispersion: an index of refraction that depends on wavelength (Sellmeier, Cauchy),
// named glasses with their makers' published coefficients, and the Fraunhofer lines.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>

namespace prism {

/// An index of refraction as a function of the vacuum wavelength in nanometres.
template <class D>
concept Dispersion = requires(const D& dispersion, typename D::scalar_type wavelength_nm) {
    requires Scalar<typename D::scalar_type>;
    { dispersion.index(wavelength_nm) } -> std::same_as<typename D::scalar_type>;
    dispersion.validate();
};

/// Sellmeier's formula, with three terms as glass makers publish it (or `Terms`):
///   n^2 = 1 + sum_i B_i lambda^2 / (lambda^2 - C_i),  lambda in micrometres, C_i in um^2.
template <Scalar T = double, std::size_t Terms = 3>
struct Sellmeier {
    /// The precision of the coefficients and the index.
    using scalar_type = T;
    std::array<T, Terms> b{}; ///< B_i, dimensionless
    std::array<T, Terms> c{}; ///< C_i, in square micrometres

    /// The index at a vacuum wavelength in nanometres.
    [[nodiscard]] T index(T wavelength_nm) const noexcept
    {
        const T l2 = (wavelength_nm * T(1e-3)) * (wavelength_nm * T(1e-3));
        T n2 = T(1);
        for (std::size_t i = 0; i < Terms; ++i) n2 += b[i] * l2 / (l2 - c[i]);
        return std::sqrt(n2);
    }

    /// Throws std::invalid_argument for a non-finite B or a C that is negative or NaN.
    constexpr void validate() const
    {
        for (std::size_t i = 0; i < Terms; ++i) {
            detail::require_finite("Sellmeier B", b[i]);
            if (!(c[i] >= T(0) && c[i] == c[i])) detail::throw_invalid("Sellmeier C must be >= 0 (um^2), got ", c[i]);
        }
    }
};

/// Cauchy's formula n = A + B / lambda^2 + C / lambda^4, lambda in micrometres.
template <Scalar T = double>
struct Cauchy {
    /// The precision of the coefficients and the index.
    using scalar_type = T;
    T a = T(1.5); ///< A, the index at infinite wavelength
    T b = T(0); ///< B, in square micrometres
    T c = T(0); ///< C, in micrometres to the fourth

    /// The index at a vacuum wavelength in nanometres.
    [[nodiscard]] T index(T wavelength_nm) const noexcept
    {
        const T l2 = (wavelength_nm * T(1e-3)) * (wavelength_nm * T(1e-3));
        return a + b / l2 + c / (l2 * l2);
    }

    /// Throws std::invalid_argument, naming the parameter, for A <= 0 or a non-finite B or C.
    constexpr void validate() const
    {
        detail::require_positive("Cauchy A", a);
        detail::require_finite("Cauchy B", b);
        detail::require_finite("Cauchy C", c);
    }
};

static_assert(Dispersion<Sellmeier<double>> && Dispersion<Cauchy<float>>);

/// Fraunhofer lines used to specify glass, vacuum wavelengths in nm.
namespace fraunhofer {
inline constexpr double F = 486.1327; ///< hydrogen, blue
inline constexpr double e = 546.0740; ///< mercury, green
inline constexpr double d = 587.5618; ///< helium, yellow
inline constexpr double C = 656.2725; ///< hydrogen, red
} // namespace fraunhofer

/// Abbe's number V_d = (n_d - 1) / (n_F - n_C): how little a glass disperses.
template <Dispersion D>
[[nodiscard]] typename D::scalar_type abbe_number(const D& glass) noexcept
{
    using T = typename D::scalar_type;
    return (glass.index(T(fraunhofer::d)) - T(1)) / (glass.index(T(fraunhofer::F)) - glass.index(T(fraunhofer::C)));
}

/// Named glasses (Schott's published Sellmeier coefficients, from their data sheets) and water.
namespace glass {
/// N-BK7, the common crown: n_d = 1.51680, V_d = 64.17.
template <Scalar T = double>
inline constexpr Sellmeier<T> bk7{{T(1.03961212), T(0.231792344), T(1.01046945)}, {T(0.00600069867), T(0.0200179144), T(103.560653)}};
/// F2, a flint: n_d = 1.62004, V_d = 36.37.
template <Scalar T = double>
inline constexpr Sellmeier<T> f2{{T(1.34533359), T(0.209073176), T(0.937357162)}, {T(0.00997743871), T(0.0470450767), T(111.886764)}};
/// Water at 20 C: Cauchy's formula through the CRC Handbook's n_F = 1.33712,
/// n_D = 1.33299 (589.29 nm) and n_C = 1.33115 (so V = 55.8); within 7e-4 of the
/// handbook down to 405 nm.
template <Scalar T = double>
inline constexpr Cauchy<T> water{.a = T(1.32263793), .b = T(3.96229730e-3), .c = T(-1.27573712e-4)};
} // namespace glass

} // namespace prism
