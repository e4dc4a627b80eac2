// SPDX-License-Identifier: MIT
// Reading files nobody here wrote: a file opened for a reader that trusts none of its bytes.
// It knows a regular file's size (so a header's claims can be checked against it before
// anything is allocated), reads a stream whose size it cannot know (a FIFO, a device) no
// further than a limit, grows what it reads into only as bytes arrive, and reads a line no
// longer than its caller allows, so that an endless stream such as /dev/zero is refused
// after a bounded amount of work and memory. Every failure names the file and the reason.
#pragma once

#include <prism/core/check.hpp>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace prism {

/// What a reader accepts at most from one file: its bytes, a guard against endless streams
/// checked before reading when the file's size is known and as bytes arrive otherwise; and
/// a compressed image's pixels (PNG, JPEG, HDR), checked against its header before
/// anything is decoded: deflate expands up to 1032 times, and a 1-bit PNG of 2 KB decodes
/// to 16 million pixels, 800 MB as a float texture. (A PFM's pixels are its bytes.)
struct ReadLimits {
    std::uint64_t max_bytes = std::uint64_t(1) << 32;  ///< 4 GiB
    std::uint64_t max_pixels = std::uint64_t(1) << 26; ///< 67 million (8192 x 8192): 800 MB as floats, 3.2 GB through a texture
};

namespace detail {

/// Throws std::runtime_error: "prism: cannot read <what> '<path>': <reason>" (a reader's
/// refusal; io/output.hpp's throw_io is a writer's).
[[noreturn]] inline void throw_read(const std::filesystem::path& path, const std::string& what, const std::string& reason)
{
    throw std::runtime_error("prism: cannot read " + what + " '" + path.string() + "': " + reason);
}

/// Text from a file as a message quotes it: a control character written out (\r, \t,
/// \xNN), so that a carriage return cannot hide the message's start on a terminal.
[[nodiscard]] inline std::string printable(const std::string& text)
{
    std::string out;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else if (byte < 0x20 || byte == 0x7f) {
            static constexpr char digits[] = "0123456789abcdef";
            out += "\\x";
            out += digits[byte >> 4];
            out += digits[byte & 15];
        } else out += c;
    }
    return out;
}

/// a * b, or nothing when it does not fit in 64 bits.
[[nodiscard]] constexpr std::optional<std::uint64_t> checked_product(std::uint64_t a, std::uint64_t b) noexcept
{
    if (a != 0 && b > UINT64_MAX / a) return std::nullopt;
    return a * b;
}

/// A file opened for reading by a reader that checks every claim its bytes make.
class InputFile {
public:
    /// Opens `path`; `what` names the kind of file in messages ("image", "mesh").
    InputFile(const std::filesystem::path& path, std::string what, ReadLimits limits = {})
        : path_(path), what_(std::move(what)), limits_(limits)
    {
        std::error_code error;
        const auto status = std::filesystem::status(path, error);
        if (error) fail(error.message());
        if (status.type() == std::filesystem::file_type::directory) fail("it is a directory");
        if (status.type() == std::filesystem::file_type::regular) {
            size_ = std::filesystem::file_size(path, error);
            if (error) fail(error.message());
        }
        in_.open(path, std::ios::binary);
        if (!in_) fail(std::strerror(errno));
    }

    /// The file's size in bytes, when it is a regular file.
    [[nodiscard]] const std::optional<std::uint64_t>& size() const noexcept { return size_; }
    /// The bytes read so far.
    [[nodiscard]] std::uint64_t position() const noexcept { return position_; }
    /// The path, as given.
    [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }

    /// The next byte, or -1 at the end of the file.
    [[nodiscard]] int get()
    {
        const int c = in_.get();
        if (c == std::char_traits<char>::eof()) return -1;
        if (++position_ > limits_.max_bytes) fail("it is longer than the limit of " + std::to_string(limits_.max_bytes) + " bytes");
        return c;
    }

    /// Whether the file has no more bytes.
    [[nodiscard]] bool at_end() { return in_.peek() == std::char_traits<char>::eof(); }

    /// The next line without its end ("\n" or "\r\n"); nothing at the end of the file. A
    /// line longer than `max` bytes, or holding a NUL byte, is refused: `what` names it.
    [[nodiscard]] std::optional<std::string> line(std::size_t max, const std::string& what)
    {
        std::string text;
        int c = get();
        if (c < 0) return std::nullopt;
        for (; c >= 0 && c != '\n'; c = get()) {
            if (c == 0) fail(what + " holds a NUL byte: it is not text");
            if (text.size() == max) fail(what + " is longer than " + std::to_string(max) + " bytes");
            text.push_back(char(c));
        }
        if (!text.empty() && text.back() == '\r') text.pop_back();
        return text;
    }

