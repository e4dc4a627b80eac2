// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as an EXR file, read as prism_merge reads a part: read_exr
// refuses them with std::runtime_error, or returns channels that fill their data window,
// never more samples than the bytes could hold compressed; to_accumulation refuses an
// image without exact sums, or adds up what it holds; its digest is 16 hexadecimal digits.
#include "file.hpp"

#include <prism/io/exr.hpp>

#include <stdexcept>
#include <string>
#include <variant>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path path = fuzz::as_file(data, size, ".exr");
    try {
        const prism::ExrImage image = prism::read_exr(path);
        FUZZ_CHECK(!image.window.empty() && prism::PixelWindow::whole(image.width, image.height).contains(image.window));
        double samples = 0;
        for (const prism::ExrChannel& c : image.channels) {
            const std::size_t n = std::holds_alternative<std::vector<float>>(c.values) ? std::get<0>(c.values).size() : std::get<1>(c.values).size();
            FUZZ_CHECK(n == image.window.area());
            samples += double(n);
        }
        const std::string digest = prism::exr_digest(image);
        FUZZ_CHECK(digest.size() == 16 && digest.find_first_not_of("0123456789abcdef") == std::string::npos);
        FUZZ_CHECK(4.0 * samples <= 1032.0 * double(size) + double(1 << 20));
        try {
            const prism::Accumulation sums = prism::to_accumulation(image);
            FUZZ_CHECK(sums.window() == image.window);
        } catch (const std::invalid_argument&) {
        }
    } catch (const std::runtime_error&) {
    }
    return 0;
}
