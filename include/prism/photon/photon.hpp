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
#include <prism/core/sampling.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

namespace prism {

/// One stored photon, 24 bytes as Jensen's compact record: where it landed (three
/// floats), the power it carries (W) in shared-exponent RGBE (Ward 1991: 8 bits of
/// mantissa per channel, rounded to nearest), the direction it came from as two 16-bit
/// octahedral coordinates (Meyer et al. 2010), and its flags.
class Photon {
public:
    enum Flags : std::uint8_t {
        direct = 1,  ///< first hit after leaving the light
        caustic = 2, ///< reached this diffuse surface only by specular bounces (L S+ D)
        shadow = 4,  ///< a shadow photon: where the straight continuation of a direct photon's path met a further surface
    };

    Vec3<float> position{};
    std::uint8_t flags = 0;

    Photon() = default;

    /// `toward_source`: unit direction back toward where the photon came from.
    Photon(const Vec3<float>& at, const Rgb<float>& power, const Vec3<float>& toward_source, std::uint8_t flag_bits) noexcept
        : position(at), flags(flag_bits), rgbe_(encode_rgbe(power)), octahedral_(encode_octahedral(toward_source))
    {
    }

    [[nodiscard]] Rgb<float> power() const noexcept
    {
        // 2^(e - 136) built from its bits where it is a normal float, ldexp below that.
        const int biased = int(rgbe_[3]) - 136 + 127;
        const float scale = biased > 0 ? std::bit_cast<float>(std::uint32_t(biased) << 23) : std::ldexp(1.0f, int(rgbe_[3]) - 136);
        return rgbe_[3] == 0 ? Rgb<float>(0.0f) : Rgb<float>(float(rgbe_[0]) * scale, float(rgbe_[1]) * scale, float(rgbe_[2]) * scale);
    }

    /// The unit direction back toward where the photon came from.
    [[nodiscard]] Vec3<float> toward_source() const noexcept { return normalize(unnormalised_toward_source()); }

    /// Whether the photon arrived on the side of a surface that the normal n points to.
    [[nodiscard]] bool arrived_on(const Vec3<float>& n) const noexcept { return dot(unnormalised_toward_source(), n) > 0.0f; }

    friend bool operator==(const Photon&, const Photon&) = default;

private:
    [[nodiscard]] Vec3<float> unnormalised_toward_source() const noexcept
    {
        const float u = float(octahedral_[0]) * (2.0f / 65535.0f) - 1.0f, v = float(octahedral_[1]) * (2.0f / 65535.0f) - 1.0f;
        const float z = 1.0f - std::abs(u) - std::abs(v);
        if (z >= 0.0f) return {u, v, z};
        return {std::copysign(1.0f - std::abs(v), u), std::copysign(1.0f - std::abs(u), v), z};
    }

    /// The largest channel's exponent e (max = m 2^(e-8), 128 <= m < 256 after
    /// rounding), every channel's mantissa rounded to nearest at that exponent.
    static std::array<std::uint8_t, 4> encode_rgbe(const Rgb<float>& c) noexcept
    {
        const float largest = std::max({c.x, c.y, c.z});
        if (!(largest > 1e-38f)) return {0, 0, 0, 0};
        int e = 0;
        std::frexp(largest, &e); // largest = f 2^e, 0.5 <= f < 1
        float scale = std::ldexp(1.0f, 8 - e);
        if (std::lround(largest * scale) > 255) { // rounding reached 256: one exponent up
            ++e;
            scale *= 0.5f;
        }
        const auto mantissa = [&](float x) { return std::uint8_t(std::clamp(std::lround(std::max(x, 0.0f) * scale), 0L, 255L)); };
        return {mantissa(c.x), mantissa(c.y), mantissa(c.z), std::uint8_t(std::clamp(e + 128, 1, 255))};
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

    std::array<std::uint8_t, 4> rgbe_{};
    std::array<std::uint16_t, 2> octahedral_{};
};

static_assert(sizeof(Photon) == 24);

} // namespace prism
