// SPDX-License-Identifier: MIT
#include <prism/geometry/triangle_mesh.hpp>

#include "../support.hpp"
#include "../uv_checks.hpp"

#include <cmath>
#include <vector>

using prism::Interval;
using prism::Random;
using prism::Ray;
using prism::TriangleIndices;
using prism::TriangleMesh;
using prism::Vec3;

namespace {

template <class T>
std::vector<Vec3<T>> soup_positions(Random& rng, int triangles, T extent, T size)
{
    std::vector<Vec3<T>> p;
    for (int i = 0; i < triangles; ++i) {
        const Vec3<T> c = test::random_point<T>(rng, extent);
        for (int k = 0; k < 3; ++k) p.push_back(c + test::random_point<T>(rng, size));
    }
    return p;
}

std::vector<TriangleIndices> soup_triangles(int triangles)
{
    std::vector<TriangleIndices> f;
    for (std::uint32_t i = 0; i < std::uint32_t(triangles); ++i) f.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    return f;
}

} // namespace

TEST_CASE_TEMPLATE("a mesh's Bvh finds what testing every triangle finds (leaves of blocks of 4 or 8)", T, float, double)
{
    Random rng(5u, 14u);
    for (const auto& [n, block] : {std::pair{1, 4}, {7, 4}, {100, 4}, {3000, 4}, {7, 8}, {3000, 8}}) {
        const auto positions = soup_positions<T>(rng, n, T(10), T(1));
        const auto triangles = soup_triangles(n);
        const TriangleMesh<T> mesh(positions, triangles, {.max_leaf_size = 2 * block, .leaf_block = block});
        CHECK_FALSE(mesh.closed());
        for (int i = 0; i < 3000; ++i) {
            Ray<T> ray{test::random_point<T>(rng, T(12)), test::random_direction<T>(rng)};
            if (i % 3 == 1) ray.origin *= T(1000);  // far away
            if (i % 3 == 2) ray.direction[i % 3] = 0; // axis-parallel
            ray.direction = prism::normalize(test::random_point<T>(rng, T(10)) - ray.origin);
            const Interval<T> range{T(0), prism::infinity<T>};
            // Every triangle tested with the ray the mesh tests them with: from afar, brought
            // near its box (core/aabb.hpp).
            const prism::NearRay<T> near = prism::brought_near(ray, mesh.bounds());
            const prism::detail::ShearedRay<T> sheared(near.ray);
            T nearest = prism::infinity<T>;
            for (int f = 0; f < n; ++f) {
                prism::detail::TriangleHit<T> h;
                const std::array<Vec3<T>, 3> c{positions[std::size_t(3 * f)], positions[std::size_t(3 * f + 1)], positions[std::size_t(3 * f + 2)]};
                if (prism::detail::hit_triangle(sheared, c, near.range(range), h)) nearest = std::min(nearest, near.back(h.t));
            }
            REQUIRE(mesh.first_crossing(ray, range) == nearest);
            CHECK(mesh.any_crossing(ray, range) == (nearest < prism::infinity<T>));
            const auto list = mesh.template crossings<false>(ray, range);
            CHECK(list.empty() == !(nearest < prism::infinity<T>));
            if (!list.empty()) CHECK(list.front().t == nearest);
            for (std::size_t k = 1; k < list.size(); ++k) CHECK(list[k - 1].t <= list[k].t);
        }
    }
}

