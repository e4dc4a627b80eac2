// SPDX-License-Identifier: MIT
// Thin-film iridescence: a soap film, an oil slick, an anodised or tempered metal.
//
// A film of real index n_f and thickness d (which may vary over the surface: a soap
// bubble drains thinner at the top) coats a substrate. Its reflectance at each
// wavelength is Airy's exact sum (optics/thin_film.hpp); integrated against the CIE
// observer under D65 it becomes the RGB the renderer uses (spectrum/cie.hpp). That
// integral costs 95 Airy evaluations, far too many per ray, so each material tabulates
// it once at construction over the incident cosine and the thickness, and a ray reads
// the table bilinearly. bench/thin_film.cpp charts the table's error and speed against
// the exact integral; FilmTable::Config sets its resolution.
//
//   ThinFilmConductor  a Fresnel policy for Conductor: a film over a metal
//   CoatedDielectric   a dielectric interface with a film on its outside: a soap bubble
//                      (ior 1: air on both sides), oil on water
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/homogeneous.hpp>
#include <prism/optics/thin_film.hpp>
#include <prism/spectrum/cie.hpp>
#include <prism/spectrum/metals.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace prism {

/// A film thickness that is the same everywhere, in nanometres.
template <Scalar T = float>
struct UniformThickness {
    /// The precision of the thickness.
    using scalar_type = T;
    T nm = T(300); ///< the film's thickness in nanometres, everywhere

    /// The thickness at any point: nm.
    [[nodiscard]] constexpr T at(const Vec3<T>&) const noexcept { return nm; }
    /// The thinnest the film gets (nm), for the tables.
    [[nodiscard]] constexpr T lowest_nm() const noexcept { return nm; }
    /// The thickest the film gets (nm), for the tables.
    [[nodiscard]] constexpr T highest_nm() const noexcept { return nm; }
    /// Throws std::invalid_argument for a negative or non-finite thickness.
    constexpr void validate() const { detail::require_non_negative("UniformThickness nm", nm); }
};

/// A film thickness that varies over the surface: `thickness(p)` in nanometres, which
/// must stay within [lowest_nm, highest_nm] (the range the tables cover; a value
/// outside reads the nearest edge of the table, and is caught by PRISM_ASSERT).
template <Scalar T, class F>
    requires std::is_invocable_r_v<T, const F&, const Vec3<T>&>
struct ThicknessTexture {
    /// The precision of the thickness.
    using scalar_type = T;
    F thickness; ///< thickness(p) in nanometres
    T lowest = T(0); ///< the least thickness(p) can return (nm)
    T highest = T(1000); ///< the most thickness(p) can return (nm)

    /// The thickness at p: thickness(p), asserted within [lowest, highest].
    [[nodiscard]] T at(const Vec3<T>& p) const noexcept
    {
        const T d = thickness(p);
        PRISM_ASSERT(d >= lowest && d <= highest);
        return d;
    }
    /// The thinnest the film gets (nm), for the tables.
    [[nodiscard]] constexpr T lowest_nm() const noexcept { return lowest; }
    /// The thickest the film gets (nm), for the tables.
    [[nodiscard]] constexpr T highest_nm() const noexcept { return highest; }
    /// Throws std::invalid_argument, naming the parameter, for a negative lowest, a non-finite highest or highest < lowest.
    constexpr void validate() const
    {
        detail::require_non_negative("ThicknessTexture lowest", lowest);
        detail::require_finite("ThicknessTexture highest", highest);
        if (!(highest >= lowest)) detail::throw_invalid("ThicknessTexture highest must be >= lowest (", lowest, "), got ", highest);
    }
};

/// A film thickness: `at(p)` within [lowest_nm(), highest_nm()], and validate().
template <class X>
concept FilmThickness = requires(const X& x, const Vec3<typename X::scalar_type>& p) {
    { x.at(p) } -> std::same_as<typename X::scalar_type>;
    { x.lowest_nm() } -> std::same_as<typename X::scalar_type>;
    { x.highest_nm() } -> std::same_as<typename X::scalar_type>;
    x.validate();
};

