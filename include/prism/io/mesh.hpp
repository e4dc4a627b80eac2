// SPDX-License-Identifier: MIT
// Mesh files: Wavefront OBJ through tinyobjloader (Debian: libtinyobjloader-dev).
//
// Opt-in: prism/prism.hpp does not include this header, and a program that does links
// tinyobjloader (the CMake target prism::mesh_io does both). Polygons are split into
// triangles (tinyobjloader's fan), every group of the file goes into one MeshBuffers,
// positions are read as float (tinyobjloader's real_t), normals and texture
// coordinates in the file are not read. Any failure throws
// std::runtime_error naming the path and the reason.
#pragma once

#include <prism/geometry/mesh_builders.hpp>

#include <tiny_obj_loader.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace prism {

/// The triangles of an OBJ file, as counter-clockwise as the file winds them.
template <Scalar T = float>
[[nodiscard]] MeshBuffers<T> load_obj(const std::filesystem::path& path)
{
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path.string(), config)) {
        std::string reason = reader.Error();
        while (!reason.empty() && (reason.back() == '\n' || reason.back() == '\r')) reason.pop_back();
        throw std::runtime_error("cannot read mesh '" + path.string() + "': " + (reason.empty() ? "unknown error" : reason));
    }
    const auto& attrib = reader.GetAttrib();
    MeshBuffers<T> out;
    out.positions.reserve(attrib.vertices.size() / 3);
    for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
        out.positions.push_back({T(attrib.vertices[i]), T(attrib.vertices[i + 1]), T(attrib.vertices[i + 2])});
    for (const auto& shape : reader.GetShapes()) {
        const auto& indices = shape.mesh.indices;
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
            TriangleIndices f{};
            for (std::size_t k = 0; k < 3; ++k) {
                const int v = indices[i + k].vertex_index;
                if (v < 0 || std::size_t(v) >= out.positions.size())
                    throw std::runtime_error("cannot read mesh '" + path.string() + "': a face refers to vertex " + std::to_string(v) + " of " + std::to_string(out.positions.size()));
                f[k] = std::uint32_t(v);
            }
            out.triangles.push_back(f);
        }
    }
    if (out.triangles.empty()) throw std::runtime_error("cannot read mesh '" + path.string() + "': it has no faces");
    return out;
}

} // namespace prism
