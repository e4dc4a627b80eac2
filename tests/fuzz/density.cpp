// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as a density grid file. read_density_grid refuses them with
// std::runtime_error, or returns the grid its header claims, never more values than the
// bytes it was given, every one finite and >= 0; a medium made of it tracks a ray
// through its box to a transmittance in [0, 1].
#include "file.hpp"

#include <prism/io/density.hpp>
#include <prism/medium/varying_fog.hpp>

#include <cmath>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path path = fuzz::as_file(data, size, ".density");
    try {
        const prism::DensityGrid<float> grid = prism::read_density_grid(path, fuzz::limits);
        FUZZ_CHECK(grid.points(0) >= 2 && grid.points(1) >= 2 && grid.points(2) >= 2);
        FUZZ_CHECK(grid.values().size() == std::size_t(grid.points(0)) * std::size_t(grid.points(1)) * std::size_t(grid.points(2)));
        FUZZ_CHECK(4 * grid.values().size() < size);
        for (float v : grid.values()) FUZZ_CHECK(std::isfinite(v) && v >= 0);
        try {
            const prism::VaryingFog fog(grid, prism::Rgb<float>(0.1f), prism::Rgb<float>(0.5f), {}, 2);
            const prism::Aabb<float> box = grid.bounds();
            const prism::Vec3<float> centre = 0.5f * (box.lo + box.hi);
            const prism::Rgb<float> tr = fog.transmittance({centre - prism::Vec3<float>(1, 0, 0), {1, 0, 0}}, 2.0f);
            for (int c = 0; c < 3; ++c) FUZZ_CHECK(tr[c] >= 0 && tr[c] <= 1);
        } catch (const std::invalid_argument&) {
        }
    } catch (const std::runtime_error&) {
    }
    return 0;
}