/// The RGB reflectance of one film stack tabulated over the incident cosine (uniform in
/// sqrt(cos_i), which packs entries towards grazing incidence, where reflectance climbs
/// steeply to 1) and the thickness (uniform over the texture's range), read bilinearly.
template <Scalar T>
class FilmTable {
public:
    /// The table's resolution over the incident cosine and over the film's thickness.
    struct Config {
        int cosines = 65;           ///< entries over sqrt(cos_i) in [0, 1]
        T thickness_step_nm = T(2); ///< spacing of the entries over the thickness
    };

    FilmTable() = default;

    /// Tabulate `spectral(cos_i, lambda_nm, d)`, a film's reflectance at one
    /// wavelength, integrated over the spectrum, at thicknesses d in [lowest_nm, highest_nm].
    template <class Spectral>
    FilmTable(const Spectral& spectral, T lowest_nm, T highest_nm, Config config) : lowest_(lowest_nm)
    {
        if (config.cosines < 2) detail::throw_invalid("FilmTable cosines must be >= 2, got ", config.cosines);
        detail::require_positive("FilmTable thickness_step_nm", config.thickness_step_nm);
        cosines_ = config.cosines;
        thicknesses_ = 1 + int(std::ceil((highest_nm - lowest_nm) / config.thickness_step_nm));
        step_ = thicknesses_ > 1 ? (highest_nm - lowest_nm) / T(thicknesses_ - 1) : T(1);
        table_.resize(std::size_t(cosines_) * std::size_t(thicknesses_));
        for (int j = 0; j < thicknesses_; ++j)
            for (int i = 0; i < cosines_; ++i) {
                const T root = T(i) / T(cosines_ - 1);
                table_[index(i, j)] = integrate(spectral, root * root, lowest_ + step_ * T(j));
            }
    }

    /// A film's reflectance integrated over the spectrum at cos_i and thickness d,
    /// computed exactly (95 wavelengths): what the table holds at its entries.
    template <class Spectral>
    [[nodiscard]] static Rgb<T> integrate(const Spectral& spectral, T cos_i, T d)
    {
        return cie::reflectance_to_rgb_in_gamut<T>([&](double lambda) { return spectral(double(cos_i), lambda, double(d)); });
    }

    /// The tabulated reflectance at cos_i and thickness d (bilinear).
    [[nodiscard]] Rgb<T> operator()(T cos_i, T d) const noexcept
    {
        const T u = std::sqrt(clamp(cos_i, T(0), T(1))) * T(cosines_ - 1);
        const int i = std::min(int(u), cosines_ - 2);
        const T fu = u - T(i);
        const T v = thicknesses_ > 1 ? clamp((d - lowest_) / step_, T(0), T(thicknesses_ - 1)) : T(0);
        const int j = std::min(int(v), std::max(thicknesses_ - 2, 0));
        const T fv = v - T(j);
        const int j1 = std::min(j + 1, thicknesses_ - 1);
        const Rgb<T> a = table_[index(i, j)] + (table_[index(i + 1, j)] - table_[index(i, j)]) * fu;
        const Rgb<T> b = table_[index(i, j1)] + (table_[index(i + 1, j1)] - table_[index(i, j1)]) * fu;
        return a + (b - a) * fv;
    }

    /// The number of tabulated reflectances (cosines x thicknesses).
    [[nodiscard]] std::size_t entries() const noexcept { return table_.size(); }

private:
    [[nodiscard]] std::size_t index(int i, int j) const noexcept { return std::size_t(j) * std::size_t(cosines_) + std::size_t(i); }

    T lowest_ = T(0);
    T step_ = T(1);
    int cosines_ = 0;
    int thicknesses_ = 0;
    std::vector<Rgb<T>> table_;
};