TEST_CASE_TEMPLATE("no ray slips through a closed mesh: aimed at its vertices, edges and faces", T, float, double)
{
    // A geodesic sphere (5120 triangles), and the same far from the origin.
    Random rng(3u, 14u);
    for (const T offset : {T(0), T(1e4)}) {
        const Vec3<T> center(offset, T(-0.5) * offset, T(0.25) * offset);
        const auto buffers = prism::icosphere<T>(center, T(1), 4);
        const TriangleMesh<T> mesh(buffers.positions, buffers.triangles);
        REQUIRE(mesh.closed());
        int missed = 0, wrong = 0, aimed = 0;
        // t = 1 at the target, up to the rounding of the target and the direction.
        const T tolerance = T(1e-4) + T(16) * std::numeric_limits<T>::epsilon() * offset;
        for (const auto& f : buffers.triangles) {
            const Vec3<T> a = buffers.positions[f[0]], b = buffers.positions[f[1]], c = buffers.positions[f[2]];
            // A vertex, the middle of an edge (as rounded), and the centroid.
            for (const Vec3<T> target : {a, T(0.5) * (a + b), (a + b + c) / T(3)}) {
                // From a side that sees the target well inside the silhouette.
                Vec3<T> eye;
                do eye = center + T(3) * test::random_direction<T>(rng);
                while (prism::dot(prism::normalize(target - center), prism::normalize(eye - target)) < T(0.2));
                const Ray<T> ray{eye, target - eye};
                ++aimed;
                const auto list = mesh.crossings(ray, {T(0), prism::infinity<T>});
                // Enters once at the target (t = 1) and leaves once; the lean queries
                // (which test a leaf's triangles four at a time first) agree.
                missed += list.empty() + !mesh.any_crossing(ray, {T(0), prism::infinity<T>});
                wrong += !list.empty() && mesh.first_crossing(ray, {T(0), prism::infinity<T>}) != list[0].t;
                if (!list.empty()) wrong += list.size() != 2 || !list[0].entering || list[1].entering || list.inside_at_start || std::abs(list[0].t - T(1)) > tolerance;
            }
        }
        CHECK(aimed == 3 * 5120);
        CHECK(missed == 0);
        CHECK(wrong == 0);
    }
}

TEST_CASE("a touch at a convex edge enters and leaves at one t; a ray through a face edge crosses once")
{
    const auto cube = prism::box_mesh<float>({0, 0, 0}, {1, 1, 1});
    const TriangleMesh<float> mesh(cube.positions, cube.triangles);
    REQUIRE(mesh.closed());
    // Along z = 0.5, grazing the edge x = y = 1 from outside: it meets the faces x = 1
    // (entering) and y = 1 (leaving) at t = 1.
    const Ray<float> graze{{2, 0, 0.5f}, {-1, 1, 0}};
    const auto touch = mesh.crossings(graze, {0, prism::infinity<float>});
    REQUIRE(touch.size() == 2);
    CHECK(touch[0].t == 1);
    CHECK(touch[1].t == 1);
    CHECK(touch[0].entering);
    CHECK_FALSE(touch[1].entering);
    CHECK_FALSE(touch.inside_at_start);
    CHECK(mesh.first_crossing(graze, {0, prism::infinity<float>}) == 1);
    // Through the diagonal edge that splits the face z = 0 into two triangles: both
    // triangles are hit at t = 1 and merged into one entering crossing.
    const auto through = mesh.crossings({{0.25f, 0.25f, -1}, {0, 0, 1}}, {0, prism::infinity<float>});
    REQUIRE(through.size() == 2);
    CHECK(through[0].t == 1);
    CHECK(through[0].entering);
    CHECK(through[1].t == 2);
    CHECK_FALSE(through[1].entering);
    // From inside: the range starts inside, and a range past its far face sees nothing.
    const auto inside = mesh.crossings({{0.5f, 0.5f, 0.5f}, {0, 0, 1}}, {0, prism::infinity<float>});
    CHECK(inside.inside_at_start);
    REQUIRE(inside.size() == 1);
    CHECK(inside[0].t == 0.5f);
    CHECK(inside[0].normal.z == 1);
    const auto inside_short = mesh.crossings({{0.5f, 0.5f, 0.5f}, {0, 0, 1}}, {0, 0.25f});
    CHECK(inside_short.inside_at_start);
    CHECK(inside_short.empty());
}

TEST_CASE("a closed mesh's inside agrees with the box it tessellates")
{
    const auto cube = prism::box_mesh<double>({-1, -2, -3}, {3, 2, 1});
    const TriangleMesh<double> mesh(cube.positions, cube.triangles);
    const prism::Box<double> box({-1, -2, -3}, {3, 2, 1});
    Random rng(9u, 14u);
    int disagree = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3<double> p = test::random_point<double>(rng, 4.0);
        disagree += mesh.contains(p) != box.contains(p);
        const Ray<double> ray{p, test::random_direction<double>(rng)};
        const auto a = mesh.crossings(ray, {0, prism::infinity<double>});
        const auto b = box.crossings(ray, {0, prism::infinity<double>});
        REQUIRE(a.size() == b.size());
        CHECK(a.inside_at_start == b.inside_at_start);
        for (std::size_t k = 0; k < a.size(); ++k) {
            CHECK(a[k].t == doctest::Approx(b[k].t).epsilon(1e-12));
            CHECK(a[k].entering == b[k].entering);
            CHECK(prism::dot(a[k].normal, b[k].normal) == doctest::Approx(1));
        }
    }
    CHECK(disagree == 0);
}

