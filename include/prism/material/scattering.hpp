// SPDX-License-Identifier: MIT
// Light transport over a material's capabilities, written once for every integrator:
// what a diffuse point reflects, how a delta interface splits a ray, what light keeps
// while it travels inside an object, what a shadow ray keeps through one, and how a
// photon scatters. The integrators (Whitted, PhotonMapper), the photon tracer and the
// scene's shadow rays call these and never read a material's fields, so a new material
// is one header that satisfies the capability concepts of material/traits.hpp.
#pragma once

#include <prism/core/ray.hpp>
#include <prism/core/rng.hpp>
#include <prism/core/sampling.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/material/traits.hpp>
#include <prism/optics/refract.hpp>
#include <prism/spectrum/bands.hpp>

#include <cstddef>
#include <optional>

namespace prism {

// Diffuse lobe

/// The diffuse response at the surface point p.
template <Material M>
    requires DiffuseLobe<M>
[[nodiscard]] constexpr DiffuseResponse<typename M::scalar_type> diffuse_response(const M& material,
                                                                                 const Vec3<typename M::scalar_type>& p) noexcept
{
    return material.diffuse(p);
}

/// A non-physical highlight (POV-Ray's `phong`), for materials that have one: its weight
/// for a light in direction wi seen along the mirror direction `mirror` of the viewing
/// ray (radiance weight * E); 0 for every other material.
template <Material M>
[[nodiscard]] constexpr typename M::scalar_type highlight(const M& material, const Vec3<typename M::scalar_type>& mirror,
                                                          const Vec3<typename M::scalar_type>& wi) noexcept
{
    if constexpr (requires { { material.highlight(dot(mirror, wi)) } -> std::same_as<typename M::scalar_type>; })
        return material.highlight(dot(mirror, wi));
    else
        return typename M::scalar_type(0);
}

// Delta interactions

/// The weights of the reflected and transmitted rays at a specular surface, the
/// transmitted direction (none under total internal reflection or for a conductor), and
/// the Fresnel reflectance before the tints (1 for a conductor; per channel for a thin
/// film): a photon reflects with the probability `reflected_share`, its mean.
template <Scalar T>
struct SpecularSplit {
    Rgb<T> kr{T(0)};
    Rgb<T> kt{T(0)};
    std::optional<Vec3<T>> refracted;
    Rgb<T> fresnel{T(1)};
    T reflected_share = T(1);

