// SPDX-License-Identifier: MIT
// SurfaceVertex and MediumVertex: a path's vertex at a surface or in a medium that
// scatters, as the bidirectional estimators see it (integrator/bidirectional.hpp): what
// its material or phase function scatters toward any direction, and the densities of
// drawing that direction from either end of the path.
//
// A camera path and a light path meet at vertices: joined by a segment (connection), or
// found near each other (merging). Each needs, at a vertex, the material's value for a
// direction the vertex did not draw itself, and for multiple importance sampling the
// densities of drawing it both ways: forward (the path arrived along d and leaves along
// wo) and reverse (a path arriving along -wo leaving along -d). Directions are unit and
// world; densities per steradian. Only a non-delta lobe (diffuse, or glossy and not a
// mirror) has a value or a density: a mirror or a clean interface is a delta, which no
// connection or merge can find (`connectible`), and a path's draw there has density 1
// both ways (its choice's probability, the same each way, cancels in the weights).
//
// A light path carries importance (Transport::importance): at a shading normal its value
// takes Veach's adjoint correction (1997, section 5.3.6), |d.ns| |wo.ng| / (|d.ng| |wo.ns|),
// as a photon's bounce does (material/scattering.hpp). The lobes are the material's:
// a diffuse lobe drawn cosine-distributed about the shading normal, a glossy one by its
// own sample(); a material with a diffuse and a delta lobe (a mirror or an interface
// beside it) chooses one by their reflectances, as scatter_photon does, and that choice's
// probability is part of the diffuse lobe's density.
//
// In a medium the lobe is the phase function, which has no delta and no cosine: every
// vertex there is connectible, and its densities both ways are the phase function's
// value at the angle between the two directions of travel (the same either way). The
// medium's scattering coefficient is not in the value: the walk's free flight put it in
// the path's throughput (medium/medium.hpp's FreeFlight).
#pragma once

#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/material/bsdf.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/phase.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace prism {

/// A vertex's non-delta lobe toward a direction wo: its value (the BSDF, without the
/// cosine), the shading cosine at wo, and the densities of drawing wo (forward) and of
/// drawing the reverse of the arriving direction from wo (reverse), per steradian.
template <Scalar T>
struct VertexValue {
    Rgb<T> f{T(0)};       ///< the BSDF toward wo (the adjoint one for importance)
    T cos = T(0);         ///< |ns . wo|, where wo is on a side the lobe reaches
    T pdf_forward = T(0); ///< the density the vertex draws wo with
    T pdf_reverse = T(0); ///< the density a path arriving along -wo draws -d with

    /// Whether the lobe sends nothing toward wo.
    [[nodiscard]] bool black() const noexcept { return !(max_component(f) > T(0)) || !(cos > T(0)); }
};

/// A direction a vertex drew, with what the path carries on by (f cos / pdf, or a delta's
/// weight over its choice's probability) and the densities both ways (1 for a delta).
template <Scalar T>
struct VertexSample {
    Vec3<T> direction;  ///< unit, leaving
    Rgb<T> weight;      ///< what the path's throughput is multiplied by
    T pdf_forward;      ///< the density it was drawn with (1 for a delta)
    T pdf_reverse;      ///< the reverse density (1 for a delta)
    bool delta;         ///< drawn from a delta lobe
};

/// A path's vertex on `material` at `hit`, arriving along the unit direction d, carrying
/// `mode`; `outside_index` is the index of refraction on a transmissive material's outer
/// side (1 in the scene's air: medium/nesting.hpp); `wavelength_nm` the light's
/// wavelength where a dispersive interface has split it (0: white), at which a
/// dispersive material refracts.
template <Material M>
class SurfaceVertex {
public:
    /// The material's precision.
    using T = typename M::scalar_type;
    /// The material's type.
    using material_type = M;

    static_assert(!(has_diffuse<M> && has_glossy<M>), "a material is a diffuse lobe or a glossy one, not both");

    /// The vertex; the material and crossing must outlive it.
    SurfaceVertex(const M& material, const Crossing<T>& hit, const Vec3<T>& d, Transport mode, T outside_index = T(1), T wavelength_nm = T(0)) noexcept
        : material_(&material), hit_(&hit), d_(d), mode_(mode), outside_index_(outside_index), wavelength_(wavelength_nm)
    {
    }

