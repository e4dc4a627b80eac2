// SPDX-License-Identifier: MIT
// What the file readers' fuzz targets share: the fuzzer's bytes written to a file of this
// process's own, for a reader that takes a path, read no further than a small limit.
#pragma once

#include "check.hpp"

#include <prism/io/input.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace fuzz {

/// The limit every reader is given: a fuzz input is never longer.
inline constexpr prism::ReadLimits limits{.max_bytes = 1 << 20};

/// The bytes as the whole of a file named with `extension`, the same file for every input
/// of this process.
inline std::filesystem::path as_file(const std::uint8_t* data, std::size_t size, const char* extension)
{
    static const std::filesystem::path path = std::filesystem::temp_directory_path() / ("prism-fuzz-" + std::to_string(::getpid()) + extension);
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return path;
}

} // namespace fuzz
