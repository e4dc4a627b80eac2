// SPDX-License-Identifier: MIT
#include <prism/io/exr.hpp>

#include "../support.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>

using namespace prism;

namespace {

std::filesystem::path scratch(const std::string& name)
{
    const auto folder = std::filesystem::temp_directory_path() / "prism-exr-test";
    std::filesystem::create_directories(folder);
    return folder / name;
}

/// What a command prints on stdout.
std::string output_of(const std::string& command)
{
    std::string text;
    if (std::FILE* pipe = popen(command.c_str(), "r")) {
        std::array<char, 4096> buffer{};
        while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) text.append(buffer.data(), n);
        pclose(pipe);
    }
    return text;
}

} // namespace

TEST_CASE("an EXR file reads back with its channels, data window and attributes, bit for bit")
{
    ExrImage image{7, 5, {2, 1, 6, 4}, {}, {{"prism.scene", "test"}, {"prism.seed", "42"}}};
    std::vector<float> r(12), g(12), b(12);
    std::vector<std::uint32_t> u(12);
    for (std::size_t i = 0; i < 12; ++i) {
        r[i] = float(i) * 0.1f;
        g[i] = std::numeric_limits<float>::denorm_min() * float(i); // denormals survive
        b[i] = 1e30f / float(i + 1);
        u[i] = 0xfffffff0u + std::uint32_t(i);
    }
    image.channels = {{"R", r}, {"G", g}, {"B", b}, {"count", u}};
    const auto path = scratch("round_trip.exr");
    write_exr(image, path);
    const ExrImage back = read_exr(path);
    CHECK(back.width == 7);
    CHECK(back.height == 5);
    CHECK(back.window == PixelWindow{2, 1, 6, 4});
    CHECK(back.attributes.at("prism.scene") == "test");
    CHECK(back.attributes.at("prism.seed") == "42");
    REQUIRE(back.find("R") != nullptr);
    CHECK(std::get<std::vector<float>>(back.find("R")->values) == r);
    CHECK(std::get<std::vector<float>>(back.find("G")->values) == g);
    CHECK(std::get<std::vector<float>>(back.find("B")->values) == b);
    CHECK(std::get<std::vector<std::uint32_t>>(back.find("count")->values) == u);
    CHECK(back.find("A") == nullptr);

    // OpenEXR's own tool reads the same windows and metadata.
    if (std::system("command -v exrheader > /dev/null 2>&1") == 0) {
        const std::string header = output_of("exrheader " + path.string());
        CHECK(header.find("displayWindow (type box2i): (0 0) - (6 4)") != std::string::npos);
        CHECK(header.find("dataWindow (type box2i): (2 1) - (5 3)") != std::string::npos);
        CHECK(header.find("prism.scene (type string): \"test\"") != std::string::npos);
        CHECK(header.find("count, 32-bit unsigned integer") != std::string::npos);
        CHECK(header.find("zip, multi-scanline blocks") != std::string::npos);
    } else {
        MESSAGE("exrheader (Debian: openexr) is not installed: its check is skipped");
    }
}

