// SPDX-License-Identifier: MIT
// CoatedDiffuse: a Lambertian base under a clear dielectric coat, smooth or rough
// (plastic, varnished wood, a glazed tile), with its energy accounted for.
//
// The coat reflects by microfacet reflection with the dielectric's exact Fresnel
// equations; what it does not reflect enters, with T(cos) = 1 - E(cos), E the coat's
// directional albedo (so light the single-scattering lobe loses among its facets is
// counted as entering, not lost). Inside, the base of albedo rho and the coat's
// underside exchange light: the coat sends back the share F_in of diffuse light,
// 1 - F_in = T_avg / eta^2 with T_avg the cosine-weighted mean of T (the coat is
// reciprocal), so the geometric series of internal bounces sums to
// rho / (1 - rho F_in). Light leaves through the coat by T again, spread by the
// radiance's eta^2 compression (the smooth and rough plastic of Mitsuba 0.6, with
// its internal scattering kept: `nonlinear`). So
//   f = f_coat + T(cos_i) T(cos_o) rho / (pi eta^2 (1 - rho F_in)),
// which is reciprocal, and whose albedo E(cos_o) + T(cos_o) rho (1 - F_in) / (1 - rho F_in)
// is 1 exactly for rho = 1 (to the precision of the table of E, 1e-3).
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/bsdf.hpp>
#include <prism/material/texture.hpp>
#include <prism/material/traits.hpp>
#include <prism/optics/fresnel.hpp>
#include <prism/optics/microfacet.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace prism {

/// A clear coat: its index of refraction and its roughness (isotropic; alpha = roughness^2).
template <Scalar T>
struct Coat {
    T ior = T(1.5); ///< the coat's index of refraction, > 1
    T roughness = T(0.1); ///< its roughness, in [0, 1]; below about 0.03, smooth

    /// Throws std::invalid_argument, naming the parameter, for an index <= 1 or a roughness outside [0, 1].
    constexpr void validate() const
    {
        if (!(ior > T(1))) detail::throw_invalid("Coat ior must be finite and > 1, got ", ior);
        detail::require_index("Coat ior", ior);
        if (!(roughness >= T(0) && roughness <= T(1))) detail::throw_invalid("Coat roughness must be in [0, 1], got ", roughness);
    }
};

/// What a coat lets in at each incident cosine, tabulated: T(cos) = 1 - E(cos), and
/// the share F_in of diffuse light inside that it sends back.
template <Scalar T>
class CoatTransmission {
public:
    /// Cosines at which T is tabulated, evenly over [0, 1].
    static constexpr int size = 64;

    /// The table of `coat` (which must be valid): E(cos) integrated over the visible
    /// normals on a 32 x 32 grid of midpoints in double.
    explicit CoatTransmission(const Coat<T>& coat) noexcept
    {
        const double alpha = double(coat.roughness) * double(coat.roughness), eta = double(coat.ior);
        const TrowbridgeReitz<double> ggx(alpha, alpha);
        double mean = 0;
        for (int k = 0; k < size; ++k) {
            const double mu = std::max(double(k) / (size - 1), 1e-3);
            const Vec3<double> wo{std::sqrt(1 - mu * mu), 0, mu};
            double albedo = 0;
            if (ggx.smooth()) {
                albedo = fresnel_dielectric(mu, eta);
            } else {
                constexpr int n = 32;
                for (int i = 0; i < n; ++i)
                    for (int j = 0; j < n; ++j) {
                        const Vec3<double> m = ggx.sample_visible(wo, (i + 0.5) / n, (j + 0.5) / n);
                        const double c = dot(wo, m);
                        const Vec3<double> wi = 2 * c * m - wo;
                        if (c > 0 && wi.z > 0) albedo += fresnel_dielectric(c, eta) * ggx.g(wo, wi) / ggx.g1(wo);
                    }
                albedo /= n * n;
            }
            table_[std::size_t(k)] = T(1 - albedo);
        }
        // T_avg = 2 int_0^1 T(mu) mu dmu, by the trapezoid rule on the table.
        for (int k = 0; k + 1 < size; ++k) {
            const double a = double(k) / (size - 1), b = double(k + 1) / (size - 1);
            mean += (double(table_[std::size_t(k)]) * a + double(table_[std::size_t(k + 1)]) * b) * (b - a);
        }
        inside_reflectance_ = T(1 - mean / (eta * eta));
    }

