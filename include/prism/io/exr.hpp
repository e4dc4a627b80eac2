// SPDX-License-Identifier: MIT
// OpenEXR files: float layers over a data window inside the display window, string
// metadata, and a render's exact sums, so that the parts of a render split across
// machines can be read back and added up to the whole render's bits.
//
// Opt-in: prism/prism.hpp does not include this header, since it needs OpenEXR
// (Debian: libopenexr-dev; CMake: prism::exr_io). Files are written as image.hpp writes
// PNG: whole or not at all over a regular file, through a device or FIFO, any failure a
// std::runtime_error naming the path. Layers are named as EXR's convention has them,
// "layer.channel" ("albedo.R"); R, G and B are the image itself.
//
// An Accumulation is stored as the mean of each of its channels (FLOAT, for any EXR
// viewer) and, for a part to be added to others, its exact sums: a channel's 128 bits
// as four UINT channels "sum.<channel>.0" (lowest word) to ".3", and the pixel's 64-bit
// weight as "weight.0" and "weight.1".
#pragma once

#include <prism/io/image.hpp>
#include <prism/io/input.hpp>
#include <prism/render/accumulation.hpp>
#include <prism/render/film.hpp>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

namespace prism {

/// What ExrImage::film does with a negative value: refuse the image, or store 0 and count it.
enum class NegativeValues { refuse, to_zero };

/// One channel of an ExrImage: its values over the data window, row by row from the top.
struct ExrChannel {
    std::string name; ///< the channel's name: R, G, B, A, albedo.R, ...
    std::variant<std::vector<float>, std::vector<std::uint32_t>> values; ///< its values: FLOAT or UINT
};

/// An EXR file as prism writes and reads it: FLOAT and UINT channels over `window` (the
/// data window) of a width x height image (the display window), and string attributes.
struct ExrImage {
    int width = 0;  ///< the display window's width
    int height = 0; ///< the display window's height
    PixelWindow window{}; ///< the data window, inside the display window
    std::vector<ExrChannel> channels; ///< the channels, in the file's order
    std::map<std::string, std::string> attributes; ///< string attributes (prism.settings and the rest)

    /// The channel named `name`, or nullptr.
    [[nodiscard]] const ExrChannel* find(const std::string& name) const noexcept
    {
        for (const ExrChannel& c : channels)
            if (c.name == name) return &c;
        return nullptr;
    }

    /// The image as radiance: its R, G and B channels, or a grey Y in all three, over a
    /// data window that covers the whole image. Throws std::runtime_error naming what is
    /// missing, or the first pixel and channel that is NaN or infinite, or negative unless
    /// `negatives` is NegativeValues::to_zero: then each negative value is stored as 0 and
    /// counted in the film's rejected() (lossy EXR compression, DWA, leaves values a little
    /// below 0 in images that had none).
    [[nodiscard]] Film film(NegativeValues negatives = NegativeValues::refuse) const
    {
        if (window != PixelWindow::whole(width, height))
            throw std::runtime_error("prism: the EXR image's data window does not cover its " + std::to_string(width) + " x " + std::to_string(height) +
                                     " pixels, so it is no whole picture");
        const auto floats = [&](const std::string& name) -> const std::vector<float>* {
            const ExrChannel* c = find(name);
            if (c == nullptr) return nullptr;
            if (!std::holds_alternative<std::vector<float>>(c->values))
                throw std::runtime_error("prism: the EXR image's channel '" + name + "' holds whole numbers (UINT), not radiance");
            return &std::get<0>(c->values);
        };
        const std::vector<float>* rgb[3] = {floats("R"), floats("G"), floats("B")};
        if (rgb[0] == nullptr || rgb[1] == nullptr || rgb[2] == nullptr) {
            const std::vector<float>* grey = floats("Y");
            if (grey == nullptr) throw std::runtime_error("prism: the EXR image has neither R, G and B channels nor a grey Y channel");
            rgb[0] = rgb[1] = rgb[2] = grey;
        }
        Film out(width, height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
                Rgb<float> p;
                for (int c = 0; c < 3; ++c) {
                    p[c] = (*rgb[c])[i];
                    if (!std::isfinite(p[c]) || (p[c] < 0 && negatives == NegativeValues::refuse))
                        throw std::runtime_error("prism: EXR pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") holds " + std::to_string(p[c]) + " in " +
                                                 "RGB"[c] + ", which radiance cannot be (a Film holds finite values >= 0" +
                                                 (p[c] < 0 ? "; film(NegativeValues::to_zero) stores negatives as 0 and counts them)" : ")"));
                }
                out.set(x, y, p);
            }
        return out;
    }
};

