// SPDX-License-Identifier: MIT
// Light transport over a material's capabilities, written once for every integrator:
// what a diffuse point reflects, how a delta interface splits a ray, what light keeps
// while it travels inside an object, what a shadow ray keeps through one, and how a
// photon scatters. The integrators (Whitted, PhotonMapper), the photon tracer and the
// scene's shadow rays call these and never read a material's fields, so a new material
// is one header that satisfies the capability concepts of material/traits.hpp.
#pragma once

#include <prism/core/ray.hpp>
#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/material/bsdf.hpp>
#include <prism/material/traits.hpp>
#include <prism/optics/refract.hpp>
#include <prism/spectrum/bands.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>

namespace prism {

// Shading normals
//
// A mesh with vertex normals shades with its interpolated normal (Crossing::shading)
// while its true normal still says where the surface is. Lobes are taken about the
// shading normal; the true one keeps every ray on its side:
// - light from the lights counts where it arrives above both (the cosine is the
//   shading normal's);
// - a mirror or an interface turns rays about the shading normal unless a ray would
//   leave on the wrong side of the true surface (a reflection into the solid, a
//   refraction back out), and then about the true normal (delta_normal);
// - a photon scattered by a diffuse lobe leaves cosine-distributed about the shading
//   normal, with Veach's adjoint correction (1997, section 5.3.6) for the shading
//   normal's asymmetry, and is absorbed where it would go into the solid
//   (scatter_photon);
// - photon density estimates stay the true surface's irradiance (they omit the
//   per-photon factor |w.ns| / |w.ng| of a shading normal).
// For every other shape the shading normal is the true one and all of this reduces to
// the true normal's arithmetic, bit for bit.

namespace detail {

/// Whether a ray sent on by a delta interaction leaves on the right side of the true
/// surface (ng: its unit normal facing the arriving ray): back for a reflection,
/// through for a refraction.
template <Scalar T>
[[nodiscard]] constexpr bool leaves_correctly(const Vec3<T>& direction, bool transmitted, const Vec3<T>& ng) noexcept
{
    return transmitted ? dot(direction, ng) < T(0) : dot(direction, ng) > T(0);
}

} // namespace detail

// Emission

/// The radiance a surface sends back along a ray that met it at `hit`: an emitting
/// material's radiance where the ray arrives at its front (where it enters), and at its
/// back only when it is two-sided; nothing from any other material.
template <Material M>
[[nodiscard]] constexpr Rgb<typename M::scalar_type> emitted(const M& material, const Crossing<typename M::scalar_type>& hit) noexcept
{
    using T = typename M::scalar_type;
    if constexpr (emits<M>) {
        if (hit.entering || material.two_sided) {
            if constexpr (emission_varies<M>()) return material.emitted_radiance(texture_point(hit));
            else return material.emitted_radiance(TexturePoint<T>{hit.point});
        }
    }
    (void)material, (void)hit;
    return Rgb<T>(T(0));
}

// Diffuse lobe

/// The diffuse response at a crossing's point (and surface coordinates, for a lobe that
/// reads them).
template <Material M>
    requires DiffuseLobe<M>
[[nodiscard]] constexpr DiffuseResponse<typename M::scalar_type> diffuse_response(const M& material,
                                                                                 const Crossing<typename M::scalar_type>& at) noexcept
{
    return diffuse_response(material, texture_point(at));
}

/// The cosine weighting light from the unit direction wi at `hit` for a diffuse lobe:
/// the shading normal's cosine (n_shading: Crossing::facing_shading) where wi is above
/// it and above the true surface (n_true: Crossing::facing_normal), else 0.
template <Scalar T>
[[nodiscard]] constexpr T shading_cosine(const Vec3<T>& n_shading, const Vec3<T>& n_true, const Vec3<T>& wi) noexcept
{
    const T cos = dot(n_shading, wi);
    return cos > T(0) && dot(n_true, wi) > T(0) ? cos : T(0);
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
    Rgb<T> kr{T(0)}; ///< the reflected ray's weight per channel
    Rgb<T> kt{T(0)}; ///< the transmitted ray's weight per channel
    std::optional<Vec3<T>> refracted; ///< the transmitted direction, if any
    Rgb<T> fresnel{T(1)}; ///< the Fresnel reflectance before the tints
    T reflected_share = T(1); ///< the probability a photon reflects

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

/// The unit normal a mirror or an interface at `hit` turns the unit direction d about,
/// for light of one wavelength (0: white; outside_index as for delta_split): the
/// shading normal facing d where d arrives against it and the reflected and refracted
/// rays about it leave on the right side of the true surface, the true normal facing d
/// elsewhere (and always, for a surface that shades flat).
template <Material M>
    requires(M::reflects || M::transmits)
[[nodiscard]] Vec3<typename M::scalar_type> delta_normal(const M& material, const Vec3<typename M::scalar_type>& d,
                                                         const Crossing<typename M::scalar_type>& hit,
                                                         typename M::scalar_type wavelength_nm = 0,
                                                         typename M::scalar_type outside_index = 1) noexcept
{
    using T = typename M::scalar_type;
    const Vec3<T> ng = hit.facing_normal();
    if (hit.shades_flat()) return ng;
    const Vec3<T> ns = hit.facing_shading();
    if (!(dot(d, ns) < T(0)) || !detail::leaves_correctly(reflect(d, ns), false, ng)) return ng;
    if constexpr (M::transmits) {
        const SpecularSplit<T> split = delta_split(material, d, ns, hit.entering, hit.point, wavelength_nm, outside_index);
        if (split.refracted && !detail::leaves_correctly(*split.refracted, true, ng)) return ng;
    }
    return ns;
}

/// The rays a mirror or an interface sends on, each passed to
/// emit(direction, weight, wavelength_nm, transmitted): the reflected ray, then the
/// refracted one. `outside_index(wavelength_nm)` is the index of the medium on the
/// material's other side. Where white light (wavelength 0) meets a dispersive interface
/// it refracts band by band, one ray per band of `bands`, each weighted by its band's
/// share of white and carrying its wavelength; the reflected ray, whose direction no
/// wavelength changes, stays white, weighted by the bands' reflectances summed (so white
/// light meeting a dispersive interface costs one ray more per band, not per band squared).
/// The rays turn about delta_normal's normal (for white light meeting a dispersive
/// interface, about the shading normal only if every band's refraction about it leaves
/// correctly).
template <Material M, class OutsideIndex, class Emit>
    requires(M::reflects || M::transmits)
void for_each_delta_ray(const M& material, const Vec3<typename M::scalar_type>& d, const Crossing<typename M::scalar_type>& hit,
                        typename M::scalar_type wavelength_nm, const SpectralBands<typename M::scalar_type>& bands,
                        OutsideIndex&& outside_index, Emit&& emit)
{
    using T = typename M::scalar_type;
    Vec3<T> n = hit.shades_flat() ? hit.facing_normal() : delta_normal(material, d, hit, wavelength_nm, T(outside_index(wavelength_nm)));
    if constexpr (disperses<M>) {
        if (wavelength_nm == T(0)) {
            if (n != hit.facing_normal())
                for (const WavelengthBand<T>& band : bands) {
                    const SpecularSplit<T> split =
                        delta_split(material, d, n, hit.entering, hit.point, band.wavelength_nm, T(outside_index(band.wavelength_nm)));
                    if (split.refracted && !detail::leaves_correctly(*split.refracted, true, hit.facing_normal())) {
                        n = hit.facing_normal();
                        break;
                    }
                }
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
        if (!hit.entering) light *= transmittance_along(material.medium(), ray, typename M::scalar_type(0), hit.t);
    }
}

/// What a shadow ray along [0, t_max] keeps through one transmissive object, given the
/// object's crossings (without surfaces) in that range: its medium's transmittance over
/// the length inside, then its transmission tint once per boundary crossed, multiplied
/// into `light`. Refraction is ignored: the classic Whitted shadow rays through
/// transparent objects.
template <Material M, std::size_t N>
    requires(M::transmits)
constexpr void attenuate_shadow_ray(const M& material, const Crossings<typename M::scalar_type, N>& crossings,
                                    const Ray<typename M::scalar_type>& ray, typename M::scalar_type t_max,
                                    Rgb<typename M::scalar_type>& light) noexcept
{
    using T = typename M::scalar_type;
    using Interior = std::remove_cvref_t<decltype(material.medium())>;
    bool inside = crossings.inside_at_start;
    T previous = T(0), inside_length = T(0);
    const auto stretch = [&](T t) {
        if constexpr (uniform_medium<Interior>)
            inside_length += t - previous;
        else
            light *= transmittance_along(material.medium(), ray, previous, t);
    };
    for (const Crossing<T>& c : crossings) {
        if (inside) stretch(c.t);
        inside = c.entering;
        previous = c.t;
    }
    if (inside) stretch(t_max);
    if constexpr (uniform_medium<Interior>)
        if (inside_length > T(0)) light *= material.medium().transmittance(inside_length * length(ray.direction));
    for (std::size_t k = 0; k < crossings.size(); ++k) light *= material.transmission_tint();
}

// Glossy lobes

/// A glossy material's lobe at a surface point, for a path that arrived along a unit
/// direction d: the lobe in the local frame about the shading normal facing d, and the
/// true normal facing d. Directions are the world's; `wo` (toward the path's start, -d)
/// is kept. A direction counts only where the shading and the true surface agree on
/// which side of the surface it lies (so a shading normal never lets light through or
/// around the surface: the usual side test).
template <Bsdf Lobe>
class GlossyAt {
public:
    /// The precision of the lobe.
    using T = typename Lobe::scalar_type;

    /// The lobe `lobe` at a point whose frame is `frame` (z: the shading normal facing
    /// the arriving path), true normal `n_true` facing it, for a path arriving along d.
    GlossyAt(const Lobe& lobe, const LocalFrame<T>& frame, const Vec3<T>& n_true, const Vec3<T>& d) noexcept
        : lobe_(lobe), frame_(frame), n_true_(n_true), wo_(frame.to_local(-d))
    {
    }

    /// Whether the lobe is a mirror or a clean interface (every sample a delta).
    [[nodiscard]] bool smooth() const noexcept { return lobe_.smooth(); }

    /// The BSDF for the path going on along the unit direction wi (world), by `mode`.
    [[nodiscard]] Rgb<T> f(const Vec3<T>& wi, Transport mode) const noexcept
    {
        const Vec3<T> local = frame_.to_local(wi);
        if (!agree(wi, local)) return Rgb<T>(T(0));
        return lobe_.f(wo_, local, mode);
    }

    /// The density with which sample() draws the unit direction wi (world).
    [[nodiscard]] T pdf(const Vec3<T>& wi) const noexcept
    {
        const Vec3<T> local = frame_.to_local(wi);
        return agree(wi, local) ? lobe_.pdf(wo_, local) : T(0);
    }

    /// The lobe's delta part, where it has one (a smooth surface's mirror, a smooth
    /// coat's reflection: a lobe's `delta_part(wo)`): its direction (world) and its whole
    /// weight, not divided by any probability of drawing it, for the estimators that
    /// follow it every time (Whitted, the photon mapper's camera rays).
    [[nodiscard]] std::optional<LobeSample<T>> delta_part() const noexcept
    {
        if constexpr (requires { { lobe_.delta_part(wo_) } -> std::same_as<std::optional<LobeSample<T>>>; }) {
            std::optional<LobeSample<T>> s = wo_.z > T(0) ? lobe_.delta_part(wo_) : std::nullopt;
            if (!s) return std::nullopt;
            const Vec3<T> wi = frame_.to_world(s->wi);
            if (!agree(wi, s->wi)) return std::nullopt;
            s->wi = wi;
            return s;
        } else {
            return std::nullopt;
        }
    }

    /// The albedo of the lobe's part about the mirror direction of the arriving path,
    /// which Whitted follows as one mirror ray (a lobe's `mirror_albedo(wo)`; none for a
    /// lobe without one).
    [[nodiscard]] Rgb<T> mirror_albedo() const noexcept
    {
        if constexpr (requires { { lobe_.mirror_albedo(wo_) } -> std::same_as<Rgb<T>>; }) return wo_.z > T(0) ? lobe_.mirror_albedo(wo_) : Rgb<T>(T(0));
        else return Rgb<T>(T(0));
    }

    /// The lobe's albedo toward the arriving path, the mean weight of 4 x 4 draws at the
    /// centres of a grid (each its own choice among the lobe's parts): a surface layer's
    /// albedo, not an estimator's.
    [[nodiscard]] Rgb<T> albedo() const noexcept
    {
        Rgb<T> sum{T(0)};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                if (const auto s = lobe_.sample(wo_, (T(4 * i + j) + T(0.5)) / T(16), (T(i) + T(0.5)) / T(4), (T(j) + T(0.5)) / T(4), Transport::radiance))
                    sum += s->weight;
        return sum / T(16);
    }

    /// The unit mirror direction of the arriving path about the shading normal (world).
    [[nodiscard]] Vec3<T> mirror() const noexcept { return frame_.to_world({-wo_.x, -wo_.y, wo_.z}); }

    /// A next direction drawn from the lobe (world), with the lobe's weight and density;
    /// nothing where the lobe draws none or the draw fails the side test.
    [[nodiscard]] std::optional<LobeSample<T>> sample(Random& rng, Transport mode) const noexcept
    {
        const T u0 = rng.uniform<T>();
        const auto [u1, u2] = rng.uniform2<T>();
        std::optional<LobeSample<T>> s = lobe_.sample(wo_, u0, u1, u2, mode);
        if (!s) return std::nullopt;
        const Vec3<T> wi = frame_.to_world(s->wi);
        if (!agree(wi, s->wi)) return std::nullopt;
        s->wi = wi;
        return s;
    }

private:
    /// Whether the true surface puts world wi on the side the shading frame puts it (local).
    [[nodiscard]] bool agree(const Vec3<T>& wi, const Vec3<T>& local) const noexcept
    {
        const T g = dot(wi, n_true_);
        return local.z > T(0) ? g > T(0) : local.z < T(0) && g < T(0);
    }

    Lobe lobe_;
    LocalFrame<T> frame_;
    Vec3<T> n_true_;
    Vec3<T> wo_;
};

/// A glossy material's lobe at `hit` for a path arriving along the unit direction d
/// (eta: n beyond / n on the arriving side, for an interface).
template <Material M>
    requires(has_glossy<M>)
[[nodiscard]] auto glossy_at(const M& material, const Crossing<typename M::scalar_type>& hit, const Vec3<typename M::scalar_type>& d,
                             typename M::scalar_type eta = 1) noexcept
{
    using T = typename M::scalar_type;
    const auto lobe = material.glossy(GlossyQuery<T>{hit.point, hit.uv, hit.entering, eta, texture_point(hit).width});
    return GlossyAt<std::remove_cvref_t<decltype(lobe)>>(lobe, LocalFrame<T>::about(hit.facing_shading()), hit.facing_normal(), d);
}

/// The ratio of indices a glossy interface's lobe takes at `hit`, n beyond / n on the
/// arriving side, with `outside_index` the index on its outer side; 1 for a material that
/// is not an interface.
template <Material M>
[[nodiscard]] constexpr typename M::scalar_type glossy_eta(const M& material, const Crossing<typename M::scalar_type>& hit,
                                                          typename M::scalar_type outside_index = 1) noexcept
{
    if constexpr (M::transmits) return hit.entering ? material.refractive_index() / outside_index : outside_index / material.refractive_index();
    else return (void)material, (void)hit, (void)outside_index, typename M::scalar_type(1);
}

/// Whether a path meeting `material` at `hit` along d sees a non-delta lobe there (a
/// diffuse one, or a glossy one that is not a mirror): where lights are sampled and
/// photons stored.
template <Material M>
[[nodiscard]] bool scatters_smoothly(const M& material, const Crossing<typename M::scalar_type>& hit, const Vec3<typename M::scalar_type>& d) noexcept
{
    if constexpr (has_diffuse<M>) return true;
    else if constexpr (has_glossy<M>) return !glossy_at(material, hit, d, glossy_eta(material, hit)).smooth(); // (an interface's lobe is smooth where its eta is 1)
    else return (void)material, (void)hit, (void)d, false;
}

/// Whether `material` may scatter light by a delta lobe somewhere: a mirror or a
/// dielectric's interface, or a glossy lobe with a delta part (a mix's mirror, a smooth
/// coat, a rough metal of roughness 0), probed at a few angles where it reads no texture
/// and taken to have one where it does. Caustics and a light tracer's paths begin there:
/// what light paths are aimed at.
template <Material M>
[[nodiscard]] bool may_scatter_by_delta(const M& material) noexcept
{
    using T = typename M::scalar_type;
    if constexpr (reflects<M> || transmits<M>) {
        return (void)material, true;
    } else if constexpr (has_glossy<M>) {
        if constexpr (reads_coordinates<M>()) {
            return (void)material, true;
        } else {
            const auto lobe = material.glossy(GlossyQuery<T>{});
            if (lobe.smooth()) return true;
            if constexpr (requires(const Vec3<T>& wo) { { lobe.delta_part(wo) } -> std::same_as<std::optional<LobeSample<T>>>; }) {
                for (const T z : {T(1), T(0.7), T(0.3), T(0.05)})
                    if (lobe.delta_part(Vec3<T>(std::sqrt(T(1) - z * z), T(0), z))) return true;
            }
            return false;
        }
    } else {
        return (void)material, false;
    }
}

// Photons

/// A photon's next direction after scattering, and whether the bounce was diffuse.
template <Scalar T>
struct PhotonBounce {
    Vec3<T> direction; ///< the new direction
    bool diffuse; ///< whether the bounce was off a non-delta lobe (diffuse or glossy)
    T pdf = T(0); ///< a glossy lobe's density for the direction (0 for the others: a diffuse one's is cos / pi)
};

/// The lobes a scattering may take: none (the path ends), the delta ones only (a caustic
/// photon or a final-gather ray goes on past a diffuse lobe whose light is counted
/// already), or all of them.
enum class Lobes { none, delta, all };

/// Scatter a photon of `power` arriving along the unit direction d at `hit`, by Russian
/// roulette per channel (Jensen 2001, section 2.4): a diffuse lobe reflects its photon reflectance into
/// a cosine-distributed direction; an interface reflects with probability F and
/// refracts otherwise, weighted by its tints; a conductor reflects by its reflectance.
/// A material with a diffuse and a delta lobe makes one decision over its lobes (the
/// diffuse one, the reflection, the refraction): each is taken with the probability of
/// its reflectance (its largest channel) and none with what is left, so a survivor's
/// power is multiplied by its lobe's reflectance over that probability, at most 1 per
/// channel, and stays bounded however many bounces it takes (where the lobes' largest
/// channels sum above 1 they are scaled down together). `lobes`: which of them it may
/// take. A photon of one wavelength (nanometres; 0: white) refracts at its index;
/// `outside_index` is the index on the material's other side (1: air). Returns nothing
/// when the photon is absorbed; scales `power` otherwise. With a shading normal (see
/// above), the diffuse direction is cosine-distributed about it and a diffuse bounce
/// sent into the solid is absorbed; a photon (Transport::importance) also takes Veach's
/// correction |d.ns| |w.ng| / (|d.ng| |w.ns|) and is absorbed where it arrives behind
/// the shading normal. A camera path (Transport::radiance) scatters by the same rules
/// without them, and without Russian roulette: it always takes a lobe (the lobes of a
/// material with a diffuse and a delta one each with the probability of its share of
/// their reflectances), its power multiplied by what the lobe carries, and its walk ends
/// it by its throughput instead (path_roulette, random_walk). A glossy lobe draws one
/// direction (its parts chosen inside it) and a photon survives with the probability of
/// the draw's largest channel (at most 1), carrying the draw's weight over it; its
/// density is the bounce's `pdf`.
template <Transport Mode = Transport::importance, Material M>
[[nodiscard]] std::optional<PhotonBounce<typename M::scalar_type>> scatter_photon(const M& material,
                                                                                   const Crossing<typename M::scalar_type>& hit,
                                                                                   const Vec3<typename M::scalar_type>& d,
                                                                                   Rgb<typename M::scalar_type>& power, Random& rng,
                                                                                   typename M::scalar_type wavelength_nm = 0,
                                                                                   typename M::scalar_type outside_index = 1,
                                                                                   Lobes lobes = Lobes::all) noexcept
{
    using T = typename M::scalar_type;
    using Bounce = std::optional<PhotonBounce<T>>;
    if (lobes == Lobes::none) return std::nullopt;
    const Vec3<T> n = hit.facing_normal();
    // A diffuse bounce's direction, once the lobe is taken.
    const auto diffuse_direction = [&]() -> Bounce {
        if (hit.shades_flat()) return PhotonBounce<T>{cosine_hemisphere(n, rng), true};
        const Vec3<T> ns = hit.facing_shading();
        const Vec3<T> w = cosine_hemisphere(ns, rng);
        const T w_g = dot(w, n);
        if (!(w_g > T(0))) return std::nullopt;
        if constexpr (Mode == Transport::importance) {
            const T d_s = -dot(d, ns), d_g = -dot(d, n), w_s = dot(w, ns);
            if (!(d_s > T(0))) return std::nullopt;
            const T correction = (d_s * w_g) / (d_g * w_s);
            if (!(correction < infinity<T>)) return std::nullopt; // d_g or w_s rounded to 0: no finite weight
            power *= correction;
        }
        return PhotonBounce<T>{w, true};
    };
    if constexpr (M::has_diffuse && (M::reflects || M::transmits)) {
        // One decision over the lobes, each by its reflectance.
        const Vec3<T> n_delta = delta_normal(material, d, hit, wavelength_nm, outside_index);
        const SpecularSplit<T> split = delta_split(material, d, n_delta, hit.entering, hit.point, wavelength_nm, outside_index);
        const Rgb<T> diffuse = lobes == Lobes::all ? diffuse_response(material, hit).photon_reflectance() : Rgb<T>(T(0));
        const Rgb<T> transmitted = split.refracted ? split.kt : Rgb<T>(T(0));
        const T w_diffuse = max_component(diffuse), w_reflected = max_component(split.kr), w_transmitted = max_component(transmitted);
        // A photon may also be absorbed (what the lobes leave of 1); a camera path is not.
        const T sum = w_diffuse + w_reflected + w_transmitted;
        const T scale = Mode == Transport::radiance ? sum : std::max(T(1), sum);
        if (!(scale > T(0)) || !(scale < infinity<T>)) return std::nullopt;
        const T u = rng.uniform<T>() * scale;
        if (u < w_diffuse) {
            power *= diffuse * (scale / w_diffuse);
            return diffuse_direction();
        }
        if (u < w_diffuse + w_reflected) {
            power *= split.kr * (scale / w_reflected);
            return PhotonBounce<T>{reflect(d, n_delta), false};
        }
        if (u < w_diffuse + w_reflected + w_transmitted) {
            power *= transmitted * (scale / w_transmitted);
            return PhotonBounce<T>{*split.refracted, false};
        }
        return std::nullopt;
    } else if constexpr (M::has_diffuse) {
        if (lobes != Lobes::all) return std::nullopt;
        const Rgb<T> reflectance = diffuse_response(material, hit).photon_reflectance();
        if constexpr (Mode == Transport::radiance) {
            if (!(max_component(reflectance) > T(0))) return std::nullopt;
            power *= reflectance;
        } else if (!russian_roulette(power, reflectance, rng)) {
            return std::nullopt;
        }
        return diffuse_direction();
    } else if constexpr (has_glossy<M>) {
        // One draw from the lobe (its parts chosen inside it), then for a photon Russian
        // roulette by the draw's weight: a survivor carries weight / p, at most 1 per
        // channel where the weight is below 1. A camera path carries the weight.
        const auto at = glossy_at(material, hit, d, glossy_eta(material, hit, outside_index));
        if (lobes != Lobes::all && !at.smooth()) return std::nullopt;
        const std::optional<LobeSample<T>> s = at.sample(rng, Mode);
        if (!s) return std::nullopt;
        Rgb<T> weight = s->weight;
        if constexpr (Mode == Transport::importance) {
            if (!s->delta && !hit.shades_flat()) {
                // Veach's correction for the shading normal, as for a diffuse bounce.
                const T correction = (std::abs(dot(d, hit.shading)) * std::abs(dot(s->wi, hit.normal))) /
                                     (std::abs(dot(d, hit.normal)) * std::abs(dot(s->wi, hit.shading)));
                if (!(correction < infinity<T>)) return std::nullopt;
                weight *= correction;
            }
        }
        if constexpr (Mode == Transport::radiance) {
            if (!(max_component(weight) > T(0))) return std::nullopt;
            power *= weight;
        } else {
            const T p = std::min(T(1), max_component(weight));
            if (!(p > T(0)) || !(rng.uniform<T>() < p)) return std::nullopt;
            power *= weight / p;
        }
        return PhotonBounce<T>{s->wi, !s->delta, s->pdf};
    } else {
        const Vec3<T> n_delta = delta_normal(material, d, hit, wavelength_nm, outside_index);
        const SpecularSplit<T> split = delta_split(material, d, n_delta, hit.entering, hit.point, wavelength_nm, outside_index);
        if constexpr (M::transmits) {
            // Reflect with probability F (the mean of F per channel), refract otherwise;
            // each then by its tint. Per-channel F weighs the survivor by F / mean.
            const bool reflect_it = rng.uniform<T>() < split.reflected_share;
            const Rgb<T> tint = reflect_it ? material.reflection_tint() : material.transmission_tint();
            if constexpr (Mode == Transport::radiance) power *= tint;
            else if (!russian_roulette(power, tint, rng)) return std::nullopt;
            if (!split.fresnel_is_grey()) {
                power *= reflect_it ? split.fresnel / split.reflected_share
                                    : (Rgb<T>(T(1)) - split.fresnel) / (T(1) - split.reflected_share);
            }
            return PhotonBounce<T>{reflect_it ? reflect(d, n_delta) : *split.refracted, false};
        } else {
            if constexpr (Mode == Transport::radiance) power *= split.kr;
            else if (!russian_roulette(power, split.kr, rng)) return std::nullopt;
            return PhotonBounce<T>{reflect(d, n_delta), false};
        }
    }
}

} // namespace prism