TEST_CASE("a closed mesh works as a CSG child: a sphere minus a tessellated box is a sphere minus the box")
{
    const auto cube = prism::box_mesh<double>({-0.5, -0.5, -2}, {0.5, 0.5, 2});
    using Cut = prism::Difference<prism::Sphere<double>, TriangleMesh<double>>;
    using Exact = prism::Difference<prism::Sphere<double>, prism::Box<double>>;
    const Cut cut(prism::Sphere<double>({0, 0, 0}, 1), TriangleMesh<double>(cube.positions, cube.triangles));
    const Exact exact(prism::Sphere<double>({0, 0, 0}, 1), prism::Box<double>({-0.5, -0.5, -2}, {0.5, 0.5, 2}));
    Random rng(4u, 14u);
    for (int i = 0; i < 20000; ++i) {
        const Ray<double> ray{test::random_point<double>(rng, 2.0), test::random_direction<double>(rng)};
        const auto a = cut.crossings(ray, {0, prism::infinity<double>});
        const auto b = exact.crossings(ray, {0, prism::infinity<double>});
        REQUIRE(a.size() == b.size());
        CHECK(a.inside_at_start == b.inside_at_start);
        for (std::size_t k = 0; k < a.size(); ++k) CHECK(a[k].t == doctest::Approx(b[k].t).epsilon(1e-12));
    }
}

TEST_CASE_TEMPLATE("a ray leaving a mesh's surface never hits the triangle it left", T, float, double)
{
    // Convex meshes (pbrt-v4's reintersection test), small and far from the origin: 2000
    // meshes, 10 pairs of rays each (a mesh takes longer to build than to trace).
    Random rng(2u, 14u);
    const int self_hits = test::reintersections(rng, 2000, [](Random& r) {
        const T scale = T(std::pow(10.0, 2 * r.uniform<double>() - 2)); // 0.01 to 1: the eye 5 away is outside
        const Vec3<T> center = test::random_point<T>(r, T(1e4) * r.uniform<T>());
        const auto b = prism::icosphere<T>(center, scale, 2);
        return std::pair{TriangleMesh<T>(b.positions, b.triangles), center};
    }, 10);
    CHECK(self_hits == 0);
}