    /// The share of light arriving at cosine mu that enters, T(mu) (linear in the table).
    [[nodiscard]] T at(T mu) const noexcept
    {
        const T u = clamp(mu, T(0), T(1)) * T(size - 1);
        const int i = std::min(int(u), size - 2);
        const T f = u - T(i);
        return table_[std::size_t(i)] + (table_[std::size_t(i + 1)] - table_[std::size_t(i)]) * f;
    }

    /// F_in: the share of diffuse light under the coat that it reflects back down.
    [[nodiscard]] T inside_reflectance() const noexcept { return inside_reflectance_; }

private:
    std::array<T, size> table_{};
    T inside_reflectance_ = T(0);
};

/// What a coat lets in at one roughness: a table's, or a blend of the two tables around
/// it (a coat whose roughness is a texture). Both of what it gives are linear in the
/// tables, so E = 1 - T still holds and a white base under it keeps all the light.
template <Scalar T>
struct CoatTransmissionAt {
    const CoatTransmission<T>* low;  ///< the table at or below the roughness
    const CoatTransmission<T>* high; ///< the table above it (low itself where there is one table)
    T weight = T(0);                 ///< how far toward `high`, in [0, 1]

    /// T(mu), blended.
    [[nodiscard]] T at(T mu) const noexcept
    {
        const T a = low->at(mu);
        return weight == T(0) ? a : a + (high->at(mu) - a) * weight;
    }

    /// F_in, blended.
    [[nodiscard]] T inside_reflectance() const noexcept
    {
        const T a = low->inside_reflectance();
        return weight == T(0) ? a : a + (high->inside_reflectance() - a) * weight;
    }
};

/// The lobe of a coated diffuse surface at one point (see the file's comment). Sampled
/// by its two parts, the coat with the probability of its share of the albedo at wo.
template <Scalar T>
class CoatedLobe {
public:
    /// The precision of the lobe.
    using scalar_type = T;

    /// The lobe of a base of albedo rho under `coat`, whose `transmission` (tables it
    /// refers to) is the coat's at its roughness.
    CoatedLobe(const Rgb<T>& rho, const Coat<T>& coat, CoatTransmissionAt<T> transmission) noexcept
        : ggx_(TrowbridgeReitz<T>::from(Roughness<T>(coat.roughness))), eta_(coat.ior), transmission_(transmission)
    {
        const T f_in = transmission.inside_reflectance();
        base_ = rho / ((Rgb<T>(T(1)) - rho * f_in) * (pi<T> * eta_ * eta_));
        escape_ = rho * (T(1) - f_in) / (Rgb<T>(T(1)) - rho * f_in);
    }

    /// Never a mirror as a whole (a smooth coat's reflection is a delta part of it).
    [[nodiscard]] static constexpr bool smooth() noexcept { return false; }

    /// The BRDF for wo and wi above the surface (0 otherwise); a smooth coat's mirror has none.
    [[nodiscard]] Rgb<T> f(const Vec3<T>& wo, const Vec3<T>& wi, Transport = Transport::radiance) const noexcept
    {
        if (!(wo.z > T(0)) || !(wi.z > T(0))) return Rgb<T>(T(0));
        return base_ * (transmission_.at(wo.z) * transmission_.at(wi.z)) + Rgb<T>(coat_f(wo, wi));
    }

