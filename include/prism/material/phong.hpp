// SPDX-License-Identifier: MIT
// Phong: the normalised modified Phong model (Lafortune and Willems 1994), the glossy
// surface of the classic photon-mapping and bidirectional test scenes. A Lambertian
// part kd / pi and a lobe about the mirror direction, ks (n + 2) / 2 pi cos^n alpha,
// whose albedo at normal incidence is ks and less elsewhere: with kd + ks <= 1 it never
// reflects more than arrives. Unlike Diffuse's `phong` (POV-Ray's highlight, seen only
// from the lights), its lobe reflects every light, the lights' and the scene's.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/bsdf.hpp>
#include <prism/material/texture.hpp>
#include <prism/material/traits.hpp>

#include <cmath>
#include <optional>

namespace prism {

/// The modified Phong lobe at one point: f = kd / pi + ks (n + 2) / 2 pi cos^n alpha
/// for wo and wi above the surface, alpha the angle between wi and wo's mirror.
/// Sampled by its two parts, each with the probability of its largest channel's share.
template <Scalar T>
struct PhongLobe {
    /// The precision of the lobe.
    using scalar_type = T;

    Rgb<T> kd; ///< the Lambertian part's albedo
    Rgb<T> ks; ///< the glossy part's albedo at normal incidence
    T exponent; ///< n: the lobe's sharpness

    /// Never a mirror.
    [[nodiscard]] static constexpr bool smooth() noexcept { return false; }

    /// The BRDF for wo and wi above the surface (0 otherwise).
    [[nodiscard]] Rgb<T> f(const Vec3<T>& wo, const Vec3<T>& wi, Transport = Transport::radiance) const noexcept
    {
        if (!(wo.z > T(0)) || !(wi.z > T(0))) return Rgb<T>(T(0));
        return kd / pi<T> + ks * ((exponent + T(2)) / (T(2) * pi<T>) * lobe(wo, wi));
    }

    /// The density of sample over the directions above the surface.
    [[nodiscard]] T pdf(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept
    {
        if (!(wo.z > T(0)) || !(wi.z > T(0))) return T(0);
        const T p = glossy_share();
        return (T(1) - p) * wi.z / pi<T> + p * (exponent + T(1)) / (T(2) * pi<T>) * lobe(wo, wi);
    }

    /// A direction: with the glossy share's probability one of density
    /// (n + 1) / 2 pi cos^n alpha about the mirror direction (none where it falls below
    /// the surface), else a cosine-distributed one.
    [[nodiscard]] std::optional<LobeSample<T>> sample(const Vec3<T>& wo, T u_lobe, T u1, T u2, Transport mode = Transport::radiance) const noexcept
    {
        if (!(wo.z > T(0))) return std::nullopt;
        const T p = glossy_share();
        Vec3<T> wi;
        if (u_lobe < p) {
            const T cos_a = std::pow(u1, T(1) / (exponent + T(1)));
            const T sin_a = std::sqrt(std::max(T(0), T(1) - cos_a * cos_a)), phi = T(2) * pi<T> * u2;
            const Vec3<T> mirror{-wo.x, -wo.y, wo.z};
            const auto [s, t] = orthonormal_frame(mirror);
            wi = sin_a * std::cos(phi) * s + sin_a * std::sin(phi) * t + cos_a * mirror;
        } else {
            wi = cosine_direction(u1, u2);
        }
        const T density = pdf(wo, wi);
        if (!(density > T(0))) return std::nullopt;
        return LobeSample<T>{wi, f(wo, wi, mode) * (wi.z / density), density, false};
    }

    /// The glossy part's albedo for wo, ks (n + 2) / (n + 1) times the mean cosine of
    /// its directions above the surface over 4 x 4 of them at the centres of a grid:
    /// what a Whitted mirror ray carries for it.
    [[nodiscard]] Rgb<T> mirror_albedo(const Vec3<T>& wo) const noexcept
    {
        const Vec3<T> mirror{-wo.x, -wo.y, wo.z};
        const auto [s, t] = orthonormal_frame(mirror);
        T sum = T(0);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const T cos_a = std::pow((T(i) + T(0.5)) / T(4), T(1) / (exponent + T(1)));
                const T sin_a = std::sqrt(std::max(T(0), T(1) - cos_a * cos_a)), phi = T(2) * pi<T> * (T(j) + T(0.5)) / T(4);
                sum += std::max((sin_a * std::cos(phi) * s + sin_a * std::sin(phi) * t + cos_a * mirror).z, T(0));
            }
        return ks * ((exponent + T(2)) / (exponent + T(1)) * sum / T(16));
    }

private:
    /// cos^n of the angle between wi and wo's mirror, 0 beyond 90 degrees.
    [[nodiscard]] T lobe(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept
    {
        const T cos_a = -wo.x * wi.x - wo.y * wi.y + wo.z * wi.z;
        return cos_a > T(0) ? std::pow(cos_a, exponent) : T(0);
    }

    /// The probability of drawing from the glossy part: its largest channel's share.
    [[nodiscard]] T glossy_share() const noexcept
    {
        const T d = max_component(kd), s = max_component(ks);
        return d + s > T(0) ? s / (d + s) : T(0);
    }
};

/// A glossy surface by the normalised modified Phong model: a Lambertian part of
/// albedo `diffuse` (a texture) and a lobe of albedo `specular` and exponent `exponent`
/// about the mirror direction. Keep diffuse + specular <= 1 in every channel for a
/// surface that reflects no more than arrives (checked where the albedo is Solid).
template <Scalar T = float, Texture Albedo = Solid<T>>
struct Phong {
    /// The precision of the material.
    using scalar_type = T;
    /// Its Lambertian part lives in the glossy lobe, which is sampled as one.
    static constexpr bool has_diffuse = false;
    /// No delta mirror.
    static constexpr bool reflects = false;
    /// Transmits nothing.
    static constexpr bool transmits = false;
    /// A glossy lobe: modified Phong.
    static constexpr bool has_glossy = true;
    /// Whether a texture of it reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates = texture_reads_coordinates<Albedo>;

    Albedo diffuse{}; ///< the Lambertian part's albedo (Solid, Checker, UvChecker or the user's)
    Rgb<T> specular{T(0.2)}; ///< the glossy part's albedo at normal incidence
    T exponent = T(40); ///< the lobe's exponent n (0: a second Lambertian part)

    /// The lobe at a point.
    [[nodiscard]] constexpr PhongLobe<T> glossy(const GlossyQuery<T>& q) const noexcept
    {
        return {albedo_at(diffuse, q.texture_point()), specular, exponent};
    }

    /// Throws std::invalid_argument, naming the parameter, for a bad albedo, a specular
    /// albedo outside [0, 1], a negative or non-finite exponent, or (with a Solid albedo)
    /// diffuse + specular above 1 in a channel.
    constexpr void validate() const
    {
        diffuse.validate();
        detail::require_non_negative("Phong specular", specular);
        if (!(max_component(specular) <= T(1))) detail::throw_invalid("Phong specular must be <= 1 in every channel, got ", detail::describe(specular));
        detail::require_lobe_exponent("Phong exponent", exponent);
        if constexpr (std::same_as<Albedo, Solid<T>>) {
            if (!(max_component(diffuse.color + specular) <= T(1)))
                detail::throw_invalid("Phong diffuse + specular must be <= 1 in every channel (energy), got ", detail::describe(diffuse.color + specular));
        }
    }
};

static_assert(Material<Phong<float>>);

} // namespace prism
