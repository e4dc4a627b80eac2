// SPDX-License-Identifier: MIT
// The vocabulary of a glossy lobe: a BSDF with evaluation, sampling and density, in the
// local frame of a surface point (z along the shading normal, on the side light
// arrives from). A material with `has_glossy` hands one out per point (GlossyLobe in
// material/traits.hpp); the integrators reach it only through material/scattering.hpp.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/sampling.hpp>
#include <prism/material/texture.hpp>
#include <prism/optics/microfacet.hpp>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <optional>

namespace prism {

/// What a path carries: light from the lights (a photon: importance transport, whose
/// scattering at a shading normal takes Veach's adjoint correction, and whose
/// refraction does not scale by 1 / eta^2), or importance from the camera (a camera
/// path: radiance transport).
enum class Transport { importance, radiance };

/// A surface point's orthonormal frame: `n` the normal, `s` and `t` the tangents
/// (the directions of a lobe's two roughnesses).
template <Scalar T>
struct LocalFrame {
    Vec3<T> s; ///< first tangent
    Vec3<T> t; ///< second tangent
    Vec3<T> n; ///< normal (local z)

    /// The frame about unit n with tangents from orthonormal_frame (any shape without
    /// its own tangents: an anisotropic lobe's direction is then arbitrary but fixed).
    [[nodiscard]] static LocalFrame about(const Vec3<T>& n) noexcept
    {
        const auto [s, t] = orthonormal_frame(n);
        return {s, t, n};
    }

    /// A world vector in the frame's coordinates.
    [[nodiscard]] constexpr Vec3<T> to_local(const Vec3<T>& v) const noexcept { return {dot(v, s), dot(v, t), dot(v, n)}; }
    /// A vector in the frame's coordinates, back in the world's.
    [[nodiscard]] constexpr Vec3<T> to_world(const Vec3<T>& v) const noexcept { return v.x * s + v.y * t + v.z * n; }
};

/// A direction a lobe drew for the outgoing direction wo, in the local frame.
template <Scalar T>
struct LobeSample {
    Vec3<T> wi;    ///< the unit direction drawn (wi.z < 0: through the surface)
    Rgb<T> weight; ///< f(wo, wi) |wi.z| / pdf; for a delta (a smooth surface's mirror or refraction), what it lets through over the probability of drawing it
    T pdf;         ///< the solid-angle density it was drawn with (over every part of the lobe); 0 for a delta
    bool delta;    ///< drawn from a delta part: no density, never found by a light sample
};

/// The cosine-distributed direction about local z for the uniform numbers u1, u2
/// (Malley's method), of density z / pi.
template <Scalar T>
[[nodiscard]] inline Vec3<T> cosine_direction(T u1, T u2) noexcept
{
    const T r = std::sqrt(u1), phi = T(2) * pi<T> * u2;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(T(0), T(1) - u1))};
}

/// What a glossy material is asked at a surface point: where (point and surface
/// coordinates), and for an interface, the side light arrives from and the ratio of
/// indices eta = n beyond / n on the arriving side.
template <Scalar T>
struct GlossyQuery {
    Vec3<T> point; ///< the surface point
    Vec2<T> uv;    ///< its surface coordinates (Crossing::uv)
    bool entering = true; ///< the light (or the camera path) arrives from outside
    T eta = T(1);  ///< n beyond / n arriving, for an interface (1 where nothing refracts)
    T width = T(0); ///< the ray's footprint there, in uv units (TexturePoint::width)

    /// Where its textures are read.
    [[nodiscard]] constexpr TexturePoint<T> texture_point() const noexcept { return {point, uv, width}; }
};

/// A material's roughness where its texture is read: a Roughness as given, or a
/// one-number texture's value on both axes (isotropic).
template <Scalar T, class R>
[[nodiscard]] constexpr Roughness<T> roughness_at(const R& roughness, const TexturePoint<T>& at) noexcept
{
    if constexpr (ScalarTexture<R>) return Roughness<T>(roughness.value(at));
    else return roughness;
}

/// Throws std::invalid_argument, naming the material, for a roughness outside [0, 1]: a
/// Roughness's, or a texture's largest value (where it knows it: max_value()).
template <class R>
constexpr void validate_roughness(const R& roughness, const char* name)
{
    if constexpr (ScalarTexture<R>) {
        roughness.validate();
        if constexpr (requires { roughness.max_value(); })
            if (!(roughness.max_value() <= 1)) detail::throw_invalid(name, " roughness texture's values must be in [0, 1], got up to ", roughness.max_value());
    } else {
        roughness.validate(name);
    }
}

/// A BSDF lobe in its local frame (directions unit, pointing away from the surface;
/// wo the direction a path leaves toward, wi the one light arrives from):
/// `f(wo, wi, mode)` its value (without the cosine), `pdf(wo, wi)` the density that
/// `sample(wo, u_lobe, u1, u2, mode)` draws wi with (nothing where it draws none), and
/// `smooth()`, whether it is a mirror or a clean interface (every sample a delta).
/// For the transport modes, see Transport.
template <class B>
concept Bsdf = requires(const B& bsdf, const Vec3<typename B::scalar_type>& w, typename B::scalar_type u, Transport mode) {
    { bsdf.f(w, w, mode) } -> std::same_as<Rgb<typename B::scalar_type>>;
    { bsdf.pdf(w, w) } -> std::same_as<typename B::scalar_type>;
    { bsdf.sample(w, u, u, u, mode) } -> std::same_as<std::optional<LobeSample<typename B::scalar_type>>>;
    { bsdf.smooth() } -> std::convertible_to<bool>;
};

} // namespace prism