namespace detail {

/// OpenEXR's output into memory, so the file can then be written whole or not at all.
class ExrMemoryStream final : public Imf::OStream {
public:
    ExrMemoryStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override
    {
        if (position_ + std::size_t(n) > bytes.size()) bytes.resize(position_ + std::size_t(n));
        std::memcpy(bytes.data() + position_, c, std::size_t(n));
        position_ += std::size_t(n);
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = std::size_t(position); }

    std::vector<unsigned char> bytes;

private:
    std::size_t position_ = 0;
};

[[nodiscard]] inline Imath::Box2i exr_box(const PixelWindow& w) { return {{w.x0, w.y0}, {w.x1 - 1, w.y1 - 1}}; }

/// The Slice OpenEXR reads or writes a channel's values through.
template <class Value>
[[nodiscard]] Imf::Slice exr_slice(Value* values, const PixelWindow& w)
{
    constexpr Imf::PixelType type = std::is_same_v<std::remove_const_t<Value>, float> ? Imf::FLOAT : Imf::UINT;
    return Imf::Slice::Make(type, const_cast<std::remove_const_t<Value>*>(values), exr_box(w), sizeof(Value), sizeof(Value) * std::size_t(w.width()));
}

} // namespace detail

namespace detail {

/// `image` as the bytes of an EXR file (ZIP-compressed scan lines); `path` names it in messages.
[[nodiscard]] inline std::vector<unsigned char> exr_bytes(const ExrImage& image, const std::filesystem::path& path)
{
    if (image.width <= 0 || image.height <= 0)
        detail::throw_io(path, "the image size must be positive, got " + std::to_string(image.width) + " x " + std::to_string(image.height));
    if (image.window.empty() || !PixelWindow::whole(image.width, image.height).contains(image.window))
        detail::throw_io(path, "the data window must be a non-empty part of the image");
    if (image.channels.empty()) detail::throw_io(path, "an image needs a channel");
    std::vector<unsigned char> bytes;
    try {
        Imf::Header header(detail::exr_box(PixelWindow::whole(image.width, image.height)), detail::exr_box(image.window));
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const auto& [name, value] : image.attributes) header.insert(name, Imf::StringAttribute(value));
        Imf::FrameBuffer frame;
        for (const ExrChannel& c : image.channels) {
            if (header.channels().findChannel(c.name) != nullptr) detail::throw_io(path, "two channels named '" + c.name + "'");
            const bool floats = std::holds_alternative<std::vector<float>>(c.values);
            const std::size_t count = floats ? std::get<0>(c.values).size() : std::get<1>(c.values).size();
            if (count != image.window.area())
                detail::throw_io(path, "channel '" + c.name + "' has " + std::to_string(count) + " values for " + std::to_string(image.window.area()) + " pixels");
            header.channels().insert(c.name, Imf::Channel(floats ? Imf::FLOAT : Imf::UINT));
            frame.insert(c.name, floats ? detail::exr_slice(std::get<0>(c.values).data(), image.window)
                                        : detail::exr_slice(std::get<1>(c.values).data(), image.window));
        }
        detail::ExrMemoryStream stream;
        {
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(image.window.height());
        }
        bytes = std::move(stream.bytes);
    } catch (const std::runtime_error&) {
        throw;
    } catch (const std::exception& e) {
        detail::throw_io(path, std::string("OpenEXR: ") + e.what());
    }
    return bytes;
}

} // namespace detail

