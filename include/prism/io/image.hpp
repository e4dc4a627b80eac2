// SPDX-License-Identifier: MIT
// Image files: PNG (sRGB, 8 bit, through stb_image_write and stb_image) and PFM (exact
// linear floats).
//
// Opt-in: prism/prism.hpp does not include this header, since it needs stb_image_write
// and stb_image (Debian: libstb-dev). A regular file is written whole or not at all:
// bytes go to a temporary file beside the target, which is renamed over it only once
// complete; a device or FIFO is written through, never replaced; any failure throws
// std::runtime_error naming the path and the reason.
#pragma once

#include <prism/core/math.hpp>
#include <prism/render/film.hpp>

#if !defined(INCLUDE_STB_IMAGE_WRITE_H)
// stb_image_write was not included before: compile a private copy of it into this
// translation unit (static functions, so any number of units may do the same).
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define PRISM_DEFINED_STB_IMPLEMENTATION
#endif
#if __has_include(<stb/stb_image_write.h>)
#include <stb/stb_image_write.h>
#else
#include <stb_image_write.h>
#endif
#ifdef PRISM_DEFINED_STB_IMPLEMENTATION
#undef STB_IMAGE_WRITE_IMPLEMENTATION
#undef PRISM_DEFINED_STB_IMPLEMENTATION
#endif

#if !defined(STBI_INCLUDE_STB_IMAGE_H)
// The same for stb_image, reading PNG only.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define PRISM_DEFINED_STBI_IMPLEMENTATION
#endif
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#if __has_include(<stb/stb_image.h>)
#include <stb/stb_image.h>
#else
#include <stb_image.h>
#endif
#pragma GCC diagnostic pop
#ifdef PRISM_DEFINED_STBI_IMPLEMENTATION
#undef STB_IMAGE_IMPLEMENTATION
#undef PRISM_DEFINED_STBI_IMPLEMENTATION
#endif

#include <atomic>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace prism {

namespace detail {

[[noreturn]] inline void throw_io(const std::filesystem::path& path, const std::string& reason)
{
    throw std::runtime_error("prism: cannot write '" + path.string() + "': " + reason);
}

/// Write every byte and close the file: 0, or the errno of what failed first.
[[nodiscard]] inline int write_and_close(std::FILE* file, std::span<const unsigned char> bytes) noexcept
{
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    const int write_errno = errno;
    const bool closed = std::fclose(file) == 0;
    if (!written) return write_errno != 0 ? write_errno : EIO;
    return closed ? 0 : (errno != 0 ? errno : EIO);
}

/// Write bytes to path: whole or not at all where the path is a regular file (or
/// nothing yet). Bytes go to a new temporary file beside it (created exclusively, never
/// through an existing name), which is renamed over the target only once complete. A
/// symbolic link is followed to what it names, so the link stays. Anything that is not
/// a regular file (a device such as /dev/null, a FIFO) is written through, never
/// replaced: renaming over it would turn it into a plain file.
inline void write_file_atomically(const std::filesystem::path& path, std::span<const unsigned char> bytes)
{
    namespace fs = std::filesystem;
    std::error_code error;
    fs::path target = path;
    if (fs::is_symlink(fs::symlink_status(path, error))) {
        target = fs::weakly_canonical(path, error);
        if (error) throw_io(path, "cannot follow the symbolic link: " + error.message());
    }
    const fs::file_status status = fs::status(target, error);
    if (status.type() == fs::file_type::directory) throw_io(path, "it is a directory");
    const bool regular_or_new = status.type() == fs::file_type::regular || status.type() == fs::file_type::not_found;
    if (!regular_or_new) {
        std::FILE* file = std::fopen(target.c_str(), "wb");
        if (file == nullptr) throw_io(path, std::strerror(errno));
        if (const int failure = write_and_close(file, bytes)) throw_io(path, std::strerror(failure));
        return;
    }
    // A temporary name of our own: "x" opens only a file that did not exist.
    static std::atomic<unsigned> serial{0};
    fs::path temporary;
    std::FILE* file = nullptr;
    for (int attempt = 0; attempt < 100 && file == nullptr; ++attempt) {
        temporary = target;
        temporary += ".prism-partial-" + std::to_string(serial++) + "-" + std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()) % 100000);
        file = std::fopen(temporary.c_str(), "wbx");
        if (file == nullptr && errno != EEXIST) throw_io(path, std::strerror(errno));
    }
    if (file == nullptr) throw_io(path, "no free temporary name beside it");
    if (const int failure = write_and_close(file, bytes)) {
        std::remove(temporary.c_str());
        throw_io(path, std::strerror(failure));
    }
    fs::rename(temporary, target, error);
    if (error) {
        std::remove(temporary.c_str());
        throw_io(path, error.message());
    }
}

