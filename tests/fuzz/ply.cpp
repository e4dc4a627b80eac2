// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as a PLY file. load_ply refuses them with std::runtime_error, or
// returns a mesh whose every index names a vertex, every position, normal and coordinate
// finite, and never more items than the bytes it was given could hold.
#include "file.hpp"

#include <prism/io/mesh.hpp>

#include <cmath>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path path = fuzz::as_file(data, size, ".ply");
    try {
        const prism::MeshBuffers<float> mesh = prism::load_ply<float>(path, fuzz::limits);
        FUZZ_CHECK(!mesh.triangles.empty());
        FUZZ_CHECK(mesh.positions.size() + mesh.triangles.size() <= size);
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
