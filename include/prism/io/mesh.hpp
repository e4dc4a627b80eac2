// SPDX-License-Identifier: MIT
// Mesh files: Wavefront OBJ through tinyobjloader (Debian: libtinyobjloader-dev), and
// PLY (ASCII and binary, either byte order) read here.
//
// Opt-in: prism/prism.hpp does not include this header, and a program that does links
// tinyobjloader (the CMake target prism::mesh_io does both). Polygons are split into
// triangles (a fan from their first vertex), every group of the file goes into one
// MeshBuffers; OBJ positions are read as float (tinyobjloader's real_t). Vertex normals
// (OBJ vn, PLY nx ny nz) and texture coordinates (OBJ vt, PLY u v, s t or texture_u
// texture_v) are read when every vertex of every face has them, and left out (the
// mesh shades flat, uv (0, 0)) when any lacks them; an OBJ vertex used with different
// normals or coordinates becomes one vertex per combination. Colours and other
// properties are not read. Any failure, a zero or non-finite normal among them, throws
// std::runtime_error naming the path and the reason. load_mesh picks the reader by the
// file's extension.
#pragma once

#include <prism/geometry/mesh_builders.hpp>
#include <prism/io/input.hpp>

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace prism {

namespace detail {

/// What prism checks of an OBJ file before tinyobjloader parses it, line by line: every
/// number a number, every index a whole number naming an element defined before it, every
/// face 3 corners or more with no vertex twice. Returns the triangles the faces make.
class ObjChecker {
public:
    explicit ObjChecker(InputFile& file) : file_(file) {}

    /// Check line `number`, its text `line`.
    void check(std::size_t number, const std::string& line)
    {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword.empty() || keyword[0] == '#') return;
        where_ = "line " + std::to_string(number);
        std::vector<std::string> rest;
        for (std::string w; words >> w;) {
            if (w[0] == '#') break;
            rest.push_back(w);
        }
        if (keyword == "v") {
            if (rest.size() != 3 && rest.size() != 4 && rest.size() != 6 && rest.size() != 7)
                fail("'v' has " + std::to_string(rest.size()) + " numbers (x y z, with w or r g b)");
            numbers(rest, "v");
            ++positions_;
        } else if (keyword == "vn") {
            if (rest.size() != 3) fail("'vn' has " + std::to_string(rest.size()) + " numbers, not 3");
            numbers(rest, "vn");
            ++normals_;
        } else if (keyword == "vt") {
            if (rest.empty() || rest.size() > 3) fail("'vt' has " + std::to_string(rest.size()) + " numbers, not 1 to 3");
            numbers(rest, "vt");
            ++uvs_;
        } else if (keyword == "f") {
            if (rest.size() < 3) fail("a face has " + std::to_string(rest.size()) + " corners: it needs 3 or more");
            std::vector<long long> corners;
            for (const std::string& corner : rest) {
                const std::size_t a = corner.find('/'), b = a == std::string::npos ? a : corner.find('/', a + 1);
                const long long v = index(corner.substr(0, a), positions_, "vertex", corner);
                if (a != std::string::npos) {
                    const std::string t = corner.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
                    if (!t.empty()) (void)index(t, uvs_, "texture coordinate", corner);
                    if (b != std::string::npos) (void)index(corner.substr(b + 1), normals_, "normal", corner);
                    else if (t.empty()) fail("the corner '" + corner + "' is not v, v/t, v//n or v/t/n");
                }
                for (const long long seen : corners)
                    if (seen == v) fail("a face names vertex " + std::to_string(v) + " twice: it is no polygon");
                corners.push_back(v);
            }
            triangles_ += rest.size() - 2;
        } else if (keyword != "o" && keyword != "g" && keyword != "s" && keyword != "usemtl" && keyword != "mtllib" && keyword != "l" && keyword != "p") {
            fail("'" + keyword.substr(0, 32) + "' is not an OBJ statement prism reads (v, vn, vt, f, o, g, s, usemtl, mtllib, l, p)");
        }
    }

    /// The triangles the faces make, fans of (corners - 2).
    [[nodiscard]] std::size_t triangles() const noexcept { return triangles_; }
    /// The v, vn and vt lines.
    [[nodiscard]] std::array<std::size_t, 3> counts() const noexcept { return {positions_, normals_, uvs_}; }

private:
    [[noreturn]] void fail(const std::string& reason) const { file_.fail(where_ + ": " + reason); }

    void numbers(const std::vector<std::string>& words, const char* keyword) const
    {
        for (const std::string& w : words) {
            char* end = nullptr;
            const double v = std::strtod(w.c_str(), &end);
            if (end != w.c_str() + w.size() || !std::isfinite(v) || !std::isfinite(float(v))) {
                // Appended, not `"'" + ...`: g++ 12 warns (-Wrestrict) about that form here.
                std::string reason = "'";
                reason.append(keyword).append("' has '").append(w, 0, 32).append("', not a finite number");
                fail(reason);
            }
        }
    }

    /// An index (1-based, or negative counting back from the last defined), resolved.
    long long index(const std::string& word, std::size_t defined, const char* what, const std::string& corner) const
    {
        const bool negative = !word.empty() && word[0] == '-';
        const std::string digits = negative ? word.substr(1) : word;
        if (digits.empty() || digits.size() > 10 || digits.find_first_not_of("0123456789") != std::string::npos || std::stoll(digits) > 2147483647)
            fail("the corner '" + corner.substr(0, 32) + "' has the " + what + " index '" + word.substr(0, 32) + "', not a whole number of at most 2147483647");
        const long long i = negative ? (long long)(defined) + 1 - std::stoll(digits) : std::stoll(digits);
        if (std::stoll(digits) == 0 || i < 1 || i > (long long)(defined))
            fail("the corner '" + corner.substr(0, 32) + "' names " + what + " " + word + ", but " + std::to_string(defined) + " are defined before it");
        return i;
    }

    InputFile& file_;
    std::string where_;
    std::size_t positions_ = 0, normals_ = 0, uvs_ = 0, triangles_ = 0;
};

} // namespace detail

