// SPDX-License-Identifier: MIT
// Mix: two reflecting materials blended by a weight, constant or a texture,
// f = (1 - w) f_first + w f_second (Cycles' Mix Shader, Mitsuba's blendbsdf): a metal
// with diffuse dirt in a mask, a varnished floor as Cycles 3.4 builds one (a Lambertian
// under a dielectric's microfacet reflection), a Phong surface worn by a texture.
//
// Each part is a glossy material or a Lambertian one (a Diffuse: its kd counts, its
// Whitted-only ka and POV-Ray highlight have no place in a lobe). The blend is one lobe:
// a sample draws its part with the probability of that part's weight and is then
// weighted by the whole blend's f and density, so multiple importance sampling sees one
// lobe; a smooth part's mirror stays a delta, weighted by its share. Parts that transmit
// are not taken: a blend of two interfaces would need the two media they bound.
#pragma once

#include <prism/core/check.hpp>
#include <prism/material/bsdf.hpp>
#include <prism/material/texture.hpp>
#include <prism/material/traits.hpp>

#include <optional>
#include <utility>

namespace prism {

/// A Lambertian lobe, f = albedo / pi, sampled by the cosine.
template <Scalar T>
struct LambertLobe {
    /// The precision of the lobe.
    using scalar_type = T;

    Rgb<T> albedo; ///< its albedo, in [0, 1] per channel

    /// Never a mirror.
    [[nodiscard]] static constexpr bool smooth() noexcept { return false; }

    /// albedo / pi for wo and wi above the surface (0 otherwise).
    [[nodiscard]] Rgb<T> f(const Vec3<T>& wo, const Vec3<T>& wi, Transport = Transport::radiance) const noexcept
    {
        return wo.z > T(0) && wi.z > T(0) ? albedo / pi<T> : Rgb<T>(T(0));
    }

    /// wi.z / pi above the surface.
    [[nodiscard]] T pdf(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept { return wo.z > T(0) && wi.z > T(0) ? wi.z / pi<T> : T(0); }

    /// A cosine-distributed direction; its weight is the albedo.
    [[nodiscard]] std::optional<LobeSample<T>> sample(const Vec3<T>& wo, T, T u1, T u2, Transport = Transport::radiance) const noexcept
    {
        if (!(wo.z > T(0))) return std::nullopt;
        const Vec3<T> wi = cosine_direction(u1, u2);
        if (!(wi.z > T(0))) return std::nullopt;
        return LobeSample<T>{wi, albedo, wi.z / pi<T>, false};
    }
};

/// A material Mix can take as a part: it reflects by a glossy lobe, or by a Lambertian
/// one alone, and transmits nothing.
template <class M>
concept MixPart = Material<M> && !M::transmits && !M::reflects && !emits<M> && (has_glossy<M> || M::has_diffuse);

/// The lobe of a Mix's part at a point: its glossy lobe, or a LambertLobe of its albedo times kd.
template <MixPart M>
[[nodiscard]] constexpr auto part_lobe(const M& material, const GlossyQuery<typename M::scalar_type>& q) noexcept
{
    using T = typename M::scalar_type;
    if constexpr (has_glossy<M>) {
        return material.glossy(q);
    } else {
        const DiffuseResponse<T> r = diffuse_response(material, q.texture_point());
        return LambertLobe<T>{r.albedo * r.kd};
    }
}

/// The blend of two lobes at a point: (1 - w) first + w second, each drawn with the
/// probability of its weight.
template <Bsdf A, Bsdf B>
class MixLobe {
public:
    /// The precision of the lobe.
    using scalar_type = typename A::scalar_type;
    using T = scalar_type; ///< shorthand

    /// The blend of `first` and `second` with weight w (second's share, in [0, 1]).
    constexpr MixLobe(A first, B second, T w) noexcept : first_(std::move(first)), second_(std::move(second)), w_(w) {}

    /// A mirror where both parts are.
    [[nodiscard]] bool smooth() const noexcept { return first_.smooth() && second_.smooth(); }

    /// (1 - w) f_first + w f_second.
    [[nodiscard]] Rgb<T> f(const Vec3<T>& wo, const Vec3<T>& wi, Transport mode = Transport::radiance) const noexcept
    {
        return first_.f(wo, wi, mode) * (T(1) - w_) + second_.f(wo, wi, mode) * w_;
    }

