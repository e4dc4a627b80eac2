// SPDX-License-Identifier: MIT
#include <prism/io/image.hpp>

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <sys/stat.h>
#include <thread>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

prism::Film gradient()
{
    prism::Film film(7, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) film.set(x, y, prism::Rgb<float>{float(x) * 0.1f, float(y) * 0.3f, 1e-3f * float(x * y) + 2.0f});
    return film;
}

/// An empty folder of this test case's own: ctest runs cases in parallel processes.
fs::path scratch_folder(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("prism-io-test-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

} // namespace

TEST_CASE("PFM round-trips every float exactly")
{
    const fs::path dir = scratch_folder("pfm");
    const prism::Film film = gradient();
    prism::write_image(film, dir / "g.pfm");
    const prism::Film back = prism::read_pfm(dir / "g.pfm").film();
    REQUIRE(back.width() == 7);
    REQUIRE(back.height() == 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) CHECK(back.at(x, y) == film.at(x, y));
    fs::remove_all(dir);
}

TEST_CASE("PNG is sRGB-encoded and complete")
{
    const fs::path dir = scratch_folder("png");
    prism::Film film(2, 1);
    film.set(0, 0, prism::Rgb<float>{0.0f, 0.5f, 1.0f});
    film.set(1, 0, prism::Rgb<float>{0.0031308f, 0.2f, 5.0f});
    const auto bytes = prism::to_srgb8(film);
    // IEC 61966-2-1: sRGB(0.5) = 0.7354 -> 188; sRGB(0.0031308) = 0.04045 -> 10;
    // sRGB(0.2) = 0.4848 -> 124; above 1 clamps to 255.
    CHECK(bytes == std::vector<unsigned char>{0, 188, 255, 10, 124, 255});
    prism::write_image(film, dir / "x.png");
    std::ifstream in(dir / "x.png", std::ios::binary);
    const std::vector<unsigned char> file{std::istreambuf_iterator<char>(in), {}};
    REQUIRE(file.size() > 8);
    CHECK(file[1] == 'P');
    CHECK(file[2] == 'N');
    CHECK(file[3] == 'G');
    // Reading it back gives the same 8-bit values.
    CHECK(prism::to_srgb8(prism::read_png(dir / "x.png")) == bytes);
    CHECK_THROWS_WITH_AS((void)prism::read_png(dir / "absent.png"), doctest::Contains("absent.png"), std::runtime_error);
    fs::remove_all(dir);
}

TEST_CASE("a failed write throws with the path and the reason and leaves no file")
{
    const fs::path dir = scratch_folder("failure");
    const prism::Film film = gradient();
    const fs::path missing = dir / "no" / "such" / "folder" / "x.png";
    CHECK_THROWS_WITH_AS(prism::write_png(film, missing), doctest::Contains(missing.c_str()), std::runtime_error);
    CHECK_THROWS_WITH_AS(prism::write_png(film, missing), doctest::Contains("No such file"), std::runtime_error);
    // The target is a directory: the bytes are written to a temporary file, then the
    // rename fails, and the temporary must be gone.
    fs::create_directories(dir / "taken.png");
    CHECK_THROWS_AS(prism::write_png(film, dir / "taken.png"), std::runtime_error);
    CHECK_THROWS_AS(prism::write_pfm(film, dir / "taken.png"), std::runtime_error);
    int files = 0;
    for ([[maybe_unused]] const auto& entry : fs::recursive_directory_iterator(dir)) files += entry.is_regular_file();
    CHECK(files == 0);
    CHECK_THROWS_WITH_AS(prism::write_image(film, dir / "x.tiff"), doctest::Contains("unknown image extension"), std::runtime_error);
    CHECK_THROWS_AS((void)prism::read_pfm(dir / "absent.pfm"), std::runtime_error);
    fs::remove_all(dir);
}

TEST_CASE("a write goes through to what is not a regular file and never replaces it")
{
    // Regression: the temporary file was renamed over any target, so a FIFO, a device node
    // or a symbolic link became a plain file (write_png(film, "/dev/null") as root would
    // have replaced /dev/null).
    const fs::path dir = scratch_folder("special");
    const prism::Film film = gradient();
    // A FIFO stays a FIFO, and a reader receives the whole PNG.
    const fs::path fifo = dir / "pipe.png";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    std::vector<unsigned char> received;
    std::thread reader([&] {
        std::ifstream in(fifo, std::ios::binary);
        received.assign(std::istreambuf_iterator<char>(in), {});
    });
    prism::write_png(film, fifo);
    reader.join();
    CHECK(fs::is_fifo(fs::symlink_status(fifo)));
    CHECK(received.size() > 8);
    std::ofstream(dir / "copy.png", std::ios::binary).write(reinterpret_cast<const char*>(received.data()), std::streamsize(received.size()));
    CHECK(prism::to_srgb8(prism::read_png(dir / "copy.png")) == prism::to_srgb8(film));
    // /dev/null takes the bytes and stays a character device.
    prism::write_pfm(film, "/dev/null");
    CHECK(fs::is_character_file(fs::symlink_status("/dev/null")));
    // A symbolic link stays a link; the file it names is replaced whole.
    const fs::path real = dir / "real.pfm", link = dir / "link.pfm";
    std::ofstream(real) << "old";
    fs::create_symlink(real, link);
    prism::write_pfm(film, link);
    CHECK(fs::is_symlink(fs::symlink_status(link)));
    CHECK(prism::read_pfm(real).film().pixels() == film.pixels());
    int leftovers = 0;
    for (const auto& entry : fs::directory_iterator(dir)) leftovers += entry.path().string().find("prism-partial") != std::string::npos;
    CHECK(leftovers == 0);
    fs::remove_all(dir);
}

TEST_CASE("read_pfm checks its header against the file's size before allocating")
{
    // Regression: 20 bytes made read_pfm allocate 4.8 GB before it reported truncation.
    const fs::path dir = scratch_folder("pfm-header");
    std::ofstream(dir / "big.pfm", std::ios::binary) << "PF\n20000 20000\n-1.0\n";
    CHECK_THROWS_WITH_AS((void)prism::read_pfm(dir / "big.pfm"), doctest::Contains("truncated"), std::runtime_error);
    CHECK_THROWS_WITH_AS((void)prism::read_pfm(dir / "big.pfm"), doctest::Contains("20000 x 20000"), std::runtime_error);
    std::ofstream(dir / "nan.pfm", std::ios::binary) << "PF\n1 1\nnan\n";
    CHECK_THROWS_AS((void)prism::read_pfm(dir / "nan.pfm"), std::runtime_error);
    fs::remove_all(dir);
}

namespace {

/// A PFM file's bytes: `header`, then `values` as little-endian floats.
std::string pfm_bytes(const std::string& header, const std::vector<float>& values)
{
    std::string bytes = header;
    for (const float v : values) {
        char raw[4];
        std::memcpy(raw, &v, 4);
        if constexpr (std::endian::native == std::endian::big) std::swap(raw[0], raw[3]), std::swap(raw[1], raw[2]);
        bytes.append(raw, 4);
    }
    return bytes;
}

void write_bytes(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

std::string message_of(const fs::path& path)
{
    try {
        (void)prism::read_pfm(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("read_pfm keeps negative, NaN and infinite values as data, and a Film refuses them by pixel")
{
    // Regression: they were set to 0 without a word (negative values are legal PFM).
    const fs::path dir = scratch_folder("pfm-data");
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    write_bytes(dir / "odd.pfm", pfm_bytes("PF\n2 1\n-1.0\n", {-1.5f, 0.25f, inf, nan, -inf, 3.0f}));
    const prism::PfmImage image = prism::read_pfm(dir / "odd.pfm");
    REQUIRE(image.width == 2);
    REQUIRE(image.channels == 3);
    CHECK(image.at(0, 0, 0) == -1.5f);
    CHECK(image.at(0, 0, 2) == inf);
    CHECK(std::isnan(image.at(1, 0, 0)));
    CHECK(image.at(1, 0, 1) == -inf);
    CHECK_THROWS_WITH_AS((void)image.film(), doctest::Contains("pixel (0, 0) holds -1.5"), std::runtime_error);
    // Grey (Pf): one float a pixel, bottom row first.
    write_bytes(dir / "grey.pfm", pfm_bytes("Pf\n1 2\n-1\n", {0.5f, 2.0f}));
    const prism::PfmImage grey = prism::read_pfm(dir / "grey.pfm");
    CHECK(grey.channels == 1);
    CHECK(grey.at(0, 0, 0) == 2.0f);
    CHECK(grey.film().at(0, 1) == prism::Rgb<float>(0.5f));
    fs::remove_all(dir);
}

TEST_CASE("read_pfm reads a header whose lines end in CRLF, and refuses one that shifts the data")
{
    // Regression: "\r\n" after the scale was read as one byte of white space and one of data.
    const fs::path dir = scratch_folder("pfm-crlf");
    write_bytes(dir / "crlf.pfm", pfm_bytes("PF\r\n1 1\r\n-1.0\r\n", {0.25f, 0.5f, 0.75f}));
    const prism::PfmImage image = prism::read_pfm(dir / "crlf.pfm");
    CHECK(image.at(0, 0, 0) == 0.25f);
    CHECK(image.at(0, 0, 2) == 0.75f);
    write_bytes(dir / "cr.pfm", pfm_bytes("PF\n1 1\n-1.0\r", {0.25f, 0.5f, 0.75f}));
    CHECK(message_of(dir / "cr.pfm").find("ends in") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("read_pfm sizes its claims in 64 bits and says how many bytes are missing")
{
    // Regression: a width past 178 956 970 overflowed `x * 12` in int; 2147483647 squared made
    // a message of -9223372036854775808 bytes.
    const fs::path dir = scratch_folder("pfm-size");
    write_bytes(dir / "wide.pfm", pfm_bytes("PF\n200000000 1\n-1.0\n", {1, 2, 3}));
    const std::string wide = message_of(dir / "wide.pfm");
    CHECK(wide.find("2400000000 bytes, but 12 follow") != std::string::npos);
    write_bytes(dir / "huge.pfm", "PF\n2147483647 2147483647\n-1.0\n");
    const std::string huge = message_of(dir / "huge.pfm");
    CHECK(huge.find("more bytes than a file can hold") != std::string::npos);
    CHECK(huge.find("-9223372036854775808") == std::string::npos);
    for (const char* header : {"PF\n-3 1\n-1\n", "PF\n0 1\n-1\n", "PF\n2147483648 1\n-1\n", "PF\n1.5 1\n-1\n", "PF\n1 1\nnan\n", "PF\n1 1\n0\n"}) {
        write_bytes(dir / "bad.pfm", pfm_bytes(header, {1, 2, 3}));
        CHECK_THROWS_AS((void)prism::read_pfm(dir / "bad.pfm"), std::runtime_error);
    }
    // Bytes past the pixels are refused, not ignored.
    write_bytes(dir / "long.pfm", pfm_bytes("PF\n1 1\n-1\n", {1, 2, 3, 4}));
    CHECK(message_of(dir / "long.pfm").find("bytes follow") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("read_pfm reads a valid PFM through a FIFO, and refuses an endless stream at once")
{
    // Regression: a FIFO's size is unknown ("file is truncated ... 0 follow it"); /dev/zero
    // made the reader's memory grow without bound.
    const fs::path dir = scratch_folder("pfm-fifo");
    const fs::path fifo = dir / "pipe.pfm";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    std::thread writer([&] { write_bytes(fifo, pfm_bytes("PF\n1 1\n-1\n", {0.5f, 1.5f, 2.5f})); });
    const prism::PfmImage image = prism::read_pfm(fifo);
    writer.join();
    CHECK(image.at(0, 0, 1) == 1.5f);
    CHECK_THROWS_WITH_AS((void)prism::read_pfm("/dev/zero"), doctest::Contains("not a PFM file"), std::runtime_error);
    // A stream is read no further than the limit. The reader closes the FIFO while the
    // writer may still be writing: the writer must get EPIPE, not a SIGPIPE that ends the
    // test program (it did with libc++'s smaller stream buffer).
    const auto previous = std::signal(SIGPIPE, SIG_IGN);
    std::thread endless([&] { write_bytes(fifo, pfm_bytes("PF\n1000 1000\n-1\n", std::vector<float>(3000, 1.0f))); });
    CHECK_THROWS_WITH_AS((void)prism::read_pfm(fifo, {.max_bytes = 4096}), doctest::Contains("limit"), std::runtime_error);
    endless.join();
    std::signal(SIGPIPE, previous);
    fs::remove_all(dir);
}

TEST_CASE("read_png refuses a truncated or corrupt file and a header its bytes cannot hold, with a reason")
{
    // Regression: a truncated PNG gave a message with an empty reason.
    const fs::path dir = scratch_folder("png-strict");
    prism::write_png(gradient(), dir / "g.png");
    std::ifstream in(dir / "g.png", std::ios::binary);
    const std::string whole((std::istreambuf_iterator<char>(in)), {});
    write_bytes(dir / "cut.png", whole.substr(0, whole.size() / 2));
    CHECK_THROWS_WITH_AS((void)prism::read_png(dir / "cut.png"), doctest::Contains("it is truncated (the chunk at byte 33 claims"), std::runtime_error);
    // A flipped bit in the pixels' chunk fails its CRC, which stb_image does not check.
    std::string flipped = whole;
    flipped[45] = char(flipped[45] ^ 1);
    write_bytes(dir / "flipped.png", flipped);
    CHECK_THROWS_WITH_AS((void)prism::read_png(dir / "flipped.png"), doctest::Contains("fails its CRC"), std::runtime_error);
    write_bytes(dir / "tail.png", whole + "x");
    CHECK_THROWS_WITH_AS((void)prism::read_png(dir / "tail.png"), doctest::Contains("1 bytes follow its IEND"), std::runtime_error);
    // The same header claiming 60000 x 60000 pixels: refused before stb_image allocates.
    std::string big = whole;
    for (const int at : {16, 20}) big[std::size_t(at)] = 0, big[std::size_t(at + 1)] = 0, big[std::size_t(at + 2)] = char(0xea), big[std::size_t(at + 3)] = 0x60;
    write_bytes(dir / "big.png", big);
    CHECK_THROWS_WITH_AS((void)prism::read_png(dir / "big.png"), doctest::Contains("60000 x 60000 pixels, more than its"), std::runtime_error);
    CHECK_THROWS_WITH_AS((void)prism::read_png("/dev/zero"), doctest::Contains("not a PNG file"), std::runtime_error);
    write_bytes(dir / "short.png", "\x89PNG");
    CHECK_THROWS_WITH_AS((void)prism::read_png(dir / "short.png"), doctest::Contains("too short"), std::runtime_error);
    fs::remove_all(dir);
}

namespace {

/// Greg Ward's RGBE encoding of one pixel (Radiance's float2rgbe): a shared exponent from
/// the largest channel, each channel's mantissa in a byte.
std::string rgbe(const prism::Rgb<float>& p)
{
    const float largest = std::max({p.x, p.y, p.z});
    if (largest < 1e-32f) return std::string(4, '\0');
    int e = 0;
    const float scale = std::frexp(largest, &e) * 256.0f / largest;
    return {char(static_cast<unsigned char>(p.x * scale)), char(static_cast<unsigned char>(p.y * scale)), char(static_cast<unsigned char>(p.z * scale)),
            char(static_cast<unsigned char>(e + 128))};
}

/// A Radiance HDR file of `pixels` (row by row from the top): flat, or each row run-length
/// encoded, a channel in runs where it repeats (at least 3 alike) and dumps elsewhere.
std::string hdr_bytes(int width, int height, const std::vector<prism::Rgb<float>>& pixels, bool encoded, const std::string& header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
{
    std::string out = header + "-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n";
    for (int y = 0; y < height; ++y) {
        std::vector<std::string> row;
        for (int x = 0; x < width; ++x) row.push_back(rgbe(pixels[std::size_t(y * width + x)]));
        if (!encoded) {
            for (const std::string& p : row) out += p;
            continue;
        }
        out += {char(2), char(2), char(width >> 8), char(width & 255)};
        for (std::size_t c = 0; c < 4; ++c)
            for (std::size_t x = 0; x < row.size();) {
                std::size_t same = 1;
                while (x + same < row.size() && same < 127 && row[x + same][c] == row[x][c]) ++same;
                if (same >= 3) {
                    out += char(128 + same);
                    out += row[x][c];
                    x += same;
                    continue;
                }
                const std::size_t count = std::min<std::size_t>(row.size() - x, 128);
                out += char(count);
                for (std::size_t i = 0; i < count; ++i) out += row[x + i][c];
                x += count;
            }
    }
    return out;
}

std::string hdr_message(const fs::path& path)
{
    try {
        (void)prism::read_hdr(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "accepted";
}

} // namespace

TEST_CASE("the readers of compressed images refuse more pixels than ReadLimits::max_pixels before decoding, naming the limit")
{
    // Regression: a 1-bit PNG of 2 KB claiming 16 million pixels (paid for by deflate's
    // 1032 to 1 and eight pixels a byte) cost 841 MB as a texture; one of 32 KB ran past
    // 4 GB. The limit is checked against the header, before anything is allocated.
    const fs::path dir = scratch_folder("max-pixels");
    prism::Film film(64, 32);
    prism::write_png(film, dir / "p.png");
    std::vector<prism::Rgb<float>> pixels(64 * 32, prism::Rgb<float>(0.5f));
    write_bytes(dir / "p.hdr", hdr_bytes(64, 32, pixels, true));
    for (const char* name : {"p.png", "p.hdr"}) {
        CAPTURE(name);
        const fs::path path = dir / name;
        const auto read = [&](std::uint64_t max_pixels) {
            const prism::ReadLimits limits{.max_pixels = max_pixels};
            const std::string extension = path.extension().string();
            if (extension == ".png") return prism::read_png(path, limits).width();
            return prism::read_hdr(path, limits).width();
        };
        CHECK(read(2048) == 64);
        CHECK_THROWS_WITH_AS((void)read(2047), doctest::Contains("64 x 32 pixels, more than the limit of 2047 (ReadLimits::max_pixels)"), std::runtime_error);
    }
    CHECK(prism::ReadLimits{}.max_pixels == std::uint64_t(1) << 26);
    fs::remove_all(dir);
}

TEST_CASE("read_hdr reads Radiance RGBE pixels exactly, flat and run-length encoded, rows from the top")
{
    const fs::path dir = scratch_folder("hdr-read");
    // Values whose mantissas fit a byte decode exactly (stb_image: byte * 2^(e - 136)).
    const auto value = [](int x, int y) { return prism::Rgb<float>{std::ldexp(float(x % 8 + 1), y - 3), 0.5f, x == 3 ? 40.0f : 0.25f}; };
    for (const int width : {5, 40}) // below 8 pixels a row is always flat
        for (const bool encoded : {false, true}) {
            const int height = 3;
            std::vector<prism::Rgb<float>> pixels;
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x) pixels.push_back(value(x, y));
            const fs::path path = dir / ("sky" + std::to_string(width) + (encoded ? "rle" : "flat") + ".hdr");
            write_bytes(path, hdr_bytes(width, height, pixels, encoded && width >= 8));
            const prism::Film film = prism::read_hdr(path);
            REQUIRE(film.width() == width);
            REQUIRE(film.height() == height);
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x) {
                    // Every channel here is a multiple of 2^-3 below 2^6: the shared
                    // exponent leaves its byte exact.
                    for (int c = 0; c < 3; ++c) CHECK_MESSAGE(film.at(x, y)[c] == value(x, y)[c], path, " (", x, ", ", y, ") channel ", c);
                }
        }
    fs::remove_all(dir);
}

TEST_CASE("read_hdr refuses what stb_image would misread or allocate for unpaid, naming the reason")
{
    const fs::path dir = scratch_folder("hdr-strict");
    const std::vector<prism::Rgb<float>> pixels(40 * 2, prism::Rgb<float>{1.0f, 0.5f, 0.25f});
    const std::string good = hdr_bytes(40, 2, pixels, true);
    const auto refused = [&](const std::string& name, const std::string& bytes) {
        write_bytes(dir / name, bytes);
        return hdr_message(dir / name);
    };
    CHECK(refused("good.hdr", good) == "accepted");
    CHECK(refused("crlf.hdr", "#?RGBE\r\n" + good.substr(11)) == "accepted");
    CHECK(refused("cut.hdr", good.substr(0, good.size() - 3)).find("it is truncated in row 1 of 2") != std::string::npos);
    CHECK(refused("tail.hdr", good + "x").find("1 bytes follow its last row") != std::string::npos);
    CHECK(refused("magic.hdr", "#?RADIANCX\n" + good.substr(11)).find("not a Radiance HDR file") != std::string::npos);
    CHECK(hdr_message("/dev/zero").find("not a Radiance HDR file") != std::string::npos);
    CHECK(refused("format.hdr", hdr_bytes(40, 2, pixels, true, "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n")).find("FORMAT=32-bit_rle_xyze (line 2) is not") != std::string::npos);
    // Regression: a header line ending in "\r\n" was quoted with its carriage return,
    // which hid the start of the message on a terminal.
    const std::string crlf_format = refused("crlf-format.hdr", hdr_bytes(40, 2, pixels, true, "#?RADIANCE\r\nFORMAT=32-bit_rle_rgbe\r\n\r\n"));
    CHECK(crlf_format.find("its FORMAT=32-bit_rle_rgbe\\r (line 2) is not FORMAT=32-bit_rle_rgbe") != std::string::npos);
    CHECK(crlf_format.find('\r') == std::string::npos);
    CHECK(refused("noformat.hdr", hdr_bytes(40, 2, pixels, true, "#?RADIANCE\nEXPOSURE=1\n\n")).find("no FORMAT=32-bit_rle_rgbe line") != std::string::npos);
    std::string flipped = good;
    flipped.replace(flipped.find("-Y 2 +X 40"), 10, "+Y 2 +X 40");
    CHECK(refused("flipped.hdr", flipped).find("rows from the top, the only order read") != std::string::npos);
    // 2^24 x 2^24 pixels claimed by a few bytes (rows that wide are flat): refused before
    // stb_image allocates; and 40 x 2^24 run-length encoded ones, by the walk.
    std::string huge = good;
    huge.replace(huge.find("-Y 2 +X 40"), 10, "-Y 16777216 +X 16777216");
    CHECK(refused("huge.hdr", huge).find("16777216 x 16777216 pixels, more than the") != std::string::npos);
    std::string tall = good;
    tall.replace(tall.find("-Y 2 +X 40"), 10, "-Y 16777216 +X 40");
    CHECK(refused("tall.hdr", tall).find("it is truncated in row 2 of 16777216") != std::string::npos);
    std::string flat = hdr_bytes(5, 2, std::vector<prism::Rgb<float>>(10, prism::Rgb<float>(1.0f)), false);
    flat.replace(flat.find("-Y 2 +X 5"), 9, "-Y 9000000 +X 5");
    CHECK(refused("flat.hdr", flat).find("9000000 pixels, more than the 40 bytes after it hold") != std::string::npos);
    CHECK(refused("side.hdr", flat.replace(flat.find("-Y 9000000"), 10, "-Y 0")).find("each side from 1 to 16777216") != std::string::npos);
    // A dump longer than what is left of its row (stb_image: "bad RLE data").
    std::string overrun = good;
    const std::size_t first_row = overrun.find("+X 40\n") + 6;
    overrun[first_row + 4] = char(41);
    CHECK(refused("overrun.hdr", overrun).find("row 0 has a dump of 41 values where 40 are left") != std::string::npos);
    CHECK(refused("long.hdr", "#?RADIANCE\n" + std::string(2000, 'x') + "\n").find("its header (line 2) is longer than 1023 bytes") != std::string::npos);
    fs::remove_all(dir);
}