/// The triangles of an OBJ file, as counter-clockwise as the file winds them. Bounded and
/// strict: the file is read no further than `limits`, a line no longer than 1 MiB; prism
/// checks every line (ObjChecker: numbers finite, indices whole and defined before their
/// face, faces of 3 corners or more with no vertex twice, no statement it does not read)
/// before tinyobjloader parses the same text, and then that tinyobjloader returned every
/// vertex and triangle. Materials are not read, so `mtllib` names no file that is opened.
namespace detail {

/// The OBJ file read through `file`, checked (ObjChecker) and parsed by tinyobjloader with
/// the material library `mtl_text` (empty: none; faces then have material -1), and what
/// tinyobjloader returned checked against what the file holds.
[[nodiscard]] inline tinyobj::ObjReader parse_obj(InputFile& file, const std::string& mtl_text = {})
{
    ObjChecker checker(file);
    std::string text;
    std::size_t number = 0;
    while (const std::optional<std::string> line = file.line(std::size_t(1) << 20, "line " + std::to_string(number + 1))) {
        checker.check(++number, *line);
        text += *line;
        text += '\n';
    }
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, mtl_text, config)) {
        std::string reason = reader.Error();
        while (!reason.empty() && (reason.back() == '\n' || reason.back() == '\r')) reason.pop_back();
        file.fail("tinyobjloader: " + (reason.empty() ? std::string("unknown error") : reason));
    }
    const auto& attrib = reader.GetAttrib();
    const std::size_t positions = attrib.vertices.size() / 3, normals = attrib.normals.size() / 3, uvs = attrib.texcoords.size() / 2;
    std::size_t triangles = 0;
    for (const auto& shape : reader.GetShapes()) triangles += shape.mesh.indices.size() / 3;
    if (std::array<std::size_t, 3>{positions, normals, uvs} != checker.counts() || triangles != checker.triangles())
        file.fail("tinyobjloader returned " + std::to_string(positions) + " vertices and " + std::to_string(triangles) + " triangles, but the file has " +
                  std::to_string(checker.counts()[0]) + " and its faces make " + std::to_string(checker.triangles()));
    return reader;
}

} // namespace detail

