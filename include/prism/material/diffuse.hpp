// SPDX-License-Identifier: MIT
// Diffuse: a Lambertian surface with Whitted's (1980) kd (diffuse) and ka (ambient) factors.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/texture.hpp>
#include <prism/material/traits.hpp>

#include <cmath>

namespace prism {

namespace detail {

/// x^n: by squaring when n is a whole number up to 1024 (a Phong exponent usually is;
/// std::pow is a slow library call), by std::pow otherwise.
template <Scalar T>
[[nodiscard]] constexpr T power(T x, T n) noexcept
{
    if (!(n >= T(0) && n <= T(1024) && n == std::floor(n))) return std::pow(x, n);
    T result = T(1);
    for (auto e = static_cast<unsigned>(n); e != 0; e >>= 1u, x *= x)
        if (e & 1u) result *= x;
    return result;
}

} // namespace detail

/// Lambertian reflection, BRDF = albedo / pi, scaled by kd for light from the lights and
/// by ka for the scene's ambient term (seen only where every light is occluded).
///
/// `phong` adds POV-Ray's Phong highlight, phong (R . L)^phong_size E / pi per light,
/// with R the mirror direction of the viewing ray (Phong 1975, as POV-Ray's `phong`
/// finish computes it, so that scenes written for POV-Ray look the same). It is a
/// non-physical highlight and off by default.
template <Scalar T = float, Texture Albedo = Solid<T>>
struct Diffuse {
    /// The precision of the material.
    using scalar_type = T;
    /// A diffuse lobe: albedo / pi.
    static constexpr bool has_diffuse = true;
    /// No mirror reflection.
    static constexpr bool reflects = false;
    /// No transmission.
    static constexpr bool transmits = false;

    Albedo albedo{}; ///< the albedo texture (Solid, Checker, UvChecker or the user's)
    T kd = T(1); ///< scale on light from the lights
    T ka = T(1); ///< scale on the scene's ambient light
    T phong = T(0); ///< POV-Ray's phong: the highlight's strength, 0 for none
    T phong_size = T(40); ///< POV-Ray's phong_size: the highlight's exponent

    /// Whether its texture reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates = texture_reads_coordinates<Albedo>;

    /// The albedo where the texture is read (point, uv and footprint), with kd and ka.
    [[nodiscard]] constexpr DiffuseResponse<T> diffuse(const TexturePoint<T>& at) const noexcept { return {albedo_at(albedo, at), kd, ka}; }

    /// The Phong highlight's weight for cos_alpha = R . L (0 when phong is 0 or the light
    /// is behind the mirror direction): radiance phong cos_alpha^phong_size E / pi.
    [[nodiscard]] constexpr T highlight(T cos_alpha) const noexcept
    {
        if (!(phong > T(0)) || !(cos_alpha > T(0))) return T(0);
        return phong * detail::power(cos_alpha, phong_size) / pi<T>;
    }

    /// Throws std::invalid_argument, naming the parameter, for a bad albedo, a negative kd, ka or phong, or a phong_size <= 0.
    constexpr void validate() const
    {
        albedo.validate();
        detail::require_non_negative("Diffuse kd", kd);
        detail::require_non_negative("Diffuse ka", ka);
        detail::require_non_negative("Diffuse phong", phong);
        detail::require_positive("Diffuse phong_size", phong_size);
        detail::require_lobe_exponent("Diffuse phong_size", phong_size);
    }
};

static_assert(Material<Diffuse<float>>);

} // namespace prism