    /// Whether Fresnel's share is the same in every channel (then a photon's choice
    /// between reflection and refraction needs no reweighting).
    [[nodiscard]] constexpr bool fresnel_is_grey() const noexcept { return fresnel.x == fresnel.y && fresnel.y == fresnel.z; }
};

namespace detail {

/// A conductor's reflectance, from cos_i alone or from the whole query; for light of
/// one wavelength, the material's value at that wavelength where it has one
/// (`reflectance_at(query, wavelength)`: a measured metal, a film), grey.
template <Material M>
[[nodiscard]] Rgb<typename M::scalar_type> conductor_reflectance(const M& material, const SpecularQuery<typename M::scalar_type>& q,
                                                                 typename M::scalar_type wavelength_nm) noexcept
{
    if constexpr (requires { { material.reflectance_at(q, wavelength_nm) } -> std::same_as<typename M::scalar_type>; }) {
        if (wavelength_nm > 0) return Rgb<typename M::scalar_type>(material.reflectance_at(q, wavelength_nm));
    }
    if constexpr (requires { material.reflectance(q.cos_i); })
        return material.reflectance(q.cos_i);
    else
        return material.reflectance(q);
}

/// An interface's Fresnel share (one, or one per channel), from the cosines and eta or
/// from the whole query; for light of one wavelength, the material's value at that
/// wavelength where it has one (`fresnel_at(query, wavelength)`: a film), grey.
template <Material M>
[[nodiscard]] auto interface_fresnel(const M& material, const SpecularQuery<typename M::scalar_type>& q,
                                     typename M::scalar_type wavelength_nm) noexcept
{
    using T = typename M::scalar_type;
    if constexpr (requires { { material.fresnel_at(q, wavelength_nm) } -> std::same_as<T>; }) {
        using Share = decltype(material.fresnel(q));
        if (wavelength_nm > 0) return Share(material.fresnel_at(q, wavelength_nm));
        return material.fresnel(q);
    } else if constexpr (requires { material.fresnel(q.cos_i, q.cos_t, q.eta); }) {
        return material.fresnel(q.cos_i, q.cos_t, q.eta);
    } else {
        return material.fresnel(q);
    }
}

} // namespace detail

/// The index of a transmissive material for light of a wavelength (nanometres; 0 for
/// white light): a dispersive one's at that wavelength, any other's own.
template <Material M>
    requires(M::transmits)
[[nodiscard]] typename M::scalar_type index_at(const M& material, typename M::scalar_type wavelength_nm) noexcept
{
    if constexpr (disperses<M>) {
        if (wavelength_nm > 0) return material.refractive_index(wavelength_nm);
    }
    return material.refractive_index();
}

/// How a mirror or an interface at point p splits the unit incident direction d
/// arriving at a surface whose unit normal n faces it (Crossing::facing_normal);
/// `entering`: d goes into the material; light of one wavelength (nanometres), or 0 for
/// white light; `outside_index`: the index of the medium on the material's other side
/// (1, the scene's air, unless the object is nested in another: medium/nesting.hpp). A
/// dielectric splits by Fresnel (all to reflection under total internal reflection)
/// times its tints, with eta = n_inside / n_outside or its inverse by the side (n at the
/// wavelength for a dispersive one); a conductor reflects by its reflectance.
template <Material M>
    requires(M::reflects || M::transmits)
[[nodiscard]] SpecularSplit<typename M::scalar_type> delta_split(const M& material, const Vec3<typename M::scalar_type>& d,
                                                                const Vec3<typename M::scalar_type>& n, bool entering,
                                                                const Vec3<typename M::scalar_type>& p,
                                                                typename M::scalar_type wavelength_nm = 0,
                                                                typename M::scalar_type outside_index = 1) noexcept
{
    using T = typename M::scalar_type;
    const T cos_i = clamp(-dot(d, n), T(0), T(1));
    SpecularSplit<T> split;
    if constexpr (M::transmits) {
        const T n_inside = index_at(material, wavelength_nm);
        const T eta = entering ? n_inside / outside_index : outside_index / n_inside;
        // Snell's cos_t, found once, serves the direction and the Fresnel equations.
        const auto refracted = refraction(d, n, eta);
        if (refracted) split.refracted = refracted->direction;
        if (refracted) {
            const SpecularQuery<T> query{cos_i, refracted->cos_t, eta, entering, p};
            const auto fresnel = detail::interface_fresnel(material, query, wavelength_nm);
            if constexpr (std::same_as<decltype(fresnel), const T>) {
                split.reflected_share = fresnel;
            } else {
                split.reflected_share = (fresnel.x + fresnel.y + fresnel.z) / T(3);
            }
            split.fresnel = Rgb<T>(fresnel);
        }
        split.kr = material.reflection_tint() * split.fresnel;
        split.kt = material.transmission_tint() * (Rgb<T>(T(1)) - split.fresnel);
    } else {
        split.kr = detail::conductor_reflectance(material, SpecularQuery<T>{cos_i, T(0), T(1), entering, p}, wavelength_nm);
    }
    return split;
}

/// The rays a mirror or an interface sends on, each passed to
/// emit(direction, weight, wavelength_nm, transmitted): the reflected ray, then the
/// refracted one. `outside_index(wavelength_nm)` is the index of the medium on the
/// material's other side. Where white light (wavelength 0) meets a dispersive interface
/// it refracts band by band, one ray per band of `bands`, each weighted by its band's
/// share of white and carrying its wavelength; the reflected ray, whose direction no
/// wavelength changes, stays white, weighted by the bands' reflectances summed (so white
/// light meeting a dispersive interface costs one ray more per band, not per band squared).
template <Material M, class OutsideIndex, class Emit>
    requires(M::reflects || M::transmits)
void for_each_delta_ray(const M& material, const Vec3<typename M::scalar_type>& d, const Vec3<typename M::scalar_type>& n,
                        const Crossing<typename M::scalar_type>& hit, typename M::scalar_type wavelength_nm,
                        const SpectralBands<typename M::scalar_type>& bands, OutsideIndex&& outside_index, Emit&& emit)
{
    using T = typename M::scalar_type;
    if constexpr (disperses<M>) {
        if (wavelength_nm == T(0)) {
            Rgb<T> kr{T(0)};
            for (const WavelengthBand<T>& band : bands) {
                const SpecularSplit<T> split =
                    delta_split(material, d, n, hit.entering, hit.point, band.wavelength_nm, T(outside_index(band.wavelength_nm)));
                kr += band.weight * split.kr;
                if (split.refracted) emit(*split.refracted, band.weight * split.kt, band.wavelength_nm, true);
            }
            emit(reflect(d, n), kr, T(0), false);
            return;
        }
    }
    const SpecularSplit<T> split = delta_split(material, d, n, hit.entering, hit.point, wavelength_nm, T(outside_index(wavelength_nm)));
    emit(reflect(d, n), split.kr, wavelength_nm, false);
    if (split.refracted) emit(*split.refracted, split.kt, wavelength_nm, true);
}

// Media

/// Light that reached `hit` along `ray` from the ray's origin travelled inside the
/// object's medium when the ray leaves there: multiply `light` by what the medium lets
/// through over that length. Nothing for a material without an interior.
template <Material M>
constexpr void attenuate_inside(const M& material, const Crossing<typename M::scalar_type>& hit,
                                const Ray<typename M::scalar_type>& ray, Rgb<typename M::scalar_type>& light) noexcept
{
    if constexpr (M::transmits) {
        if (!hit.entering) light *= material.medium().transmittance(hit.t * length(ray.direction));
    }
}

/// What a shadow ray along [0, t_max] keeps through one transmissive object, given the
/// object's crossings (without surfaces) in that range: its medium's transmittance over
/// the length inside, then its transmission tint once per boundary crossed, multiplied
/// into `light`. Refraction is ignored: the lecture notes' shadow rays through
/// transparent objects.
template <Material M, std::size_t N>
    requires(M::transmits)
constexpr void attenuate_shadow_ray(const M& material, const Crossings<typename M::scalar_type, N>& crossings,
                                    const Ray<typename M::scalar_type>& ray, typename M::scalar_type t_max,
                                    Rgb<typename M::scalar_type>& light) noexcept
{
    using T = typename M::scalar_type;
    bool inside = crossings.inside_at_start;
    T previous = T(0), inside_length = T(0);
    for (const Crossing<T>& c : crossings) {
        if (inside) inside_length += c.t - previous;
        inside = c.entering;
        previous = c.t;
    }
    if (inside) inside_length += t_max - previous;
    if (inside_length > T(0)) light *= material.medium().transmittance(inside_length * length(ray.direction));
    for (std::size_t k = 0; k < crossings.size(); ++k) light *= material.transmission_tint();
}

// Photons

/// A photon's next direction after scattering, and whether the bounce was diffuse.
template <Scalar T>
struct PhotonBounce {
    Vec3<T> direction;
    bool diffuse;
};

/// Scatter a photon of `power` arriving along the unit direction d at `hit` (n: the
/// unit normal facing it), by Russian roulette per channel (errata 7): a diffuse lobe
/// reflects its photon reflectance into a cosine-distributed direction; an interface
/// reflects with probability F and refracts otherwise, weighted by its tints; a
/// conductor reflects by its reflectance. A material with a diffuse and a delta lobe
/// first chooses one by their largest channels, dividing the power by that choice's
/// probability. A photon of one wavelength (nanometres; 0: white) refracts at its
/// index; `outside_index` is the index on the material's other side (1: air). Returns nothing when the photon is absorbed; scales `power` otherwise.
template <Material M>
[[nodiscard]] std::optional<PhotonBounce<typename M::scalar_type>> scatter_photon(const M& material,
                                                                                   const Crossing<typename M::scalar_type>& hit,
                                                                                   const Vec3<typename M::scalar_type>& d,
                                                                                   const Vec3<typename M::scalar_type>& n,
                                                                                   Rgb<typename M::scalar_type>& power, Pcg32& rng,
                                                                                   typename M::scalar_type wavelength_nm = 0,
                                                                                   typename M::scalar_type outside_index = 1) noexcept
{
    using T = typename M::scalar_type;
    using Bounce = std::optional<PhotonBounce<T>>;
    // Each lobe's scattering, given what the material does here (computed once, also for
    // choosing between two lobes).
    const auto scatter_diffusely = [&](const Rgb<T>& reflectance) -> Bounce {
        if (!russian_roulette(power, reflectance, rng)) return std::nullopt;
        return PhotonBounce<T>{cosine_hemisphere(n, rng), true};
    };
    const auto scatter_specularly = [&](const SpecularSplit<T>& split) -> Bounce {
        if constexpr (M::transmits) {
            // Reflect with probability F (the mean of F per channel), refract otherwise;
            // each then by its tint. Per-channel F weighs the survivor by F / mean.
            const bool reflect_it = rng.uniform<T>() < split.reflected_share;
            if (!russian_roulette(power, reflect_it ? material.reflection_tint() : material.transmission_tint(), rng)) return std::nullopt;
            if (!split.fresnel_is_grey()) {
                power *= reflect_it ? split.fresnel / split.reflected_share
                                    : (Rgb<T>(T(1)) - split.fresnel) / (T(1) - split.reflected_share);
            }
            return PhotonBounce<T>{reflect_it ? reflect(d, n) : *split.refracted, false};
        } else {
            if (!russian_roulette(power, split.kr, rng)) return std::nullopt;
            return PhotonBounce<T>{reflect(d, n), false};
        }
    };
    if constexpr (M::has_diffuse && (M::reflects || M::transmits)) {
        // Both lobes: choose one by its share of the reflected light (largest channels).
        const Rgb<T> reflectance = diffuse_response(material, hit.point).photon_reflectance();
        const SpecularSplit<T> split = delta_split(material, d, n, hit.entering, hit.point, wavelength_nm, outside_index);
        const T w_diffuse = max_component(reflectance), w_delta = max_component(split.kr + split.kt);
        if (!(w_diffuse + w_delta > T(0))) return std::nullopt;
        const T p_diffuse = w_diffuse / (w_diffuse + w_delta);
        if (rng.uniform<T>() < p_diffuse) {
            power /= p_diffuse;
            return scatter_diffusely(reflectance);
        }
        power /= T(1) - p_diffuse;
        return scatter_specularly(split);
    } else if constexpr (M::has_diffuse) {
        return scatter_diffusely(diffuse_response(material, hit.point).photon_reflectance());
    } else {
        return scatter_specularly(delta_split(material, d, n, hit.entering, hit.point, wavelength_nm, outside_index));
    }
}

} // namespace prism