/// A film of real index `film_index` and thickness `thickness` over a metal (a measured
/// spectral index, or one complex index for every wavelength): a Fresnel policy for
/// Conductor, e.g. anodised titanium or tempered steel's colours.
template <Scalar T = float, FilmThickness Thickness = UniformThickness<T>>
class ThinFilmConductor {
public:
    /// A film over a measured metal (kept by reference: static data such as metals::gold, or the caller's, which must outlive it).
    ThinFilmConductor(T film_index, Thickness thickness, const metals::MeasuredIndex& substrate,
                      typename FilmTable<T>::Config config = {})
        : ThinFilmConductor(film_index, thickness, &substrate, {}, config)
    {
    }

    /// It keeps a reference to a measured substrate (static data, or the user's): not a temporary.
    ThinFilmConductor(T, Thickness, const metals::MeasuredIndex&&, typename FilmTable<T>::Config = {}) = delete;

    /// A film over a metal of one complex index n + ik at every wavelength.
    ThinFilmConductor(T film_index, Thickness thickness, std::complex<double> substrate, typename FilmTable<T>::Config config = {})
        : ThinFilmConductor(film_index, thickness, nullptr, substrate, config)
    {
    }

    /// The tabulated reflectance where the query's point is.
    [[nodiscard]] Rgb<T> reflectance(const SpecularQuery<T>& q) const noexcept { return table_(q.cos_i, thickness_.at(q.point)); }

    /// The tabulated reflectance.
    [[nodiscard]] const FilmTable<T>& table() const noexcept { return table_; }
    /// Nothing to check: the constructors refuse bad parameters.
    constexpr void validate() const {} // checked at construction

    /// The exact reflectance at one wavelength, for rays that carry one.
    [[nodiscard]] double spectral_reflectance(double cos_i, double lambda_nm, double d) const noexcept
    {
        return thin_film(FilmStack<double>{1.0, film_index_, d, substrate(lambda_nm)}, cos_i, lambda_nm).reflected();
    }
    /// The reflectance at one wavelength, for a ray that carries one (dispersion).
    [[nodiscard]] T reflectance_at(const SpecularQuery<T>& q, T wavelength_nm) const noexcept
    {
        return T(spectral_reflectance(double(q.cos_i), double(wavelength_nm), double(thickness_.at(q.point))));
    }

private:
    ThinFilmConductor(T film_index, Thickness thickness, const metals::MeasuredIndex* measured, std::complex<double> constant,
                      typename FilmTable<T>::Config config)
        : film_index_((detail::require_positive("ThinFilmConductor film_index", film_index), double(film_index))),
          thickness_((thickness.validate(), thickness)), measured_(measured), constant_(constant)
    {
        if (!measured) {
            detail::require_positive("ThinFilmConductor substrate eta", constant.real());
            detail::require_non_negative("ThinFilmConductor substrate k", constant.imag());
        }
        table_ = FilmTable<T>([&](double c, double l, double d) { return spectral_reflectance(c, l, d); }, thickness.lowest_nm(),
                              thickness.highest_nm(), config);
    }

    [[nodiscard]] std::complex<double> substrate(double lambda_nm) const noexcept { return measured_ ? measured_->at(lambda_nm) : constant_; }

    double film_index_;
    Thickness thickness_;
    const metals::MeasuredIndex* measured_; // static data of spectrum/metals.hpp, or the user's
    std::complex<double> constant_;
    FilmTable<T> table_;
};

/// A dielectric interface (index `ior` inside, 1 outside) coated on its outside with a
/// film of real index `film_index` and thickness `thickness`: a soap bubble is a film
/// with air on both sides (ior 1), an oil slick a film over water (ior 1.333). The film
/// does not bend light (its faces are parallel), so rays refract as at the bare
/// interface, but it splits them per channel: reflectance R from Airy's sum, tabulated
/// for light arriving from outside, and transmittance 1 - R (the film absorbs nothing).
template <Scalar T = float, FilmThickness Thickness = UniformThickness<T>, Medium Interior = Homogeneous<T>>
    requires std::same_as<typename Thickness::scalar_type, T> && std::same_as<typename Interior::scalar_type, T>
