// SPDX-License-Identifier: MIT
// What a material can do, as capabilities the integrators branch on with if constexpr.
//
// A material declares three facts as static constexpr members, and each fact it
// declares is a promise of the functions that capability needs, checked by the
// Material concept (so a promise without its function fails at the user's line, not
// inside an integrator):
//   has_diffuse  a Lambertian lobe, lit by shadow rays and photons     DiffuseLobe
//   reflects     a mirror (delta) reflection that is not a dielectric's DeltaReflection
//   transmits    a dielectric interface: Fresnel-split delta reflection  DeltaTransmission
//                and refraction into the medium() that fills it          InteriorMedium
// and two that a material declares only where it has them (the others have neither):
//   has_glossy   a lobe with evaluation, sampling and density: rough     GlossyLobe
//                metal, Phong, a coated surface, frosted glass (with       (GlossyInterface)
//                transmits; material/bsdf.hpp)
//   emits        radiance leaving its surface: an area light             Emission
// A scene whose materials never transmit compiles no refraction code at all. The
// light transport over these capabilities (what a diffuse point reflects, how an
// interface splits a ray, how a photon scatters, what a shadow ray lets through) is
// written once, in material/scattering.hpp; integrators call it and never read a
// material's fields.
#pragma once

#include <prism/core/math.hpp>
#include <prism/material/bsdf.hpp>
#include <prism/medium/medium.hpp>

#include <concepts>
#include <type_traits>
#include <utility>

namespace prism {

/// What a diffuse lobe reflects at one point: Lambert's BRDF albedo kd / pi for light
/// from the lights, albedo ka for the scene's ambient light (Whitted's kd and ka scale
/// factors on top of a physical albedo).
template <Scalar T>
struct DiffuseResponse {
    Rgb<T> albedo; ///< reflectance at the point, in [0, 1] per channel
    T kd;          ///< scale on light from the lights
    T ka;          ///< scale on the ambient term

    /// The BRDF, albedo kd / pi.
    [[nodiscard]] constexpr Rgb<T> brdf() const noexcept { return albedo * (kd / pi<T>); }

    /// Radiance reflected for irradiance E from the lights and ambient radiance A
    /// reaching the point unoccluded by the fraction `unlit`: albedo (kd/pi E + ka A unlit).
    [[nodiscard]] constexpr Rgb<T> reflected(const Rgb<T>& irradiance, const Rgb<T>& ambient, const Rgb<T>& unlit) const noexcept
    {
        return albedo * ((kd / pi<T>)*irradiance + ka * ambient * unlit);
    }

