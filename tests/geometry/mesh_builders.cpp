// SPDX-License-Identifier: MIT
#include <prism/geometry/mesh_builders.hpp>

#include "../support.hpp"

#include <algorithm>
#include <cmath>

using prism::Vec3;

namespace {

/// The volume a closed mesh encloses (the divergence theorem over its faces).
template <class T>
double volume(const prism::MeshBuffers<T>& m)
{
    double v = 0;
    for (const auto& f : m.triangles)
        v += prism::dot(Vec3<double>(m.positions[f[0]]), prism::cross(Vec3<double>(m.positions[f[1]]), Vec3<double>(m.positions[f[2]]))) / 6;
    return v;
}

} // namespace

TEST_CASE("an icosphere has 20 4^n triangles and 10 4^n + 2 vertices on the sphere, and its volume tends to the ball's")
{
    double previous_error = 1;
    for (int n = 0; n <= 5; ++n) {
        const auto m = prism::icosphere<double>({1, 2, 3}, 2, n);
        CHECK(m.triangles.size() == std::size_t(20 * std::pow(4, n)));
        CHECK(m.positions.size() == std::size_t(10 * std::pow(4, n) + 2));
        for (const auto& p : m.positions) CHECK(prism::length(p - Vec3<double>(1, 2, 3)) == doctest::Approx(2).epsilon(1e-14));
        CHECK(prism::TriangleMesh<double>(m.positions, m.triangles).closed());
        // Inscribed: below the ball's volume, and 4x closer each level (the chord's sag).
        const double error = 1 - volume(m) / (4.0 / 3 * prism::pi<double> * 8);
        CHECK(error > 0);
        if (n >= 2) CHECK(error / previous_error == doctest::Approx(0.25).epsilon(0.05));
        previous_error = error;
    }
    CHECK_THROWS_WITH_AS((void)prism::icosphere<float>({0, 0, 0}, -1, 2), doctest::Contains("icosphere radius"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((void)prism::icosphere<float>({0, 0, 0}, 1, 11), doctest::Contains("icosphere subdivisions must be in [0, 10], got 11"), std::invalid_argument);
}

TEST_CASE("a box mesh is closed, wound outward, and encloses the box's volume")
{
    const auto m = prism::box_mesh<double>({-1, 0, 2}, {1, 3, 2.5});
    CHECK(m.triangles.size() == 12);
    CHECK(volume(m) == doctest::Approx(2 * 3 * 0.5));
    CHECK(prism::TriangleMesh<double>(m.positions, m.triangles).closed());
    CHECK_THROWS_WITH_AS((void)prism::box_mesh<float>({0, 0, 0}, {1, 0, 1}), doctest::Contains("box_mesh lo must be below hi"), std::invalid_argument);
}

TEST_CASE("a height field samples its function, faces up, and is open")
{
    const auto m = prism::height_field<double>(-1, 1, 0, 4, 8, [](double x, double z) { return x * x + 0.5 * z; });
    CHECK(m.triangles.size() == 2 * 64);
    CHECK(m.positions.size() == 81);
    for (const auto& p : m.positions) CHECK(p.y == doctest::Approx(p.x * p.x + 0.5 * p.z));
    for (const auto& f : m.triangles)
        CHECK(prism::cross(m.positions[f[1]] - m.positions[f[0]], m.positions[f[2]] - m.positions[f[0]]).y > 0);
    const prism::TriangleMesh<double> surface(m.positions, m.triangles);
    CHECK_FALSE(surface.closed());
    // A vertical ray meets it at its height.
    const auto c = surface.crossings({{0.3, 10, 1.7}, {0, -1, 0}}, {0, prism::infinity<double>});
    REQUIRE(c.size() == 1);
    CHECK(10 - c[0].t == doctest::Approx(0.3 * 0.3 + 0.85).epsilon(0.01));
    CHECK(c[0].entering);
    CHECK_THROWS_WITH_AS((void)prism::height_field<float>(0, 1, 0, 1, 0, [](float, float) { return 0.f; }), doctest::Contains("height_field cells"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((void)prism::height_field<float>(0, 1, 0, 1, 2, [](float x, float) { return x > 0.5f ? std::nanf("") : 0.f; }), doctest::Contains("must be finite"),
                         std::invalid_argument);
}

TEST_CASE("height_field_solid is a closed solid: a vertical ray through a lattice point enters at the floor and leaves at the height there; a point between is inside")
{
    const auto height = [](double x, double z) { return 0.2 * std::sin(3 * x) * std::cos(2 * z) + 0.05 * x; };
    const auto m = prism::height_field_solid<double>(-1, 2, 0, 1, 6, -0.5, height);
    CHECK(m.triangles.size() == 4 * 6 * 6 + 8 * 6);
    const prism::TriangleMesh<double> solid(m.positions, m.triangles); // refuses a mesh that is not closed or winds inward
    for (int i = 0; i <= 6; ++i) {
        const double x = -1 + 3.0 * i / 6, z = 0.5;
        CAPTURE(x);
        const auto c = solid.crossings<false>(prism::Ray<double>{{x, -2, z}, {0, 1, 0}}, {0.0, prism::infinity<double>});
        REQUIRE(c.size() == 2);
        CHECK(c[0].entering);
        CHECK(c[0].t == doctest::Approx(1.5));
        CHECK(!c[1].entering);
        CHECK(c[1].t == doctest::Approx(2 + height(x, z)));
        CHECK(solid.crossings<false>(prism::Ray<double>{{std::clamp(x, -0.9, 1.9), -0.3, z}, {0, 0, 1}}, {0.0, prism::infinity<double>}).inside_at_start); // (off the walls)
    }
    CHECK_THROWS_WITH_AS((void)prism::height_field_solid<float>(0, 1, 0, 1, 2, 0.5f, [](float x, float) { return x; }),
                         doctest::Contains("must be above the bottom 0.5"), std::invalid_argument);
}
