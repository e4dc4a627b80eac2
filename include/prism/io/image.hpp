// SPDX-License-Identifier: MIT
// Image files: PNG (sRGB, 8 bit, through stb_image_write and stb_image), PFM (exact
// linear floats), and Radiance HDR (RGBE, read through stb_image).
//
// Opt-in: prism/prism.hpp does not include this header, since it needs stb_image_write
// and stb_image (Debian: libstb-dev). A regular file is written whole or not at all:
// bytes go to a temporary file beside the target, which is renamed over it only once
// complete; a device or FIFO is written through, never replaced; any failure throws
// std::runtime_error naming the path and the reason.
#pragma once

#include <prism/core/math.hpp>
#include <prism/io/input.hpp>
#include <prism/io/output.hpp>
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
// The same for stb_image, reading PNG, baseline JPEG and Radiance HDR only.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_HDR
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

#include <algorithm>
#include <atomic>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace prism {

namespace detail {

/// CRC-32 as PNG computes it (ISO 3309, polynomial 0xedb88320).
[[nodiscard]] inline std::uint32_t png_crc(const unsigned char* data, std::size_t size) noexcept
{
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xffffffffu;
}

/// A PNG's bytes with every chunk checked (it fits in the file, its CRC is right, IEND
/// ends the file), and empty IDAT chunks left out (stb_image would copy from a null
/// pointer for them).
template <class File>
[[nodiscard]] std::vector<unsigned char> checked_png_chunks(const std::vector<unsigned char>& bytes, File& file)
{
    std::vector<unsigned char> out(bytes.begin(), bytes.begin() + 8);
    std::size_t at = 8;
    for (;;) {
        if (bytes.size() - at < 12) file.fail("it is truncated (a chunk's header or CRC is cut at byte " + std::to_string(at) + ")");
        const std::uint32_t length = std::uint32_t(bytes[at]) << 24 | std::uint32_t(bytes[at + 1]) << 16 | std::uint32_t(bytes[at + 2]) << 8 | bytes[at + 3];
        if (length > bytes.size() - at - 12) file.fail("it is truncated (the chunk at byte " + std::to_string(at) + " claims " + std::to_string(length) + " bytes)");
        const unsigned char* chunk = bytes.data() + at;
        const std::uint32_t stored = std::uint32_t(chunk[8 + length]) << 24 | std::uint32_t(chunk[9 + length]) << 16 | std::uint32_t(chunk[10 + length]) << 8 | chunk[11 + length];
        if (png_crc(chunk + 4, 4 + std::size_t(length)) != stored)
            file.fail("the chunk '" + std::string(reinterpret_cast<const char*>(chunk + 4), 4) + "' at byte " + std::to_string(at) + " fails its CRC: the file is corrupt");
        const bool end = std::memcmp(chunk + 4, "IEND", 4) == 0;
        if (!(length == 0 && std::memcmp(chunk + 4, "IDAT", 4) == 0)) out.insert(out.end(), chunk, chunk + 12 + length);
        at += 12 + std::size_t(length);
        if (end) break;
    }
    if (at != bytes.size()) file.fail(std::to_string(bytes.size() - at) + " bytes follow its IEND chunk");
    return out;
}

/// sRGB transfer function (IEC 61966-2-1) of a linear value clamped to [0, 1].
[[nodiscard]] inline float srgb_encode(float linear) noexcept
{
    const float x = clamp(linear, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

/// The linear value of an sRGB-encoded one in [0, 1] (IEC 61966-2-1).
[[nodiscard]] inline float srgb_decode(float encoded) noexcept
{
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

/// An 8-bit picture as a file holds it: width x height x 3 bytes, row by row from the top.
struct Bytes8 {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};

/// stb_image's 8-bit RGB decoding of `bytes`, which the caller has checked; a failure
/// throws through `file`, with stb_image's reason.
template <class File>
[[nodiscard]] Bytes8 stb_decode8(const std::vector<unsigned char>& bytes, File& file)
{
    int w = 0, h = 0, channels = 0;
    unsigned char* data = stbi_load_from_memory(bytes.data(), int(std::min<std::size_t>(bytes.size(), INT32_MAX)), &w, &h, &channels, 3);
    if (data == nullptr) {
        const char* reason = stbi_failure_reason();
        file.fail(std::string("it is truncated or corrupt (stb_image: ") + (reason != nullptr && *reason != 0 ? reason : "no reason given") + ")");
    }
    struct Free {
        unsigned char* data;
        ~Free() { stbi_image_free(data); }
    } owner{data};
    return {w, h, std::vector<unsigned char>(data, data + std::size_t(w) * std::size_t(h) * 3)};
}

/// An 8-bit picture as a Film of linear values: sRGB decoded, or each byte / 255.
[[nodiscard]] inline Film to_film(const Bytes8& picture, bool srgb)
{
    float table[256];
    for (int i = 0; i < 256; ++i) table[i] = srgb ? srgb_decode(float(i) / 255.0f) : float(i) / 255.0f;
    Film film(picture.width, picture.height);
    for (int y = 0; y < picture.height; ++y)
        for (int x = 0; x < picture.width; ++x) {
            const unsigned char* p = picture.rgb.data() + 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(picture.width) + static_cast<std::size_t>(x));
            film.set(x, y, Rgb<float>{table[p[0]], table[p[1]], table[p[2]]});
        }
    return film;
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

/// The film as the bytes of an 8-bit sRGB PNG (values clamped to [0, 1]).
[[nodiscard]] inline std::vector<unsigned char> encode_png(const Film& film)
{
    const std::vector<unsigned char> rgb = to_srgb8(film);
    std::vector<unsigned char> encoded;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        const auto* bytes = static_cast<const unsigned char*>(data);
        out->insert(out->end(), bytes, bytes + size);
    };
    if (stbi_write_png_to_func(append, &encoded, film.width(), film.height(), 3, rgb.data(), film.width() * 3) == 0)
        throw std::runtime_error("prism: PNG encoding failed");
    return encoded;
}

/// Write the film as an 8-bit sRGB PNG (values clamped to [0, 1]).
inline void write_png(const Film& film, const std::filesystem::path& path) { detail::write_file_atomically(path, encode_png(film)); }

/// The film as the bytes of a little-endian PFM: exact linear floats, bottom row first.
[[nodiscard]] inline std::vector<unsigned char> encode_pfm(const Film& film)
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
    return bytes;
}

/// Write the film as a little-endian PFM: exact linear floats, bottom row first.
inline void write_pfm(const Film& film, const std::filesystem::path& path) { detail::write_file_atomically(path, encode_pfm(film)); }

/// Write the film in the format named by the path's extension: .png or .pfm.
inline void write_image(const Film& film, const std::filesystem::path& path)
{
    const std::string extension = path.extension().string();
    if (extension == ".png") return write_png(film, path);
    if (extension == ".pfm") return write_pfm(film, path);
    detail::throw_io(path, "unknown image extension '" + extension + "' (use .png or .pfm)");
}

/// Read a PNG (grey, RGB or with alpha; 16-bit channels are cut to 8) as its 8-bit RGB
/// bytes. The file is read no further than `limits`, and its header's size is checked
/// against its bytes before stb_image allocates the picture: deflate expands at most 1032
/// times, so a header that claims more pixels than its compressed bytes can hold is
/// refused. Every chunk must fit in the file and pass its CRC, and nothing may follow IEND.
[[nodiscard]] inline detail::Bytes8 read_png_bytes(const std::filesystem::path& path, ReadLimits limits = {})
try {
    detail::InputFile file(path, "image", limits);
    // The signature and the header first, so that what is no PNG (/dev/zero) is refused
    // before the rest is read.
    std::vector<unsigned char> bytes;
    if (file.size() && *file.size() < 33) file.fail("it is too short to be a PNG file (" + std::to_string(*file.size()) + " bytes)");
    file.read(bytes, 33, "a PNG signature and header");
    static constexpr unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (std::memcmp(bytes.data(), signature, 8) != 0 || std::memcmp(bytes.data() + 12, "IHDR", 4) != 0)
        file.fail("it is not a PNG file (no PNG signature and IHDR chunk)");
    const std::vector<unsigned char> rest = file.rest();
    bytes.insert(bytes.end(), rest.begin(), rest.end());
    const auto be32 = [&](std::size_t at) { return std::uint32_t(bytes[at]) << 24 | std::uint32_t(bytes[at + 1]) << 16 | std::uint32_t(bytes[at + 2]) << 8 | bytes[at + 3]; };
    const std::uint32_t width = be32(16), height = be32(20), depth = bytes[24];
    if (width == 0 || height == 0 || width > (1u << 24) || height > (1u << 24))
        file.fail("its header says " + std::to_string(width) + " x " + std::to_string(height) + " pixels (each side must be 1 to 16777216)");
    if (depth != 1 && depth != 2 && depth != 4 && depth != 8 && depth != 16) file.fail("its bit depth " + std::to_string(depth) + " is not 1, 2, 4, 8 or 16");
    // Raw scanlines: a filter byte and at least one channel of `depth` bits a pixel.
    const double raw = double(height) * (1.0 + std::ceil(double(width) * double(depth) / 8.0));
    if (raw > 1032.0 * double(bytes.size()) + 1024.0)
        file.fail("its header says " + std::to_string(width) + " x " + std::to_string(height) + " pixels, more than its " + std::to_string(bytes.size()) +
                  " bytes can hold compressed");
    file.check_pixels(width, height, "its header");
    bytes = detail::checked_png_chunks(bytes, file);
    return detail::stb_decode8(bytes, file);
} catch (const allocation_error&) {
    throw;
} catch (const std::bad_alloc&) {
    throw detail::out_of_memory(path, "image");
}

/// Read a PNG (read_png_bytes) into linear radiance, undoing sRGB.
[[nodiscard]] inline Film read_png(const std::filesystem::path& path, ReadLimits limits = {}) { return detail::to_film(read_png_bytes(path, limits), true); }

/// Read a baseline JPEG (JFIF or Exif; grey or YCbCr) as its 8-bit RGB bytes. The file is
/// read no further than `limits`, and its markers are walked before stb_image allocates
/// the picture: the frame header and the Huffman and quantization tables must come
/// before the scan, its size be 1 to 65535 on each side, and its pixels no more than its
/// bytes can hold (a baseline scan spends at least two bits on each 8 x 8 block: 256
/// pixels a byte). Progressive and arithmetic-coded
/// JPEGs are refused (a progressive scan can cover thousands of blocks with one code).
[[nodiscard]] inline detail::Bytes8 read_jpeg_bytes(const std::filesystem::path& path, ReadLimits limits = {})
try {
    detail::InputFile file(path, "image", limits);
    std::vector<unsigned char> bytes;
    if (file.size() && *file.size() < 4) file.fail("it is too short to be a JPEG file (" + std::to_string(*file.size()) + " bytes)");
    file.read(bytes, 2, "a JPEG start-of-image marker");
    if (bytes[0] != 0xff || bytes[1] != 0xd8) file.fail("it is not a JPEG file (no start-of-image marker FF D8)");
    const std::vector<unsigned char> rest = file.rest();
    bytes.insert(bytes.end(), rest.begin(), rest.end());
    // The markers up to the first scan: each segment's length must fit in the file.
    std::size_t at = 2;
    bool frame = false, huffman = false, quantization = false;
    while (true) {
        if (at + 4 > bytes.size()) file.fail("it is truncated (no scan before byte " + std::to_string(bytes.size()) + ")");
        if (bytes[at] != 0xff) file.fail("it is corrupt (byte " + std::to_string(at) + " is not a marker)");
        const unsigned marker = bytes[at + 1];
        if (marker == 0xff) { // fill byte
            ++at;
            continue;
        }
        const std::size_t length = std::size_t(bytes[at + 2]) << 8 | bytes[at + 3];
        if (length < 2 || at + 2 + length > bytes.size())
            file.fail("it is truncated (the segment at byte " + std::to_string(at) + " claims " + std::to_string(length) + " bytes)");
        if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc) {
            if (marker != 0xc0 && marker != 0xc1)
                file.fail(marker == 0xc2 ? std::string("it is a progressive JPEG (save it as baseline, or as PNG)")
                                         : "its frame type (marker FF " + std::to_string(marker) + ") is not baseline");
            if (length < 8) file.fail("its frame header is " + std::to_string(length) + " bytes long (at least 8)");
            const std::uint32_t height = std::uint32_t(bytes[at + 5]) << 8 | bytes[at + 6], width = std::uint32_t(bytes[at + 7]) << 8 | bytes[at + 8];
            if (width == 0 || height == 0) file.fail("its frame header says " + std::to_string(width) + " x " + std::to_string(height) + " pixels");
            if (double(width) * double(height) > 256.0 * double(bytes.size()) + 65536.0)
                file.fail("its frame header says " + std::to_string(width) + " x " + std::to_string(height) + " pixels, more than its " +
                          std::to_string(bytes.size()) + " bytes can hold");
            file.check_pixels(width, height, "its frame header");
            frame = true;
        }
        huffman = huffman || marker == 0xc4;
        quantization = quantization || marker == 0xdb;
        if (marker == 0xda) {
            if (!frame) file.fail("its scan comes before a frame header");
            // stb_image would decode with tables it never filled (a motion-JPEG frame
            // that relies on the standard's tables has none).
            if (!huffman) file.fail("it has no Huffman table (a DHT segment) before its scan");
            if (!quantization) file.fail("it has no quantization table (a DQT segment) before its scan");
            break;
        }
        at += 2 + length;
    }
    return detail::stb_decode8(bytes, file);
} catch (const allocation_error&) {
    throw;
} catch (const std::bad_alloc&) {
    throw detail::out_of_memory(path, "image");
}

/// Read a baseline JPEG (read_jpeg_bytes) into linear radiance, undoing sRGB.
[[nodiscard]] inline Film read_jpeg(const std::filesystem::path& path, ReadLimits limits = {}) { return detail::to_film(read_jpeg_bytes(path, limits), true); }

/// Read a Radiance HDR file (RGBE, "#?RADIANCE" or "#?RGBE", FORMAT=32-bit_rle_rgbe, rows
/// from the top: "-Y height +X width") into linear radiance, through stb_image. The file is
/// read no further than `limits`; its header must be text of at most 1024 lines of at most
/// 1023 bytes, and its rows are walked before stb_image allocates the picture: each must be
/// there whole, every run and dump inside its row, and nothing may follow the last.
[[nodiscard]] inline Film read_hdr(const std::filesystem::path& path, ReadLimits limits = {})
try {
    detail::InputFile file(path, "image", limits);
    // The first line alone, so that what is no HDR (/dev/zero) is refused before the rest is read.
    std::string magic;
    for (int c = file.get(); c != '\n'; c = file.get()) {
        if (c < 0 || magic.size() == 11) file.fail("it is not a Radiance HDR file (its first line is not #?RADIANCE or #?RGBE)");
        magic.push_back(char(c));
    }
    if (!magic.empty() && magic.back() == '\r') magic.pop_back();
    if (magic != "#?RADIANCE" && magic != "#?RGBE") file.fail("it is not a Radiance HDR file (its first line is not #?RADIANCE or #?RGBE)");
    std::vector<unsigned char> bytes(magic.begin(), magic.end());
    bytes.push_back('\n');
    const std::vector<unsigned char> rest = file.rest();
    bytes.insert(bytes.end(), rest.begin(), rest.end());
    std::size_t at = magic.size() + 1;
    std::size_t number = 1;
    const auto next_line = [&](const std::string& what) {
        ++number;
        const std::string name = what + " (line " + std::to_string(number) + ")";
        std::string text;
        for (;; ++at) {
            if (at == bytes.size()) file.fail("it ends inside " + name);
            const unsigned char c = bytes[at];
            if (c == '\n') break;
            if (c == 0) file.fail(name + " holds a NUL byte: it is not text");
            if (text.size() == 1023) file.fail(name + " is longer than 1023 bytes");
            text.push_back(char(c));
        }
        ++at;
        return text;
    };
    bool format = false;
    for (;;) {
        if (number == 1024) file.fail("its header has more than 1024 lines");
        const std::string line = next_line("its header");
        if (line.empty()) break;
        if (line.rfind("FORMAT=", 0) == 0) {
            if (line != "FORMAT=32-bit_rle_rgbe") file.fail("its " + detail::printable(line) + " (line " + std::to_string(number) + ") is not FORMAT=32-bit_rle_rgbe, the only format read");
            format = true;
        }
    }
    if (!format) file.fail("its header has no FORMAT=32-bit_rle_rgbe line");
    const std::string size = next_line("its size line");
    const auto number_at = [&](std::size_t from, std::size_t to) {
        const std::string text = size.substr(from, to - from);
        if (text.empty() || text.size() > 8 || text.find_first_not_of("0123456789") != std::string::npos || std::stol(text) < 1 ||
            std::stol(text) > (1l << 24))
            file.fail("its size line '" + detail::printable(size) + "' is not \"-Y height +X width\" with each side from 1 to 16777216");
        return std::uint64_t(std::stol(text));
    };
    const std::size_t plus = size.find(" +X ");
    if (size.rfind("-Y ", 0) != 0 || plus == std::string::npos)
        file.fail("its size line '" + detail::printable(size) + "' is not \"-Y height +X width\" (rows from the top, the only order read)");
    const std::uint64_t height = number_at(3, plus), width = number_at(plus + 4, size.size());
    // Walk the rows as stb_image will read them, so that the pixels it allocates are
    // paid for in bytes and nothing follows the last row: run-length encoded rows (8 to
    // 32767 pixels wide, each starting 2 2 and its width) hold each channel as runs (a
    // count above 128 and one value) and dumps (a count and that many values); any other
    // file is flat, 4 bytes a pixel.
    const auto byte = [&](std::uint64_t row) {
        if (at == bytes.size()) file.fail("it is truncated in row " + std::to_string(row) + " of " + std::to_string(height));
        return bytes[at++];
    };
    const bool encoded = width >= 8 && width < 32768 && bytes.size() - at >= 4 && bytes[at] == 2 && bytes[at + 1] == 2 && (bytes[at + 2] & 0x80) == 0;
    if (!encoded) {
        const auto flat = detail::checked_product(width * height, 4);
        if (!flat || *flat > bytes.size() - at)
            file.fail("its size line says " + std::to_string(width) + " x " + std::to_string(height) + " pixels, more than the " +
                      std::to_string(bytes.size() - at) + " bytes after it hold (4 a pixel)");
        at += std::size_t(*flat);
    }
    for (std::uint64_t row = 0; encoded && row < height; ++row) {
        const unsigned char a = byte(row), b = byte(row), c = byte(row), d = byte(row);
        if (a != 2 || b != 2 || (std::uint64_t(c) << 8 | d) != width)
            file.fail("row " + std::to_string(row) + " does not start as a run-length encoded row of " + std::to_string(width) + " pixels");
        for (int channel = 0; channel < 4; ++channel)
            for (std::uint64_t done = 0; done < width;) {
                std::uint64_t count = byte(row);
                const bool run = count > 128;
                if (run) count -= 128;
                if (count == 0 || count > width - done)
                    file.fail("row " + std::to_string(row) + " has a " + (run ? "run" : "dump") + " of " + std::to_string(count) + " values where " +
                              std::to_string(width - done) + " are left");
                for (std::uint64_t i = 0; i < (run ? 1 : count); ++i) (void)byte(row);
                done += count;
            }
    }
    if (at != bytes.size()) file.fail(std::to_string(bytes.size() - at) + " bytes follow its last row");
    int w = 0, h = 0, channels = 0;
    file.check_pixels(width, height, "its size line");
    float* data = stbi_loadf_from_memory(bytes.data(), int(std::min<std::size_t>(bytes.size(), INT32_MAX)), &w, &h, &channels, 3);
    if (data == nullptr) {
        const char* reason = stbi_failure_reason();
        file.fail(std::string("it is truncated or corrupt (stb_image: ") + (reason != nullptr && *reason != 0 ? reason : "no reason given") + ")");
    }
    struct Free {
        float* data;
        ~Free() { stbi_image_free(data); }
    } owner{data};
    if (std::uint64_t(w) != width || std::uint64_t(h) != height)
        file.fail("stb_image read " + std::to_string(w) + " x " + std::to_string(h) + " pixels where its size line says " + std::to_string(width) + " x " +
                  std::to_string(height));
    Film film(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* p = data + 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
            film.set(x, y, Rgb<float>{p[0], p[1], p[2]});
        }
    return film;
} catch (const allocation_error&) {
    throw;
} catch (const std::bad_alloc&) {
    throw detail::out_of_memory(path, "image");
}

/// A PFM file's pixels as they are stored: any float, negative, NaN and infinite included
/// (PFM is a data format), row by row from the top, `channels` floats a pixel.
struct PfmImage {
    int width = 0;             ///< pixels a row
    int height = 0;            ///< rows
    int channels = 0;          ///< 3 (PF) or 1 (Pf, grey)
    double scale = -1;         ///< the header's scale: its sign is the byte order (negative: little endian), its size is kept, not applied
    std::vector<float> values; ///< width x height x channels, row by row from the top

