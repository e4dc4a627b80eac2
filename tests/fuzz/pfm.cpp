// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as a PFM file. read_pfm refuses them with std::runtime_error, or
// returns the pixels its header claims, never more than the bytes it was given; a Film is
// made of them only where every value is radiance.
#include "file.hpp"

#include <prism/io/image.hpp>

#include <cmath>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path path = fuzz::as_file(data, size, ".pfm");
    try {
        const prism::PfmImage image = prism::read_pfm(path, fuzz::limits);
        FUZZ_CHECK(image.width >= 1 && image.height >= 1 && (image.channels == 1 || image.channels == 3));
        FUZZ_CHECK(image.values.size() == std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels));
        FUZZ_CHECK(4 * image.values.size() < size);
        FUZZ_CHECK(std::isfinite(image.scale) && image.scale != 0);
        try {
            const prism::Film film = image.film();
            for (const prism::Rgb<float>& p : film.pixels()) FUZZ_CHECK(std::isfinite(p.x) && p.x >= 0 && std::isfinite(p.y) && p.y >= 0 && std::isfinite(p.z) && p.z >= 0);
        } catch (const std::runtime_error&) {
        }
    } catch (const std::runtime_error&) {
    }
    return 0;
}
