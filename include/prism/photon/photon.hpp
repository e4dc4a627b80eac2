// SPDX-License-Identifier: MIT
// Photon: what a photon map stores, and the sampling a photon tracer needs.
//
// Jensen, "Global Illumination using Photon Maps" (1996) and "Realistic Image Synthesis
// Using Photon Mapping" (2001), with the seed's errata 4, 6 and 7
// (shared/seeds/README.md): emission directions uniform on the sphere, each photon
// carrying the light's power divided by the photons emitted, Russian roulette that
// scales a survivor's power per channel by reflectance over survival probability.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/rng.hpp>

#include <cmath>
#include <cstdint>
#include <utility>

namespace prism {

/// One stored photon: where it landed, the power it carries (W) and where it came from.
struct Photon {
    enum Flags : std::uint8_t {
        direct = 1,  ///< first hit after leaving the light
        caustic = 2, ///< reached this diffuse surface only by specular bounces (L S+ D)
        shadow = 4,  ///< a shadow photon: where the straight continuation of a direct photon's path met a further surface
    };

    Vec3<float> position{};
    Rgb<float> power{};
    Vec3<float> from{}; ///< unit direction back toward where the photon came from
    std::uint8_t flags = 0;

    friend bool operator==(const Photon&, const Photon&) = default;
};

/// A direction uniform on the unit sphere: z = 1 - 2u, phi = 2 pi v (errata 4: no
/// rejection sampling of a cube, whose accepted points were never normalised).
template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_sphere(T u, T v) noexcept
{
    const T z = T(1) - T(2) * u;
    const T r = prism::sqrt(clamp(T(1) - z * z, T(0), T(1)));
    const T phi = T(2) * pi<T> * v;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

template <Scalar T>
[[nodiscard]] inline Vec3<T> uniform_sphere(Pcg32& rng) noexcept
{
    const T u = rng.uniform<T>();
    return uniform_sphere(u, rng.uniform<T>());
}

/// Two unit vectors that make an orthonormal frame with the unit vector n (Duff et al.
/// 2017, "Building an Orthonormal Basis, Revisited").
template <Scalar T>
[[nodiscard]] inline std::pair<Vec3<T>, Vec3<T>> orthonormal_frame(const Vec3<T>& n) noexcept
{
    const T sign = std::copysign(T(1), n.z);
    const T a = T(-1) / (sign + n.z);
    const T b = n.x * n.y * a;
    return {{T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}};
}

/// A cosine-distributed direction about the unit normal n (Malley's method: a uniform
/// point on the disk, lifted onto the hemisphere): the diffuse bounce of a photon.
template <Scalar T>
[[nodiscard]] inline Vec3<T> cosine_hemisphere(const Vec3<T>& n, Pcg32& rng) noexcept
{
    const T r = prism::sqrt(rng.uniform<T>());
    const T phi = T(2) * pi<T> * rng.uniform<T>();
    const T x = r * std::cos(phi), y = r * std::sin(phi);
    const T z = prism::sqrt(clamp(T(1) - x * x - y * y, T(0), T(1)));
    const auto [s, t] = orthonormal_frame(n);
    return x * s + y * t + z * n;
}

/// Russian roulette (errata 7): the photon survives with probability p = the largest
/// channel of its reflectance (at most 1), and a survivor's power is scaled per channel
/// by reflectance / p, so the expected power leaving is reflectance times the power
/// arriving, in every channel. Returns false when the photon is absorbed.
template <Scalar T>
[[nodiscard]] inline bool russian_roulette(Rgb<T>& power, const Rgb<T>& reflectance, Pcg32& rng) noexcept
{
    const T p = clamp(max_component(reflectance), T(0), T(1));
    if (!(p > T(0)) || rng.uniform<T>() >= p) return false;
    power *= reflectance / p;
    return true;
}

} // namespace prism
