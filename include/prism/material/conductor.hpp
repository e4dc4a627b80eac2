// SPDX-License-Identifier: MIT
// Conductor: a metal mirror, with a constant kr or the complex-index Fresnel equations.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/traits.hpp>
#include <prism/optics/fresnel.hpp>
#include <prism/spectrum/cie.hpp>
#include <prism/spectrum/metals.hpp>

#include <array>
#include <complex>

namespace prism {

/// Reflectance independent of angle (the common approximation for metals, as in Whitted 1980).
template <Scalar T = float>
struct ConstantKr {
    Rgb<T> kr{T(1)}; ///< the reflectance at every angle

    /// The reflectance: kr at any angle.
    [[nodiscard]] constexpr Rgb<T> reflectance(T) const noexcept { return kr; }
    /// Throws std::invalid_argument for a negative or non-finite kr.
    constexpr void validate() const { detail::require_non_negative("ConstantKr kr", kr); }
};

/// The Fresnel equations for a complex index n + i k per channel (Born and Wolf 1999, section 14.2).
template <Scalar T = float>
struct ComplexIor {
    Rgb<T> eta{T(1)}; ///< real part n
    Rgb<T> k{T(0)};   ///< extinction coefficient

    /// The unpolarised Fresnel reflectance per channel at incidence cosine cos_i.
    [[nodiscard]] Rgb<T> reflectance(T cos_i) const noexcept
    {
        return {fresnel_conductor(cos_i, std::complex<T>(eta.x, k.x)),
                fresnel_conductor(cos_i, std::complex<T>(eta.y, k.y)),
                fresnel_conductor(cos_i, std::complex<T>(eta.z, k.z))};
    }

    /// Throws std::invalid_argument, naming the parameter, for eta <= 0 or non-finite in a channel, or a negative k.
    constexpr void validate() const
    {
        detail::require_finite("ComplexIor eta", eta);
        if (!(eta.x > T(0) && eta.y > T(0) && eta.z > T(0)))
            detail::throw_invalid("ComplexIor eta must be > 0 in every channel, got ", detail::describe(eta));
        detail::require_non_negative("ComplexIor k", k);
    }
};

/// A metal with a measured spectral index (spectrum/metals.hpp): the exact Fresnel
/// reflectance at each wavelength, integrated against the CIE observer under D65 into
/// linear sRGB (not three wavelengths sampled) and clipped to the gamut (cie.hpp),
/// tabulated once at construction at `table_size` incident cosines and interpolated
/// linearly. `spectral_reflectance` gives the exact value at one wavelength, for rays
/// that carry one.
template <Scalar T = float>
class MeasuredConductor {
public:
    /// The incident cosines at which the reflectance is tabulated.
    static constexpr int table_size = 129;

    /// The reflectance of `index` (kept by reference: static data such as metals::gold, or the caller's, which must outlive it) integrated over the spectrum.
    explicit MeasuredConductor(const metals::MeasuredIndex& index) : index_(&index)
    {
        for (int i = 0; i < metals::MeasuredIndex::count; ++i) {
            const double n = index.eta[std::size_t(i)], k = index.k[std::size_t(i)];
            if (!(n > 0 && n < infinity<double>)) detail::throw_invalid("MeasuredConductor eta must be finite and > 0, got ", n, " at entry ", i);
            if (!(k >= 0 && k < infinity<double>)) detail::throw_invalid("MeasuredConductor k must be finite and >= 0, got ", k, " at entry ", i);
        }
        for (int i = 0; i < table_size; ++i) table_[std::size_t(i)] = integrated_reflectance(T(i) / T(table_size - 1));
    }

    /// It keeps a reference to its index (static data, or the user's): not a temporary.
    MeasuredConductor(const metals::MeasuredIndex&&) = delete;

    /// The RGB reflectance at the incident cosine cos_i, from the table.
    [[nodiscard]] constexpr Rgb<T> reflectance(T cos_i) const noexcept
    {
        const T u = clamp(cos_i, T(0), T(1)) * T(table_size - 1);
        const int i = std::min(int(u), table_size - 2);
        const T f = u - T(i);
        return table_[std::size_t(i)] + (table_[std::size_t(i + 1)] - table_[std::size_t(i)]) * f;
    }