    /// Append the next `count` bytes to `out`. The claim is checked against what a regular
    /// file still holds before anything is allocated; a stream's bytes are taken as they
    /// arrive, a MiB at a time. `what` names the bytes in the message when they are not there.
    void read(std::vector<unsigned char>& out, std::uint64_t count, const std::string& what)
    {
        if (size_ && count > (*size_ > position_ ? *size_ - position_ : 0))
            fail(what + " needs " + std::to_string(count) + " bytes, but " + std::to_string(*size_ - position_) + " follow: the file is truncated");
        if (count > limits_.max_bytes - position_) fail(what + " needs " + std::to_string(count) + " bytes, more than the limit of " + std::to_string(limits_.max_bytes));
        const std::uint64_t chunk = std::uint64_t(1) << 20;
        for (std::uint64_t done = 0; done < count;) {
            const std::uint64_t n = count - done < chunk ? count - done : chunk;
            const std::size_t at = out.size();
            grow(out, at + std::size_t(n), what);
            in_.read(reinterpret_cast<char*>(out.data() + at), std::streamsize(n));
            const auto got = std::uint64_t(in_.gcount());
            position_ += got;
            done += got;
            if (got < n)
                fail(what + " needs " + std::to_string(count) + " bytes, but the file ends after " + std::to_string(done) + ": it is truncated");
        }
    }

    /// Every byte left, for a format whose header says nothing of its length: a regular
    /// file's size is checked against the limit first, a stream is read until it ends or
    /// passes the limit.
    [[nodiscard]] std::vector<unsigned char> rest()
    {
        std::vector<unsigned char> out;
        if (size_) {
            read(out, *size_ - position_, "the file");
            return out;
        }
        const std::uint64_t chunk = std::uint64_t(1) << 20;
        for (;;) {
            const std::size_t at = out.size();
            if (position_ + chunk > limits_.max_bytes + 1)
                fail("it is longer than the limit of " + std::to_string(limits_.max_bytes) + " bytes");
            grow(out, at + std::size_t(chunk), "the file");
            in_.read(reinterpret_cast<char*>(out.data() + at), std::streamsize(chunk));
            const auto got = std::uint64_t(in_.gcount());
            position_ += got;
            out.resize(at + std::size_t(got));
            if (position_ > limits_.max_bytes) fail("it is longer than the limit of " + std::to_string(limits_.max_bytes) + " bytes");
            if (got < chunk) return out;
        }
    }

    /// Fails unless `width` x `height` pixels, as `source` gives them, are within the
    /// limit on pixels (ReadLimits::max_pixels).
    void check_pixels(std::uint64_t width, std::uint64_t height, const std::string& source) const
    {
        const auto pixels = checked_product(width, height);
        if (!pixels || *pixels > limits_.max_pixels)
            fail(source + " says " + std::to_string(width) + " x " + std::to_string(height) + " pixels, more than the limit of " +
                 std::to_string(limits_.max_pixels) + " (ReadLimits::max_pixels)");
    }

    /// Throws std::runtime_error: "cannot read <what> '<path>': <reason>".
    [[noreturn]] void fail(const std::string& reason) const { throw_read(path_, what_, reason); }

private:
    /// out.resize(size), or a message naming the file and what was being read when the
    /// memory cannot be had (not a bare std::bad_alloc).
    void grow(std::vector<unsigned char>& out, std::size_t size, const std::string& what) const
    {
        try {
            out.resize(size);
        } catch (const std::bad_alloc&) {
            throw allocation_error("prism: cannot read " + what_ + " '" + path_.string() + "': " + what + " needs " + describe_bytes(double(size)) +
                                   ", which could not be allocated");
        }
    }

    std::filesystem::path path_;
    std::string what_;
    ReadLimits limits_;
    std::ifstream in_;
    std::optional<std::uint64_t> size_;
    std::uint64_t position_ = 0;
};

/// The error for a reader that ran out of memory: its file and what it is, instead of a
/// bare std::bad_alloc (an allocation_error thrown with its own numbers passes as it is).
[[nodiscard]] inline allocation_error out_of_memory(const std::filesystem::path& path, const std::string& what)
{
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    return allocation_error("prism: cannot read " + what + " '" + path.string() + "': out of memory while reading it" +
                            (error ? std::string() : " (a file of " + describe_bytes(double(size)) + ")"));
}

} // namespace detail

} // namespace prism
