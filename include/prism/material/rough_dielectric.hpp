// SPDX-License-Identifier: MIT
// RoughDielectric: frosted glass, a dielectric interface whose surface is a field of tiny
// facets, Trowbridge-Reitz (GGX) distributed, each reflecting and refracting by the exact
// Fresnel equations (Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces"), sampled by the normals the path sees (Heitz 2018), written after pbrt-v4's
// DielectricBxDF.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/bsdf.hpp>
#include <prism/material/dielectric.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/homogeneous.hpp>
#include <prism/optics/fresnel.hpp>
#include <prism/optics/microfacet.hpp>

#include <cmath>
#include <optional>

namespace prism {

/// Microfacet reflection and refraction at an interface, in the local frame with +z on
/// one side and -z on the other, eta = n(-z side) / n(+z side). For light arriving from
/// wo (either side), a facet m reflects F(wo.m) and refracts the rest:
///   reflection   D(m) G F / |4 cos_o cos_i|, m the half vector wo + wi;
///   refraction   D(m) G (1 - F) |wi.m wo.m| / |cos_o cos_i (wi.m + wo.m / eta')^2|,
///                m along -(eta' wi + wo), eta' the ratio toward wi's side,
/// for either transport: prism's camera paths carry radiance across an interface as its
/// photons carry power, without the 1 / eta'^2 of radiance compressed into a denser
/// medium (pbrt's radiance mode), as Dielectric does: on every path from air to air the
/// factors cancel, and a camera path that entered glass by a Dielectric may leave it by
/// frosted glass. So f(wo, wi) / n(wi's side)^2 = f(wi, wo) / n(wo's side)^2. Single
/// scattering: light that would meet a second facet is lost. A smooth distribution is the
/// clean interface of Dielectric: a Fresnel-weighted delta reflection or refraction.
template <Scalar T>
class MicrofacetDielectric {
public:
    /// The precision of the lobe.
    using scalar_type = T;

    /// The lobe of `distribution` between a +z side and a -z side of n(-z) / n(+z) = eta.
    constexpr MicrofacetDielectric(TrowbridgeReitz<T> distribution, T eta) noexcept : distribution_(distribution), eta_(eta) {}

    /// Whether the interface is clean (every sample a delta).
    [[nodiscard]] constexpr bool smooth() const noexcept { return distribution_.smooth() || eta_ == T(1); }

    /// The BSDF for a path from wo going on along wi (0 for a clean interface).
    [[nodiscard]] Rgb<T> f(const Vec3<T>& wo, const Vec3<T>& wi, Transport mode = Transport::radiance) const noexcept
    {
        // From -z the interface is the same one mirrored, its indices swapped.
        if (wo.z < T(0)) return flipped().f(mirror(wo), mirror(wi), mode);
        const auto h = half_vector(wo, wi);
        if (smooth() || !h) return Rgb<T>(T(0));
        const T cos_o = wo.z, cos_i = wi.z;
        const T fresnel = fresnel_dielectric(dot(wo, h->m), eta_);
        const T dg = distribution_.d(h->m) * distribution_.g(wo, wi);
        if (h->reflect) {
            const T value = dg * fresnel / std::abs(T(4) * cos_i * cos_o);
            return Rgb<T>(value < infinity<T> ? value : T(0));
        }
        const T denom = sqr(dot(wi, h->m) + dot(wo, h->m) / eta_) * cos_i * cos_o;
        const T value = dg * (T(1) - fresnel) * std::abs(dot(wi, h->m) * dot(wo, h->m) / denom);
        return Rgb<T>(value < infinity<T> ? value : T(0));
    }

