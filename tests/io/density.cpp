// SPDX-License-Identifier: MIT
#include <prism/io/density.hpp>

#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace prism;

namespace {

std::filesystem::path density_scratch(const std::string& name) { return std::filesystem::temp_directory_path() / ("prism_density_" + name); }

/// A file of `header` and then `values` as little-endian float32.
std::filesystem::path density_file_of(const std::string& name, const std::string& header, const std::vector<float>& values)
{
    const auto path = density_scratch(name);
    std::ofstream out(path, std::ios::binary);
    out << header;
    for (float v : values) {
        unsigned char b[4];
        std::memcpy(b, &v, 4);
        out.write(reinterpret_cast<const char*>(b), 4);
    }
    return path;
}

std::string density_refusal(const std::filesystem::path& path)
{
    try {
        (void)read_density_grid(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "accepted";
}

} // namespace

TEST_CASE("a density grid written in prism's raw format reads back bit for bit, and a file written by hand (CRLF, tabs) reads")
{
    std::vector<float> values;
    for (int i = 0; i < 3 * 2 * 4; ++i) values.push_back(0.125f * float(i) + 1e-7f * float(i * i));
    const DensityGrid<float> grid(3, 2, 4, {{-1.5f, 0, 2}, {1, 0.1f, 3.75f}}, values);
    const auto path = density_scratch("round_trip.density");
    write_density_grid(path, grid);
    const DensityGrid<float> back = read_density_grid(path);
    CHECK(back.points(0) == 3);
    CHECK(back.points(1) == 2);
    CHECK(back.points(2) == 4);
    CHECK(back.values() == values);
    CHECK(back.bounds().lo.x == -1.5f);
    CHECK(back.bounds().hi.y == 0.1f);
    CHECK(back.bounds().hi.z == 3.75f);
    CHECK(back.density({0, 0.05f, 3}) == grid.density({0, 0.05f, 3}));
    // By hand: the numbers as a user would type them.
    const auto hand = density_file_of("hand.density", "prism density 1\r\n2\t2 2\r\n0 0 0  1 1 1\n", {0, 1, 2, 3, 4, 5, 6, 7});
    const DensityGrid<double> read = read_density_grid<double>(hand);
    CHECK(read.density({1, 1, 1}) == 7);
    CHECK(read.density({0.5, 0.5, 0.5}) == doctest::Approx(3.5));
    std::filesystem::remove(path);
    std::filesystem::remove(hand);
}

TEST_CASE("a density grid file is refused, naming what is wrong: magic, counts, box, values, length")
{
    const std::string box = "0 0 0 1 1 1\n";
    const std::vector<float> eight(8, 1.0f);
    CHECK(density_refusal(density_file_of("magic", "prism density 2\n2 2 2\n" + box, eight)).find("'prism density 1'") != std::string::npos);
    CHECK(density_refusal(density_file_of("count", "prism density 1\n2 1 2\n" + box, std::vector<float>(4, 1.0f))).find("point count '1' on axis y") != std::string::npos);
    CHECK(density_refusal(density_file_of("fields", "prism density 1\n2 2\n" + box, eight)).find("does not hold 3 fields") != std::string::npos);
    CHECK(density_refusal(density_file_of("sign", "prism density 1\n2 -2 2\n" + box, eight)).find("'-2'") != std::string::npos);
    CHECK(density_refusal(density_file_of("box", "prism density 1\n2 2 2\n0 0 0 1 nan 1\n", eight)).find("box coordinate 'nan'") != std::string::npos);
    CHECK(density_refusal(density_file_of("flat", "prism density 1\n2 2 2\n0 0 0 1 0 1\n", eight)).find("least corner is not below") != std::string::npos);
    std::vector<float> negative = eight;
    negative[6] = -2;
    CHECK(density_refusal(density_file_of("negative", "prism density 1\n2 2 2\n" + box, negative)).find("value 6 (x 0, y 1, z 1) is -2") != std::string::npos);
    CHECK(density_refusal(density_file_of("short", "prism density 1\n2 2 2\n" + box, std::vector<float>(7, 1.0f))).find("truncated") != std::string::npos);
    CHECK(density_refusal(density_file_of("long", "prism density 1\n2 2 2\n" + box, std::vector<float>(9, 1.0f))).find("bytes follow") != std::string::npos);
    // A header that claims 10^26 bytes is refused before anything is allocated.
    CHECK(density_refusal(density_file_of("huge", "prism density 1\n999999999 999999999 999999999\n" + box, eight)).find("more bytes than a file can hold") != std::string::npos);
    CHECK(density_refusal(density_file_of("big", "prism density 1\n1000 1000 1000\n" + box, eight)).find("needs 4000000000 bytes, but 32 follow") != std::string::npos);
    CHECK(density_refusal(density_file_of("empty", "", {})).find("ends before its first line") != std::string::npos);
    CHECK(density_refusal(density_scratch("missing_file")).find("prism_density_missing_file") != std::string::npos);
    for (const char* name : {"magic", "count", "fields", "sign", "box", "flat", "negative", "short", "long", "huge", "big", "empty"}) std::filesystem::remove(density_scratch(name));
}
