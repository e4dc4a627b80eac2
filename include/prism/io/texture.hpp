// SPDX-License-Identifier: MIT
// Image textures from files: PNG and baseline JPEG (8-bit; sRGB decoded where they hold
// colour, read as bytes / 255 where they hold data: roughness, heights, normals),
// Radiance HDR and PFM (linear as stored). An EXR is read by io/exr.hpp and handed to
// texture_from: texture_from(read_exr(path).film(), {...}).
//
// Opt-in, as io/image.hpp is (stb_image).
#pragma once

#include <prism/io/image.hpp>
#include <prism/io/input.hpp>
#include <prism/material/image_texture.hpp>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace prism {

/// What an 8-bit file's values mean.
enum class TextureEncoding {
    srgb,  ///< colour, sRGB-encoded: decoded to linear (IEC 61966-2-1)
    linear ///< data (roughness, height, a normal map): byte / 255
};

/// How load_texture reads a file.
struct TextureFile {
    TextureEncoding encoding = TextureEncoding::srgb; ///< for PNG and JPEG; HDR and PFM are linear as stored
    int channels = 3; ///< 3 (RGB) or 1 (the file's first channel: red, or grey)
    TextureSampling sampling{}; ///< wrap and filter
    ReadLimits limits{}; ///< how much of the file may be read
};

/// The texture of a picture of linear values: its RGB, or its first channel.
/// Throws std::invalid_argument for channels other than 1 or 3, or a negative or
/// non-finite value (naming the texel).
template <Scalar T = float>
[[nodiscard]] ImageTexture<T> texture_from(const Film& film, int channels = 3, TextureSampling sampling = {})
{
    if (channels != 1 && channels != 3) detail::throw_invalid("texture channels must be 1 or 3, got ", channels);
    std::vector<float> texels;
    texels.reserve(film.pixels().size() * std::size_t(channels));
    for (const Rgb<float>& p : film.pixels()) {
        texels.push_back(p.x);
        if (channels == 3) texels.push_back(p.y), texels.push_back(p.z);
    }
    return ImageTexture<T>(film.width(), film.height(), channels, texels, sampling);
}

/// The texture in the file at `path`, by its extension: .png, .jpg or .jpeg (8-bit,
/// decoded by `file.encoding`), .hdr or .pfm (linear). Throws std::runtime_error naming
/// the path for a file that cannot be read or holds what no texture can (negative or
/// non-finite values), and for any other extension.
template <Scalar T = float>
[[nodiscard]] ImageTexture<T> load_texture(const std::filesystem::path& path, TextureFile file = {})
{
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (file.channels != 1 && file.channels != 3) detail::throw_read(path, "texture", "texture channels must be 1 or 3, got " + std::to_string(file.channels));
    const bool srgb = file.encoding == TextureEncoding::srgb;
    // A PFM is data: its values as stored (a Film would zero what is negative or not
    // finite, which the texture refuses instead).
    if (extension == ".pfm") {
        const PfmImage pfm = read_pfm(path, file.limits);
        std::vector<float> texels;
        texels.reserve(std::size_t(pfm.width) * std::size_t(pfm.height) * std::size_t(file.channels));
        for (int y = 0; y < pfm.height; ++y)
            for (int x = 0; x < pfm.width; ++x)
                for (int c = 0; c < file.channels; ++c) texels.push_back(pfm.at(x, y, std::min(c, pfm.channels - 1)));
        try {
            return ImageTexture<T>(pfm.width, pfm.height, file.channels, texels, file.sampling);
        } catch (const std::invalid_argument& e) {
            detail::throw_read(path, "texture", std::string("it cannot be a texture: ") + e.what());
        }
    }
    const Film film = [&] {
        if (extension == ".png") return detail::to_film(read_png_bytes(path, file.limits), srgb);
        if (extension == ".jpg" || extension == ".jpeg") return detail::to_film(read_jpeg_bytes(path, file.limits), srgb);
        if (extension == ".hdr") return read_hdr(path, file.limits);
        detail::throw_read(path, "texture", "unknown texture extension '" + extension + "' (use .png, .jpg, .jpeg, .hdr or .pfm; an EXR through texture_from(read_exr(path).film()))");
    }();
    return texture_from<T>(film, file.channels, file.sampling);
}

} // namespace prism
