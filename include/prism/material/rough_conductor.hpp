// SPDX-License-Identifier: MIT
// RoughConductor: a metal whose surface is a field of tiny mirrors, Trowbridge-Reitz
// (GGX) distributed, each reflecting by the Fresnel policy of a Conductor (Cook and
// Torrance 1982; Walter et al. 2007), sampled by the normals the viewer sees (Heitz 2018).
#pragma once

#include <prism/material/bsdf.hpp>
#include <prism/material/conductor.hpp>
#include <prism/optics/microfacet.hpp>

#include <cmath>
#include <optional>

namespace prism {

/// The microfacet reflection lobe f = D(m) F(wo.m) G(wo, wi) / (4 cos_o cos_i), m the
/// half vector, with F a conductor's Fresnel policy (ConstantKr, ComplexIor,
/// MeasuredConductor): it keeps F's per-channel reflectance where each facet mirrors.
/// Single scattering: light that would reflect twice among the facets is lost, which
/// at roughness 1 is about a third of it at grazing angles (tests/material/rough_conductor.cpp).
/// A smooth distribution (TrowbridgeReitz::smooth) is the mirror of Conductor.
template <Scalar T, class Fresnel>
class MicrofacetReflection {
public:
    /// The precision of the lobe.
    using scalar_type = T;

    /// The lobe of `distribution` with the facets' Fresnel policy (kept by reference: the material's).
    constexpr MicrofacetReflection(TrowbridgeReitz<T> distribution, const Fresnel& fresnel) noexcept
        : distribution_(distribution), fresnel_(&fresnel)
    {
    }

    /// Whether the surface is a mirror.
    [[nodiscard]] constexpr bool smooth() const noexcept { return distribution_.smooth(); }

    /// The BRDF for wo and wi both above the surface (0 otherwise, and for a mirror).
    [[nodiscard]] Rgb<T> f(const Vec3<T>& wo, const Vec3<T>& wi, Transport = Transport::radiance) const noexcept
    {
        if (smooth() || !(wo.z > T(0)) || !(wi.z > T(0))) return Rgb<T>(T(0));
        const Vec3<T> h = wo + wi;
        if (!(length_squared(h) > T(0))) return Rgb<T>(T(0));
        const Vec3<T> m = normalize(h);
        const T scale = distribution_.d(m) * distribution_.g(wo, wi) / (T(4) * wo.z * wi.z);
        return scale < infinity<T> ? fresnel_->reflectance(std::abs(dot(wo, m))) * scale : Rgb<T>(T(0));
    }

