// SPDX-License-Identifier: MIT
#include <prism/io/texture.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

fs::path texture_scratch(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("prism-texture-test-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void texture_bytes_to(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size())); }

std::string texture_file_bytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

/// A 256 x 1 grey PNG or JPEG whose pixel x holds the byte x (stb_image_write).
void write_texture_ramp(const fs::path& path, bool jpeg)
{
    std::vector<unsigned char> bytes(256);
    for (int i = 0; i < 256; ++i) bytes[std::size_t(i)] = static_cast<unsigned char>(i);
    const int ok = jpeg ? stbi_write_jpg(path.c_str(), 256, 1, 1, bytes.data(), 100) : stbi_write_png(path.c_str(), 256, 1, 1, bytes.data(), 256);
    REQUIRE(ok != 0);
}

/// IEC 61966-2-1's decoding, written out here: linear from the encoded value V in [0, 1].
double iec_srgb_decode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

} // namespace

TEST_CASE("an 8-bit PNG as a texture: sRGB decoded by IEC 61966-2-1 as colour, byte / 255 as data")
{
    const fs::path dir = texture_scratch("ramp");
    write_texture_ramp(dir / "ramp.png", false);
    const auto colour = prism::load_texture<double>(dir / "ramp.png", {.sampling = {prism::Wrap::clamp, prism::TextureFilter::nearest}});
    const auto data = prism::load_texture<double>(dir / "ramp.png", {.encoding = prism::TextureEncoding::linear, .channels = 1, .sampling = {prism::Wrap::clamp, prism::TextureFilter::nearest}});
    CHECK(colour.width() == 256);
    CHECK(colour.channels() == 3);
    CHECK(data.channels() == 1);
    double worst = 0;
    for (int i = 0; i < 256; ++i) {
        const prism::TexturePoint<double> at{{}, {(i + 0.5) / 256, 0.5}, 0};
        worst = std::max(worst, std::abs(colour.albedo(at).y - iec_srgb_decode(i / 255.0)));
        CHECK(data.value(at) == doctest::Approx(i / 255.0).epsilon(1e-6));
    }
    CHECK(worst < 1e-6);
    // Published points of the curve: 128 decodes to 0.2158605, 10 to 0.0030353.
    CHECK(colour.albedo({{}, {128.5 / 256, 0.5}, 0}).x == doctest::Approx(0.2158605).epsilon(1e-5));
    CHECK(colour.albedo({{}, {10.5 / 256, 0.5}, 0}).x == doctest::Approx(0.0030353).epsilon(1e-4));
    fs::remove_all(dir);
}

TEST_CASE("a baseline JPEG as a texture, within JPEG's own loss; progressive and oversized ones refused by name")
{
    const fs::path dir = texture_scratch("jpeg");
    write_texture_ramp(dir / "ramp.jpg", true);
    const auto data = prism::load_texture<double>(dir / "ramp.jpg", {.encoding = prism::TextureEncoding::linear, .channels = 1, .sampling = {prism::Wrap::clamp, prism::TextureFilter::nearest}});
    double worst = 0;
    for (int i = 0; i < 256; ++i) worst = std::max(worst, std::abs(data.value({{}, {(i + 0.5) / 256, 0.5}, 0}) - i / 255.0));
    CHECK(worst < 4.0 / 255); // quality 100
    const std::string whole = texture_file_bytes(dir / "ramp.jpg");
    // Its frame header (FF C0) claiming 65535 x 65535 pixels: refused before decoding.
    const std::size_t sof = whole.find("\xff\xc0");
    REQUIRE(sof != std::string::npos);
    std::string big = whole;
    for (std::size_t k = 5; k <= 8; ++k) big[sof + k] = char(0xff);
    texture_bytes_to(dir / "big.jpg", big);
    CHECK_THROWS_WITH_AS((void)prism::read_jpeg(dir / "big.jpg"), doctest::Contains("65535 x 65535 pixels, more than its"), std::runtime_error);
    std::string progressive = whole;
    progressive[sof + 1] = char(0xc2);
    texture_bytes_to(dir / "progressive.jpg", progressive);
    CHECK_THROWS_WITH_AS((void)prism::read_jpeg(dir / "progressive.jpg"), doctest::Contains("progressive JPEG"), std::runtime_error);
    // The limit on pixels (ReadLimits::max_pixels), through load_texture as a .mtl's
    // map_Kd reaches it: the ramp's 256 x 1, and one fewer allowed.
    CHECK_THROWS_WITH_AS((void)prism::load_texture(dir / "ramp.jpg", {.limits = {.max_pixels = 255}}),
                         doctest::Contains("256 x 1 pixels, more than the limit of 255 (ReadLimits::max_pixels)"), std::runtime_error);
    CHECK(prism::load_texture(dir / "ramp.jpg", {.limits = {.max_pixels = 256}}).width() == 256);
    // Regression: without Huffman tables stb_image decoded from memory it never wrote
    // (valgrind). Each table's segments cut out, up to the scan.
    const auto without = [&](unsigned char marker) {
        std::string out = whole.substr(0, 2);
        for (std::size_t at = 2; at + 4 <= whole.size();) {
            const auto length = std::size_t(static_cast<unsigned char>(whole[at + 2])) << 8 | static_cast<unsigned char>(whole[at + 3]);
            if (static_cast<unsigned char>(whole[at + 1]) == 0xda) return out + whole.substr(at);
            if (static_cast<unsigned char>(whole[at + 1]) != marker) out += whole.substr(at, 2 + length);
            at += 2 + length;
        }
        return out;
    };
    texture_bytes_to(dir / "no-huffman.jpg", without(0xc4));
    CHECK_THROWS_WITH_AS((void)prism::read_jpeg(dir / "no-huffman.jpg"), doctest::Contains("it has no Huffman table (a DHT segment) before its scan"),
                         std::runtime_error);
    texture_bytes_to(dir / "no-quantization.jpg", without(0xdb));
    CHECK_THROWS_WITH_AS((void)prism::read_jpeg(dir / "no-quantization.jpg"), doctest::Contains("it has no quantization table (a DQT segment) before its scan"),
                         std::runtime_error);
    texture_bytes_to(dir / "cut.jpg", whole.substr(0, sof + 4));
    CHECK_THROWS_WITH_AS((void)prism::read_jpeg(dir / "cut.jpg"), doctest::Contains("it is truncated"), std::runtime_error);
    texture_bytes_to(dir / "torn.jpg", whole.substr(0, whole.size() - 200));
    CHECK_THROWS_AS((void)prism::read_jpeg(dir / "torn.jpg"), std::runtime_error);
    CHECK_THROWS_WITH_AS((void)prism::read_jpeg("/dev/zero"), doctest::Contains("not a JPEG file"), std::runtime_error);
    fs::remove_all(dir);
}

TEST_CASE("HDR and PFM textures are linear as stored; a negative texel and an unknown extension are refused naming the file")
{
    const fs::path dir = texture_scratch("linear");
    prism::Film film(3, 2);
    film.set(0, 0, prism::Rgb<float>{4.0f, 0.5f, 0.25f});
    film.set(2, 1, prism::Rgb<float>{0.125f, 8.0f, 1.0f});
    prism::write_pfm(film, dir / "f.pfm");
    const auto t = prism::load_texture<double>(dir / "f.pfm", {.sampling = {prism::Wrap::clamp, prism::TextureFilter::nearest}});
    CHECK(t.albedo({{}, {0.1, 0.9}, 0}).x == 4.0); // (0, 0) is the top-left pixel: v near 1
    CHECK(t.albedo({{}, {0.9, 0.1}, 0}).y == 8.0);
    // A grey PFM (rows from the bottom, little endian) with one negative value: texel 4
    // is (x 1, y 1) counted from the top, the second value of the file's first row.
    std::string negative = "Pf\n3 2\n-1\n";
    for (const float v : {0.5f, -1.0f, 0.5f, 0.5f, 0.5f, 0.5f}) negative.append(reinterpret_cast<const char*>(&v), 4);
    texture_bytes_to(dir / "negative.pfm", negative);
    CHECK_THROWS_WITH_AS((void)prism::load_texture(dir / "negative.pfm"), doctest::Contains("negative.pfm"), std::runtime_error);
    CHECK_THROWS_WITH_AS((void)prism::load_texture(dir / "negative.pfm"), doctest::Contains("texel 4 (x 1, y 1)"), std::runtime_error);
    // Regression: a texture that could not be read said "cannot write".
    CHECK_THROWS_WITH_AS((void)prism::load_texture(dir / "f.tga"), doctest::Contains("prism: cannot read texture '"), std::runtime_error);
    CHECK_THROWS_WITH_AS((void)prism::load_texture(dir / "f.tga"), doctest::Contains("unknown texture extension '.tga'"), std::runtime_error);
    CHECK_THROWS_WITH_AS((void)prism::load_texture(dir / "f.pfm", {.channels = 2}), doctest::Contains("channels must be 1 or 3, got 2"), std::runtime_error);
    fs::remove_all(dir);
}