/// `image` as the bytes of an EXR file (ZIP-compressed scan lines), for an OutputSet.
[[nodiscard]] inline std::vector<unsigned char> encode_exr(const ExrImage& image) { return detail::exr_bytes(image, "an EXR image"); }

/// Write `image` as an EXR file (ZIP-compressed scan lines).
inline void write_exr(const ExrImage& image, const std::filesystem::path& path) { detail::write_file_atomically(path, detail::exr_bytes(image, path)); }

namespace detail {

/// The bytes OpenEXR 3 reads for an attribute of a fixed-size type, whatever the size the
/// file declares; 0 for a type it reads by the declared size or by its own structure.
inline std::uint64_t exr_fixed_size(const std::string& type)
{
    static const std::map<std::string, std::uint64_t> sizes{
        {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"double", 8}, {"envmap", 1}, {"float", 4}, {"int", 4},
        {"keycode", 28}, {"lineOrder", 1}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"rational", 8}, {"tiledesc", 9},
        {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24}, {"deepImageState", 1}};
    const auto found = sizes.find(type);
    return found == sizes.end() ? 0 : found->second;
}

/// Walk an EXR file's header(s) as OpenEXR 3 will read them, before it does: names and
/// types at most 255 bytes, fixed-size attributes their type's size, a channel list by its
/// structure, a preview's pixels and every other attribute's declared size no more than
/// the bytes left in the file. OpenEXR allocates an attribute's declared size before it
/// reads it, so without this a few bytes could make it allocate 2 GB. Throws
/// std::runtime_error naming the attribute.
inline void check_exr_headers(const std::filesystem::path& path)
{
    InputFile file(path, "image");
    std::vector<unsigned char> scratch;
    const auto bytes = [&](std::uint64_t n, const std::string& what) {
        scratch.clear();
        file.read(scratch, n, what);
        return scratch;
    };
    const auto le32 = [](const std::vector<unsigned char>& b, std::size_t at) {
        return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 | std::uint32_t(b[at + 3]) << 24;
    };
    const std::vector<unsigned char> start = bytes(8, "an EXR magic number and version");
    if (!(start[0] == 0x76 && start[1] == 0x2f && start[2] == 0x31 && start[3] == 0x01)) file.fail("it is not an OpenEXR file (no magic number)");
    const bool multipart = (start[5] & 0x10) != 0;
    const auto text = [&](const std::string& what) {
        std::string word;
        for (int c = file.get(); c != 0; c = file.get()) {
            if (c < 0) file.fail("its header ends inside " + what);
            if (word.size() == 255) file.fail(what + " is longer than 255 bytes");
            word.push_back(char(c));
        }
        return word;
    };
    // What OpenEXR allocates in proportion to the header (its line or tile buffers), against
    // what the file can hold: no EXR compression expands more than deflate's 1032 times.
    const double most = 1032.0 * double(file.size().value_or(0)) + double(1 << 20);
    const auto check_claim = [&](double values, const std::string& what) {
        if (4.0 * values > most)
            file.fail(what + " needs " + describe_bytes(4.0 * values) + ", more than its " + std::to_string(file.size().value_or(0)) + " bytes can hold compressed");
    };
    for (int headers = 0;; ++headers) {
        bool empty = true;
        double channels = 0;
        std::optional<std::array<std::int32_t, 4>> window;
        std::optional<std::array<std::uint32_t, 2>> tile;
        for (;;) {
            const std::string name = text("an attribute's name");
            if (name.empty()) break;
            empty = false;
            const std::string type = text("attribute '" + name + "''s type");
            const std::int32_t size = std::int32_t(le32(bytes(4, "the size of attribute '" + name + "'"), 0));
            if (size < 0) file.fail("its attribute '" + name + "' has a size of " + std::to_string(size) + " bytes");
            const std::string what = "its attribute '" + name + "' (" + type + ")";
            if (const std::uint64_t fixed = exr_fixed_size(type)) {
                const std::vector<unsigned char> value = bytes(fixed, what);
                if (name == "dataWindow" && type == "box2i")
                    window = {std::int32_t(le32(value, 0)), std::int32_t(le32(value, 4)), std::int32_t(le32(value, 8)), std::int32_t(le32(value, 12))};
                if (type == "tiledesc") tile = {le32(value, 0), le32(value, 4)};
            } else if (type == "chlist") {
                for (int count = 0; !text("a channel's name in '" + name + "'").empty(); ++count) {
                    if (count == 1 << 16) file.fail(what + " lists more than 65536 channels");
                    (void)bytes(16, what);
                    if (name == "channels") ++channels;
                }
            } else if (type == "preview") {
                const std::vector<unsigned char> extent = bytes(8, what);
                const std::uint64_t pixels = std::uint64_t(le32(extent, 0)) * std::uint64_t(le32(extent, 4));
                (void)bytes(4 * pixels, what + "'s preview pixels");
            } else {
                (void)bytes(std::uint64_t(size), what);
            }
        }
        if (window)
            check_claim((double((*window)[2]) - double((*window)[0]) + 1) * (double((*window)[3]) - double((*window)[1]) + 1) * channels,
                        "its data window [" + std::to_string((*window)[0]) + ", " + std::to_string((*window)[2]) + "] x [" + std::to_string((*window)[1]) + ", " +
                            std::to_string((*window)[3]) + "] of " + std::to_string(int(channels)) + " channels");
        if (tile) check_claim(double((*tile)[0]) * double((*tile)[1]) * channels, "its tiles of " + std::to_string((*tile)[0]) + " x " + std::to_string((*tile)[1]) + " pixels");
        if (!multipart || empty) return;
        if (headers == 1 << 16) file.fail("it has more than 65536 parts");
    }
}

} // namespace detail