TEST_CASE("an Accumulation's exact sums go through an EXR file unchanged")
{
    Accumulation sums(9, 6, {3, 2, 8, 6}, {"R", "G", "B", "depth"});
    for (int y = 2; y < 6; ++y)
        for (int x = 3; x < 8; ++x) {
            // Sums whose bits reach every one of the four words, some negative.
            const ExactSum s[4] = {ExactSum::of(1e11 * x + 1e-12 * y), ExactSum::of(0x1p-64 * (x + 1)),
                                   ExactSum::from_bits(Int128::from_words(std::uint64_t(y), std::uint64_t(x) << 36)), ExactSum::of(-2.5 * y)};
            sums.add(x, y, s, (std::uint64_t(1) << 40) + std::uint64_t(x));
        }
    const auto path = scratch("sums.exr");
    write_exr(to_exr(sums, true, {{"prism.scene", "sums"}}), path);
    const ExrImage image = read_exr(path);
    const Accumulation back = to_accumulation(image, {"R", "G", "B", "depth"});
    CHECK(back.window() == sums.window());
    for (int y = 2; y < 6; ++y)
        for (int x = 3; x < 8; ++x) {
            REQUIRE(back.sums(x, y) == sums.sums(x, y));
            REQUIRE(back.weight(x, y) == sums.weight(x, y));
        }
    // The means are there for any viewer: depth -2.5 y over 2^40 + x samples.
    const auto& depth = std::get<std::vector<float>>(image.find("depth")->values);
    CHECK(depth[0] == float(-2.5 * 2 / double((std::uint64_t(1) << 40) + 3)));
    CHECK(image.find("sum.R.4") == nullptr); // no sum passed 2^63: four words each
    // Sums past 2^63 (samples up to the largest float) take eight words each, and come
    // back the same.
    Accumulation wide = sums;
    const ExactSum big[4] = {ExactSum::of(3e38), ExactSum::of(-1e30), ExactSum::of(0x1p70), {}};
    wide.add(4, 3, big, 1);
    wide.add(7, 5, big, 1);
    REQUIRE(wide.wide());
    write_exr(to_exr(wide, true), path);
    const ExrImage wide_image = read_exr(path);
    CHECK(wide_image.find("sum.depth.7") != nullptr);
    const Accumulation wide_back = to_accumulation(wide_image, {"R", "G", "B", "depth"});
    for (int y = 2; y < 6; ++y)
        for (int x = 3; x < 8; ++x) REQUIRE(wide_back.sums(x, y) == wide.sums(x, y));
    CHECK(wide_back.sum(4, 3, 0).value() == wide.sum(4, 3, 0).value());
    CHECK(wide_back.sum(4, 3, 1).value() < -1e29);
    // Without the sums, there is nothing to add up, and the error says so.
    write_exr(to_exr(sums, false), path);
    CHECK_THROWS_WITH_AS((void)to_accumulation(read_exr(path)), doctest::Contains("has no UINT channel 'weight.0'"), std::invalid_argument);
}

TEST_CASE("64-bit FNV-1a matches the published test vectors")
{
    // draft-eastlake-fnv's test vectors (and Noll's own table) for FNV-1a 64.
    const std::pair<std::string, std::uint64_t> vectors[] = {{"", 0xcbf29ce484222325u}, {"a", 0xaf63dc4c8601ec8cu}, {"foobar", 0x85944171f73967e8u}};
    for (const auto& [text, expected] : vectors) {
        detail::Fnv1a hash;
        hash.add(text.data(), text.size());
        CHECK(hash.value == expected);
    }
}

TEST_CASE("a part's digest is written with its sums, read back alike, and changed by any change of what it holds")
{
    Accumulation sums(6, 4, {1, 1, 5, 3}, {"R", "G", "B"});
    for (int y = 1; y < 3; ++y)
        for (int x = 1; x < 5; ++x) {
            const ExactSum s[3] = {ExactSum::of(0.25 * x), ExactSum::of(0.5 * y), ExactSum::of(x - y)};
            sums.add(x, y, s, 2);
        }
    const ExrImage written = to_exr(sums, true, {{"prism.seed", "0"}, {"prism.part.passes", "0:2"}});
    const std::string digest = written.attributes.at("prism.part.digest");
    CHECK(digest.size() == 16);
    CHECK(digest == exr_digest(written));
    const auto path = scratch("digest.exr");
    write_exr(written, path);
    const ExrImage read = read_exr(path);
    CHECK(read.attributes.at("prism.part.digest") == digest);
    CHECK(exr_digest(read) == digest); // the file's channel order is not the writer's
    // Each thing a part holds changes it: an attribute, a new prism. attribute, a bit of a
    // sum or a weight, a mean, the window.
    const auto changed = [&](auto edit) {
        ExrImage copy = written;
        edit(copy);
        return exr_digest(copy) != digest;
    };
    CHECK(changed([](ExrImage& i) { i.attributes["prism.part.passes"] = "1:3"; }));
    CHECK(changed([](ExrImage& i) { i.attributes["prism.seed"] = "1"; }));
    CHECK(changed([](ExrImage& i) { i.attributes["prism.spp"] = "2"; }));
    CHECK(changed([](ExrImage& i) { std::get<1>(const_cast<ExrChannel*>(i.find("weight.0"))->values)[3] ^= 1; }));
    CHECK(changed([](ExrImage& i) { std::get<1>(const_cast<ExrChannel*>(i.find("sum.G.2"))->values)[0] ^= 0x80000000u; }));
    CHECK(changed([](ExrImage& i) { std::get<0>(const_cast<ExrChannel*>(i.find("B"))->values)[7] = -0.0f; }));
    CHECK(changed([](ExrImage& i) { i.window.x0 = 0; }));
    CHECK(changed([](ExrImage& i) { i.find("R") == nullptr ? void() : (void)(i.channels[0].name = "Q"); }));
    // What is not the part's: another program's attribute, the digest itself.
    CHECK_FALSE(changed([](ExrImage& i) { i.attributes["comments"] = "looked at in a viewer"; }));
    CHECK_FALSE(changed([](ExrImage& i) { i.attributes["prism.part.digest"] = "0"; }));
}

