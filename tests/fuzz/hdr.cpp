// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as a Radiance HDR file. read_hdr refuses them with
// std::runtime_error, or returns a picture its bytes pay for (a run-length encoded row
// holds at most 127 values of a channel in 2 bytes), every pixel radiance.
#include "file.hpp"

#include <prism/io/image.hpp>

#include <cmath>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path path = fuzz::as_file(data, size, ".hdr");
    try {
        const prism::Film film = prism::read_hdr(path, fuzz::limits);
        FUZZ_CHECK(film.width() >= 1 && film.height() >= 1);
        FUZZ_CHECK(double(film.width()) * double(film.height()) <= 127.0 / 8.0 * double(size));
        for (const prism::Rgb<float>& p : film.pixels()) FUZZ_CHECK(std::isfinite(p.x) && p.x >= 0 && std::isfinite(p.y) && p.y >= 0 && std::isfinite(p.z) && p.z >= 0);
    } catch (const std::runtime_error&) {
    }
    return 0;
}