    /// The density of sample (0 for a clean interface).
    [[nodiscard]] T pdf(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept
    {
        if (wo.z < T(0)) return flipped().pdf(mirror(wo), mirror(wi));
        const auto h = half_vector(wo, wi);
        if (smooth() || !h) return T(0);
        const T fresnel = fresnel_dielectric(dot(wo, h->m), eta_);
        const T visible = distribution_.visible_d(wo, h->m);
        const T value = h->reflect ? visible / (T(4) * dot(wo, h->m)) * fresnel
                                   : visible * std::abs(dot(wi, h->m)) / sqr(dot(wi, h->m) + dot(wo, h->m) / eta_) * (T(1) - fresnel);
        return value < infinity<T> ? value : T(0);
    }

    /// A direction for wo: a visible normal m, then reflection about it with probability
    /// F(wo.m), refraction through it otherwise; nothing where the result falls on the
    /// wrong side. A clean interface reflects or refracts about z as a delta, by Fresnel's
    /// share (u_lobe chooses).
    [[nodiscard]] std::optional<LobeSample<T>> sample(const Vec3<T>& wo, T u_lobe, T u1, T u2, Transport mode = Transport::radiance) const noexcept
    {
        if (wo.z == T(0)) return std::nullopt;
        const T side = wo.z > T(0) ? T(1) : T(-1); // work with wo above (mirrored), turn the answer back
        const Vec3<T> w{wo.x, wo.y, wo.z * side};
        const T eta = side > T(0) ? eta_ : T(1) / eta_; // n beyond / n on wo's side
        if (smooth()) {
            const T fresnel = fresnel_dielectric(w.z, eta);
            if (u_lobe < fresnel) return LobeSample<T>{{-wo.x, -wo.y, wo.z}, Rgb<T>(T(1)), T(0), true};
            const auto t = refract(w, Vec3<T>(T(0), T(0), T(1)), eta);
            if (!t) return std::nullopt; // (total internal reflection has F = 1)
            return LobeSample<T>{{t->x, t->y, t->z * side}, Rgb<T>(T(1)), T(0), true};
        }
        Vec3<T> m = distribution_.sample_visible(w, u1, u2);
        const T cos_om = dot(w, m);
        if (!(cos_om > T(0))) return std::nullopt;
        const T fresnel = fresnel_dielectric(cos_om, eta);
        Vec3<T> wi;
        if (u_lobe < fresnel) {
            wi = T(2) * cos_om * m - w;
            if (!(wi.z > T(0))) return std::nullopt;
        } else {
            const auto t = refract(w, m, eta);
            if (!t || !(t->z < T(0))) return std::nullopt;
            wi = *t;
        }
        wi.z *= side;
        const T density = pdf(wo, wi);
        if (!(density > T(0))) return std::nullopt;
        const Rgb<T> value = f(wo, wi, mode);
        return LobeSample<T>{wi, value * (std::abs(wi.z) / density), density, false};
    }

private:
    struct Half {
        Vec3<T> m; ///< the facet normal, on +z's side
        bool reflect;
    };

    [[nodiscard]] static constexpr T sqr(T x) noexcept { return x * x; }
    [[nodiscard]] static constexpr Vec3<T> mirror(const Vec3<T>& v) noexcept { return {v.x, v.y, -v.z}; }
    /// The same interface seen from -z.
    [[nodiscard]] constexpr MicrofacetDielectric flipped() const noexcept { return {distribution_, T(1) / eta_}; }

    /// The refraction of w (above the facet m, unit) through it into eta = n beyond / n on
    /// w's side: nothing under total internal reflection.
    [[nodiscard]] static std::optional<Vec3<T>> refract(const Vec3<T>& w, const Vec3<T>& m, T eta) noexcept
    {
        const T cos_i = dot(w, m);
        const T sin2_t = std::max(T(0), T(1) - cos_i * cos_i) / (eta * eta);
        if (sin2_t >= T(1)) return std::nullopt;
        const T cos_t = std::sqrt(T(1) - sin2_t);
        return -w / eta + (cos_i / eta - cos_t) * m;
    }

    /// For wo above: the facet normal that turns wo into wi, and whether by reflection;
    /// nothing for grazing directions or a facet that one of them sees from behind.
    [[nodiscard]] std::optional<Half> half_vector(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept
    {
        const T cos_o = wo.z, cos_i = wi.z;
        if (!(cos_o > T(0)) || cos_i == T(0)) return std::nullopt;
        const bool reflect = cos_i > T(0);
        Vec3<T> m = wi * (reflect ? T(1) : eta_) + wo;
        if (!(length_squared(m) > T(0))) return std::nullopt;
        m = normalize(m);
        if (m.z < T(0)) m = -m;
        if (dot(m, wi) * cos_i < T(0) || dot(m, wo) < T(0)) return std::nullopt;
        return Half{m, reflect};
    }

    TrowbridgeReitz<T> distribution_;
    T eta_;
};

/// Frosted glass: a dielectric of index `ior` whose surface has Trowbridge-Reitz roughness
/// (alpha = roughness^2), filled with `interior` (Beer-Lambert by default), nested with
/// other transmissive objects by `priority` as Dielectric is. Below roughness 0.03 it is
/// Dielectric's clean interface. Whitted's shadow rays pass it as they pass clear glass.
template <Scalar T = float, Medium Interior = Homogeneous<T>, class RoughnessMap = Roughness<T>>
    requires std::same_as<typename Interior::scalar_type, T>
struct RoughDielectric {
    /// The precision of the material.
    using scalar_type = T;
    /// No Lambertian lobe.
    static constexpr bool has_diffuse = false;
    /// No delta mirror of its own.
    static constexpr bool reflects = false;
    /// An interface with an interior (its refraction is the glossy lobe's).
    static constexpr bool transmits = true;
    /// A glossy lobe: microfacet reflection and refraction.
    static constexpr bool has_glossy = true;
    /// Whether a texture of it reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates = texture_reads_coordinates<RoughnessMap>;

    T ior = T(1.5); ///< the index of refraction inside
    RoughnessMap roughness{}; ///< roughness, alpha = roughness^2: a Roughness, or a one-number texture (ImageTexture) of it
    Interior interior{}; ///< the medium that fills it
    int priority = 0; ///< where it overlaps another transmissive object, the higher priority's medium wins (medium/nesting.hpp)

    /// The lobe at a point, for light arriving where the index beyond over the index on its side is q.eta.
    [[nodiscard]] constexpr MicrofacetDielectric<T> glossy(const GlossyQuery<T>& q) const noexcept
    {
        return {TrowbridgeReitz<T>::from(roughness_at(roughness, q.texture_point())), q.eta};
    }

    /// The clean glass of the same index, interior and priority (what Whitted refracts by).
    [[nodiscard]] constexpr Dielectric<T, ExactFresnel, Interior> clean() const noexcept { return {.ior = ior, .interior = interior, .priority = priority}; }

    /// The index of refraction inside.
    [[nodiscard]] constexpr T refractive_index() const noexcept { return ior; }
    /// What a Whitted shadow ray keeps crossing the surface: all (the medium inside attenuates).
    [[nodiscard]] constexpr Rgb<T> transmission_tint() const noexcept { return Rgb<T>(T(1)); }
    /// The medium inside.
    [[nodiscard]] constexpr const Interior& medium() const noexcept { return interior; }

    /// Throws std::invalid_argument, naming the parameter, for ior <= 0, a roughness outside [0, 1] or a bad interior.
    constexpr void validate() const
    {
        detail::require_index("RoughDielectric ior", ior);
        validate_roughness(roughness, "RoughDielectric");
        interior.validate();
    }
};

} // namespace prism