/// sRGB transfer function (IEC 61966-2-1) of a linear value clamped to [0, 1].
[[nodiscard]] inline float srgb_encode(float linear) noexcept
{
    const float x = clamp(linear, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

} // namespace detail

/// 8-bit sRGB bytes, row by row from the top, 3 per pixel.
[[nodiscard]] inline std::vector<unsigned char> to_srgb8(const Film& film)
{
    std::vector<unsigned char> bytes;
    bytes.reserve(film.pixels().size() * 3);
    for (const Rgb<float>& p : film.pixels())
        for (int c = 0; c < 3; ++c)
            bytes.push_back(static_cast<unsigned char>(std::lround(255.0f * detail::srgb_encode(p[c]))));
    return bytes;
}

/// Write the film as an 8-bit sRGB PNG (values clamped to [0, 1]).
inline void write_png(const Film& film, const std::filesystem::path& path)
{
    const std::vector<unsigned char> rgb = to_srgb8(film);
    std::vector<unsigned char> encoded;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        const auto* bytes = static_cast<const unsigned char*>(data);
        out->insert(out->end(), bytes, bytes + size);
    };
    if (stbi_write_png_to_func(append, &encoded, film.width(), film.height(), 3, rgb.data(), film.width() * 3) == 0)
        detail::throw_io(path, "PNG encoding failed");
    detail::write_file_atomically(path, encoded);
}

/// Write the film as a little-endian PFM: exact linear floats, bottom row first.
inline void write_pfm(const Film& film, const std::filesystem::path& path)
{
    const std::string header = "PF\n" + std::to_string(film.width()) + " " + std::to_string(film.height()) + "\n-1.0\n";
    std::vector<unsigned char> bytes(header.begin(), header.end());
    bytes.reserve(header.size() + film.pixels().size() * 12);
    for (int y = film.height() - 1; y >= 0; --y)
        for (int x = 0; x < film.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const float value = film.at(x, y)[c];
                unsigned char raw[4];
                std::memcpy(raw, &value, 4);
                if constexpr (std::endian::native == std::endian::big) std::swap(raw[0], raw[3]), std::swap(raw[1], raw[2]);
                bytes.insert(bytes.end(), raw, raw + 4);
            }
    detail::write_file_atomically(path, bytes);
}

/// Write the film in the format named by the path's extension: .png or .pfm.
inline void write_image(const Film& film, const std::filesystem::path& path)
{
    const std::string extension = path.extension().string();
    if (extension == ".png") return write_png(film, path);
    if (extension == ".pfm") return write_pfm(film, path);
    detail::throw_io(path, "unknown image extension '" + extension + "' (use .png or .pfm)");
}

/// Read an 8-bit PNG (grey, RGB or with alpha) into linear radiance, undoing sRGB.
[[nodiscard]] inline Film read_png(const std::filesystem::path& path)
{
    int width = 0, height = 0, channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 3);
    if (data == nullptr) throw std::runtime_error("prism: cannot read '" + path.string() + "': " + stbi_failure_reason());
    Film film(width, height);
    const auto linear = [](unsigned char byte) {
        const float x = float(byte) / 255.0f;
        return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
    };
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const unsigned char* p = data + 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
            film.set(x, y, Rgb<float>{linear(p[0]), linear(p[1]), linear(p[2])});
        }
    stbi_image_free(data);
    return film;
}

/// Read a PFM written by write_pfm (3 channels, either byte order).
[[nodiscard]] inline Film read_pfm(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("prism: cannot read '" + path.string() + "': " + std::strerror(errno));
    std::string magic;
    int width = 0, height = 0;
    double scale = 0;
    in >> magic >> width >> height >> scale;
    in.get();
    if (!in || magic != "PF" || width <= 0 || height <= 0 || scale == 0 || !std::isfinite(scale))
        throw std::runtime_error("prism: cannot read '" + path.string() + "': not an RGB PFM file");
    // The header is checked against the file's size before anything is allocated: 20
    // bytes must not make a reader ask for gigabytes.
    const std::streamoff header_end = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streamoff file_size = in.tellg();
    in.seekg(header_end);
    const double needed = 12.0 * double(width) * double(height);
    if (header_end < 0 || file_size < 0 || double(file_size - header_end) < needed)
        throw std::runtime_error("prism: cannot read '" + path.string() + "': file is truncated (the header says " + std::to_string(width) +
                                 " x " + std::to_string(height) + " pixels, " + std::to_string(static_cast<long long>(needed)) +
                                 " bytes, but " + std::to_string(static_cast<long long>(file_size - header_end)) + " follow it)");
    Film film(width, height);
    const bool little = scale < 0;
    std::vector<unsigned char> raw(static_cast<std::size_t>(width) * 12);
    for (int y = height - 1; y >= 0; --y) {
        if (!in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(raw.size())))
            throw std::runtime_error("prism: cannot read '" + path.string() + "': file is truncated");
        for (int x = 0; x < width; ++x) {
            Rgb<float> p;
            for (int c = 0; c < 3; ++c) {
                unsigned char* b = raw.data() + x * 12 + c * 4;
                if (little != (std::endian::native == std::endian::little)) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
                std::memcpy(&p[c], b, 4);
            }
            film.set(x, y, p);
        }
    }
    return film;
}

} // namespace prism