    /// The RGB reflectance integrated over the spectrum at cos_i, in gamut (what the table holds).
    [[nodiscard]] Rgb<T> integrated_reflectance(T cos_i) const
    {
        return cie::reflectance_to_rgb_in_gamut<T>([&](double lambda) { return spectral_reflectance(double(cos_i), lambda); });
    }

    /// The exact unpolarised reflectance at one wavelength (nanometres).
    template <Scalar U>
    [[nodiscard]] U spectral_reflectance(U cos_i, U lambda_nm) const noexcept
    {
        const std::complex<double> n = index_->at(double(lambda_nm));
        return U(fresnel_conductor(double(cos_i), n));
    }

    /// The exact reflectance at the query's cosine and one wavelength.
    [[nodiscard]] T reflectance_at(const SpecularQuery<T>& q, T wavelength_nm) const noexcept { return spectral_reflectance(q.cos_i, wavelength_nm); }

    /// The measured index.
    [[nodiscard]] constexpr const metals::MeasuredIndex& index() const noexcept { return *index_; }
    /// Nothing to check: the constructor reads the measured data.
    constexpr void validate() const {}

private:
    const metals::MeasuredIndex* index_; // static data of spectrum/metals.hpp, or the user's
    std::array<Rgb<T>, table_size> table_{};
};

/// A perfect specular conductor: mirror reflection weighted by Fresnel(cos_i), no diffuse.
/// A Fresnel policy with `reflectance(SpecularQuery)` (a film of textured thickness)
/// makes the conductor's reflectance vary over the surface.
template <Scalar T = float, class Fresnel = ConstantKr<T>>
struct Conductor {
    /// The precision of the material.
    using scalar_type = T;
    /// No diffuse lobe.
    static constexpr bool has_diffuse = false;
    /// Reflects, by the Fresnel policy.
    static constexpr bool reflects = true;
    /// Transmits nothing.
    static constexpr bool transmits = false;

    Fresnel fresnel{}; ///< the reflectance policy: ConstantKr, ComplexIor, MeasuredConductor, ThinFilmConductor or the user's

    /// The reflectance at incidence cosine cos_i, where the policy depends on the angle alone.
    [[nodiscard]] Rgb<T> reflectance(T cos_i) const noexcept
        requires requires(const Fresnel& f, T c) { f.reflectance(c); }
    {
        return fresnel.reflectance(cos_i);
    }
    /// The reflectance for a query (point, side, cosines), where the policy varies over the surface.
    [[nodiscard]] Rgb<T> reflectance(const SpecularQuery<T>& query) const noexcept
        requires requires(const Fresnel& f, const SpecularQuery<T>& q) { f.reflectance(q); }
    {
        return fresnel.reflectance(query);
    }
    /// The reflectance at one wavelength, for light that carries one (a band of
    /// dispersed light), where the Fresnel policy knows it.
    [[nodiscard]] T reflectance_at(const SpecularQuery<T>& query, T wavelength_nm) const noexcept
        requires requires(const Fresnel& f, const SpecularQuery<T>& q, T l) { { f.reflectance_at(q, l) } -> std::same_as<T>; }
    {
        return fresnel.reflectance_at(query, wavelength_nm);
    }
    /// Checks the Fresnel policy's parameters.
    constexpr void validate() const { fresnel.validate(); }
};

/// A mirror with constant reflectance kr.
template <Scalar T = float>
using Mirror = Conductor<T, ConstantKr<T>>;

/// A metal with a complex index per RGB channel.
template <Scalar T = float>
using Metal = Conductor<T, ComplexIor<T>>;

/// A metal with a measured spectral index, e.g. measured_metal<float>(metals::gold).
template <Scalar T = float>
[[nodiscard]] Conductor<T, MeasuredConductor<T>> measured_metal(const metals::MeasuredIndex& index)
{
    return {MeasuredConductor<T>(index)};
}
template <Scalar T = float>
Conductor<T, MeasuredConductor<T>> measured_metal(const metals::MeasuredIndex&&) = delete; // it would dangle

static_assert(Material<Mirror<float>> && Material<Metal<double>> && Material<Conductor<float, MeasuredConductor<float>>>);

} // namespace prism