    /// Channel c of pixel (x, y), from the top left.
    [[nodiscard]] float at(int x, int y, int c) const noexcept
    {
        return values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) + std::size_t(c)];
    }

    /// The pixels as radiance (a grey image's value in every channel). Throws
    /// std::runtime_error naming the first pixel that is negative, NaN or infinite, which a
    /// Film cannot hold.
    [[nodiscard]] Film film() const
    {
        Film out(width, height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                Rgb<float> p;
                for (int c = 0; c < 3; ++c) {
                    p[c] = at(x, y, channels == 3 ? c : 0);
                    if (!(std::isfinite(p[c]) && p[c] >= 0))
                        throw std::runtime_error("prism: PFM pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") holds " + std::to_string(p[c]) +
                                                 ", which radiance cannot be (a Film holds finite values >= 0)");
                }
                out.set(x, y, p);
            }
        return out;
    }
};

/// Read a PFM file (PF: RGB, Pf: grey; either byte order; lines ending in "\n" or "\r\n"),
/// keeping every value as it is stored. The header is read a byte at a time and no longer
/// than 64 bytes a field; the pixels it claims are checked against a regular file's size
/// before anything is allocated, and a stream's (a FIFO's) are taken as they arrive; a file
/// with bytes past its pixels is refused.
[[nodiscard]] inline PfmImage read_pfm(const std::filesystem::path& path, ReadLimits limits = {})
try {
    detail::InputFile file(path, "image", limits);
    PfmImage image;
    const int p = file.get(), f = file.get();
    if (p != 'P' || (f != 'F' && f != 'f')) file.fail("it is not a PFM file (it does not start with PF or Pf)");
    image.channels = f == 'F' ? 3 : 1;
    // Fields separated by white space; the scale ends with one line end ("\n" or "\r\n").
    const auto space = [](int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    int last = file.get();
    if (!space(last)) file.fail("its magic PF or Pf is not followed by white space");
    const auto field = [&](const char* name) {
        int c = file.get();
        while (space(c)) c = file.get();
        std::string text;
        for (; c >= 0 && !space(c); c = file.get()) {
            if (text.size() == 64) file.fail(std::string("its header's ") + name + " is longer than 64 bytes");
            text.push_back(char(c));
        }
        if (text.empty()) file.fail(std::string("its header ends before its ") + name);
        last = c;
        return text;
    };
    const auto dimension = [&](const char* name) {
        const std::string text = field(name);
        if (text.find_first_not_of("0123456789") != std::string::npos || text.size() > 10 || std::stoll(text) < 1 || std::stoll(text) > INT32_MAX)
            file.fail(std::string("its ") + name + " '" + text + "' is not a whole number from 1 to 2147483647");
        return int(std::stoll(text));
    };
    image.width = dimension("width");
    image.height = dimension("height");
    const std::string scale = field("scale");
    char* end = nullptr;
    image.scale = std::strtod(scale.c_str(), &end);
    if (end != scale.c_str() + scale.size() || !std::isfinite(image.scale) || image.scale == 0)
        file.fail("its scale '" + scale + "' is not a finite, non-zero number");
    if (last == '\r' && file.get() != '\n') file.fail("its scale's line ends in \\r without \\n");
    const auto floats = detail::checked_product(std::uint64_t(image.width) * std::uint64_t(image.height), std::uint64_t(image.channels));
    const auto bytes = floats ? detail::checked_product(*floats, 4) : std::nullopt;
    if (!bytes) file.fail("its header says " + std::to_string(image.width) + " x " + std::to_string(image.height) + " pixels, more bytes than a file can hold");
    std::vector<unsigned char> raw;
    file.read(raw, *bytes, "the header's " + std::to_string(image.width) + " x " + std::to_string(image.height) + " pixels");
    if (!file.at_end()) file.fail("bytes follow its " + std::to_string(image.width) + " x " + std::to_string(image.height) + " pixels");
    // Stored bottom row first.
    image.values.resize(std::size_t(*floats));
    const bool swap = (image.scale < 0) != (std::endian::native == std::endian::little);
    const std::size_t row = std::size_t(image.width) * std::size_t(image.channels);
    for (std::size_t y = 0; y < std::size_t(image.height); ++y)
        for (std::size_t i = 0; i < row; ++i) {
            unsigned char* b = raw.data() + 4 * ((std::size_t(image.height) - 1 - y) * row + i);
            if (swap) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
            std::memcpy(&image.values[y * row + i], b, 4);
        }
    return image;
} catch (const allocation_error&) {
    throw;
} catch (const std::bad_alloc&) {
    throw detail::out_of_memory(path, "image");
}

} // namespace prism