TEST_CASE("EXR errors name the file and the reason, and a failed write leaves no file")
{
    const auto missing = scratch("missing.exr");
    std::filesystem::remove(missing);
    const std::string missing_name = missing.string();
    CHECK_THROWS_WITH_AS((void)read_exr(missing), doctest::Contains(missing_name.c_str()), std::runtime_error);
    const auto junk = scratch("junk.exr");
    std::ofstream(junk) << "not an EXR file";
    const std::string junk_message = "cannot read image '" + junk.string() + "'";
    CHECK_THROWS_WITH_AS((void)read_exr(junk), doctest::Contains(junk_message.c_str()), std::runtime_error);
    // A truncated file: the first half of a real one.
    const auto whole = scratch("whole.exr"), first_half = scratch("half.exr");
    write_exr(to_exr(Film(64, 64)), whole);
    const auto size = std::filesystem::file_size(whole);
    std::filesystem::copy_file(whole, first_half, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(first_half, size / 2);
    CHECK_THROWS_WITH_AS((void)read_exr(first_half), doctest::Contains("cannot read"), std::runtime_error);

    ExrImage bad{4, 4, {0, 0, 4, 4}, {{"R", std::vector<float>(15)}}, {}};
    const auto target = scratch("bad.exr");
    std::filesystem::remove(target);
    CHECK_THROWS_WITH_AS(write_exr(bad, target), doctest::Contains("channel 'R' has 15 values for 16 pixels"), std::runtime_error);
    CHECK(!std::filesystem::exists(target));
    bad.channels = {{"R", std::vector<float>(16)}, {"R", std::vector<float>(16)}};
    CHECK_THROWS_WITH_AS(write_exr(bad, target), doctest::Contains("two channels named 'R'"), std::runtime_error);
    bad.window = {0, 0, 5, 4};
    CHECK_THROWS_WITH_AS(write_exr(bad, target), doctest::Contains("data window"), std::runtime_error);
    CHECK(!std::filesystem::exists(target));
    CHECK_THROWS_WITH_AS(write_exr(to_exr(Film(2, 2)), std::filesystem::temp_directory_path()), doctest::Contains("is a directory"), std::runtime_error);
}

TEST_CASE("an EXR whose data window claims more pixels than its bytes can hold is refused before allocating")
{
    // Regression: 262 KB declaring a 65536 x 32768 data window and no pixel data allocated
    // 8.4 GB before "Scan line 0 is missing".
    const auto small = scratch("claim.exr");
    write_exr(to_exr(Film(1, 1)), small);
    std::ifstream in(small, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    in.close();
    for (const std::string name : {"dataWindow", "displayWindow"}) {
        const std::size_t at = bytes.find(name + std::string(1, '\0') + "box2i");
        REQUIRE(at != std::string::npos);
        const std::size_t value = at + name.size() + 1 + 6 + 4; // name, NUL, "box2i", NUL, size
        const std::int32_t box[4] = {0, 0, 65535, 32767};
        std::memcpy(bytes.data() + value, box, sizeof box); // EXR is little-endian, as is this test's host
    }
    bytes += std::string(262144, '\0');
    std::ofstream(small, std::ios::binary | std::ios::trunc) << bytes;
    CHECK_THROWS_WITH_AS((void)read_exr(small), doctest::Contains("its data window [0, 65535] x [0, 32767] of 3 channels needs 24.0 GiB"), std::runtime_error);
}

// Regression: OpenEXR out of memory came out as "cannot read image '...': std::bad_alloc",
// a std::runtime_error. It is an allocation_error that says so.
TEST_CASE("read_exr out of memory names its file")
{
    if (test::sanitized) return; // a sanitizer keeps its own operator new
    // 2048 x 2048 zeros (16 MiB as floats), written from one row (a y stride of 0).
    const auto path = scratch("zeros.exr");
    {
        Imf::Header header(2048, 2048);
        header.compression() = Imf::ZIP_COMPRESSION;
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(path.c_str(), header);
        std::vector<float> row(2048, 0.0f);
        Imf::FrameBuffer frame;
        frame.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(row.data()), sizeof(float), 0));
        file.setFrameBuffer(frame);
        file.writePixels(2048);
    }
    const std::string thrown = test::thrown_with_memory_short(std::size_t(2) << 20, [&] { (void)read_exr(path); });
    MESSAGE(thrown);
    CHECK(thrown.starts_with("allocation_error: prism: cannot read image '" + path.string() + "': out of memory while reading it (a file of"));
    std::filesystem::remove(path);
}

