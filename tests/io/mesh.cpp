// SPDX-License-Identifier: MIT
#include <prism/io/mesh.hpp>

#include "../support.hpp"

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <sys/stat.h>
#include <thread>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

fs::path write_file(const std::string& name, const std::string& text)
{
    const fs::path path = fs::temp_directory_path() / ("prism-mesh-test-" + std::to_string(::getpid()) + "-" + name);
    std::ofstream(path) << text;
    return path;
}

} // namespace

TEST_CASE("the bunny loads as the closed mesh its package holds")
{
    // Counts and volume from the npm package's own arrays (tools/fetch_bunny.sh), worked
    // out by node: 1839 positions, 3674 triangles, 6 V = 1165.7302308745172.
    const auto bunny = prism::load_obj<double>(fs::path(PRISM_TEST_ASSETS) / "bunny.obj");
    CHECK(bunny.positions.size() == 1839);
    CHECK(bunny.triangles.size() == 3674);
    double volume6 = 0;
    for (const auto& f : bunny.triangles)
        volume6 += prism::dot(bunny.positions[f[0]], prism::cross(bunny.positions[f[1]], bunny.positions[f[2]]));
    CHECK(volume6 == doctest::Approx(1165.7302308745172).epsilon(1e-6)); // tinyobjloader reads float
    const prism::TriangleMesh<double> mesh(bunny.positions, bunny.triangles);
    CHECK(mesh.closed());
    CHECK(mesh.contains({0, 3, 0}));
    CHECK_FALSE(mesh.contains({0, 12, 0}));
}

TEST_CASE("polygons are split into triangles, and a broken file is refused with its path and reason")
{
    const auto quad = prism::load_obj<float>(write_file("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"));
    CHECK(quad.triangles.size() == 2);
    CHECK(quad.positions.size() == 4);
    const fs::path missing = fs::temp_directory_path() / "prism-no-such-mesh.obj";
    const std::string named = "cannot read mesh '" + missing.string() + "'";
    CHECK_THROWS_WITH_AS((void)prism::load_obj<float>(missing), doctest::Contains(named.c_str()), std::runtime_error);
    const fs::path empty = write_file("empty.obj", "v 0 0 0\nv 1 0 0\n");
    CHECK_THROWS_WITH_AS((void)prism::load_obj<float>(empty), doctest::Contains("it has no faces"), std::runtime_error);
    const fs::path past = write_file("past.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 7\n");
    CHECK_THROWS_AS((void)prism::load_obj<float>(past), std::runtime_error);
    for (const auto& p : {empty, past}) fs::remove(p);
    fs::remove(fs::temp_directory_path() / ("prism-mesh-test-" + std::to_string(::getpid()) + "-quad.obj"));
}

namespace {

/// Appends v as `Size` bytes of the given byte order.
template <class V>
void put(std::string& out, V v, bool big)
{
    char bytes[sizeof(V)];
    std::memcpy(bytes, &v, sizeof(V));
    if (big == (std::endian::native == std::endian::little)) std::reverse(bytes, bytes + sizeof(V));
    out.append(bytes, sizeof(V));
}

/// The bunny as a PLY file, written here (not by prism): with extra vertex properties
/// (a normal, a colour), an extra element, and faces whose lists are uchar + int.
std::string bunny_ply(const prism::MeshBuffers<float>& b, const std::string& format)
{
    std::string text = "ply\nformat " + format + " 1.0\ncomment from tests/io/mesh.cpp\nelement vertex " + std::to_string(b.positions.size()) +
                       "\nproperty float x\nproperty float nx\nproperty float y\nproperty float z\nproperty uchar red\nelement face " +
                       std::to_string(b.triangles.size()) + "\nproperty list uchar int vertex_indices\nproperty ushort flags\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
    const bool ascii = format == "ascii", big = format == "binary_big_endian";
    for (const auto& p : b.positions) {
        if (ascii) {
            char line[200];
            std::snprintf(line, sizeof line, "%.9g 0.5 %.9g %.9g 200\n", double(p.x), double(p.y), double(p.z));
            text += line;
        } else {
            put(text, p.x, big), put(text, 0.5f, big), put(text, p.y, big), put(text, p.z, big), put(text, std::uint8_t(200), big);
        }
    }
    for (const auto& f : b.triangles) {
        if (ascii) text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + " 7\n";
        else put(text, std::uint8_t(3), big), put(text, std::int32_t(f[0]), big), put(text, std::int32_t(f[1]), big), put(text, std::int32_t(f[2]), big),
            put(text, std::uint16_t(7), big);
    }
    if (ascii) text += "0 1\n";
    else put(text, std::int32_t(0), big), put(text, std::int32_t(1), big);
    return text;
}

} // namespace

