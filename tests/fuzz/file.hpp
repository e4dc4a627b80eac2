// SPDX-License-Identifier: MIT
// What the file readers' fuzz targets share: the fuzzer's bytes written to a file of this
// process's own, for a reader that takes a path, read no further than a small limit.
#pragma once

#include "check.hpp"

#include <prism/io/input.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace fuzz {

/// The limit every reader is given: a fuzz input is never longer.
inline constexpr prism::ReadLimits limits{.max_bytes = 1 << 20};

/// A file of this process's own in the temporary folder ($TMPDIR), named with `extension`,
/// removed when the process exits (libFuzzer's end of a run included; a crash leaves it, and
/// its input is kept apart anyway). Call it once for each file, from a static's initializer.
inline std::filesystem::path process_file(const char* extension)
{
    struct Removed {
        std::vector<std::filesystem::path> paths;
        ~Removed()
        {
            std::error_code ignored;
            for (const auto& path : paths) std::filesystem::remove(path, ignored);
        }
    };
    static Removed removed;
    removed.paths.push_back(std::filesystem::temp_directory_path() / ("prism-fuzz-" + std::to_string(::getpid()) + extension));
    return removed.paths.back();
}

/// The bytes as the whole of a file named with `extension`, the same file for every input
/// of this process.
inline std::filesystem::path as_file(const std::uint8_t* data, std::size_t size, const char* extension)
{
    static const std::filesystem::path path = process_file(extension);
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return path;
}

/// What a mesh reader returns, checked: at least one triangle, never more vertices and
/// triangles than `size` bytes could hold, normals and coordinates one per vertex or none,
/// every value finite, every index naming a vertex.
template <class Mesh>
void check_mesh(const Mesh& mesh, std::size_t size)
{
    FUZZ_CHECK(!mesh.triangles.empty());
    FUZZ_CHECK(mesh.positions.size() + mesh.triangles.size() <= size);
    FUZZ_CHECK(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size());
    FUZZ_CHECK(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size());
    for (const auto& p : mesh.positions) FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    for (const auto& n : mesh.normals) FUZZ_CHECK(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    for (const auto& t : mesh.uvs) FUZZ_CHECK(std::isfinite(t.x) && std::isfinite(t.y));
    for (const auto& f : mesh.triangles)
        for (const auto v : f) FUZZ_CHECK(v < mesh.positions.size());
}

} // namespace fuzz