template <Scalar T = float>
[[nodiscard]] MeshBuffers<T> load_obj(const std::filesystem::path& path, ReadLimits limits = {})
try {
    detail::InputFile file(path, "mesh", limits);
    const tinyobj::ObjReader reader = detail::parse_obj(file);
    const auto& attrib = reader.GetAttrib();
    const auto fail = [&](const std::string& reason) { file.fail(reason); };
    const std::size_t positions = attrib.vertices.size() / 3, normals = attrib.normals.size() / 3, uvs = attrib.texcoords.size() / 2;
    // Normals and coordinates only where every face corner names one (in range).
    bool with_normals = normals > 0, with_uvs = uvs > 0;
    for (const auto& shape : reader.GetShapes())
        for (const tinyobj::index_t& corner : shape.mesh.indices) {
            if (corner.vertex_index < 0 || std::size_t(corner.vertex_index) >= positions)
                fail("a face refers to vertex " + std::to_string(corner.vertex_index) + " of " + std::to_string(positions));
            with_normals = with_normals && corner.normal_index >= 0 && std::size_t(corner.normal_index) < normals;
            with_uvs = with_uvs && corner.texcoord_index >= 0 && std::size_t(corner.texcoord_index) < uvs;
        }
    MeshBuffers<T> out;
    const auto position = [&](int v) { return Vec3<T>(T(attrib.vertices[3 * std::size_t(v)]), T(attrib.vertices[3 * std::size_t(v) + 1]), T(attrib.vertices[3 * std::size_t(v) + 2])); };
    // One vertex per (position, normal, uv) used, in order of first use; positions alone
    // keep the file's numbering.
    std::map<std::array<int, 3>, std::uint32_t> vertex_of;
    if (!with_normals && !with_uvs)
        for (std::size_t v = 0; v < positions; ++v) out.positions.push_back(position(int(v)));
    const auto vertex = [&](const tinyobj::index_t& corner) -> std::uint32_t {
        if (!with_normals && !with_uvs) return std::uint32_t(corner.vertex_index);
        const std::array<int, 3> key{corner.vertex_index, with_normals ? corner.normal_index : -1, with_uvs ? corner.texcoord_index : -1};
        const auto [at, fresh] = vertex_of.try_emplace(key, std::uint32_t(out.positions.size()));
        if (fresh) {
            out.positions.push_back(position(key[0]));
            if (with_normals) {
                const std::size_t n = 3 * std::size_t(key[1]);
                const Vec3<T> normal(T(attrib.normals[n]), T(attrib.normals[n + 1]), T(attrib.normals[n + 2]));
                if (!is_finite(normal) || !(length(Vec3<double>(normal)) > 0)) fail("normal " + std::to_string(key[1] + 1) + " is " + detail::describe(normal));
                out.normals.push_back(normal);
            }
            if (with_uvs) {
                const std::size_t t = 2 * std::size_t(key[2]);
                out.uvs.push_back({T(attrib.texcoords[t]), T(attrib.texcoords[t + 1])});
            }
        }
        return at->second;
    };
    for (const auto& shape : reader.GetShapes()) {
        const auto& indices = shape.mesh.indices;
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3) out.triangles.push_back({vertex(indices[i]), vertex(indices[i + 1]), vertex(indices[i + 2])});
    }
    if (out.triangles.empty()) fail("it has no faces");
    return out;
} catch (const allocation_error&) {
    throw;
} catch (const std::bad_alloc&) {
    throw detail::out_of_memory(path, "mesh");
}

