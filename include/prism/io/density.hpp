// SPDX-License-Identifier: MIT
// Density grids in a file: prism's raw format, three lines of text and the values.
//
//     prism density 1
//     NX NY NZ
//     X0 Y0 Z0 X1 Y1 Z1
//     <NX NY NZ little-endian IEEE-754 float32 values, x fastest, then y, then z>
//
// Each text line ends in "\n" (or "\r\n"); fields are separated by single spaces or
// tabs. NX, NY, NZ are whole numbers of at least 2 (the lattice's points on each axis);
// (X0, Y0, Z0) and (X1, Y1, Z1) the box's least and greatest corners, the lattice's first
// and last points. Every value must be finite and >= 0, and nothing may follow the last
// one. A simulation's grid is written by any language in a few lines (numpy:
// `f.write(header); f.write(values.astype('<f4').tobytes())`).
#pragma once

#include <prism/core/check.hpp>
#include <prism/io/input.hpp>
#include <prism/io/output.hpp>
#include <prism/medium/density.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace prism {

/// Read a density grid in prism's raw format (above). Every claim is checked: the values
/// its header counts against a regular file's size before anything is allocated, each
/// value finite and >= 0. Throws std::runtime_error naming the file and what is wrong.
template <Scalar T = float>
[[nodiscard]] DensityGrid<T> read_density_grid(const std::filesystem::path& path, ReadLimits limits = {})
try {
    detail::InputFile file(path, "density grid", limits);
    const auto line = [&](const char* what) {
        auto text = file.line(256, std::string("its ") + what + " line");
        if (!text) file.fail(std::string("it ends before its ") + what + " line");
        return *text;
    };
    if (line("first") != "prism density 1") file.fail("its first line is not 'prism density 1'");
    const auto fields = [&](const std::string& text, std::size_t count, const char* what) {
        std::vector<std::string> out;
        std::string field;
        for (const char c : text + ' ') {
            if (c == ' ' || c == '\t') {
                if (!field.empty()) out.push_back(field);
                field.clear();
            } else {
                field.push_back(c);
            }
        }
        if (out.size() != count) file.fail(std::string("its ") + what + " line '" + text + "' does not hold " + std::to_string(count) + " fields");
        return out;
    };
    const std::vector<std::string> counts = fields(line("size"), 3, "size");
    int n[3];
    for (int a = 0; a < 3; ++a) {
        const std::string& text = counts[std::size_t(a)];
        if (text.find_first_not_of("0123456789") != std::string::npos || text.size() > 9 || std::stol(text) < 2)
            file.fail("its point count '" + text + "' on axis " + "xyz"[a] + " is not a whole number from 2 to 999999999");
        n[a] = int(std::stol(text));
    }
    const std::vector<std::string> corners = fields(line("box"), 6, "box");
    T corner[6];
    for (int i = 0; i < 6; ++i) {
        const std::string& text = corners[std::size_t(i)];
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end != text.c_str() + text.size() || !std::isfinite(value) || !std::isfinite(T(value)))
            file.fail("its box coordinate '" + text + "' is not a finite number");
        corner[i] = T(value);
    }
    const Aabb<T> box{{corner[0], corner[1], corner[2]}, {corner[3], corner[4], corner[5]}};
    if (!(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z))
        file.fail("its box's least corner is not below its greatest on every axis");
    const std::string size = std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]);
    const auto count = detail::checked_product(std::uint64_t(n[0]) * std::uint64_t(n[1]), std::uint64_t(n[2]));
    const auto bytes = count ? detail::checked_product(*count, 4) : std::nullopt;
    if (!bytes) file.fail("its header says " + size + " values, more bytes than a file can hold");
    std::vector<unsigned char> raw;
    file.read(raw, *bytes, "the header's " + size + " values");
    if (!file.at_end()) file.fail("bytes follow its " + size + " values");
    std::vector<float> values(static_cast<std::size_t>(*count));
    for (std::size_t i = 0; i < values.size(); ++i) {
        unsigned char* b = raw.data() + 4 * i;
        if constexpr (std::endian::native == std::endian::big) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
        std::memcpy(&values[i], b, 4);
        if (!(std::isfinite(values[i]) && values[i] >= 0.0f)) {
            std::ostringstream where;
            where << "its value " << i << " (x " << i % std::size_t(n[0]) << ", y " << i / std::size_t(n[0]) % std::size_t(n[1]) << ", z "
                  << i / (std::size_t(n[0]) * std::size_t(n[1])) << ") is " << values[i] << ", not finite and >= 0";
            file.fail(where.str());
        }
    }
    return DensityGrid<T>(n[0], n[1], n[2], box, std::move(values));
} catch (const allocation_error&) {
    throw;
} catch (const std::bad_alloc&) {
    throw detail::out_of_memory(path, "density grid");
}

/// Write `grid` in prism's raw format, all or nothing (a failed write leaves no file).
template <Scalar T>
void write_density_grid(const std::filesystem::path& path, const DensityGrid<T>& grid)
{
    std::ostringstream out;
    out.precision(9);
    const Aabb<T> box = grid.bounds();
    out << "prism density 1\n" << grid.points(0) << ' ' << grid.points(1) << ' ' << grid.points(2) << '\n';
    out << double(box.lo.x) << ' ' << double(box.lo.y) << ' ' << double(box.lo.z) << ' ' << double(box.hi.x) << ' ' << double(box.hi.y) << ' ' << double(box.hi.z) << '\n';
    const std::string header = out.str();
    std::vector<unsigned char> bytes(header.begin(), header.end());
    for (float v : grid.values()) {
        unsigned char b[4];
        std::memcpy(b, &v, 4);
        if constexpr (std::endian::native == std::endian::big) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
        bytes.insert(bytes.end(), b, b + 4);
    }
    OutputSet files;
    files.add(path, std::move(bytes));
    files.commit();
}

} // namespace prism