    /// The fraction of a photon's power the lobe sends on (albedo kd, at most 1).
    [[nodiscard]] constexpr Rgb<T> photon_reflectance() const noexcept { return component_min(albedo * kd, Rgb<T>(T(1))); }
};

/// A Lambertian lobe: `diffuse(p)`, or `diffuse(p, uv)` for one that reads surface
/// coordinates, or `diffuse(at)` for one that also reads the footprint (TexturePoint),
/// gives its response at the surface point.
template <class M>
concept DiffuseLobe = requires(const M& material, const Vec3<typename M::scalar_type>& p) {
    { material.diffuse(p) } -> std::same_as<DiffuseResponse<typename M::scalar_type>>;
} || requires(const M& material, const Vec3<typename M::scalar_type>& p, const Vec2<typename M::scalar_type>& uv) {
    { material.diffuse(p, uv) } -> std::same_as<DiffuseResponse<typename M::scalar_type>>;
} || requires(const M& material, const TexturePoint<typename M::scalar_type>& at) {
    { material.diffuse(at) } -> std::same_as<DiffuseResponse<typename M::scalar_type>>;
};

/// The diffuse response of a material's Lambertian lobe where a texture is read, whichever
/// form its diffuse() takes.
template <class M>
    requires DiffuseLobe<M>
[[nodiscard]] constexpr DiffuseResponse<typename M::scalar_type> diffuse_response(const M& material,
                                                                                 const TexturePoint<typename M::scalar_type>& at) noexcept
{
    if constexpr (requires { material.diffuse(at); })
        return material.diffuse(at);
    else if constexpr (requires { material.diffuse(at.point, at.uv); })
        return material.diffuse(at.point, at.uv);
    else
        return material.diffuse(at.point);
}

/// What a delta interaction sees at a surface point: the incident cosine, the refracted
/// one and eta = n_t / n_i (where light refracts), the side (`entering`: arriving from
/// outside) and the point. Materials whose response varies over the surface (a film of
/// textured thickness) or with the side (a coating on the outside) take this whole.
template <Scalar T>
struct SpecularQuery {
    T cos_i; ///< cosine of the incident angle, >= 0
    T cos_t; ///< cosine of the refracted angle (0 where nothing refracts)
    T eta; ///< n_t / n_i
    bool entering; ///< the light arrives from outside
    Vec3<T> point; ///< where on the surface
};

/// A mirror that is not an interface (a conductor): its reflectance per channel for
/// light arriving at cosine cos_i, as `reflectance(cos_i)` or, where it varies over
/// the surface, `reflectance(SpecularQuery)`.
template <class M>
concept DeltaReflection = requires(const M& material, typename M::scalar_type cos_i) {
    { material.reflectance(cos_i) } -> std::same_as<Rgb<typename M::scalar_type>>;
} || requires(const M& material, const SpecularQuery<typename M::scalar_type>& query) {
    { material.reflectance(query) } -> std::same_as<Rgb<typename M::scalar_type>>;
};

/// A Fresnel reflectance: one share for every channel, or one per channel (a thin film).
template <class F, class T>
concept FresnelShare = std::same_as<F, T> || std::same_as<F, Rgb<T>>;

/// A dielectric interface with index `refractive_index()` inside and 1 outside.
/// `fresnel(cos_i, cos_t, eta)` is the share of light reflected for the incident and
/// refracted cosines and eta = n_t / n_i, or `fresnel(SpecularQuery)` where it varies
/// over the surface or with the side; either returns one share or one per channel, and
/// is asked only where light refracts (under total internal reflection all of it is
/// reflected). The reflected and refracted rays are then weighted by
/// `reflection_tint()` and `transmission_tint()` (Whitted's kr and kt).
template <class M>
concept DeltaTransmission = requires(const M& material) {
    { material.refractive_index() } -> std::same_as<typename M::scalar_type>;
    { material.reflection_tint() } -> std::same_as<Rgb<typename M::scalar_type>>;
    { material.transmission_tint() } -> std::same_as<Rgb<typename M::scalar_type>>;
} && (requires(const M& material, typename M::scalar_type cos_i) {
    { material.fresnel(cos_i, cos_i, cos_i) } -> FresnelShare<typename M::scalar_type>;
} || requires(const M& material, const SpecularQuery<typename M::scalar_type>& query) {
    { material.fresnel(query) } -> FresnelShare<typename M::scalar_type>;
});

/// The medium filling a transmissive object: `medium()` (see medium/medium.hpp).
template <class M>
concept InteriorMedium = requires(const M& material) {
    requires Medium<std::remove_cvref_t<decltype(material.medium())>>;
    requires std::same_as<typename std::remove_cvref_t<decltype(material.medium())>::scalar_type, typename M::scalar_type>;
};

namespace detail {

template <class M>
constexpr bool declares_emission() noexcept
{
    if constexpr (requires { M::emits; }) return bool(M::emits);
    else return false;
}

template <class M>
constexpr bool declares_glossy() noexcept
{
    if constexpr (requires { M::has_glossy; }) return bool(M::has_glossy);
    else return false;
}

} // namespace detail

/// A glossy lobe: `glossy(GlossyQuery)` gives the material's Bsdf at a surface point, in
/// the point's local frame (material/bsdf.hpp). A material declares it with
/// `has_glossy = true`; one that does not declare it has none.
template <class M>
concept GlossyLobe = requires(const M& material, const GlossyQuery<typename M::scalar_type>& query) {
    requires Bsdf<std::remove_cvref_t<decltype(material.glossy(query))>>;
    requires std::same_as<typename std::remove_cvref_t<decltype(material.glossy(query))>::scalar_type, typename M::scalar_type>;
};

/// A glossy interface (has_glossy and transmits: frosted glass), whose lobe reflects and
/// refracts: `refractive_index()`, the index inside, and `transmission_tint()`, what a
/// Whitted shadow ray keeps crossing it.
template <class M>
concept GlossyInterface = requires(const M& material) {
    { material.refractive_index() } -> std::same_as<typename M::scalar_type>;
    { material.transmission_tint() } -> std::same_as<Rgb<typename M::scalar_type>>;
};

/// A surface that emits light (an area light): `emitted_radiance(at)`, its radiance per
/// channel at a TexturePoint, the same in every direction of its front, and `two_sided`,
/// whether its back emits too. A material declares it with `emits = true`; one that does
/// not declare it emits nothing. One whose radiance changes over the surface says so
/// with `emission_varies = true` (emission_varies()).
template <class M>
concept Emission = requires(const M& material, const TexturePoint<typename M::scalar_type>& at) {
    { material.emitted_radiance(at) } -> std::same_as<Rgb<typename M::scalar_type>>;
    { material.two_sided } -> std::convertible_to<bool>;
};

/// Whether an emitting material's radiance changes over its surface (`emission_varies`;
/// false when it does not say): the scene then works out an emitter's power from points
/// spread over it, and reads the radiance at each point a light sample or photon leaves.
template <class M>
[[nodiscard]] consteval bool emission_varies() noexcept
{
    if constexpr (requires { M::emission_varies; }) return bool(M::emission_varies);
    else return false;
}

/// A material: its scalar type, the three capability flags and validate() (throws
/// std::invalid_argument for a bad parameter, naming it), and for each flag it sets,
/// that capability's functions. A compiler reports an unkept promise on its own line.
template <class M>
concept Material = requires(const M& material) {
    requires Scalar<typename M::scalar_type>;
    { M::has_diffuse } -> std::convertible_to<bool>;
    { M::reflects } -> std::convertible_to<bool>;
    { M::transmits } -> std::convertible_to<bool>;
    material.validate();
} && (M::has_diffuse || M::reflects || M::transmits || detail::declares_glossy<M>() || detail::declares_emission<M>()) // a material does at least one thing
  && (!detail::declares_emission<M>() || Emission<M>) // emits promises emitted_radiance(TexturePoint) -> Rgb<T> and two_sided
  && (!detail::declares_glossy<M>() || GlossyLobe<M>) // has_glossy promises glossy(GlossyQuery) -> a Bsdf of the same scalar type
  && (!detail::declares_glossy<M>() || (!M::has_diffuse && !M::reflects)) // a glossy lobe holds all of its material's scattering
  && (!detail::declares_glossy<M>() || !M::transmits || GlossyInterface<M>) // a glossy interface promises refractive_index() and transmission_tint()
  && (!M::has_diffuse || DiffuseLobe<M>)             // has_diffuse promises diffuse(p) or diffuse(p, uv) -> DiffuseResponse<T>
  && (!M::reflects || M::transmits || DeltaReflection<M>) // reflects (without transmits) promises reflectance(cos_i or query) -> Rgb<T>
  && (!M::transmits || detail::declares_glossy<M>() || DeltaTransmission<M>) // transmits (without has_glossy) promises refractive_index(), fresnel(cos_i, cos_t, eta or query), reflection_tint(), transmission_tint()
  && (!M::transmits || InteriorMedium<M>);          // transmits promises medium(), a Medium of the same scalar type

/// A dispersive interface: besides the DeltaTransmission functions, `disperses = true`
/// and `refractive_index(wavelength_nm)`, the index at a vacuum wavelength in nanometres
/// (refractive_index() is then the index for white light where it is not split).
template <class M>
concept Dispersive = requires(const M& material, typename M::scalar_type wavelength_nm) {
    requires bool(M::disperses);
    { material.refractive_index(wavelength_nm) } -> std::same_as<typename M::scalar_type>;
};

/// Whether a material reads surface coordinates, so that the scene adds them to its
/// crossings (Scene::closest_hit, add_coordinates): as it says (`reads_coordinates`), or
/// else whenever its diffuse lobe takes uv or a TexturePoint, and for every glossy lobe.
/// A scene whose materials read none never computes them.
template <Material M>
[[nodiscard]] consteval bool reads_coordinates() noexcept
{
    if constexpr (requires { M::reads_coordinates; }) return bool(M::reads_coordinates);
    else if constexpr (detail::declares_glossy<M>()) return true;
    else if constexpr (M::has_diffuse) return !requires(const M& m, const Vec3<typename M::scalar_type>& p) { m.diffuse(p); };
    else return false;
}

/// The material has a glossy lobe (GlossyLobe).
template <Material M>
inline constexpr bool has_glossy = detail::declares_glossy<M>();

/// Purely specular: every scattered direction is a delta (no diffuse or glossy lobe).
template <Material M>
inline constexpr bool is_delta = !M::has_diffuse && !has_glossy<M> && (M::reflects || M::transmits);

template <Material M>
inline constexpr bool has_diffuse = M::has_diffuse;

template <Material M>
inline constexpr bool reflects = M::reflects;

template <Material M>
inline constexpr bool transmits = M::transmits;

/// The material emits light: its surfaces are area lights.
template <Material M>
inline constexpr bool emits = detail::declares_emission<M>();

template <Material M>
inline constexpr bool disperses = M::transmits && Dispersive<M>;

namespace detail {
template <Material M>
[[nodiscard]] consteval bool interior_scatters() noexcept
{
    if constexpr (M::transmits) return scatters_light<std::remove_cvref_t<decltype(std::declval<const M&>().medium())>>;
    else return false;
}
} // namespace detail

/// The material is an interface whose medium() scatters light (a Fog): a walker inside it
/// may scatter anywhere along its way, not only at surfaces.
template <Material M>
inline constexpr bool has_scattering_interior = detail::interior_scatters<M>();

/// The material is an interface that may vanish: a smooth dielectric whose reflectance is
/// 0 where the indices on its two sides are equal (`index_matched(outside_index)`), so
/// that light crosses it unbent and unreflected, only tinted (an index-1 Dielectric
/// around a fog in the air: a ball of smoke). Paths and shadow rays alike pass such a
/// boundary as if it were not there, taking its tint and what its medium lets through,
/// so that every estimator finds the light behind it the same way (a point light's
/// included: it could never be found through a real interface). A dispersive or glossy
/// interface, or a thin film, never vanishes.
template <Material M>
inline constexpr bool may_match_index = M::transmits && !has_glossy<M> && !disperses<M> && requires(const M& m, typename M::scalar_type outside) {
    { m.index_matched(outside) } -> std::same_as<bool>;
};

/// Whether a light path crossing `material` from a medium of index `outside_index` meets
/// no interface at all (may_match_index).
template <Material M>
[[nodiscard]] constexpr bool index_matched(const M& material, typename M::scalar_type outside_index) noexcept
{
    if constexpr (may_match_index<M>) return material.index_matched(outside_index);
    else return (void)material, (void)outside_index, false;
}

} // namespace prism