TEST_CASE("a PLY file in ASCII and in binary of either byte order holds the OBJ's bunny")
{
    const auto obj = prism::load_obj<float>(fs::path(PRISM_TEST_ASSETS) / "bunny.obj");
    for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        CAPTURE(format);
        const fs::path path = write_file("bunny-" + format + ".ply", bunny_ply(obj, format));
        const auto ply = prism::load_mesh<float>(path);
        REQUIRE(ply.positions.size() == obj.positions.size());
        REQUIRE(ply.triangles.size() == obj.triangles.size());
        CHECK(ply.positions == obj.positions);
        CHECK(ply.triangles == obj.triangles);
        fs::remove(path);
    }
    // A quad and a pentagon: fans of 2 and 3 triangles.
    const fs::path poly = write_file("poly.ply", "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
                                                 "element face 2\nproperty list uchar uint vertex_index\nend_header\n"
                                                 "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 1.5 0\n4 0 1 2 3\n5 0 1 2 4 3\n");
    const auto shapes = prism::load_ply<double>(poly);
    CHECK(shapes.triangles.size() == 5);
    CHECK(shapes.triangles[1] == prism::TriangleIndices{0, 2, 3});
    fs::remove(poly);
}

TEST_CASE("a broken PLY file is refused with its path and the reason")
{
    const auto refused = [](const std::string& name, const std::string& text, const char* reason) {
        const fs::path path = write_file(name, text);
        CHECK_THROWS_WITH_AS((void)prism::load_mesh<float>(path), doctest::Contains(reason), std::runtime_error);
        fs::remove(path);
    };
    const std::string head = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    refused("magic.ply", "plx\n", "does not start with 'ply'");
    refused("format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", "binary_middle_endian");
    refused("unended.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", "no end_header");
    refused("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n", "a type PLY does not define");
    refused("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n", "lacks an x, y or z");
    refused("short.ply", head + std::string(20, '\0'), "truncated");
    refused("past.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
                        "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", "refers to vertex 5");
    refused("word.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 zero 0\n", "not a number");
    refused("mesh.stl", "solid\n", "neither .obj nor .ply");
}