namespace detail {

/// One property of a PLY element: a scalar, or a list (its count's type and its items').
struct PlyProperty {
    std::string name;
    std::string type;       ///< the scalar's type, or the list items' type
    std::string count_type; ///< empty for a scalar
};

/// One element of a PLY header: its name, how many items it has, and their properties.
struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

/// A PLY type's size in bytes, or 0 for a name PLY does not define.
inline std::size_t ply_type_size(const std::string& type)
{
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

/// Whether a PLY type holds whole numbers.
inline bool ply_integer(const std::string& type) { return type != "float" && type != "float32" && type != "double" && type != "float64"; }

/// The range of a PLY integer type.
inline std::pair<double, double> ply_range(const std::string& type)
{
    if (type == "char" || type == "int8") return {-128, 127};
    if (type == "uchar" || type == "uint8") return {0, 255};
    if (type == "short" || type == "int16") return {-32768, 32767};
    if (type == "ushort" || type == "uint16") return {0, 65535};
    if (type == "int" || type == "int32") return {-2147483648.0, 2147483647.0};
    return {0, 4294967295.0};
}

/// Reads PLY values one at a time, as text or as binary of either byte order, refusing a
/// word that is not a number of its type (a fraction where a whole number belongs, a
/// number out of its type's range) by the element and item it belongs to.
class PlyReader {
public:
    PlyReader(InputFile& file, int format) : file_(file), format_(format) {}

    /// The next value, of PLY type `type`; `where` names it in a message.
    double value(const std::string& type, const std::string& where)
    {
        if (format_ == 0) return text_value(type, where);
        const std::size_t size = ply_type_size(type);
        unsigned char bytes[8] = {};
        for (std::size_t i = 0; i < size; ++i) {
            const int c = file_.get();
            if (c < 0) file_.fail("the data ends early, in " + where);
            bytes[i] = static_cast<unsigned char>(c);
        }
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

    /// Whether only white space is left (ASCII), or nothing (binary).
    [[nodiscard]] bool at_end()
    {
        for (int c = file_.get(); c >= 0; c = file_.get())
            if (format_ != 0 || !(c == ' ' || c == '\t' || c == '\r' || c == '\n')) return false;
        return true;
    }

private:
    double text_value(const std::string& type, const std::string& where)
    {
        int c = file_.get();
        while (c == ' ' || c == '\t' || c == '\r' || c == '\n') c = file_.get();
        std::string word;
        for (; c >= 0 && !(c == ' ' || c == '\t' || c == '\r' || c == '\n'); c = file_.get()) {
            if (c == 0) file_.fail("a NUL byte in its text data, in " + where);
            if (word.size() == 64) file_.fail(where + " is a word longer than 64 bytes");
            word.push_back(char(c));
        }
        if (word.empty()) file_.fail("the data ends early, in " + where);
        char* end = nullptr;
        const double v = std::strtod(word.c_str(), &end);
        if (end != word.c_str() + word.size()) file_.fail(where + " is '" + word + "', not a number");
        if (ply_integer(type)) {
            const auto [low, high] = ply_range(type);
            if (word.find_first_not_of("+-0123456789") != std::string::npos || !(v >= low && v <= high))
                file_.fail(where + " is '" + word + "', not a whole number that a PLY " + type + " holds");
        }
        return v;
    }

    InputFile& file_;
    int format_; ///< 0 ascii, 1 little endian, 2 big endian
};

/// A header line's next word as a count: a whole number from 0 to 2^32 - 1.
inline std::uint64_t ply_count(InputFile& file, std::istringstream& words, const std::string& line)
{
    std::string word;
    words >> word;
    if (word.empty() || word.size() > 10 || word.find_first_not_of("0123456789") != std::string::npos || std::stoull(word) > 4294967295ull)
        file.fail("the header line '" + line + "' has a count that is not a whole number from 0 to 4294967295");
    return std::stoull(word);
}

} // namespace detail

/// The triangles of a PLY file (its vertex element's x, y, z and its face element's
/// vertex_indices or vertex_index list), in ASCII or binary of either byte order. Bounded
/// and strict: a header's counts are checked against the bytes the file holds before any
/// item is read, every value must be a number of its type (a whole number in range where
/// the type is an integer), positions, normals and coordinates must be finite, a face must
/// have 3 vertices or more, and nothing may follow the last element.
template <Scalar T = float>
[[nodiscard]] MeshBuffers<T> load_ply(const std::filesystem::path& path, ReadLimits limits = {})
try {
    detail::InputFile file(path, "mesh", limits);
    const auto fail = [&](const std::string& reason) { file.fail(reason); };
    const auto header_line = [&]() {
        const std::optional<std::string> line = file.line(4096, "a header line");
        if (!line) fail("its header has no end_header");
        return *line;
    };
    if (file.get() != 'p' || file.get() != 'l' || file.get() != 'y') fail("it does not start with 'ply'");
    if (const std::string rest = header_line(); !rest.empty()) fail("it does not start with 'ply' alone on its line (it starts 'ply" + rest.substr(0, 32) + "')");
    int format = -1;
    std::vector<detail::PlyElement> elements;
    for (int lines = 0;; ++lines) {
        if (lines == 100000) fail("its header is longer than 100000 lines");
        const std::string line = header_line();
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word == "end_header") break;
        if (word == "format") {
            std::string kind, version;
            words >> kind >> version;
            format = kind == "ascii" ? 0 : kind == "binary_little_endian" ? 1 : kind == "binary_big_endian" ? 2 : -1;
            if (format < 0) fail("its format '" + kind + "' is not ascii, binary_little_endian or binary_big_endian");
            if (version != "1.0") fail("its format version '" + version + "' is not 1.0");
        } else if (word == "element") {
            detail::PlyElement element;
            if (!(words >> element.name)) fail("a header line '" + line + "' has no element name and count");
            element.count = detail::ply_count(file, words, line);
            elements.push_back(element);
        } else if (word == "property") {
            if (elements.empty()) fail("a property comes before any element");
            detail::PlyProperty property;
            std::string type;
            words >> type;
            if (type == "list") words >> property.count_type >> property.type >> property.name;
            else property.type = type, words >> property.name;
            if (property.name.empty() || detail::ply_type_size(property.type) == 0 || (!property.count_type.empty() && detail::ply_type_size(property.count_type) == 0))
                fail("the property line '" + line + "' has a type PLY does not define, or no name");
            if (!property.count_type.empty() && !detail::ply_integer(property.count_type)) fail("the list '" + property.name + "' has a count of type " + property.count_type + ", not a whole-number type");
            if ((property.name == "vertex_indices" || property.name == "vertex_index") && !detail::ply_integer(property.type))
                fail("the list '" + property.name + "' holds indices of type " + property.type + ", not a whole-number type");
            elements.back().properties.push_back(property);
        } else if (word != "comment" && word != "obj_info" && !word.empty()) {
            fail("its header has a line '" + line.substr(0, 64) + "' PLY does not define");
        }
    }
    if (format < 0) fail("its header has no format line");
    for (const detail::PlyElement& element : elements)
        if (element.properties.empty() && element.count > 0) fail("its element '" + element.name + "' has " + std::to_string(element.count) + " items but no properties");
    // What the counts claim, against what the file holds: each item takes at least its
    // scalars' and list counts' bytes in binary, and two bytes a value in ASCII.
    if (file.size()) {
        double least = 0;
        for (const detail::PlyElement& element : elements) {
            double item = 0;
            for (const detail::PlyProperty& property : element.properties)
                item += format == 0 ? 2.0 : double(detail::ply_type_size(property.count_type.empty() ? property.type : property.count_type));
            least += item * double(element.count);
        }
        const double left = double(*file.size() - file.position());
        if (least > left + 1)
            fail("its header's counts need at least " + std::to_string(static_cast<unsigned long long>(least)) + " bytes, but " + std::to_string(static_cast<unsigned long long>(left)) +
                 " follow: the file is truncated");
    }
    detail::PlyReader reader(file, format);
    MeshBuffers<T> out;
    const char* axes[8] = {"x", "y", "z", "nx", "ny", "nz", "u", "v"};
    for (const detail::PlyElement& element : elements) {
        const bool vertices = element.name == "vertex", faces = element.name == "face";
        // Which scalar property holds x, y, z, nx, ny, nz, u, v.
        std::array<int, 8> slot_of;
        slot_of.fill(-1);
        bool with_normals = false, with_uvs = false;
        if (vertices) {
            const std::array<std::array<const char*, 3>, 8> names = {{{"x", "x", "x"}, {"y", "y", "y"}, {"z", "z", "z"}, {"nx", "nx", "nx"},
                                                                    {"ny", "ny", "ny"}, {"nz", "nz", "nz"}, {"u", "s", "texture_u"}, {"v", "t", "texture_v"}}};
            for (std::size_t k = 0; k < element.properties.size(); ++k)
                for (std::size_t a = 0; a < names.size(); ++a)
                    for (const char* spelling : names[a])
                        if (element.properties[k].name == spelling && element.properties[k].count_type.empty()) slot_of[a] = int(k);
            if (slot_of[0] < 0 || slot_of[1] < 0 || slot_of[2] < 0) fail("its vertex element lacks an x, y or z property");
            with_normals = slot_of[3] >= 0 && slot_of[4] >= 0 && slot_of[5] >= 0;
            with_uvs = slot_of[6] >= 0 && slot_of[7] >= 0;
        }
        for (std::uint64_t item = 0; item < element.count; ++item) {
            const std::string where = element.name + " " + std::to_string(item);
            std::array<double, 8> at{};
            for (std::size_t k = 0; k < element.properties.size(); ++k) {
                const detail::PlyProperty& property = element.properties[k];
                if (property.count_type.empty()) {
                    const double v = reader.value(property.type, where + "'s " + property.name);
                    for (std::size_t a = 0; a < at.size(); ++a)
                        if (vertices && slot_of[a] == int(k)) {
                            if (!std::isfinite(v)) fail(where + "'s " + axes[a] + " is " + std::to_string(v));
                            at[a] = v;
                        }
                    continue;
                }
                const double count = reader.value(property.count_type, where + "'s " + property.name + " count");
                if (!(count >= 0 && count <= 1e6)) fail(where + "'s " + property.name + " has " + std::to_string(count) + " items (0 to 10^6)");
                const bool indices = faces && (property.name == "vertex_indices" || property.name == "vertex_index");
                if (indices && count < 3) fail(where + " has " + std::to_string(int(count)) + " vertices: a face needs 3 or more");
                std::vector<std::uint32_t> polygon;
                for (std::size_t i = 0; i < std::size_t(count); ++i) {
                    const double v = reader.value(property.type, where + "'s " + property.name);
                    if (!indices) continue;
                    if (!(v >= 0 && v < double(out.positions.size())))
                        fail(where + " refers to vertex " + std::to_string(static_cast<long long>(v)) + " of " + std::to_string(out.positions.size()));
                    polygon.push_back(std::uint32_t(v));
                }
                for (std::size_t i = 1; i + 1 < polygon.size(); ++i) out.triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
            }
            if (vertices) {
                out.positions.push_back({T(at[0]), T(at[1]), T(at[2])});
                if (!is_finite(out.positions.back())) fail(where + " is " + detail::describe(out.positions.back()) + " in this precision");
                if (with_normals) {
                    const Vec3<T> normal{T(at[3]), T(at[4]), T(at[5])};
                    if (!is_finite(normal) || !(length(Vec3<double>(normal)) > 0)) fail("the normal of vertex " + std::to_string(item) + " is " + detail::describe(normal));
                    out.normals.push_back(normal);
                }
                if (with_uvs) {
                    out.uvs.push_back({T(at[6]), T(at[7])});
                    if (!std::isfinite(out.uvs.back().x) || !std::isfinite(out.uvs.back().y))
                        fail(where + "'s texture coordinates (" + std::to_string(at[6]) + ", " + std::to_string(at[7]) + ") are not finite in this precision");
                }
            }
        }
    }
    if (!reader.at_end()) fail("bytes follow its last element");
    if (out.triangles.empty()) fail("it has no faces");
    return out;
} catch (const allocation_error&) {
    throw;
} catch (const std::bad_alloc&) {
    throw detail::out_of_memory(path, "mesh");
}

/// load_obj or load_ply, by the file's extension (.obj, .ply, in any case).
template <Scalar T = float>
[[nodiscard]] MeshBuffers<T> load_mesh(const std::filesystem::path& path)
{
    std::string extension = path.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".obj") return load_obj<T>(path);
    if (extension == ".ply") return load_ply<T>(path);
    throw std::runtime_error("prism: cannot read mesh '" + path.string() + "': its extension '" + path.extension().string() + "' is neither .obj nor .ply");
}

} // namespace prism