class CoatedDielectric {
public:
    /// The precision of the material.
    using scalar_type = T;
    /// No diffuse lobe.
    static constexpr bool has_diffuse = false;
    /// Reflects (per channel, from the film).
    static constexpr bool reflects = true;
    /// Transmits (1 - R per channel).
    static constexpr bool transmits = true;

    /// The interface with index `ior` inside, coated outside with a film of index `film_index`; throws std::invalid_argument, naming the parameter, for an index <= 0 or a bad thickness.
    CoatedDielectric(T ior, T film_index, Thickness thickness, Interior interior = {}, typename FilmTable<T>::Config config = {})
        : ior_((detail::require_positive("CoatedDielectric ior", ior), ior)),
          film_index_((detail::require_positive("CoatedDielectric film_index", film_index), film_index)),
          thickness_((thickness.validate(), thickness)), interior_((interior.validate(), interior))
    {
        from_outside_ = FilmTable<T>([&](double c, double l, double d) { return spectral_reflectance(c, l, d, true); },
                                     thickness.lowest_nm(), thickness.highest_nm(), config);
    }

    // Dielectric capabilities (DeltaTransmission, InteriorMedium)

    /// The index inside.
    [[nodiscard]] constexpr T refractive_index() const noexcept { return ior_; }
    /// The film's reflectance per channel. Light arriving from inside reflects as much
    /// as light arriving from outside along its refracted path would: the stack absorbs
    /// nothing, so its transmittance, and with it its reflectance, is reciprocal. One
    /// table, read at the outside cosine, serves both sides, and never straddles the
    /// critical angle.
    [[nodiscard]] Rgb<T> fresnel(const SpecularQuery<T>& q) const noexcept
    {
        return from_outside_(q.entering ? q.cos_i : q.cos_t, thickness_.at(q.point));
    }
    /// White: the film's colour is in fresnel().
    [[nodiscard]] constexpr Rgb<T> reflection_tint() const noexcept { return Rgb<T>(T(1)); }
    /// White: the film's colour is in fresnel().
    [[nodiscard]] constexpr Rgb<T> transmission_tint() const noexcept { return Rgb<T>(T(1)); }
    /// The medium inside.
    [[nodiscard]] constexpr const Interior& medium() const noexcept { return interior_; }
    /// Nothing to check: the constructor refuses bad parameters.
    constexpr void validate() const {} // checked at construction
    /// The number of tabulated reflectances.
    [[nodiscard]] std::size_t table_entries() const noexcept { return from_outside_.entries(); }

    /// The film's exact reflectance at one wavelength, for light that carries one.
    [[nodiscard]] T fresnel_at(const SpecularQuery<T>& q, T wavelength_nm) const noexcept
    {
        return T(spectral_reflectance(double(q.cos_i), double(wavelength_nm), double(thickness_.at(q.point)), q.entering));
    }

    /// The exact reflectance at one wavelength, arriving from outside or from inside.
    [[nodiscard]] double spectral_reflectance(double cos_i, double lambda_nm, double d, bool from_outside) const noexcept
    {
        const double outside = 1.0, inside = double(ior_);
        const FilmStack<double> stack{from_outside ? outside : inside, double(film_index_), d, from_outside ? inside : outside};
        return thin_film(stack, cos_i, lambda_nm).reflected();
    }

private:
    T ior_;
    T film_index_;
    Thickness thickness_;
    Interior interior_;
    FilmTable<T> from_outside_;
};

static_assert(Material<CoatedDielectric<float>>);

} // namespace prism