TEST_CASE("a mesh is hit wherever its analytic twin is, from 10 to 10^7 times its size away, and missed where the twin is missed (float)")
{
    // A geodesic sphere of radius 1 (two subdivisions) and an instance of it scaled by
    // 1/1000, seen from afar, each ray aimed anywhere across the sphere's disk (its
    // incidence normal at the middle, grazing at the rim). The float ray itself, in double:
    // a ray whose line passes within the polyhedron's inscribed sphere (less a margin of
    // 10^-3) must hit it, one passing outside the circumscribed sphere (plus the margin)
    // must not, and a hit lies between the two spheres. Regression: the bound on t's
    // rounding (pbrt's) grows as the square of the distance, and from 5 10^4 radii it
    // refused 12 % of these hits, from 10^5 all of them.
    const auto b = prism::icosphere<float>({0, 0, 0}, 1, 2);
    const TriangleMesh<float> mesh(b.positions, b.triangles);
    const prism::Transformed<TriangleMesh<float>> small(mesh, prism::Transform<float>::scale(Vec3<float>(1e-3f)));
    double inscribed = 1;
    for (const auto& [i, j, k] : b.triangles) {
        const Vec3<double> p0(b.positions[i]), p1(b.positions[j]), p2(b.positions[k]);
        inscribed = std::min(inscribed, std::abs(prism::dot(prism::normalize(prism::cross(p1 - p0, p2 - p0)), p0)));
    }
    Random rng(9u, 2u);
    for (const double distance : {1e1, 1e3, 1e4, 5e4, 1e5, 1e6, 1e7})
        for (const double size : {1.0, 1e-3}) {
            CAPTURE(distance);
            CAPTURE(size);
            int lost = 0, false_hits = 0, misplaced = 0, must_hit = 0;
            for (int i = 0; i < 20000; ++i) {
                const Vec3<double> toward = test::random_direction<double>(rng);
                const Vec3<double> aim = test::random_point<double>(rng, 1.05);
                const Ray<float> ray{Vec3<float>(-toward * (distance * size)), prism::normalize(Vec3<float>(aim * size + toward * (distance * size)))};
                const float t = size == 1.0 ? mesh.first_crossing(ray, {0, prism::infinity<float>}) : small.first_crossing(ray, {0, prism::infinity<float>});
                // The float ray's line in double, in the unit sphere's frame.
                const Vec3<double> o = Vec3<double>(ray.origin) / size, d = prism::normalize(Vec3<double>(ray.direction));
                const double along = -prism::dot(o, d);
                const Vec3<double> closest = o + along * d; // (not |o|^2 - along^2, which cancels to nothing from afar)
                const double miss2 = prism::dot(closest, closest);
                const double margin = 1e-3;
                if (miss2 < (inscribed - margin) * (inscribed - margin)) {
                    ++must_hit;
                    lost += !(t < prism::infinity<float>);
                    const double scale = size / prism::length(Vec3<double>(ray.direction));
                    const double entry_outer = (along - std::sqrt(1 - miss2)) * scale, entry_inner = (along - std::sqrt(inscribed * inscribed - miss2)) * scale;
                    const double slack = 1e-6 * distance * size; // t's own precision, a few floats
                    misplaced += t < prism::infinity<float> && !(t >= entry_outer - slack && t <= entry_inner + slack);
                } else if (miss2 > (1 + margin) * (1 + margin)) {
                    false_hits += t < prism::infinity<float>;
                }
            }
            CHECK(must_hit > 10000);
            CHECK(lost == 0);
            CHECK(false_hits == 0);
            CHECK(misplaced == 0);
        }
}

TEST_CASE("a ray with a NaN or an infinity in it crosses no mesh and no instance of one")
{
    // Regression: an all-NaN ray wrote past the Bvh walk's stack (accel/bvh.hpp).
    const auto b = prism::icosphere<float>({0, 0, 0}, 1, 2);
    const TriangleMesh<float> mesh(b.positions, b.triangles);
    const prism::Transformed<TriangleMesh<float>> moved(mesh, prism::Transform<float>::translate({5, 0, 0}));
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = prism::infinity<float>;
    for (const Ray<float>& ray : {Ray<float>{Vec3<float>(nan), Vec3<float>(nan)}, Ray<float>{{nan, 0, -3}, {0, 0, 1}}, Ray<float>{{0, 0, -3}, {0, nan, 1}},
                                  Ray<float>{{0, 0, -inf}, {0, 0, 1}}, Ray<float>{{0, 0, -3}, {0, 0, inf}}}) {
        for (const Interval<float> range : {Interval<float>{0, inf}, Interval<float>{0, 10}}) {
            CHECK_FALSE(mesh.first_crossing(ray, range) < inf);
            CHECK_FALSE(mesh.any_crossing(ray, range));
            CHECK(mesh.crossings(ray, range).empty());
            CHECK_FALSE(moved.first_crossing(ray, range) < inf);
            CHECK(moved.crossings(ray, range).empty());
        }
    }
}

