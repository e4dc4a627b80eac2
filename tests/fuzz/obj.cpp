// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as an OBJ file. load_obj refuses them with std::runtime_error, or
// returns a mesh whose every index names a vertex and every value is finite, with no more
// vertices and triangles than the bytes it was given could hold.
#include "file.hpp"

#include <prism/io/mesh.hpp>

#include <cmath>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path path = fuzz::as_file(data, size, ".obj");
    try {
        const prism::MeshBuffers<float> mesh = prism::load_obj<float>(path, fuzz::limits);
        FUZZ_CHECK(!mesh.triangles.empty());
        FUZZ_CHECK(mesh.triangles.size() <= size);
        FUZZ_CHECK(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size());
        FUZZ_CHECK(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size());
        for (const auto& p : mesh.positions) FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        for (const auto& n : mesh.normals) FUZZ_CHECK(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        for (const auto& t : mesh.uvs) FUZZ_CHECK(std::isfinite(t.x) && std::isfinite(t.y));
        for (const auto& f : mesh.triangles)
            for (const std::uint32_t v : f) FUZZ_CHECK(v < mesh.positions.size());
    } catch (const std::runtime_error&) {
    }
    return 0;
}