/// Read an EXR file: its FLOAT and HALF channels as float, its UINT channels as they
/// are, and its string attributes. Its headers are walked first (no attribute larger than
/// the bytes left in the file), and the data window's size is checked against the file's
/// before anything is allocated (no EXR compression expands more than 1032 times).
[[nodiscard]] inline ExrImage read_exr(const std::filesystem::path& path)
{
    detail::check_exr_headers(path);
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i display = header.displayWindow(), data = header.dataWindow();
        ExrImage image;
        if (display.min.x != 0 || display.min.y != 0)
            throw std::runtime_error("the display window starts at (" + std::to_string(display.min.x) + ", " + std::to_string(display.min.y) +
                                     "), not (0, 0)");
        image.width = display.max.x + 1;
        image.height = display.max.y + 1;
        image.window = {data.min.x, data.min.y, data.max.x + 1, data.max.y + 1};
        if (image.window.empty() || !PixelWindow::whole(image.width, image.height).contains(image.window))
            throw std::runtime_error("the data window is not inside the display window");
        for (auto a = header.begin(); a != header.end(); ++a)
            if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&a.attribute())) image.attributes[a.name()] = text->value();
        Imf::FrameBuffer frame;
        for (auto c = header.channels().begin(); c != header.channels().end(); ++c) {
            if (c.channel().xSampling != 1 || c.channel().ySampling != 1)
                throw std::runtime_error("channel '" + std::string(c.name()) + "' is subsampled");
            ExrChannel& channel = image.channels.emplace_back(ExrChannel{c.name(), {}});
            if (c.channel().type == Imf::UINT) channel.values = std::vector<std::uint32_t>(image.window.area());
            else channel.values = std::vector<float>(image.window.area());
        }
        for (ExrChannel& c : image.channels)
            frame.insert(c.name, std::holds_alternative<std::vector<float>>(c.values) ? detail::exr_slice(std::get<0>(c.values).data(), image.window)
                                                                                      : detail::exr_slice(std::get<1>(c.values).data(), image.window));
        file.setFrameBuffer(frame);
        file.readPixels(data.min.y, data.max.y);
        return image;
    } catch (const std::bad_alloc&) {
        throw detail::out_of_memory(path, "image");
    } catch (const std::exception& e) {
        throw std::runtime_error("prism: cannot read image '" + path.string() + "': " + e.what());
    }
}

