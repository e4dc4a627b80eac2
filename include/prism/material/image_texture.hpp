// SPDX-License-Identifier: MIT
// Image textures: a picture over a surface's (u, v), filtered to the footprint a ray sees.
//
// An ImageTexture holds linear texels (io/texture.hpp reads them from PNG, JPEG, HDR, PFM
// or EXR, undoing sRGB where the file holds colour) and a pyramid of ever smaller copies,
// each the area average of the one above (mipmaps, Williams 1983). A lookup at (u, v)
// with a footprint of width w in uv units reads the level whose texels are w wide,
// bilinearly, and blends the two levels around it (trilinear filtering); with w = 0 it
// reads the full picture bilinearly. (u, v) = (0, 0) is the picture's bottom-left corner
// and (1, 1) its top-right one (OBJ's and OpenGL's convention: v runs up the picture).
// Outside [0, 1] the picture repeats or its edge texels stretch (Wrap).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/material/texture.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace prism {

/// What a lookup outside [0, 1] reads: the picture again (repeat), or its nearest edge (clamp).
enum class Wrap { repeat, clamp };

/// How texels are blended: the nearest one; bilinearly in the full picture; or
/// trilinearly, between the two pyramid levels the footprint falls between.
enum class TextureFilter { nearest, bilinear, trilinear };

/// How a texture reads its texels.
struct TextureSampling {
    Wrap wrap = Wrap::repeat;           ///< outside [0, 1]
    TextureFilter filter = TextureFilter::trilinear;  ///< between texels and levels
};

/// A picture of linear values (1 or 3 channels) with its mipmap pyramid. Copies share the
/// texels. As a Texture it gives an albedo (a grey picture gives grey); `value` gives the
/// first channel, for a parameter that is one number (roughness, a height).
template <Scalar T = float>
class ImageTexture {
public:
    /// The precision of the values it returns.
    using scalar_type = T;

    /// One level of the pyramid: width x height texels of `channels` floats, row 0 at the
    /// top of the picture.
    struct Level {
        int width = 0;  ///< texels a row
        int height = 0; ///< rows
        std::vector<float> texels; ///< width x height x channels values, row 0 at the top
    };

    /// An empty texture; reads as black. (Only for default construction: validate() refuses it.)
    ImageTexture() = default;

    /// The texture of `texels` (width x height x channels floats, row by row from the top,
    /// linear values), read by `sampling`. Throws std::invalid_argument naming the value for
    /// a size below 1, channels other than 1 or 3, a texel count that does not match, or a
    /// texel that is negative or not finite.
    ImageTexture(int width, int height, int channels, std::span<const float> texels, TextureSampling sampling = {})
        : sampling_(sampling)
    {
        if (width < 1 || height < 1) detail::throw_invalid("ImageTexture size must be at least 1 x 1, got ", width, " x ", height);
        if (channels != 1 && channels != 3) detail::throw_invalid("ImageTexture channels must be 1 or 3, got ", channels);
        const std::size_t count = std::size_t(width) * std::size_t(height) * std::size_t(channels);
        if (texels.size() != count)
            detail::throw_invalid("ImageTexture texels must be width x height x channels = ", count, ", got ", texels.size());
        for (std::size_t i = 0; i < count; ++i)
            if (!(texels[i] >= 0.0f) || !std::isfinite(texels[i]))
                detail::throw_invalid("ImageTexture texel ", i / std::size_t(channels), " (x ", (i / std::size_t(channels)) % std::size_t(width), ", y ",
                                      i / std::size_t(channels) / std::size_t(width), ") must be finite and non-negative, got ", texels[i]);
        auto data = std::make_shared<Data>();
        data->channels = channels;
        for (std::size_t i = 0; i < count; ++i) data->max_value = std::max(data->max_value, texels[i]);
        data->levels.push_back({width, height, std::vector<float>(texels.begin(), texels.end())});
        while (data->levels.back().width > 1 || data->levels.back().height > 1) data->levels.push_back(halved(data->levels.back(), channels));
        data_ = std::move(data);
    }