TEST_CASE("an EXR image is radiance from its R, G, B or grey Y channels, over the whole picture, and nothing else")
{
    ExrImage rgb{3, 2, {0, 0, 3, 2}, {}, {}};
    rgb.channels = {{"B", std::vector<float>{6, 5, 4, 3, 2, 1}}, {"G", std::vector<float>(6, 0.5f)}, {"R", std::vector<float>{0, 1, 2, 3, 4, 1e30f}}};
    const auto path = scratch("radiance.exr");
    write_exr(rgb, path);
    const Film film = read_exr(path).film();
    REQUIRE(film.width() == 3);
    CHECK(film.at(2, 1) == Rgb<float>(1e30f, 0.5f, 1));
    CHECK(film.at(1, 0) == Rgb<float>(1, 0.5f, 5));
    ExrImage grey{2, 1, {0, 0, 2, 1}, {{"Y", std::vector<float>{0.25f, 8}}}, {}};
    CHECK(grey.film().at(1, 0) == Rgb<float>(8));
    const auto refused = [](const ExrImage& image) {
        try {
            (void)image.film();
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    ExrImage negative = rgb;
    std::get<0>(negative.channels[0].values)[4] = -2;
    CHECK(refused(negative) == "prism: EXR pixel (1, 1) holds -2.000000 in B, which radiance cannot be (a Film holds finite values >= 0; "
                               "film(NegativeValues::to_zero) stores negatives as 0 and counts them)");
    // Asked to, negatives become 0 and are counted; NaN is refused all the same.
    const Film zeroed = negative.film(NegativeValues::to_zero);
    CHECK(zeroed.at(1, 1) == Rgb<float>(4, 0.5f, 0));
    CHECK(zeroed.rejected() == 1);
    std::get<0>(negative.channels[1].values)[0] = NAN;
    CHECK_THROWS_WITH_AS((void)negative.film(NegativeValues::to_zero), "prism: EXR pixel (0, 0) holds nan in G, which radiance cannot be (a Film holds finite values >= 0)",
                         std::runtime_error);
    ExrImage counts = grey;
    counts.channels[0].values = std::vector<std::uint32_t>{1, 2};
    CHECK(refused(counts) == "prism: the EXR image's channel 'Y' holds whole numbers (UINT), not radiance");
    ExrImage partial = rgb;
    partial.window = {0, 0, 3, 1};
    CHECK(refused(partial).find("data window does not cover its 3 x 2 pixels") != std::string::npos);
    ExrImage alpha{1, 1, {0, 0, 1, 1}, {{"R", std::vector<float>{1}}, {"A", std::vector<float>{1}}}, {}};
    CHECK(refused(alpha) == "prism: the EXR image has neither R, G and B channels nor a grey Y channel");
}
