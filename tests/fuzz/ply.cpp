// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as a PLY file. load_ply refuses them with std::runtime_error, or
// returns a mesh whose every index names a vertex, every position, normal and coordinate
// finite, and never more items than the bytes it was given could hold.
#include "file.hpp"

#include <prism/io/mesh.hpp>

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path path = fuzz::as_file(data, size, ".ply");
    try {
        const prism::MeshBuffers<float> mesh = prism::load_ply<float>(path, fuzz::limits);
        fuzz::check_mesh(mesh, size);
    } catch (const std::runtime_error&) {
    }
    return 0;
}
