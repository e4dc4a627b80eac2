// SPDX-License-Identifier: MIT
// The Trowbridge-Reitz (GGX) distribution of microfacet normals (Trowbridge and Reitz
// 1975; Walter et al. 2007), with Smith's height-correlated masking-shadowing and
// sampling of the normals a direction sees (Heitz 2018, "Sampling the GGX Distribution
// of Visible Normals"). Every vector is in the surface's local frame: z along the
// macro-normal, x and y along the directions of roughness alpha_x and alpha_y.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>

#include <algorithm>
#include <cmath>

namespace prism {

/// The roughness of a microfacet surface along its two tangent directions, as
/// Blender's Cycles and Disney's principled model take it: alpha = roughness^2, so a
/// roughness the eye reads as halfway rough (0.5) gives alpha 0.25.
template <Scalar T>
struct Roughness {
    T u = T(0.3); ///< roughness along the first tangent, in [0, 1]
    T v = T(0.3); ///< roughness along the second tangent, in [0, 1]

    constexpr Roughness() noexcept = default;
    /// An isotropic roughness (implicit, so a material reads `.roughness = 0.2`).
    constexpr Roughness(T r) noexcept : u(r), v(r) {} // NOLINT(google-explicit-constructor)
    /// An anisotropic roughness: r_u along the first tangent, r_v along the second.
    constexpr Roughness(T r_u, T r_v) noexcept : u(r_u), v(r_v) {}

    /// Throws std::invalid_argument, naming the parameter (`name` u or v), for a roughness outside [0, 1].
    constexpr void validate(const char* name) const
    {
        if (!(u >= T(0) && u <= T(1))) detail::throw_invalid(name, " roughness must be in [0, 1], got ", u);
        if (!(v >= T(0) && v <= T(1))) detail::throw_invalid(name, " roughness along v must be in [0, 1], got ", v);
    }
};

/// The Trowbridge-Reitz (GGX) normal distribution with widths alpha_x, alpha_y.
template <Scalar T>
class TrowbridgeReitz {
public:
    /// Below this alpha a surface is a mirror: its lobe is narrower than float's
    /// directions resolve, and it is rendered as the delta material (pbrt-v4's limit).
    static constexpr T smooth_alpha = T(1e-3);

    /// The distribution of a roughness: alpha = roughness^2 on each axis.
    [[nodiscard]] static constexpr TrowbridgeReitz from(const Roughness<T>& r) noexcept { return TrowbridgeReitz(r.u * r.u, r.v * r.v); }

    /// The distribution with widths alpha_x, alpha_y (each >= 0).
    constexpr TrowbridgeReitz(T alpha_x, T alpha_y) noexcept : alpha_x_(alpha_x), alpha_y_(alpha_y) {}

    /// The width along x.
    [[nodiscard]] constexpr T alpha_x() const noexcept { return alpha_x_; }
    /// The width along y.
    [[nodiscard]] constexpr T alpha_y() const noexcept { return alpha_y_; }

    /// Whether the surface is effectively a mirror (both widths below smooth_alpha).
    [[nodiscard]] constexpr bool smooth() const noexcept { return std::max(alpha_x_, alpha_y_) < smooth_alpha; }

    /// The density of microfacet normals m per unit projected area, D(m): its integral
    /// of D(m) m.z over the hemisphere is 1 (and no facet faces down: 0 for m.z <= 0).
    [[nodiscard]] T d(const Vec3<T>& m) const noexcept
    {
        if (!(m.z > T(0))) return T(0);
        const T cos2 = m.z * m.z;
        const T e = (m.x * m.x / (alpha_x_ * alpha_x_) + m.y * m.y / (alpha_y_ * alpha_y_)) / cos2;
        const T denom = pi<T> * alpha_x_ * alpha_y_ * cos2 * cos2 * (T(1) + e) * (T(1) + e);
        return denom > T(0) && denom < infinity<T> ? T(1) / denom : T(0);
    }

    /// Smith's Lambda(w): the shadowed microfacet area seen from w over its projected area.
    [[nodiscard]] T lambda(const Vec3<T>& w) const noexcept
    {
        const T cos2 = w.z * w.z;
        const T a2_tan2 = (alpha_x_ * alpha_x_ * w.x * w.x + alpha_y_ * alpha_y_ * w.y * w.y) / cos2;
        if (!(a2_tan2 < infinity<T>)) return infinity<T>;
        return (std::sqrt(T(1) + a2_tan2) - T(1)) / T(2);
    }

    /// Smith's masking: the fraction of microfacets facing w that w sees, 1 / (1 + Lambda(w)).
    [[nodiscard]] T g1(const Vec3<T>& w) const noexcept { return T(1) / (T(1) + lambda(w)); }

    /// Smith's height-correlated masking-shadowing of wo and wi (Heitz 2014), 1 / (1 + Lambda(wo) + Lambda(wi)).
    [[nodiscard]] T g(const Vec3<T>& wo, const Vec3<T>& wi) const noexcept { return T(1) / (T(1) + lambda(wo) + lambda(wi)); }

    /// The density of the normals a direction w sees (Heitz 2018, eq. 3):
    /// G1(w) max(0, w.m) D(m) / |w.z|, per unit solid angle of m.
    [[nodiscard]] T visible_d(const Vec3<T>& w, const Vec3<T>& m) const noexcept
    {
        const T cos_o = std::abs(w.z);
        if (!(cos_o > T(0))) return T(0);
        return g1(w) * std::max(T(0), dot(w, m)) * d(m) / cos_o;
    }

    /// A normal drawn from visible_d(w, .) for w above the surface (w.z > 0), from two
    /// uniform numbers (Heitz 2018): w stretched to the unit-roughness configuration, a
    /// point on the half disk it sees, lifted onto the hemisphere and unstretched.
    [[nodiscard]] Vec3<T> sample_visible(const Vec3<T>& w, T u1, T u2) const noexcept
    {
        const Vec3<T> wh = normalize(Vec3<T>(alpha_x_ * w.x, alpha_y_ * w.y, w.z));
        const T lensq = wh.x * wh.x + wh.y * wh.y;
        const Vec3<T> t1 = lensq > T(0) ? Vec3<T>(-wh.y, wh.x, T(0)) / std::sqrt(lensq) : Vec3<T>(T(1), T(0), T(0));
        const Vec3<T> t2 = cross(wh, t1);
        const T r = std::sqrt(u1), phi = T(2) * pi<T> * u2;
        const T p1 = r * std::cos(phi);
        const T s = T(0.5) * (T(1) + wh.z);
        const T p2 = (T(1) - s) * std::sqrt(std::max(T(0), T(1) - p1 * p1)) + s * r * std::sin(phi);
        const T p3 = std::sqrt(std::max(T(0), T(1) - p1 * p1 - p2 * p2));
        const Vec3<T> nh = p1 * t1 + p2 * t2 + p3 * wh;
        return normalize(Vec3<T>(alpha_x_ * nh.x, alpha_y_ * nh.y, std::max(T(1e-6), nh.z)));
    }

private:
    T alpha_x_, alpha_y_;
};

} // namespace prism