TEST_CASE("vertex normals and texture coordinates are read where every face has them; a vertex used with two normals becomes two")
{
    // A unit cube's top and front faces: corner (0, 1, 1) and (1, 1, 1) are shared with
    // different normals (one per face, as an exporter writes a hard edge).
    const std::string cube = "v 0 1 0\nv 1 1 0\nv 1 1 1\nv 0 1 1\nv 0 0 1\nv 1 0 1\n"
                             "vn 0 1 0\nvn 0 0 2\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                             "f 1/1/1 4/4/1 3/3/1 2/2/1\nf 5/1/2 6/2/2 3/3/2 4/4/2\n";
    const fs::path path = write_file("cube.obj", cube);
    const auto mesh = prism::load_obj<double>(path);
    CHECK(mesh.positions.size() == 8); // 4 on top, 4 in front: two corners twice
    REQUIRE(mesh.normals.size() == 8);
    REQUIRE(mesh.uvs.size() == 8);
    CHECK(mesh.triangles.size() == 4);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (const std::uint32_t v : mesh.triangles[f]) {
            const prism::Vec3<double> expected = f < 2 ? prism::Vec3<double>{0, 1, 0} : prism::Vec3<double>{0, 0, 2};
            CHECK(mesh.normals[v] == expected); // as in the file; TriangleMesh makes them unit
        }
    CHECK(mesh.uvs[0] == prism::Vec2<double>{0, 0});
    CHECK(mesh.uvs[1] == prism::Vec2<double>{0, 1});
    // The front face shades with its own normal at the shared edge.
    const prism::TriangleMesh<double> shape(mesh);
    const auto front = shape.crossings({{0.5, 0.5, 3}, {0, 0, -1}}, {0, prism::infinity<double>});
    REQUIRE(front.size() == 1);
    CHECK(front.front().shading == prism::Vec3<double>{0, 0, 1});
    CHECK(front.front().uv.x == doctest::Approx(0.5));
    // One face without normals: none are read (and the positions keep their numbering).
    const fs::path partial = write_file("partial.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 4\n");
    const auto flat = prism::load_obj<float>(partial);
    CHECK(flat.normals.empty());
    CHECK(flat.positions.size() == 4);
    // A zero normal is refused, naming it.
    const fs::path zero = write_file("zero.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n");
    CHECK_THROWS_WITH_AS((void)prism::load_obj<float>(zero), doctest::Contains("normal 1 is (0, 0, 0)"), std::runtime_error);
    // PLY: nx ny nz and u v (or s t) on the vertex element.
    const fs::path ply = write_file("normals.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                                   "property float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\n"
                                                   "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                                   "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n0 1 0 0 0.6 0.8 0 1\n3 0 1 2\n");
    const auto read = prism::load_ply<double>(ply);
    REQUIRE(read.normals.size() == 3);
    CHECK(read.normals[2] == prism::Vec3<double>{0, 0.6, 0.8});
    REQUIRE(read.uvs.size() == 3);
    CHECK(read.uvs[2] == prism::Vec2<double>{0, 1});
    const fs::path ply_zero = write_file("zero.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                                     "property float nx\nproperty float ny\nproperty float nz\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                                     "0 0 0 0 0 1\n1 0 0 0 0 0\n0 1 0 0 0 1\n3 0 1 2\n");
    CHECK_THROWS_WITH_AS((void)prism::load_ply<float>(ply_zero), doctest::Contains("the normal of vertex 1 is (0, 0, 0)"), std::runtime_error);
    for (const auto& p : {path, partial, zero, ply, ply_zero}) fs::remove(p);
}

namespace {

std::string ply_refusal(const std::string& name, const std::string& text)
{
    const fs::path path = write_file(name, text);
    std::string message;
    try {
        (void)prism::load_ply<float>(path);
    } catch (const std::runtime_error& e) {
        message = e.what();
    }
    fs::remove(path);
    return message;
}

const std::string triangle_head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";

} // namespace

TEST_CASE("PLY counts are whole numbers the file can hold: no endless element, no claim past the file's bytes")
{
    // Regression: an element with no properties and count -1 (read as 2^64 - 1) or 2^63, in
    // a 196-byte file, never returned.
    const std::string head = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    CHECK(ply_refusal("minus.ply", head + "element junk -1\nend_header\n").find("not a whole number from 0 to 4294967295") != std::string::npos);
    CHECK(ply_refusal("huge.ply", head + "element junk 9223372036854775808\nend_header\n").find("not a whole number") != std::string::npos);
    CHECK(ply_refusal("empty.ply", head + "element junk 5\nend_header\n" + std::string(36, '\0')).find("no properties") != std::string::npos);
    CHECK(ply_refusal("claim.ply", head + "element face 4000000000\nproperty list uchar int vertex_indices\nend_header\n" + std::string(36, '\0'))
              .find("truncated") != std::string::npos);
}

TEST_CASE("PLY values are numbers of their type: no fractional index or count, no bad magic, no NaN position")
{
    // Regression: indices 0.9 1.5 2.7 and a count 2.5 were truncated or misread, a header
    // 'plyfoo' was accepted, and binary NaN or infinite positions reached TriangleMesh.
    CHECK(ply_refusal("fraction.ply", triangle_head + "3 0.9 1.5 2.7\n").find("'0.9', not a whole number") != std::string::npos);
    CHECK(ply_refusal("count.ply", triangle_head + "2.5 0 1 2\n").find("'2.5', not a whole number") != std::string::npos);
    CHECK(ply_refusal("range.ply", triangle_head + "300 0 1 2\n").find("'300', not a whole number that a PLY uchar holds") != std::string::npos);
    CHECK(ply_refusal("magic.ply", "plyfoo\nformat ascii 1.0\nend_header\n").find("'ply' alone") != std::string::npos);
    CHECK(ply_refusal("two.ply", triangle_head + "2 0 1\n").find("face 0 has 2 vertices") != std::string::npos);
    CHECK(ply_refusal("tail.ply", triangle_head + "3 0 1 2\n7\n").find("bytes follow") != std::string::npos);
    // Found by the ply fuzz target: a coordinate finite as a double but not as a float.
    CHECK(ply_refusal("uv.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty double u\n"
                                "property double v\nend_header\n0 0 0 1e300 0\n")
              .find("vertex 0's texture coordinates") != std::string::npos);
    CHECK(ply_refusal("nan.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 nan 0\n")
              .find("vertex 0's y is nan") != std::string::npos);
    for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
        const float corners[9] = {0, 0, 0, 1, 0, bad, 0, 1, 0};
        for (float c : corners) {
            char raw[4];
            std::memcpy(raw, &c, 4);
            if constexpr (std::endian::native == std::endian::big) std::swap(raw[0], raw[3]), std::swap(raw[1], raw[2]);
            binary.append(raw, 4);
        }
        binary += std::string("\x03\0\0\0\0\x01\0\0\0\x02\0\0\0", 13);
        CHECK(ply_refusal("binary-nan.ply", binary).find("vertex 1's z is") != std::string::npos);
    }
}