/// A film as an EXR image: R, G, B over the whole image.
[[nodiscard]] inline ExrImage to_exr(const Film& film, std::map<std::string, std::string> attributes = {})
{
    ExrImage image{film.width(), film.height(), PixelWindow::whole(film.width(), film.height()), {}, std::move(attributes)};
    for (int c = 0; c < 3; ++c) {
        std::vector<float> values(film.pixels().size());
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = film.pixels()[i][c];
        image.channels.push_back({std::string(1, "RGB"[c]), std::move(values)});
    }
    return image;
}

namespace detail {

/// 64-bit FNV-1a (Fowler, Noll and Vo; the IETF draft draft-eastlake-fnv): each byte
/// XORed into the hash, then the hash multiplied by the FNV prime.
struct Fnv1a {
    std::uint64_t value = 0xcbf29ce484222325u; ///< the hash of what was added so far

    /// Add `size` bytes at `data`.
    void add(const void* data, std::size_t size) noexcept
    {
        for (const unsigned char* b = static_cast<const unsigned char*>(data); size-- > 0; ++b) value = (value ^ *b) * 0x100000001b3u;
    }
};

} // namespace detail

/// A digest of what an image holds: its size and data window, its "prism." string
/// attributes but "prism.part.digest" itself, and each channel's name, type and values,
/// in name order, hashed by 64-bit FNV-1a, as 16 hexadecimal digits. to_exr stores it with a part's exact
/// sums, and prism_merge refuses a part whose contents no longer have it: a part whose
/// metadata (its passes, seed or settings) or sums were changed after it was written, or
/// that was damaged on its way. It is a checksum, not a signature: whoever edits a part
/// on purpose can compute it again.
[[nodiscard]] inline std::string exr_digest(const ExrImage& image)
{
    detail::Fnv1a hash;
    const auto bytes = [&](const void* data, std::size_t size) { hash.add(data, size); };
    const auto number = [&](std::uint64_t n) {
        for (int i = 0; i < 8; ++i) { // little-endian, whatever the machine
            const unsigned char b = static_cast<unsigned char>(n >> (8 * i));
            bytes(&b, 1);
        }
    };
    const auto text = [&](const std::string& s) {
        number(s.size());
        bytes(s.data(), s.size());
    };
    for (const int n : {image.width, image.height, image.window.x0, image.window.x1, image.window.y0, image.window.y1}) number(std::uint64_t(std::int64_t(n)));
    for (const auto& [name, value] : image.attributes) // a std::map: in name order
        if (name.starts_with("prism.") && name != "prism.part.digest") {
            text(name);
            text(value);
        }
    std::vector<const ExrChannel*> channels;
    for (const ExrChannel& c : image.channels) channels.push_back(&c);
    std::sort(channels.begin(), channels.end(), [](const ExrChannel* a, const ExrChannel* b) { return a->name < b->name; });
    for (const ExrChannel* c : channels) {
        text(c->name);
        std::visit(
            [&](const auto& values) {
                number(std::is_same_v<typename std::decay_t<decltype(values)>::value_type, float> ? 2 : 0); // EXR's FLOAT and UINT
                number(values.size());
                for (const auto v : values) number(std::bit_cast<std::uint32_t>(v));
            },
            c->values);
    }
    char digits[17];
    std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(hash.value));
    return digits;
}

