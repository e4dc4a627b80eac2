// SPDX-License-Identifier: MIT
// Side by side with POV-Ray: prism | POV-Ray | 4 x |difference|, and how far apart they are
// (compare.cpp).
#pragma once

#include <prism/render/film.hpp>

#include <string>

namespace examples {

/// Write `out` with prism's film, POV-Ray's PNG of the same scene and their difference
/// (in 8-bit sRGB, amplified 4 times), and print the mean difference.
void write_comparison(const prism::Film& film, const std::string& povray_png, const std::string& out);

} // namespace examples
