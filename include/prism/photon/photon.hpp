// SPDX-License-Identifier: MIT
// Photon: what a photon map stores, and the sampling a photon tracer needs.
//
// Jensen, "Global Illumination using Photon Maps" (1996) and "Realistic Image Synthesis
// Using Photon Mapping" (2001): emission directions uniform on the sphere, each photon
// carrying the light's power divided by the photons emitted, Russian roulette that
// scales a survivor's power per channel by reflectance over survival probability.
#pragma once

#include <prism/core/math.hpp>
#include <prism/core/rng.hpp>
#include <prism/core/sampling.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

namespace prism {

/// One stored photon, 28 bytes: where it landed (three floats), the power it carries
/// (W) with a shared exponent and a 16-bit mantissa per channel (rounded to nearest:
/// 2^-16 relative at worst, so a map of equal photons sums to its power to 10^-5; Ward's
/// 8-bit RGBE read a furnace 0.25 % bright), the direction it came from and the normal
/// of the surface it landed on (facing the side it arrived from), each as two 16-bit
/// octahedral coordinates (Meyer et al. 2010), its flags, and the segments its path took
/// from the light (4 bits: up to 15).
class Photon {
public:
    /// What a stored photon is.
    enum Flags : std::uint8_t {
        direct = 1,  ///< first hit after leaving the light (for a volume photon: its first scattering)
        caustic = 2, ///< reached this diffuse surface only by specular bounces (L S+ D)
        shadow = 4,  ///< a shadow photon: where the straight continuation of a direct photon's path met a further surface
        volume = 8,  ///< scattered in a medium, not on a surface (its normal is its direction)
    };

    /// The most segments a photon's record holds (flags' high 4 bits); a longer path
    /// records this many.
    static constexpr int max_segments = 15;

    /// The flag bits that record a path of `segments` segments from the light (at most
    /// max_segments kept).
    [[nodiscard]] static constexpr std::uint8_t segments_bits(int segments) noexcept
    {
        return std::uint8_t(std::clamp(segments, 0, max_segments) << 4);
    }

    Vec3<float> position{}; ///< where the photon landed

    Photon() = default;

    /// `toward_source`: unit direction back toward where the photon came from;
    /// `normal`: the unit normal of the surface it landed on, on the side it arrived from.
    Photon(const Vec3<float>& at, const Rgb<float>& power, const Vec3<float>& toward_source, const Vec3<float>& normal, std::uint8_t flag_bits) noexcept
        : position(at), direction_(encode_octahedral(toward_source)), normal_(encode_octahedral(normal)), flags(flag_bits)
    {
        encode_power(power);
    }

    /// The photon's power, decoded.
    [[nodiscard]] Rgb<float> power() const noexcept
    {
        if (exponent_ == 0) return Rgb<float>(0.0f);
        const float scale = std::ldexp(1.0f, int(exponent_) - 144); // 2^(e - 16), e = exponent_ - 128
        return {float(mantissa_[0]) * scale, float(mantissa_[1]) * scale, float(mantissa_[2]) * scale};
    }

    /// The unit direction back toward where the photon came from.
    [[nodiscard]] Vec3<float> toward_source() const noexcept { return normalize(decode_octahedral(direction_)); }

    /// The unit normal of the surface the photon landed on, on its side.
    [[nodiscard]] Vec3<float> normal() const noexcept { return normalize(decode_octahedral(normal_)); }

    /// Whether the photon lies on a surface facing the way n does: the cosine between its
    /// normal and n exceeds `min_cos`. The other side of a thin wall (normals opposite)
    /// and a perpendicular wall in a corner are left out; a curved surface is kept where
    /// it turns by less than acos(min_cos).
    [[nodiscard]] bool faces(const Vec3<float>& n, float min_cos) const noexcept
    {
        const Vec3<float> m = decode_octahedral(normal_);
        const float d = dot(m, n);
        return d > 0.0f && d * d > min_cos * min_cos * length_squared(m) * length_squared(n);
    }

    /// The segments of the photon's path from the light to where it landed (1: it came
    /// straight from the light), at most max_segments; 0 where none was recorded.
    [[nodiscard]] int segments() const noexcept { return flags >> 4; }

    /// Photons are equal when every stored bit is.
    friend bool operator==(const Photon&, const Photon&) = default;

private:
    [[nodiscard]] static Vec3<float> decode_octahedral(const std::array<std::uint16_t, 2>& q) noexcept
    {
        const float u = float(q[0]) * (2.0f / 65535.0f) - 1.0f, v = float(q[1]) * (2.0f / 65535.0f) - 1.0f;
        const float z = 1.0f - std::abs(u) - std::abs(v);
        if (z >= 0.0f) return {u, v, z};
        return {std::copysign(1.0f - std::abs(v), u), std::copysign(1.0f - std::abs(u), v), z};
    }

    /// The largest channel's exponent e (max = m 2^(e-16), 2^15 <= m < 2^16 after
    /// rounding), every channel's mantissa rounded to nearest at that exponent. Worked
    /// in double, where 2^(16 - e) cannot overflow; e is kept within [-127, 127], so a
    /// power below 2^-128 keeps fewer bits and one above 2^127 (not a photon's) saturates.
    void encode_power(const Rgb<float>& c) noexcept
    {
        const double largest = std::max({c.x, c.y, c.z});
        if (!(largest > 0.0) || !std::isfinite(largest)) return; // carries nothing
        int e = 0;
        std::frexp(largest, &e); // largest = f 2^e, 0.5 <= f < 1
        if (std::llround(std::ldexp(largest, 16 - e)) > 65535) ++e; // rounding reached 2^16: one exponent up
        e = std::clamp(e, -127, 127);
        const double scale = std::ldexp(1.0, 16 - e);
        for (int i = 0; i < 3; ++i) mantissa_[i] = std::uint16_t(std::clamp(std::llround(std::max(double(c[i]), 0.0) * scale), 0LL, 65535LL));
        exponent_ = std::uint8_t(e + 128);
        if (mantissa_ == std::array<std::uint16_t, 3>{}) exponent_ = 0;
    }

    static std::array<std::uint16_t, 2> encode_octahedral(const Vec3<float>& d) noexcept
    {
        const float l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
        float u = l1 > 0.0f ? d.x / l1 : 0.0f, v = l1 > 0.0f ? d.y / l1 : 0.0f;
        if (d.z < 0.0f) {
            const float x = u;
            u = (1.0f - std::abs(v)) * (x >= 0.0f ? 1.0f : -1.0f);
            v = (1.0f - std::abs(x)) * (v >= 0.0f ? 1.0f : -1.0f);
        }
        const auto quantise = [](float x) { return std::uint16_t(std::lround((std::clamp(x, -1.0f, 1.0f) * 0.5f + 0.5f) * 65535.0f)); };
        return {quantise(u), quantise(v)};
    }

    std::array<std::uint16_t, 3> mantissa_{};
    std::array<std::uint16_t, 2> direction_{};
    std::array<std::uint16_t, 2> normal_{};
    std::uint8_t exponent_ = 0; ///< 0: no power; else the shared exponent + 128

public:
    std::uint8_t flags = 0; ///< Flags in the low 4 bits, the segments from the light in the high 4 (segments())
};

static_assert(sizeof(Photon) == 28);

} // namespace prism
