// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as a JPEG file. read_jpeg refuses them with std::runtime_error, or
// returns a picture no larger than its bytes can hold, every pixel in [0, 1].
#include "file.hpp"

#include <prism/io/image.hpp>

#include <cmath>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path path = fuzz::as_file(data, size, ".jpg");
    try {
        const prism::Film film = prism::read_jpeg(path, fuzz::limits);
        FUZZ_CHECK(film.width() >= 1 && film.height() >= 1);
        FUZZ_CHECK(double(film.width()) * double(film.height()) <= 256.0 * double(size) + 65536.0);
        for (const prism::Rgb<float>& p : film.pixels()) FUZZ_CHECK(std::isfinite(p.x) && p.x >= 0 && p.x <= 1 && std::isfinite(p.y) && p.y >= 0 && p.y <= 1 && std::isfinite(p.z) && p.z >= 0 && p.z <= 1);
    } catch (const std::runtime_error&) {
    }
    return 0;
}