/// An Accumulation as an EXR image over its window: each channel's mean (sum / weight,
/// 0 where the weight is 0), and with `exact` the sums and weights themselves, bit for
/// bit, for to_accumulation to add to other parts, and their exr_digest as the attribute
/// "prism.part.digest".
[[nodiscard]] inline ExrImage to_exr(const Accumulation& sums, bool exact, std::map<std::string, std::string> attributes = {})
{
    if (sums.overflowed()) detail::throw_invalid("to_exr: the Accumulation overflowed (its sums are wrong)");
    const PixelWindow& w = sums.window();
    ExrImage image{sums.width(), sums.height(), w, {}, std::move(attributes)};
    const std::size_t n = sums.channels().size();
    for (std::size_t c = 0; c < n; ++c) {
        std::vector<float> mean;
        mean.reserve(w.area());
        for (int y = w.y0; y < w.y1; ++y)
            for (int x = w.x0; x < w.x1; ++x) mean.push_back(detail::mean(sums.sum(x, y, c), sums.weight(x, y)));
        image.channels.push_back({sums.channels()[c], std::move(mean)});
    }
    if (!exact) return image;
    // Each sum's 32-bit words, low first: four, or eight once some sum passed 2^63.
    const int words = sums.wide() ? 8 : 4;
    for (std::size_t c = 0; c < n; ++c)
        for (int word = 0; word < words; ++word) {
            std::vector<std::uint32_t> bits;
            bits.reserve(w.area());
            for (int y = w.y0; y < w.y1; ++y)
                for (int x = w.x0; x < w.x1; ++x) {
                    const ExactSum sum = sums.sum(x, y, c);
                    const Int128 half = word < 4 ? sum.low() : sum.high();
                    bits.push_back(std::uint32_t((word % 4 < 2 ? half.low() : half.high()) >> (32 * (word % 2))));
                }
            image.channels.push_back({"sum." + sums.channels()[c] + "." + std::to_string(word), std::move(bits)});
        }
    for (int word = 0; word < 2; ++word) {
        std::vector<std::uint32_t> bits;
        bits.reserve(w.area());
        for (int y = w.y0; y < w.y1; ++y)
            for (int x = w.x0; x < w.x1; ++x) bits.push_back(std::uint32_t(sums.weight(x, y) >> (32 * word)));
        image.channels.push_back({"weight." + std::to_string(word), std::move(bits)});
    }
    image.attributes["prism.part.digest"] = exr_digest(image);
    return image;
}

/// The exact sums of an image written by to_exr(sums, exact = true), over its data
/// window; `channels` lists what to take (R, G, B first). Throws naming what is missing.
[[nodiscard]] inline Accumulation to_accumulation(const ExrImage& image, std::vector<std::string> channels = {"R", "G", "B"})
{
    const auto words = [&](const std::string& name) -> const std::vector<std::uint32_t>& {
        const ExrChannel* c = image.find(name);
        if (c == nullptr || !std::holds_alternative<std::vector<std::uint32_t>>(c->values))
            detail::throw_invalid("to_accumulation: the image has no UINT channel '", name, "' (it was not written with its exact sums)");
        return std::get<1>(c->values);
    };
    Accumulation sums(image.width, image.height, image.window, channels);
    const PixelWindow& w = image.window;
    const auto& weight_lo = words("weight.0");
    const auto& weight_hi = words("weight.1");
    // Four words a sum, or eight (the upper half's) when the first channel has them.
    const std::size_t per_sum = channels.empty() || image.find("sum." + channels[0] + ".4") == nullptr ? 4 : 8;
    std::vector<const std::vector<std::uint32_t>*> parts;
    for (const std::string& channel : channels)
        for (std::size_t word = 0; word < per_sum; ++word) parts.push_back(&words("sum." + channel + "." + std::to_string(word)));
    std::vector<ExactSum> pixel(channels.size());
    std::size_t i = 0;
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x, ++i) {
            for (std::size_t c = 0; c < channels.size(); ++c) {
                const auto word = [&](std::size_t k) { return std::uint64_t((*parts[c * per_sum + k])[i]); };
                const Int128 low = Int128::from_words(word(1) << 32 | word(0), word(3) << 32 | word(2));
                pixel[c] = per_sum == 4 ? ExactSum::from_bits(low) : ExactSum::from_bits(low, Int128::from_words(word(5) << 32 | word(4), word(7) << 32 | word(6)));
            }
            sums.add(x, y, pixel, (std::uint64_t(weight_hi[i]) << 32) | weight_lo[i]);
        }
    return sums;
}

} // namespace prism
