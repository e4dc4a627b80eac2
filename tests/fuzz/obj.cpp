// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as an OBJ file. load_obj refuses them with std::runtime_error, or
// returns a mesh whose every index names a vertex and every value is finite, with no more
// vertices and triangles than the bytes it was given could hold.
#include "file.hpp"

#include <prism/io/mesh.hpp>

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path path = fuzz::as_file(data, size, ".obj");
    try {
        const prism::MeshBuffers<float> mesh = prism::load_obj<float>(path, fuzz::limits);
        fuzz::check_mesh(mesh, size);
    } catch (const std::runtime_error&) {
    }
    return 0;
}