    /// Whether the vertex has a non-delta lobe: where connections and merges are made.
    [[nodiscard]] bool connectible() const noexcept { return scatters_smoothly(*material_, *hit_, d_); }

    /// The material.
    [[nodiscard]] const M& material() const noexcept { return *material_; }

    /// The non-delta lobe toward the unit direction wo (nothing for a vertex that has none).
    [[nodiscard]] VertexValue<T> value(const Vec3<T>& wo) const noexcept
    {
        VertexValue<T> v;
        if constexpr (has_diffuse<M>) {
            const Vec3<T> ns = hit_->facing_shading(), ng = hit_->facing_normal();
            const T cos_out = shading_cosine(ns, ng, wo), cos_in = shading_cosine(ns, ng, -d_);
            if (!(cos_out > T(0)) || !(cos_in > T(0))) return v;
            v.f = diffuse_response(*material_, *hit_).brdf() * correction(wo);
            v.cos = cos_out;
            v.pdf_forward = diffuse_share(d_) * cos_out / pi<T>;
            v.pdf_reverse = diffuse_share(-wo) * cos_in / pi<T>;
        } else if constexpr (has_glossy<M>) {
            const auto lobe = glossy_at(*material_, *hit_, d_, glossy_eta(*material_, *hit_, outside_index_));
            if (lobe.smooth()) return v;
            v.f = lobe.f(wo, mode_) * correction(wo);
            v.cos = std::abs(dot(wo, hit_->shading));
            v.pdf_forward = lobe.pdf(wo);
            v.pdf_reverse = reverse_pdf(wo);
        } else {
            (void)wo;
        }
        return v;
    }

    /// A direction drawn from the vertex's lobes, or nothing where it draws none (its
    /// lobes are black, or the draw fails a side test).
    [[nodiscard]] std::optional<VertexSample<T>> sample(Random& rng) const noexcept
    {
        using Sample = std::optional<VertexSample<T>>;
        if constexpr (has_diffuse<M>) {
            if constexpr (reflects<M> || transmits<M>) {
                // One decision over the lobes, each by its reflectance (scatter_photon's).
                const Shares s = shares(d_);
                if (!(s.sum > T(0)) || !(s.sum < infinity<T>)) return std::nullopt;
                const T u = rng.uniform<T>() * s.sum;
                if (u >= s.diffuse) {
                    const bool reflected = u < s.diffuse + s.reflected;
                    if (!reflected && !s.split.refracted) return std::nullopt;
                    const Rgb<T> weight = reflected ? s.split.kr * (s.sum / s.reflected) : s.split.kt * (s.sum / s.transmitted);
                    return VertexSample<T>{reflected ? reflect(d_, s.normal) : *s.split.refracted, weight, T(1), T(1), true};
                }
                // The diffuse lobe: its choice's probability is in value()'s densities.
            }
            const Vec3<T> ns = hit_->facing_shading(), ng = hit_->facing_normal();
            if (!(shading_cosine(ns, ng, -d_) > T(0))) return std::nullopt;
            const Vec3<T> wo = cosine_hemisphere(ns, rng);
            const VertexValue<T> v = value(wo);
            if (v.black() || !(v.pdf_forward > T(0))) return std::nullopt;
            return VertexSample<T>{wo, v.f * (v.cos / v.pdf_forward), v.pdf_forward, v.pdf_reverse, false};
        } else if constexpr (has_glossy<M>) {
            const auto lobe = glossy_at(*material_, *hit_, d_, glossy_eta(*material_, *hit_, outside_index_));
            const std::optional<LobeSample<T>> s = lobe.sample(rng, mode_);
            if (!s) return std::nullopt;
            if (s->delta) return VertexSample<T>{s->wi, s->weight, T(1), T(1), true};
            if (!(s->pdf > T(0))) return std::nullopt;
            return VertexSample<T>{s->wi, s->weight * correction(s->wi), s->pdf, reverse_pdf(s->wi), false};
        } else if constexpr (reflects<M> || transmits<M>) {
            Rgb<T> weight{T(1)};
            const auto next = scatter_photon<Transport::radiance>(*material_, *hit_, d_, weight, rng, wavelength_, outside_index_);
            if (!next) return std::nullopt;
            return VertexSample<T>{next->direction, weight, T(1), T(1), true};
        } else {
            (void)rng;
            return Sample{};
        }
    }

private:
    /// The shares of a material's lobes for a path arriving along `arriving`: the diffuse
    /// lobe's photon reflectance, the mirror's and the interface's, each by its largest
    /// channel (scatter_photon's decision), and the split they come from.
    struct Shares {
        T diffuse = T(0), reflected = T(0), transmitted = T(0), sum = T(0);
        SpecularSplit<T> split{};
        Vec3<T> normal{};
    };