TEST_CASE("a PLY file is read through a FIFO, and an endless stream is refused at once")
{
    // Regression: /dev/zero as PLY made memory grow without bound.
    CHECK_THROWS_WITH_AS((void)prism::load_ply<float>("/dev/zero"), doctest::Contains("does not start with 'ply'"), std::runtime_error);
    const fs::path fifo = fs::temp_directory_path() / ("prism-mesh-test-" + std::to_string(::getpid()) + "-pipe.ply");
    fs::remove(fifo);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    std::thread writer([&] { std::ofstream(fifo) << triangle_head << "3 0 1 2\n"; });
    const auto mesh = prism::load_ply<float>(fifo);
    writer.join();
    CHECK(mesh.triangles.size() == 1);
    fs::remove(fifo);
}

namespace {

std::string obj_refusal(const std::string& name, const std::string& text)
{
    const fs::path path = write_file(name, text);
    std::string message;
    try {
        (void)prism::load_obj<float>(path);
    } catch (const std::runtime_error& e) {
        message = e.what();
    }
    fs::remove(path);
    return message;
}

const std::string obj_triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

} // namespace

TEST_CASE("OBJ numbers are finite numbers and its indices whole numbers naming what is defined, by line")
{
    // Regression: 'v nan 0 0', 'v hello 0 0' and 'v 0' were read as 0 without a word;
    // indices 4294967297.. wrapped to 1 2 3, 99999999999999999999 to the last vertex.
    CHECK(obj_refusal("nan.obj", "v nan 0 0\n" + obj_triangle + "f 2 3 4\n").find("line 1: 'v' has 'nan', not a finite number") != std::string::npos);
    CHECK(obj_refusal("word.obj", "v hello 0 0\n").find("line 1: 'v' has 'hello'") != std::string::npos);
    CHECK(obj_refusal("short.obj", obj_triangle + "v 0\n").find("line 4: 'v' has 1 numbers") != std::string::npos);
    CHECK(obj_refusal("wrap.obj", obj_triangle + "f 4294967297 4294967298 4294967299\n").find("line 4: the corner '4294967297'") != std::string::npos);
    CHECK(obj_refusal("long.obj", obj_triangle + "f 1 2 99999999999999999999\n").find("not a whole number of at most 2147483647") != std::string::npos);
    CHECK(obj_refusal("ahead.obj", "f 1 2 3\n" + obj_triangle).find("line 1: the corner '1' names vertex 1, but 0 are defined") != std::string::npos);
    CHECK(obj_refusal("zero.obj", obj_triangle + "f 0 1 2\n").find("names vertex 0") != std::string::npos);
    CHECK(obj_refusal("fraction.obj", obj_triangle + "f 1 2.5 3\n").find("'2.5', not a whole number") != std::string::npos);
    CHECK(obj_refusal("normal.obj", obj_triangle + "f 1//1 2//1 3//1\n").find("names normal 1, but 0 are defined") != std::string::npos);
    CHECK(obj_refusal("verb.obj", obj_triangle + "cstype bspline\nf 1 2 3\n").find("line 4: 'cstype' is not an OBJ statement") != std::string::npos);
    // Counting back from the last defined vertex.
    const fs::path relative = write_file("relative.obj", obj_triangle + "f -3 -2 -1\n");
    CHECK(prism::load_obj<float>(relative).triangles == std::vector<prism::TriangleIndices>{{0, 1, 2}});
    fs::remove(relative);
}