TEST_CASE("a mesh is closed only when every edge pairs with its reverse, and must wind outward")
{
    auto sphere = prism::icosphere<float>({0, 0, 0}, 1, 1);
    CHECK(TriangleMesh<float>(sphere.positions, sphere.triangles).closed());
    auto open = sphere;
    open.triangles.pop_back();
    const TriangleMesh<float> cup(open.positions, open.triangles);
    CHECK_FALSE(cup.closed());
    CHECK_FALSE(cup.contains({0, 0, 0}));
    CHECK_FALSE(cup.crossings({{0, 0, 0}, {0, 0, 1}}, {0, prism::infinity<float>}).inside_at_start);
    auto inward = sphere;
    for (auto& f : inward.triangles) std::swap(f[1], f[2]);
    CHECK_THROWS_WITH_AS(TriangleMesh<float>(inward.positions, inward.triangles), doctest::Contains("wind inward"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(TriangleMesh<float>(sphere.positions, std::vector<TriangleIndices>{}), doctest::Contains("triangles must not be empty"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(TriangleMesh<float>(sphere.positions, std::vector<TriangleIndices>{{0, 1, 9999}}), doctest::Contains("vertex index 9999"), std::invalid_argument);
    auto nan = sphere;
    nan.positions[3].y = std::nanf("");
    CHECK_THROWS_WITH_AS(TriangleMesh<float>(nan.positions, nan.triangles), doctest::Contains("position 3 must be finite"), std::invalid_argument);
}

TEST_CASE("copies of a mesh share its data; transformed copies are instances")
{
    const auto b = prism::icosphere<float>({0, 0, 0}, 1, 3);
    const TriangleMesh<float> mesh(b.positions, b.triangles);
    const prism::Transformed<TriangleMesh<float>> moved(mesh, prism::Transform<float>::translate({5, 0, 0}));
    CHECK(&moved.shape().bvh() == &mesh.bvh());
    // Hit through the instance where the moved sphere is.
    const float t = moved.first_crossing({{5, 0, -3}, {0, 0, 1}}, {0, prism::infinity<float>});
    CHECK(t == doctest::Approx(2).epsilon(0.01));
    CHECK(moved.crossings<false>({{5, 0, -3}, {0, 0, 1}}, {0, prism::infinity<float>}).front().t == t);
    CHECK(mesh.memory_bytes() > 1280 * 36);
}

TEST_CASE_TEMPLATE("vertex normals shade a tessellated sphere as the sphere: the interpolated normal is the true sphere's to the interpolation's error", T, float, double)
{
    // The icosphere's vertices lie on the unit sphere, so their exact normals are the
    // positions themselves. Between them the interpolated normal is off the sphere's by
    // at most about theta^2 / 8 for an edge of angle theta (~0.06 rad at 4 subdivisions:
    // 4e-4 rad), the facet's own normal by up to theta / sqrt(3) (~0.03 rad).
    const auto buffers = prism::icosphere<T>({0, 0, 0}, 1, 4);
    prism::MeshBuffers<T> smooth = buffers;
    smooth.normals = buffers.positions;
    const TriangleMesh<T> mesh(smooth);
    CHECK(mesh.has_normals());
    CHECK_FALSE(mesh.has_uvs());
    // Angle-weighted vertex normals of the same mesh are the sphere's to a few 1e-3 (the
    // subdivided triangles are not all alike around a vertex): a tenth of a facet's error.
    const std::vector<Vec3<T>> estimated = prism::vertex_normals(buffers);
    double worst_vertex = 0;
    for (std::size_t i = 0; i < estimated.size(); ++i)
        worst_vertex = std::max(worst_vertex, std::acos(std::min(1.0, double(prism::dot(estimated[i], buffers.positions[i])))));
    CHECK(worst_vertex < 5e-3);
    Random rng(41, 2);
    double worst_shading = 0, worst_facet = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3<T> from = test::random_direction<T>(rng) * T(3);
        const Vec3<T> at = test::random_direction<T>(rng) * T(0.9);
        const auto all = mesh.crossings({from, at - from}, {T(0), prism::infinity<T>});
        REQUIRE(all.size() == 2);
        for (const auto& c : all) {
            const Vec3<double> sphere = prism::normalize(Vec3<double>(c.point));
            worst_shading = std::max(worst_shading, std::acos(std::min(1.0, prism::dot(sphere, Vec3<double>(c.shading)))));
            worst_facet = std::max(worst_facet, std::acos(std::min(1.0, prism::dot(sphere, Vec3<double>(c.normal)))));
            CHECK(std::abs(prism::length(c.shading) - T(1)) < T(1e-5));
        }
    }
    CHECK(worst_shading < 1e-3);
    CHECK(worst_facet > 0.01); // the facets alone are visibly off
}

TEST_CASE_TEMPLATE("uvs interpolate: an affine map of the positions comes back exactly at every hit", T, float, double)
{
    // A square [0, 2] x [0, 2] at y = 0, split in two, with uv = (x / 2, 1 - z / 2).
    prism::MeshBuffers<T> square;
    square.positions = {{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}};
    square.triangles = {{0, 2, 1}, {0, 3, 2}};
    for (const Vec3<T>& p : square.positions) square.uvs.push_back({p.x / 2, 1 - p.z / 2});
    const TriangleMesh<T> mesh(square);
    CHECK(mesh.has_uvs());
    Random rng(3, 8);
    for (int i = 0; i < 10000; ++i) {
        const T x = T(2) * rng.uniform<T>(), z = T(2) * rng.uniform<T>();
        const auto all = mesh.crossings({{x, 1, z}, {0, -1, 0}}, {T(0), prism::infinity<T>});
        if (all.empty()) continue; // a ray exactly through the diagonal may touch
        const auto& c = all.front();
        CHECK(c.uv.x == doctest::Approx(x / 2).epsilon(1e-5));
        CHECK(c.uv.y == doctest::Approx(1 - z / 2).epsilon(1e-5));
        CHECK(c.shading == c.normal); // no normals: flat
    }
}

TEST_CASE("a shading normal that leans over to the triangle's back gives way to the true normal")
{
    // Corners 1 and 2 lean far past the edge; corner 0 stands up. Near corner 0 the
    // interpolation is above the triangle, near the far edge behind it.
    prism::MeshBuffers<double> leaning;
    leaning.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}};
    leaning.triangles = {{0, 1, 2}};
    leaning.normals = {{0, 1, 0}, {0, -1, 0.2}, {0.2, -1, 0}};
    const TriangleMesh<double> mesh(leaning);
    const auto near_0 = mesh.crossings({{0.05, 1, -0.05}, {0, -1, 0}}, {0, prism::infinity<double>});
    REQUIRE(near_0.size() == 1);
    CHECK(prism::dot(near_0.front().shading, near_0.front().normal) > 0.5);
    CHECK(near_0.front().shading != near_0.front().normal);
    const auto far_edge = mesh.crossings({{0.45, 1, -0.45}, {0, -1, 0}}, {0, prism::infinity<double>});
    REQUIRE(far_edge.size() == 1);
    CHECK(far_edge.front().shading == far_edge.front().normal);
}

TEST_CASE("a transformed mesh carries its shading normal as a normal, and a CSG difference turns it with the surface")
{
    const auto buffers = prism::icosphere<double>({0, 0, 0}, 1, 2);
    prism::MeshBuffers<double> smooth = buffers;
    smooth.normals = buffers.positions;
    const TriangleMesh<double> mesh(smooth);
    // Squashed to an ellipsoid x^2/4 + y^2 + z^2 = 1: normals go by the inverse transpose.
    const prism::Transformed<TriangleMesh<double>> squashed(mesh, prism::Transform<double>::scale({2, 1, 1}));
    Random rng(9, 4);
    for (int i = 0; i < 2000; ++i) {
        const Vec3<double> from = test::random_direction<double>(rng) * 5.0;
        const Vec3<double> at = test::random_direction<double>(rng) * 0.5;
        const Ray<double> ray{from, at - from};
        const auto world = squashed.crossings(ray, {0, prism::infinity<double>});
        const auto local = mesh.crossings({{from.x / 2, from.y, from.z}, {ray.direction.x / 2, ray.direction.y, ray.direction.z}}, {0, prism::infinity<double>});
        REQUIRE(world.size() == local.size());
        for (std::size_t k = 0; k < world.size(); ++k) {
            const Vec3<double> expected = prism::normalize(Vec3<double>{local[k].shading.x / 2, local[k].shading.y, local[k].shading.z});
            CHECK(prism::length(world[k].shading - expected) < 1e-12);
        }
    }
    // A ball with a smooth mesh ball cut out of its middle: inside the cavity's wall the
    // outward normal of the difference points into the cavity, and so does its shading.
    const prism::Difference<prism::Sphere<double>, TriangleMesh<double>> shell(prism::Sphere<double>({0, 0, 0}, 2), mesh);
    const auto through = shell.crossings({{-3, 0.1, 0.05}, {1, 0, 0}}, {0, prism::infinity<double>});
    REQUIRE(through.size() == 4);
    for (std::size_t k = 1; k < 3; ++k) {
        CHECK(prism::dot(through[k].shading, through[k].normal) > 0.9);
        CHECK(prism::dot(through[k].normal, through[k].point) < 0); // into the cavity, toward the centre
    }
}

TEST_CASE("vertex normals and uvs are checked: one per position, finite, non-zero, not all against the winding")
{
    prism::MeshBuffers<float> b;
    b.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}};
    b.triangles = {{0, 1, 2}};
    b.normals = {{0, 1, 0}, {0, 1, 0}};
    CHECK_THROWS_WITH_AS(TriangleMesh<float>{b}, "prism: TriangleMesh normals must be one per position (3), got 2", std::invalid_argument);
    b.normals = {{0, 1, 0}, {0, 0, 0}, {0, 1, 0}};
    CHECK_THROWS_WITH_AS(TriangleMesh<float>{b}, doctest::Contains("TriangleMesh normal 1 must be finite and non-zero"), std::invalid_argument);
    b.normals = {{0, -1, 0}, {0, -1, 0}, {0.1f, -1, 0}};
    CHECK_THROWS_WITH_AS(TriangleMesh<float>{b}, doctest::Contains("TriangleMesh triangle 0 has all three normals pointing against its winding"), std::invalid_argument);
    b.normals = {{0, 2, 0}, {0, 1, 0}, {0, 1, 0}}; // need not be unit: normalised
    b.uvs = {{0, 0}, {1, 0}};
    CHECK_THROWS_WITH_AS(TriangleMesh<float>{b}, "prism: TriangleMesh uvs must be one per position (3), got 2", std::invalid_argument);
    b.uvs = {{0, 0}, {1, 0}, {0, std::numeric_limits<float>::quiet_NaN()}};
    CHECK_THROWS_WITH_AS(TriangleMesh<float>{b}, doctest::Contains("TriangleMesh uv 2 must be finite"), std::invalid_argument);
    b.uvs = {{0, 0}, {1, 0}, {0, 1}};
    const TriangleMesh<float> mesh(b);
    const auto c = mesh.crossings({{0.2f, 1, -0.2f}, {0, -1, 0}}, {0, prism::infinity<float>}).front();
    CHECK(c.shading.y == doctest::Approx(1));
    // Normals and uvs are kept at every leaf-order position, with the padding of the blocks of four.
    CHECK(mesh.bvh().primitives().size() == 4);
    CHECK_THROWS_WITH_AS(TriangleMesh<float>(b.positions, b.triangles, {.leaf_block = 2}),
                         "prism: TriangleMesh BvhConfig leaf_block must be a multiple of 4 (its triangles are tested in blocks), got 2", std::invalid_argument);
    CHECK(mesh.memory_bytes() == TriangleMesh<float>(b.positions, b.triangles).memory_bytes() + 4 * (3 * sizeof(Vec3<float>) + 3 * sizeof(prism::Vec2<float>)));
}