    /// The density of sample's non-delta directions.
    [[nodiscard]] T pdf(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept
    {
        if (!(wo.z > T(0)) || !(wi.z > T(0))) return T(0);
        const T p = coat_share(wo.z);
        return (T(1) - p) * wi.z / pi<T> + (ggx_.smooth() ? T(0) : p * coat_pdf(wo, wi));
    }

    /// A direction: the coat's reflection (a visible normal's mirror; a smooth coat's
    /// mirror as a delta) with the coat's share of the albedo, else a cosine-distributed one.
    [[nodiscard]] std::optional<LobeSample<T>> sample(const Vec3<T>& wo, T u_lobe, T u1, T u2, Transport mode = Transport::radiance) const noexcept
    {
        if (!(wo.z > T(0))) return std::nullopt;
        const T p = coat_share(wo.z);
        Vec3<T> wi;
        if (u_lobe < p) {
            if (ggx_.smooth()) return LobeSample<T>{{-wo.x, -wo.y, wo.z}, Rgb<T>(fresnel_dielectric(wo.z, eta_) / p), T(0), true};
            const Vec3<T> m = ggx_.sample_visible(wo, u1, u2);
            wi = T(2) * dot(wo, m) * m - wo;
        } else {
            wi = cosine_direction(u1, u2);
        }
        const T density = pdf(wo, wi);
        if (!(density > T(0))) return std::nullopt;
        return LobeSample<T>{wi, f(wo, wi, mode) * (wi.z / density), density, false};
    }

    /// A smooth coat's reflection (its whole weight F); nothing for a rough coat.
    [[nodiscard]] std::optional<LobeSample<T>> delta_part(const Vec3<T>& wo) const noexcept
    {
        if (!ggx_.smooth()) return std::nullopt;
        return LobeSample<T>{{-wo.x, -wo.y, wo.z}, Rgb<T>(fresnel_dielectric(wo.z, eta_)), T(0), true};
    }

    /// The coat's albedo for wo, 1 - T(wo.z): what a Whitted mirror ray carries for it.
    [[nodiscard]] Rgb<T> mirror_albedo(const Vec3<T>& wo) const noexcept { return Rgb<T>(T(1) - transmission_.at(wo.z)); }

private:
    /// The coat's microfacet reflection (0 for a smooth coat: its mirror is a delta).
    [[nodiscard]] T coat_f(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept
    {
        if (ggx_.smooth()) return T(0);
        const Vec3<T> m = normalize(wo + wi);
        const T value = ggx_.d(m) * ggx_.g(wo, wi) * fresnel_dielectric(dot(wo, m), eta_) / (T(4) * wo.z * wi.z);
        return value < infinity<T> ? value : T(0);
    }

    /// The density of the coat's visible-normal sampling.
    [[nodiscard]] T coat_pdf(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept
    {
        const Vec3<T> m = normalize(wo + wi);
        const T c = dot(wo, m);
        const T value = c > T(0) ? ggx_.visible_d(wo, m) / (T(4) * c) : T(0);
        return value < infinity<T> ? value : T(0);
    }

    /// The probability of drawing from the coat at cosine mu: its share of the albedo
    /// (E against the base's T(mu) times the mean of its escaping albedo).
    [[nodiscard]] T coat_share(T mu) const noexcept
    {
        const T t = transmission_.at(mu), e = T(1) - t;
        const T base = t * (escape_.x + escape_.y + escape_.z) / T(3);
        return e + base > T(0) ? e / (e + base) : T(1);
    }

    TrowbridgeReitz<T> ggx_;
    T eta_;
    CoatTransmissionAt<T> transmission_;
    Rgb<T> base_{T(0)};   // rho / (pi eta^2 (1 - rho F_in))
    Rgb<T> escape_{T(0)}; // rho (1 - F_in) / (1 - rho F_in): the base's albedo through the coat, per unit entering
};

/// A Lambertian base of albedo `albedo` (a texture) under a clear coat (see the file's
/// comment): plastic, varnish, glaze. The coat's roughness is its Coat's, or a one-number
/// texture (`CoatRoughness`, an ImageTexture read by value()) that varies over the
/// surface: worn varnish, a glaze rubbed matte in places. What such a coat lets in is
/// tabulated at roughness 0, 1/16, ..., 1 and blended between the two tables around the
/// point's (17 tables of 64 cosines, built once, about 30 ms).
template <Scalar T = float, Texture Albedo = Solid<T>, class CoatRoughness = T>
class CoatedDiffuse {
public:
    /// The precision of the material.
    using scalar_type = T;
    /// Its Lambertian base lives in the glossy lobe, which is sampled as one.
    static constexpr bool has_diffuse = false;
    /// No delta mirror of its own (a smooth coat's is the lobe's delta part).
    static constexpr bool reflects = false;
    /// Transmits nothing.
    static constexpr bool transmits = false;
    /// A glossy lobe: coat and base.
    static constexpr bool has_glossy = true;
    /// Whether the coat's roughness is a texture.
    static constexpr bool textured_coat = ScalarTexture<CoatRoughness>;
    static_assert(textured_coat || std::same_as<CoatRoughness, T>, "a CoatedDiffuse's coat roughness is its Coat's (T) or a one-number texture");
    /// Whether a texture of it reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates = texture_reads_coordinates<Albedo> || textured_coat;
    /// Roughness steps between a textured coat's tables.
    static constexpr int coat_levels = 16;

    /// A base of `albedo` under `coat`; throws std::invalid_argument, naming the parameter, for a bad albedo or coat.
    explicit CoatedDiffuse(Albedo albedo = {}, Coat<T> coat = {})
        requires(!textured_coat)
        : albedo_(std::move(albedo)), coat_(checked(coat)), transmission_(coat_)
    {
        validate();
    }

    /// A base of `albedo` under a coat of index coat.ior whose roughness is the texture
    /// `roughness` (values in [0, 1]; coat.roughness is not read); throws
    /// std::invalid_argument, naming the parameter, for a bad albedo, index or texture.
    CoatedDiffuse(Albedo albedo, Coat<T> coat, CoatRoughness roughness)
        requires textured_coat
        : albedo_(std::move(albedo)), coat_(checked(coat)), roughness_(std::move(roughness))
    {
        validate();
        transmission_.reserve(coat_levels + 1);
        for (int k = 0; k <= coat_levels; ++k) transmission_.emplace_back(Coat<T>{coat_.ior, T(k) / T(coat_levels)});
    }

    /// The lobe at a point.
    [[nodiscard]] CoatedLobe<T> glossy(const GlossyQuery<T>& q) const noexcept
    {
        const Rgb<T> rho = albedo_at(albedo_, q.texture_point());
        if constexpr (textured_coat) {
            const T r = clamp(roughness_.value(q.texture_point()), T(0), T(1));
            const T x = r * T(coat_levels);
            const int k = std::min(int(x), coat_levels - 1);
            const auto i = std::size_t(k);
            return {rho, Coat<T>{coat_.ior, r}, CoatTransmissionAt<T>{&transmission_[i], &transmission_[i + 1], x - T(k)}};
        } else {
            return {rho, coat_, CoatTransmissionAt<T>{&transmission_, &transmission_, T(0)}};
        }
    }

    /// The base's albedo texture.
    [[nodiscard]] const Albedo& albedo() const noexcept { return albedo_; }
    /// The coat (its roughness unread where the coat's roughness is a texture).
    [[nodiscard]] const Coat<T>& coat() const noexcept { return coat_; }
    /// What the coat lets in.
    [[nodiscard]] const CoatTransmission<T>& transmission() const noexcept
        requires(!textured_coat)
    {
        return transmission_;
    }

    /// Throws std::invalid_argument, naming the parameter, for a bad albedo (above 1 in
    /// a channel, where it is Solid), coat or coat roughness texture.
    constexpr void validate() const
    {
        albedo_.validate();
        if constexpr (std::same_as<Albedo, Solid<T>>) {
            if (!(max_component(albedo_.color) <= T(1)))
                detail::throw_invalid("CoatedDiffuse albedo must be <= 1 in every channel, got ", detail::describe(albedo_.color));
        }
        coat_.validate();
        if constexpr (textured_coat) validate_roughness(roughness_, "CoatedDiffuse coat");
    }

private:
    static Coat<T> checked(const Coat<T>& coat)
    {
        coat.validate();
        return coat;
    }

    Albedo albedo_;
    Coat<T> coat_;
    [[no_unique_address]] std::conditional_t<textured_coat, CoatRoughness, std::monostate> roughness_{};
    std::conditional_t<textured_coat, std::vector<CoatTransmission<T>>, CoatTransmission<T>> transmission_;
};

static_assert(Material<CoatedDiffuse<float>>);

} // namespace prism
