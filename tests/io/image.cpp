// SPDX-License-Identifier: MIT
#include <prism/io/image.hpp>

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
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
    const prism::Film back = prism::read_pfm(dir / "g.pfm");
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
    // Issue 10: the temporary file was renamed over any target, so a FIFO, a device node
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
    CHECK(prism::read_pfm(real).pixels() == film.pixels());
    int leftovers = 0;
    for (const auto& entry : fs::directory_iterator(dir)) leftovers += entry.path().string().find("prism-partial") != std::string::npos;
    CHECK(leftovers == 0);
    fs::remove_all(dir);
}

TEST_CASE("read_pfm checks its header against the file's size before allocating")
{
    // Issue 10: 20 bytes made read_pfm allocate 4.8 GB before it reported truncation.
    const fs::path dir = scratch_folder("pfm-header");
    std::ofstream(dir / "big.pfm", std::ios::binary) << "PF\n20000 20000\n-1.0\n";
    CHECK_THROWS_WITH_AS((void)prism::read_pfm(dir / "big.pfm"), doctest::Contains("truncated"), std::runtime_error);
    CHECK_THROWS_WITH_AS((void)prism::read_pfm(dir / "big.pfm"), doctest::Contains("20000 x 20000"), std::runtime_error);
    std::ofstream(dir / "nan.pfm", std::ios::binary) << "PF\n1 1\nnan\n";
    CHECK_THROWS_AS((void)prism::read_pfm(dir / "nan.pfm"), std::runtime_error);
    fs::remove_all(dir);
}