TEST_CASE("an OBJ polygon that names a vertex twice is refused, not dropped")
{
    // Regression: 'f 1 2 3 1 2 3' beside a good triangle was dropped without a word.
    CHECK(obj_refusal("twice.obj", obj_triangle + "f 1 2 3\nf 1 2 3 1 2 3\n").find("line 5: a face names vertex 1 twice") != std::string::npos);
    CHECK(obj_refusal("two.obj", obj_triangle + "f 1 2\n").find("a face has 2 corners") != std::string::npos);
}

TEST_CASE("an OBJ file is read no further than its limit, an endless stream is refused at once, and mtllib opens nothing")
{
    // Regression: /dev/zero as an OBJ, or named by its mtllib, never returned.
    CHECK_THROWS_WITH_AS((void)prism::load_obj<float>("/dev/zero"), doctest::Contains("NUL byte"), std::runtime_error);
    const fs::path with_mtl = write_file("mtl.obj", "mtllib /dev/zero\nusemtl red\n" + obj_triangle + "f 1 2 3\n");
    CHECK(prism::load_obj<float>(with_mtl).triangles.size() == 1);
    CHECK_THROWS_WITH_AS((void)prism::load_obj<float>(with_mtl, {.max_bytes = 16}), doctest::Contains("limit of 16 bytes"), std::runtime_error);
    fs::remove(with_mtl);
}

// Regression: a reader out of memory threw a bare std::bad_alloc, which names neither the
// file nor what was being done. With only 2 MiB to allocate, reading a 6.5 MiB OBJ
// (and a 5.7 MiB PLY) fails with the file's name.
TEST_CASE("a mesh reader out of memory names its file")
{
    if (test::sanitized) return; // a sanitizer keeps its own operator new
    const fs::path big_obj = write_file("big.obj", "");
    {
        std::ofstream out(big_obj);
        for (int i = 0; i < 400000; ++i) out << "v 0.125 0.25 0.5\n";
        out << "f 1 2 3\n";
    }
    const std::string from_obj = test::thrown_with_memory_short(std::size_t(2) << 20, [&] { (void)prism::load_obj<float>(big_obj); });
    CHECK(from_obj == "allocation_error: prism: cannot read mesh '" + big_obj.string() + "': out of memory while reading it (a file of 6.5 MiB)");
    const fs::path big_ply = write_file("big.ply", "");
    {
        std::ofstream out(big_ply);
        out << "ply\nformat ascii 1.0\nelement vertex 400000\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
               "property list uchar int vertex_indices\nend_header\n";
        for (int i = 0; i < 400000; ++i) out << "0.125 0.25 0.5\n";
        out << "3 0 1 2\n";
    }
    const std::string from_ply = test::thrown_with_memory_short(std::size_t(2) << 20, [&] { (void)prism::load_ply<float>(big_ply); });
    CHECK(from_ply.starts_with("allocation_error: prism: cannot read mesh '" + big_ply.string() + "': out of memory while reading it"));
    MESSAGE(from_obj, "\n", from_ply);
    fs::remove(big_obj);
    fs::remove(big_ply);
}