    /// Width of the full picture, in texels.
    [[nodiscard]] int width() const noexcept { return data_ ? data_->levels[0].width : 0; }
    /// Height of the full picture, in texels.
    [[nodiscard]] int height() const noexcept { return data_ ? data_->levels[0].height : 0; }
    /// 1 (grey) or 3 (RGB); 0 when empty.
    [[nodiscard]] int channels() const noexcept { return data_ ? data_->channels : 0; }
    /// The number of pyramid levels (1 + floor(log2(max(width, height)))).
    [[nodiscard]] std::size_t levels() const noexcept { return data_ ? data_->levels.size() : 0; }
    /// Level k of the pyramid (0: the full picture).
    [[nodiscard]] const Level& level(std::size_t k) const noexcept { return data_->levels[k]; }
    /// How it reads its texels.
    [[nodiscard]] TextureSampling sampling() const noexcept { return sampling_; }
    /// The largest texel value of any channel (0 when empty).
    [[nodiscard]] float max_value() const noexcept { return data_ ? data_->max_value : 0.0f; }
    /// Bytes held by the texels of every level.
    [[nodiscard]] std::size_t memory_bytes() const noexcept
    {
        std::size_t bytes = 0;
        if (data_)
            for (const Level& l : data_->levels) bytes += l.texels.size() * sizeof(float);
        return bytes;
    }

    /// The pyramid level (fractional) a footprint `width` wide in uv units reads:
    /// log2(width x the picture's larger side), 0 at most a texel wide, and at most the
    /// last level.
    [[nodiscard]] T level_for(T footprint) const noexcept
    {
        if (!data_ || !(footprint > T(0))) return T(0);
        const T texels = footprint * T(std::max(width(), height()));
        if (!(texels > T(1))) return T(0);
        return std::min(T(std::log2(texels)), T(levels() - 1));
    }

    /// The filtered RGB at `at` (its footprint in at.width).
    [[nodiscard]] Rgb<T> rgb(const TexturePoint<T>& at) const noexcept
    {
        if (!data_) return Rgb<T>(T(0));
        switch (sampling_.filter) {
        case TextureFilter::nearest: return nearest(0, at.uv);
        case TextureFilter::bilinear: return bilinear(0, at.uv);
        case TextureFilter::trilinear: break;
        }
        const T l = level_for(at.width);
        const std::size_t k = std::size_t(l);
        const T f = l - T(k);
        const Rgb<T> fine = bilinear(k, at.uv);
        if (f == T(0) || k + 1 >= levels()) return fine;
        return fine + f * (bilinear(k + 1, at.uv) - fine);
    }

    /// The albedo at `at`: its RGB (Texture).
    [[nodiscard]] Rgb<T> albedo(const TexturePoint<T>& at) const noexcept { return rgb(at); }
    /// The first channel at `at`, for one-number parameters.
    [[nodiscard]] T value(const TexturePoint<T>& at) const noexcept { return rgb(at).x; }

    /// Throws std::invalid_argument for an empty texture.
    void validate() const
    {
        if (!data_) detail::throw_invalid("ImageTexture is empty (construct it from texels, or read it with load_texture)");
    }

private:
    struct Data {
        int channels = 3;
        float max_value = 0.0f;
        std::vector<Level> levels;
    };