    /// The density of sample: the visible normals' density D_wo(m) / (4 wo.m).
    [[nodiscard]] T pdf(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept
    {
        if (smooth() || !(wo.z > T(0)) || !(wi.z > T(0))) return T(0);
        const Vec3<T> h = wo + wi;
        if (!(length_squared(h) > T(0))) return T(0);
        const Vec3<T> m = normalize(h);
        const T pdf = distribution_.visible_d(wo, m) / (T(4) * dot(wo, m));
        return pdf < infinity<T> ? pdf : T(0);
    }

    /// A direction for wo: a visible normal m, wi wo's mirror about it; its weight is
    /// F G(wo, wi) / G1(wo). Nothing where wi falls below the surface. A mirror reflects
    /// about z as a delta.
    [[nodiscard]] std::optional<LobeSample<T>> sample(const Vec3<T>& wo, T, T u1, T u2, Transport = Transport::radiance) const noexcept
    {
        if (!(wo.z > T(0))) return std::nullopt;
        if (smooth()) return LobeSample<T>{{-wo.x, -wo.y, wo.z}, fresnel_->reflectance(wo.z), T(0), true};
        const Vec3<T> m = distribution_.sample_visible(wo, u1, u2);
        const T cos_om = dot(wo, m);
        if (!(cos_om > T(0))) return std::nullopt;
        const Vec3<T> wi = T(2) * cos_om * m - wo;
        if (!(wi.z > T(0))) return std::nullopt;
        const T pdf = distribution_.visible_d(wo, m) / (T(4) * cos_om);
        if (!(pdf > T(0) && pdf < infinity<T>)) return std::nullopt;
        const T weight = distribution_.g(wo, wi) / distribution_.g1(wo);
        return LobeSample<T>{wi, fresnel_->reflectance(cos_om) * weight, pdf, false};
    }

    /// A mirror's reflection (its whole weight F); nothing for a rough surface.
    [[nodiscard]] std::optional<LobeSample<T>> delta_part(const Vec3<T>& wo) const noexcept
    {
        if (!smooth()) return std::nullopt;
        return LobeSample<T>{{-wo.x, -wo.y, wo.z}, fresnel_->reflectance(wo.z), T(0), true};
    }

    /// The lobe's albedo for wo, F G(wo, wi) / G1(wo) averaged over 4 x 4 visible
    /// normals at the centres of a grid: what a Whitted mirror ray carries for it.
    [[nodiscard]] Rgb<T> mirror_albedo(const Vec3<T>& wo) const noexcept
    {
        if (smooth()) return fresnel_->reflectance(wo.z);
        Rgb<T> sum{T(0)};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                if (const auto s = sample(wo, T(0), (T(i) + T(0.5)) / T(4), (T(j) + T(0.5)) / T(4))) sum += s->weight;
        return sum / T(16);
    }

private:
    TrowbridgeReitz<T> distribution_;
    const Fresnel* fresnel_;
};

/// A rough metal: microfacets of Trowbridge-Reitz roughness (alpha = roughness^2,
/// isotropic or along the frame's two tangents) reflecting by the Fresnel policy of a
/// Conductor (ConstantKr, ComplexIor, MeasuredConductor). At roughness below about
/// 0.03 (alpha below TrowbridgeReitz::smooth_alpha) it is the mirror Conductor.
template <Scalar T = float, class Fresnel = ConstantKr<T>, class RoughnessMap = Roughness<T>>
struct RoughConductor {
    /// The precision of the material.
    using scalar_type = T;
    /// No Lambertian lobe.
    static constexpr bool has_diffuse = false;
    /// No delta mirror (its mirror, when smooth, is the glossy lobe's delta sample).
    static constexpr bool reflects = false;
    /// Transmits nothing.
    static constexpr bool transmits = false;
    /// A glossy lobe: microfacet reflection.
    static constexpr bool has_glossy = true;
    /// Whether a texture of it reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates = texture_reads_coordinates<RoughnessMap>;

    Fresnel fresnel{}; ///< each facet's reflectance: ConstantKr, ComplexIor, MeasuredConductor or the user's
    RoughnessMap roughness{}; ///< roughness, alpha = roughness^2: a Roughness, or a one-number texture (ImageTexture) of it

    /// The lobe at a point.
    [[nodiscard]] constexpr MicrofacetReflection<T, Fresnel> glossy(const GlossyQuery<T>& q) const noexcept
    {
        return {TrowbridgeReitz<T>::from(roughness_at(roughness, q.texture_point())), fresnel};
    }

    /// Throws std::invalid_argument, naming the parameter, for a roughness outside [0, 1] or a bad Fresnel policy.
    constexpr void validate() const
    {
        validate_roughness(roughness, "RoughConductor");
        fresnel.validate();
    }
};

/// A rough metal with a measured spectral index, e.g. rough_metal<float>(metals::gold, 0.3).
template <Scalar T = float>
[[nodiscard]] RoughConductor<T, MeasuredConductor<T>> rough_metal(const metals::MeasuredIndex& index, Roughness<T> roughness)
{
    return {MeasuredConductor<T>(index), roughness};
}
template <Scalar T = float>
RoughConductor<T, MeasuredConductor<T>> rough_metal(const metals::MeasuredIndex&&, Roughness<T>) = delete; // it would dangle

} // namespace prism