TEST_CASE("a mesh's dp/du and dp/dv come from its triangles' uvs: finite differences on a skewed, sheared map")
{
    // A folded strip with uv an affine map of position that is neither orthogonal nor
    // unit: each triangle's derivatives are that map's inverse.
    prism::MeshBuffers<double> strip;
    strip.positions = {{0, 0, 0}, {2, 0, 0}, {2, 0.5, 2}, {0, 0.5, 2}, {2, 1.5, 3}, {0, 1.5, 3}};
    strip.triangles = {{0, 2, 1}, {0, 3, 2}, {3, 4, 2}, {3, 5, 4}};
    for (const Vec3<double>& p : strip.positions) strip.uvs.push_back({0.3 * p.x + 0.1 * p.z, -0.2 * p.x + 0.4 * (p.z + p.y)});
    const TriangleMesh<double> mesh(strip);
    const auto found = uv_checks::check_derivatives(mesh, {1, 0.7, 1.5}, 1.5, 3000, [](const auto&) { return false; });
    CHECK(found.checked > 500);
    CHECK(found.worst < 1e-6);
    // Collinear uvs: none.
    strip.uvs.assign(strip.positions.size(), prism::Vec2<double>{0.5, 0.5});
    const auto flat = TriangleMesh<double>(strip).crossings({{1, 5, 0.5}, {0, -1, 0}}, {0, prism::infinity<double>});
    REQUIRE(!flat.empty());
    CHECK_FALSE(flat.front().has_uv());
}
