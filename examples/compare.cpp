// SPDX-License-Identifier: MIT
// Side by side with POV-Ray, compiled once for the examples that compare.
#include "compare.hpp"

#include "cli.hpp"

#include <prism/io/image.hpp>
#include <prism/io/output.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace examples {

/// Write `out` with prism's film, POV-Ray's PNG of the same scene and their difference
/// (in 8-bit sRGB, amplified 4 times), and print the mean difference.
void write_comparison(const prism::Film& film, const std::string& povray_png, const std::string& out)
{
    const prism::Film pov = prism::read_png(povray_png);
    if (pov.width() != film.width() || pov.height() != film.height())
        throw std::invalid_argument("--povray: " + povray_png + " is " + std::to_string(pov.width()) + "x" +
                                    std::to_string(pov.height()) + ", prism rendered " + std::to_string(film.width()) + "x" +
                                    std::to_string(film.height()));
    const int w = film.width(), h = film.height();
    const auto ours = prism::to_srgb8(film), theirs = prism::to_srgb8(pov);
    prism::Film side(3 * w, h);
    double total = 0;
    long far = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
            prism::Rgb<float> diff;
            int largest = 0;
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(ours[i + c]) - int(theirs[i + c]));
                total += d;
                largest = std::max(largest, d);
                const float encoded = std::min(1.0f, 4.0f * float(d) / 255.0f);
                diff[c] = encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
            }
            far += largest > 16;
            side.set(x, y, film.at(x, y));
            side.set(w + x, y, pov.at(x, y));
            side.set(2 * w + x, y, diff);
        }
    examples::outputs().add(out, prism::encode_png(side)); // written with the render's own images
    std::printf("compared with %s: mean |prism - POV-Ray| = %.2f of 255, %.2f%% of pixels differ by more than 16; wrote %s\n",
                povray_png.c_str(), total / (3.0 * w * h), 100.0 * double(far) / double(w * h), out.c_str());
}

} // namespace examples