    [[nodiscard]] Shares shares(const Vec3<T>& arriving) const noexcept
        requires(has_diffuse<M> && (reflects<M> || transmits<M>))
    {
        Shares s;
        s.normal = delta_normal(*material_, arriving, *hit_, wavelength_, outside_index_);
        s.split = delta_split(*material_, arriving, s.normal, hit_->entering, hit_->point, wavelength_, outside_index_);
        s.diffuse = max_component(diffuse_response(*material_, *hit_).photon_reflectance());
        s.reflected = max_component(s.split.kr);
        s.transmitted = s.split.refracted ? max_component(s.split.kt) : T(0);
        s.sum = s.diffuse + s.reflected + s.transmitted;
        return s;
    }

    /// The probability of choosing the diffuse lobe for a path arriving along `arriving`
    /// (1 for a material with no other).
    [[nodiscard]] T diffuse_share(const Vec3<T>& arriving) const noexcept
    {
        if constexpr (has_diffuse<M> && (reflects<M> || transmits<M>)) {
            const Shares s = shares(arriving);
            return s.sum > T(0) ? s.diffuse / s.sum : T(0);
        } else {
            (void)arriving;
            return T(1);
        }
    }

    /// Veach's adjoint correction for importance at a shading normal, toward wo (1 for
    /// radiance and for a surface that shades flat).
    [[nodiscard]] T correction(const Vec3<T>& wo) const noexcept
    {
        if (mode_ == Transport::radiance || hit_->shades_flat()) return T(1);
        const T c = (std::abs(dot(d_, hit_->shading)) * std::abs(dot(wo, hit_->normal))) / (std::abs(dot(d_, hit_->normal)) * std::abs(dot(wo, hit_->shading)));
        return c < infinity<T> ? c : T(0);
    }

    /// A glossy lobe's density of drawing -d for a path arriving along -wo (from wo's
    /// side of the surface: the other side's indices for a refraction).
    [[nodiscard]] T reverse_pdf(const Vec3<T>& wo) const noexcept
        requires(has_glossy<M>)
    {
        Crossing<T> other = *hit_;
        other.entering = dot(wo, hit_->normal) > T(0);
        return glossy_at(*material_, other, -wo, glossy_eta(*material_, other, outside_index_)).pdf(-d_);
    }

    const M* material_;
    const Crossing<T>* hit_;
    Vec3<T> d_;
    Transport mode_;
    T outside_index_;
    T wavelength_;
};

/// A path's vertex in a medium that scatters by `phase`, arriving along the unit
/// direction d.
template <PhaseFunction P>
class MediumVertex {
public:
    /// The phase function's precision.
    using T = typename P::scalar_type;

    /// The vertex; the phase function must outlive it.
    MediumVertex(const P& phase, const Vec3<T>& d) noexcept : phase_(&phase), d_(d) {}

    /// Every vertex in a medium can be joined and merged.
    [[nodiscard]] static constexpr bool connectible() noexcept { return true; }

    /// The phase function toward the unit direction wo, cosine 1, its value the density both ways.
    [[nodiscard]] VertexValue<T> value(const Vec3<T>& wo) const noexcept
    {
        const T p = phase_->value(dot(d_, wo));
        return {Rgb<T>(p), T(1), p, p};
    }

    /// A direction drawn from the phase function (exactly its density: weight 1).
    [[nodiscard]] std::optional<VertexSample<T>> sample(Random& rng) const noexcept
    {
        const auto [u1, u2] = rng.uniform2<T>();
        const PhaseSample<T> s = phase_->sample(d_, u1, u2);
        if (!(s.pdf > T(0)) || !(s.pdf < infinity<T>)) return std::nullopt;
        return VertexSample<T>{s.direction, Rgb<T>(T(1)), s.pdf, s.pdf, false};
    }

private:
    const P* phase_;
    Vec3<T> d_;
};

} // namespace prism
