// SPDX-License-Identifier: MIT
// Mesh files: Wavefront OBJ through tinyobjloader (Debian: libtinyobjloader-dev), and
// PLY (ASCII and binary, either byte order) read here.
//
// Opt-in: prism/prism.hpp does not include this header, and a program that does links
// tinyobjloader (the CMake target prism::mesh_io does both). Polygons are split into
// triangles (a fan from their first vertex), every group of the file goes into one
// MeshBuffers; OBJ positions are read as float (tinyobjloader's real_t); normals, texture
// coordinates and other properties in the file are not read. Any failure throws
// std::runtime_error naming the path and the reason. load_mesh picks the reader by the
// file's extension.
#pragma once

#include <prism/geometry/mesh_builders.hpp>

#include <tiny_obj_loader.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

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

namespace detail {

/// One property of a PLY element: a scalar, or a list (its count's type and its items').
struct PlyProperty {
    std::string name;
    std::string type;       ///< the scalar's type, or the list items' type
    std::string count_type; ///< empty for a scalar
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

inline std::size_t ply_type_size(const std::string& type)
{
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

/// Reads PLY values one at a time, as text or as binary of either byte order.
class PlyReader {
public:
    PlyReader(std::istream& in, int format, std::string path) : in_(in), format_(format), path_(std::move(path)) {}

    double value(const std::string& type)
    {
        if (format_ == 0) {
            double v = 0;
            if (!(in_ >> v)) fail("the data ends early or holds a word that is not a number");
            return v;
        }
        const std::size_t size = ply_type_size(type);
        unsigned char bytes[8] = {};
        if (!in_.read(reinterpret_cast<char*>(bytes), std::streamsize(size))) fail("the data ends early");
        const bool swap = (format_ == 1) != (std::endian::native == std::endian::little);
        if (swap) std::reverse(bytes, bytes + size);
        const auto as = [&]<class V>(V) {
            V v;
            std::memcpy(&v, bytes, sizeof v);
            return double(v);
        };
        if (type == "char" || type == "int8") return as(std::int8_t{});
        if (type == "uchar" || type == "uint8") return as(std::uint8_t{});
        if (type == "short" || type == "int16") return as(std::int16_t{});
        if (type == "ushort" || type == "uint16") return as(std::uint16_t{});
        if (type == "int" || type == "int32") return as(std::int32_t{});
        if (type == "uint" || type == "uint32") return as(std::uint32_t{});
        if (type == "float" || type == "float32") return as(float{});
        return as(double{});
    }

    [[noreturn]] void fail(const std::string& reason) const { throw std::runtime_error("cannot read mesh '" + path_ + "': " + reason); }

private:
    std::istream& in_;
    int format_; ///< 0 ascii, 1 little endian, 2 big endian
    std::string path_;
};

} // namespace detail

/// The triangles of a PLY file (its vertex element's x, y, z and its face element's
/// vertex_indices or vertex_index list), in ASCII or binary of either byte order.
template <Scalar T = float>
[[nodiscard]] MeshBuffers<T> load_ply(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    const std::string name = path.string();
    const auto fail = [&](const std::string& reason) -> void { throw std::runtime_error("cannot read mesh '" + name + "': " + reason); };
    if (!in) fail(std::strerror(errno));
    std::string line;
    if (!std::getline(in, line) || line.substr(0, 3) != "ply") fail("it does not start with 'ply'");
    int format = -1;
    std::vector<detail::PlyElement> elements;
    for (;;) {
        if (!std::getline(in, line)) fail("its header has no end_header");
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word == "end_header") break;
        if (word == "format") {
            std::string kind;
            words >> kind;
            format = kind == "ascii" ? 0 : kind == "binary_little_endian" ? 1 : kind == "binary_big_endian" ? 2 : -1;
            if (format < 0) fail("its format '" + kind + "' is not ascii, binary_little_endian or binary_big_endian");
        } else if (word == "element") {
            detail::PlyElement element;
            if (!(words >> element.name >> element.count)) fail("a header line '" + line + "' has no element name and count");
            elements.push_back(element);
        } else if (word == "property") {
            if (elements.empty()) fail("a property comes before any element");
            detail::PlyProperty property;
            std::string type;
            words >> type;
            if (type == "list") words >> property.count_type >> property.type >> property.name;
            else property.type = type, words >> property.name;
            if (detail::ply_type_size(property.type) == 0 || (!property.count_type.empty() && detail::ply_type_size(property.count_type) == 0))
                fail("the property line '" + line + "' has a type PLY does not define");
            elements.back().properties.push_back(property);
        }
        // comment, obj_info and anything else: skipped.
    }
    if (format < 0) fail("its header has no format line");
    detail::PlyReader reader(in, format, name);
    MeshBuffers<T> out;
    for (const detail::PlyElement& element : elements) {
        const bool vertices = element.name == "vertex", faces = element.name == "face";
        int axis_of[3] = {-1, -1, -1};
        if (vertices) {
            for (std::size_t k = 0; k < element.properties.size(); ++k)
                for (int a = 0; a < 3; ++a)
                    if (element.properties[k].name == std::string(1, char('x' + a)) && element.properties[k].count_type.empty()) axis_of[a] = int(k);
            if (axis_of[0] < 0 || axis_of[1] < 0 || axis_of[2] < 0) fail("its vertex element lacks an x, y or z property");
        }
        for (std::uint64_t item = 0; item < element.count; ++item) {
            Vec3<T> p{};
            for (std::size_t k = 0; k < element.properties.size(); ++k) {
                const detail::PlyProperty& property = element.properties[k];
                if (property.count_type.empty()) {
                    const double v = reader.value(property.type);
                    for (int a = 0; a < 3; ++a)
                        if (vertices && axis_of[a] == int(k)) p[a] = T(v);
                    continue;
                }
                const double count = reader.value(property.count_type);
                if (!(count >= 0 && count <= 1e6)) fail("a list of " + std::to_string(count) + " items");
                const bool indices = faces && (property.name == "vertex_indices" || property.name == "vertex_index");
                std::vector<std::uint32_t> polygon;
                for (std::size_t i = 0; i < std::size_t(count); ++i) {
                    const double v = reader.value(property.type);
                    if (!indices) continue;
                    if (!(v >= 0 && v < double(out.positions.size())))
                        fail("face " + std::to_string(item) + " refers to vertex " + std::to_string(v) + " of " + std::to_string(out.positions.size()));
                    polygon.push_back(std::uint32_t(v));
                }
                for (std::size_t i = 1; i + 1 < polygon.size(); ++i) out.triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
            }
            if (vertices) out.positions.push_back(p);
        }
    }
    if (out.triangles.empty()) fail("it has no faces");
    return out;
}

/// load_obj or load_ply, by the file's extension (.obj, .ply, in any case).
template <Scalar T = float>
[[nodiscard]] MeshBuffers<T> load_mesh(const std::filesystem::path& path)
{
    std::string extension = path.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".obj") return load_obj<T>(path);
    if (extension == ".ply") return load_ply<T>(path);
    throw std::runtime_error("cannot read mesh '" + path.string() + "': its extension '" + path.extension().string() + "' is neither .obj nor .ply");
}

} // namespace prism
