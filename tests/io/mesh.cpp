// SPDX-License-Identifier: MIT
#include <prism/io/mesh.hpp>

#include "../support.hpp"

#include <filesystem>
#include <fstream>
#include <string>

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