    /// The density of sample's non-delta directions: (1 - w) pdf_first + w pdf_second.
    [[nodiscard]] T pdf(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept { return first_.pdf(wo, wi) * (T(1) - w_) + second_.pdf(wo, wi) * w_; }

    /// A direction from the second part with probability w, else from the first, weighted
    /// by the blend's f and density (a delta keeps its part's weight: its share w of the
    /// blend is drawn with probability w).
    [[nodiscard]] std::optional<LobeSample<T>> sample(const Vec3<T>& wo, T u_lobe, T u1, T u2, Transport mode = Transport::radiance) const noexcept
    {
        const bool second = u_lobe < w_;
        const T u = second ? u_lobe / w_ : (u_lobe - w_) / (T(1) - w_); // uniform in [0, 1) again
        const std::optional<LobeSample<T>> s = second ? second_.sample(wo, u, u1, u2, mode) : first_.sample(wo, u, u1, u2, mode);
        if (!s || s->delta) return s;
        const T density = pdf(wo, s->wi);
        if (!(density > T(0))) return std::nullopt;
        return LobeSample<T>{s->wi, f(wo, s->wi, mode) * (std::abs(s->wi.z) / density), density, false};
    }

    /// The smooth parts' mirror, weighted by their shares (nothing where neither is smooth).
    [[nodiscard]] std::optional<LobeSample<T>> delta_part(const Vec3<T>& wo) const noexcept
    {
        const std::optional<LobeSample<T>> a = delta_of(first_, wo), b = delta_of(second_, wo);
        if (!a && !b) return std::nullopt;
        const Rgb<T> weight = (a ? a->weight * (T(1) - w_) : Rgb<T>(T(0))) + (b ? b->weight * w_ : Rgb<T>(T(0)));
        return LobeSample<T>{a ? a->wi : b->wi, weight, T(0), true}; // both mirror wo about z
    }

    /// What a Whitted mirror ray carries: the parts' mirror albedos by their shares (a
    /// part without one, such as a Lambertian, carries none).
    [[nodiscard]] Rgb<T> mirror_albedo(const Vec3<T>& wo) const noexcept
    {
        return mirror_of(first_, wo) * (T(1) - w_) + mirror_of(second_, wo) * w_;
    }

private:
    template <class L>
    [[nodiscard]] static std::optional<LobeSample<T>> delta_of(const L& lobe, const Vec3<T>& wo) noexcept
    {
        if constexpr (requires { lobe.delta_part(wo); }) return lobe.delta_part(wo);
        else return std::nullopt;
    }

    template <class L>
    [[nodiscard]] static Rgb<T> mirror_of(const L& lobe, const Vec3<T>& wo) noexcept
    {
        if constexpr (requires { lobe.mirror_albedo(wo); }) return lobe.mirror_albedo(wo);
        else return Rgb<T>(T(0));
    }

    A first_;
    B second_;
    T w_;
};

/// Two reflecting materials (MixPart) blended by `weight`, second's share: a number in
/// [0, 1] or a one-number texture (ScalarTexture, such as ImageTexture) of it.
template <Scalar T, MixPart First, MixPart Second, class Weight = T>
struct Mix {
    /// The precision of the material.
    using scalar_type = T;
    /// Its parts' Lambertian lobes live in the blend's glossy lobe.
    static constexpr bool has_diffuse = false;
    /// No delta mirror of its own (a smooth part's is the lobe's delta part).
    static constexpr bool reflects = false;
    /// Transmits nothing.
    static constexpr bool transmits = false;
    /// A glossy lobe: the blend.
    static constexpr bool has_glossy = true;
    /// Whether a part or the weight reads surface coordinates (reads_coordinates).
    static constexpr bool reads_coordinates =
        prism::reads_coordinates<First>() || prism::reads_coordinates<Second>() || texture_reads_coordinates<Weight>;

    First first{};   ///< the part weighted 1 - w
    Second second{}; ///< the part weighted w
    Weight weight{}; ///< w: second's share, in [0, 1], a number or a ScalarTexture

    /// The blended lobe at a point.
    [[nodiscard]] constexpr auto glossy(const GlossyQuery<T>& q) const noexcept
    {
        return MixLobe(part_lobe(first, q), part_lobe(second, q), weight_at(q.texture_point()));
    }

    /// Throws std::invalid_argument, naming the parameter, for a bad part, a weight
    /// outside [0, 1] (a texture's largest value, where it knows it), or a Diffuse part
    /// with a POV-Ray highlight (which a lobe cannot hold).
    constexpr void validate() const
    {
        first.validate();
        second.validate();
        if constexpr (ScalarTexture<Weight>) {
            weight.validate();
            if constexpr (requires { weight.max_value(); })
                if (!(weight.max_value() <= 1)) detail::throw_invalid("Mix weight texture's values must be in [0, 1], got up to ", weight.max_value());
        } else {
            if (!(weight >= T(0) && weight <= T(1))) detail::throw_invalid("Mix weight must be in [0, 1], got ", weight);
        }
        no_highlight(first, "Mix first");
        no_highlight(second, "Mix second");
    }

private:
    [[nodiscard]] constexpr T weight_at(const TexturePoint<T>& at) const noexcept
    {
        if constexpr (ScalarTexture<Weight>) return weight.value(at);
        else return weight;
    }

    template <class M>
    static constexpr void no_highlight(const M& part, const char* name)
    {
        if constexpr (requires { part.phong; })
            if (part.phong != 0) detail::throw_invalid(name, " is a Diffuse with a POV-Ray phong highlight, which a blended lobe cannot hold: got phong ", part.phong);
    }
};

/// Deduces Mix's scalar type from its first part.
template <MixPart First, MixPart Second, class Weight>
Mix(First, Second, Weight) -> Mix<typename First::scalar_type, First, Second, Weight>;

} // namespace prism
