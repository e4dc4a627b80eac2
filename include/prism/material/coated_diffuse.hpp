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

#include <array>
#include <cmath>
#include <optional>
#include <utility>

namespace prism {

/// A clear coat: its index of refraction and its roughness (isotropic; alpha = roughness^2).
template <Scalar T>
struct Coat {
    T ior = T(1.5); ///< the coat's index of refraction, > 1
    T roughness = T(0.1); ///< its roughness, in [0, 1]; below about 0.03, smooth

    /// Throws std::invalid_argument, naming the parameter, for an index <= 1 or a roughness outside [0, 1].
    constexpr void validate() const
    {
        if (!(ior > T(1) && ior < infinity<T>)) detail::throw_invalid("Coat ior must be finite and > 1, got ", ior);
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

/// The lobe of a coated diffuse surface at one point (see the file's comment). Sampled
/// by its two parts, the coat with the probability of its share of the albedo at wo.
template <Scalar T>
class CoatedLobe {
public:
    /// The precision of the lobe.
    using scalar_type = T;

    /// The lobe of a base of albedo rho under `coat`, whose `transmission` table it keeps by reference.
    CoatedLobe(const Rgb<T>& rho, const Coat<T>& coat, const CoatTransmission<T>& transmission) noexcept
        : ggx_(TrowbridgeReitz<T>::from(Roughness<T>(coat.roughness))), eta_(coat.ior), transmission_(&transmission)
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
        return base_ * (transmission_->at(wo.z) * transmission_->at(wi.z)) + Rgb<T>(coat_f(wo, wi));
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
    [[nodiscard]] Rgb<T> mirror_albedo(const Vec3<T>& wo) const noexcept { return Rgb<T>(T(1) - transmission_->at(wo.z)); }

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
        const T t = transmission_->at(mu), e = T(1) - t;
        const T base = t * (escape_.x + escape_.y + escape_.z) / T(3);
        return e + base > T(0) ? e / (e + base) : T(1);
    }

    TrowbridgeReitz<T> ggx_;
    T eta_;
    const CoatTransmission<T>* transmission_;
    Rgb<T> base_{T(0)};   // rho / (pi eta^2 (1 - rho F_in))
    Rgb<T> escape_{T(0)}; // rho (1 - F_in) / (1 - rho F_in): the base's albedo through the coat, per unit entering
};

/// A Lambertian base of albedo `albedo` (a texture) under a clear coat (see the file's
/// comment): plastic, varnish, glaze.
template <Scalar T = float, Texture Albedo = Solid<T>>
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
    /// Whether a texture of it reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates = texture_reads_coordinates<Albedo>;

    /// A base of `albedo` under `coat`; throws std::invalid_argument, naming the parameter, for a bad albedo or coat.
    explicit CoatedDiffuse(Albedo albedo = {}, Coat<T> coat = {}) : albedo_(std::move(albedo)), coat_(checked(coat)), transmission_(coat_)
    {
        validate();
    }

    /// The lobe at a point.
    [[nodiscard]] CoatedLobe<T> glossy(const GlossyQuery<T>& q) const noexcept
    {
        return {albedo_at(albedo_, q.texture_point()), coat_, transmission_};
    }

    /// The base's albedo texture.
    [[nodiscard]] const Albedo& albedo() const noexcept { return albedo_; }
    /// The coat.
    [[nodiscard]] const Coat<T>& coat() const noexcept { return coat_; }
    /// What the coat lets in.
    [[nodiscard]] const CoatTransmission<T>& transmission() const noexcept { return transmission_; }

    /// Throws std::invalid_argument, naming the parameter, for a bad albedo (above 1 in
    /// a channel, where it is Solid) or coat.
    constexpr void validate() const
    {
        albedo_.validate();
        if constexpr (std::same_as<Albedo, Solid<T>>) {
            if (!(max_component(albedo_.color) <= T(1)))
                detail::throw_invalid("CoatedDiffuse albedo must be <= 1 in every channel, got ", detail::describe(albedo_.color));
        }
        coat_.validate();
    }

private:
    static Coat<T> checked(const Coat<T>& coat)
    {
        coat.validate();
        return coat;
    }

    Albedo albedo_;
    Coat<T> coat_;
    CoatTransmission<T> transmission_;
};

static_assert(Material<CoatedDiffuse<float>>);

} // namespace prism