    /// Half the size on each side (at least 1), each texel the area average of what it
    /// covers above: exact for odd sizes too, where a texel covers 1.5 texels of a side.
    [[nodiscard]] static Level halved(const Level& from, int channels)
    {
        // f(j, weight) for each texel j of n_in that texel i of n_out covers, weights summing to 1.
        const auto covered = [](int n_in, int n_out, int i, auto&& f) {
            const double scale = double(n_in) / double(n_out), lo = i * scale, hi = (i + 1) * scale;
            for (int j = int(lo); j < n_in && double(j) < hi; ++j) f(std::size_t(j), (std::min(hi, double(j + 1)) - std::max(lo, double(j))) / scale);
        };
        const int w = std::max(1, from.width / 2), h = std::max(1, from.height / 2);
        const std::size_t c = std::size_t(channels), in_w = std::size_t(from.width);
        // Across, then down.
        std::vector<double> across(std::size_t(w) * std::size_t(from.height) * c, 0.0);
        for (std::size_t y = 0; y < std::size_t(from.height); ++y)
            for (int i = 0; i < w; ++i)
                covered(from.width, w, i, [&](std::size_t j, double weight) {
                    for (std::size_t ch = 0; ch < c; ++ch) across[(y * std::size_t(w) + std::size_t(i)) * c + ch] += weight * from.texels[(y * in_w + j) * c + ch];
                });
        Level out{w, h, std::vector<float>(std::size_t(w) * std::size_t(h) * c)};
        for (int y = 0; y < h; ++y)
            for (std::size_t i = 0; i < std::size_t(w); ++i)
                for (std::size_t ch = 0; ch < c; ++ch) {
                    double sum = 0;
                    covered(from.height, h, y, [&](std::size_t j, double weight) { sum += weight * across[(j * std::size_t(w) + i) * c + ch]; });
                    out.texels[(std::size_t(y) * std::size_t(w) + i) * c + ch] = float(sum);
                }
        return out;
    }

    [[nodiscard]] static T wrapped(T x, Wrap wrap) noexcept
    {
        if (!std::isfinite(x)) return T(0);
        return wrap == Wrap::repeat ? x - std::floor(x) : std::clamp(x, T(0), T(1));
    }

    /// Texel (i, j) of level k as RGB, with i and j brought inside by the wrap mode.
    [[nodiscard]] Rgb<T> texel(const Level& l, int i, int j) const noexcept
    {
        if (sampling_.wrap == Wrap::repeat) {
            i = i < 0 ? i + l.width : (i >= l.width ? i - l.width : i);
            j = j < 0 ? j + l.height : (j >= l.height ? j - l.height : j);
        } else {
            i = std::clamp(i, 0, l.width - 1);
            j = std::clamp(j, 0, l.height - 1);
        }
        const std::size_t c = std::size_t(data_->channels);
        const float* p = l.texels.data() + (std::size_t(j) * std::size_t(l.width) + std::size_t(i)) * c;
        return c == 3 ? Rgb<T>(T(p[0]), T(p[1]), T(p[2])) : Rgb<T>(T(p[0]));
    }

    [[nodiscard]] Rgb<T> nearest(std::size_t k, const Vec2<T>& uv) const noexcept
    {
        const Level& l = data_->levels[k];
        const T u = wrapped(uv.x, sampling_.wrap), v = wrapped(uv.y, sampling_.wrap);
        const int i = std::min(int(u * T(l.width)), l.width - 1), j = std::min(int((T(1) - v) * T(l.height)), l.height - 1);
        return texel(l, i, j);
    }

    [[nodiscard]] Rgb<T> bilinear(std::size_t k, const Vec2<T>& uv) const noexcept
    {
        const Level& l = data_->levels[k];
        // Texel centres sit at (i + 1/2) / width; row 0 at the top (v = 1).
        const T x = wrapped(uv.x, sampling_.wrap) * T(l.width) - T(0.5);
        const T y = (T(1) - wrapped(uv.y, sampling_.wrap)) * T(l.height) - T(0.5);
        const T fx = std::floor(x), fy = std::floor(y);
        const int i = int(fx), j = int(fy);
        const T ax = x - fx, ay = y - fy;
        const Rgb<T> top = (T(1) - ax) * texel(l, i, j) + ax * texel(l, i + 1, j);
        const Rgb<T> bottom = (T(1) - ax) * texel(l, i, j + 1) + ax * texel(l, i + 1, j + 1);
        return (T(1) - ay) * top + ay * bottom;
    }

    std::shared_ptr<const Data> data_;
    TextureSampling sampling_{};
};

} // namespace prism
