// SPDX-License-Identifier: MIT
#include <prism/geometry/triangle.hpp>

#include "../support.hpp"

#include <algorithm>
#include <array>
#include <cmath>

using prism::Random;
using prism::Ray;
using prism::Vec3;

namespace {

/// Moller-Trumbore in long double: an independent test for rays that pass well clear of
/// every edge. Returns t, or a negative value for a miss.
template <class T>
long double moller_trumbore(const Ray<T>& ray, const std::array<Vec3<T>, 3>& c, long double& margin)
{
    using L = long double;
    const L o[3] = {ray.origin.x, ray.origin.y, ray.origin.z}, d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    L p0[3], e1[3], e2[3];
    for (int i = 0; i < 3; ++i) p0[i] = c[0][i], e1[i] = L(c[1][i]) - L(c[0][i]), e2[i] = L(c[2][i]) - L(c[0][i]);
    const auto crs = [](const L* a, const L* b, L* r) { r[0] = a[1] * b[2] - a[2] * b[1], r[1] = a[2] * b[0] - a[0] * b[2], r[2] = a[0] * b[1] - a[1] * b[0]; };
    const auto dt = [](const L* a, const L* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    L p[3], q[3], s[3];
    crs(d, e2, p);
    const L det = dt(e1, p);
    if (det == 0) return margin = 0, -1;
    for (int i = 0; i < 3; ++i) s[i] = o[i] - p0[i];
    const L u = dt(s, p) / det;
    crs(s, e1, q);
    const L v = dt(d, q) / det;
    margin = std::min({u, v, 1 - u - v});
    if (margin < 0) return -1;
    return dt(e2, q) / det;
}

/// Four triangles around a hub, as a fan of shared vertices and edges (a ray through one
/// is on the edge of its neighbours), in a block, and a ray's eye and target: aimed at a
/// corner, an edge's midpoint or a random point, some axis-parallel, every fourth 10^4 away.
template <class T>
struct Fan {
    std::array<std::array<Vec3<T>, 3>, 4> fan;
    prism::detail::TriangleBlock<T> block;
    std::array<Vec3<T>, 3> aim; ///< the triangle aimed at
    Vec3<T> target, eye;
};

template <class T>
Fan<T> fan_and_eye(Random& rng, int i)
{
    Fan<T> out;
    const T scale = i % 4 == 3 ? T(1e4) : T(1);
    const Vec3<T> center = test::random_point<T>(rng, T(2)) * scale;
    const Vec3<T> hub = center + test::random_point<T>(rng, T(0.1));
    Vec3<T> previous = center + test::random_point<T>(rng, T(1));
    for (auto& t : out.fan) {
        const Vec3<T> next = center + test::random_point<T>(rng, T(1));
        t = {hub, previous, next};
        previous = next;
    }
    for (std::uint32_t lane = 0; lane < 4; ++lane)
        for (std::size_t c = 0; c < 3; ++c)
            for (int axis = 0; axis < 3; ++axis) out.block.corner[3 * c + std::size_t(axis)][lane] = out.fan[lane][c][axis];
    out.aim = out.fan[std::size_t(i % 4)];
    const auto& aim = out.aim;
    out.target = i % 3 == 0 ? aim[0] : (i % 3 == 1 ? aim[1] + T(0.5) * (aim[2] - aim[1]) : center + test::random_point<T>(rng, T(1)));
    out.eye = out.target + T(3) * test::random_direction<T>(rng);
    if (i % 7 == 0) out.eye[i % 3] = out.target[i % 3]; // axis-parallel
    return out;
}

} // namespace

TEST_CASE_TEMPLATE("a triangle's hit against Moller-Trumbore in long double, away from its edges", T, float, double)
{
    Random rng(11u, 14u);
    int hits = 0, compared = 0;
    for (int i = 0; i < 200000; ++i) {
        const std::array<Vec3<T>, 3> c{test::random_point<T>(rng, T(1)), test::random_point<T>(rng, T(1)), test::random_point<T>(rng, T(1))};
        // Aimed near the triangle: about half hit it.
        const T u = T(1.6) * rng.uniform<T>() - T(0.3), v = T(1.6) * rng.uniform<T>() - T(0.3);
        const Vec3<T> origin = test::random_point<T>(rng, T(4));
        const Ray<T> ray{origin, prism::normalize(c[0] + u * (c[1] - c[0]) + v * (c[2] - c[0]) - origin)};
        long double margin = 0;
        const long double t = moller_trumbore(ray, c, margin);
        prism::detail::TriangleHit<T> h{};
        const bool hit = prism::detail::hit_triangle(prism::detail::ShearedRay<T>(ray), c, {T(0), prism::infinity<T>}, h);
        // Too near an edge, the origin, or the triangle's plane to judge at float precision.
        const Vec3<T> n = prism::normalize(prism::cross(c[1] - c[0], c[2] - c[0]));
        if (std::fabs(double(margin)) < 1e-4 || (t >= 0 && t < 1e-3) || std::abs(prism::dot(n, ray.direction)) < T(0.01)) continue;
        ++compared;
        REQUIRE(hit == (t > 0));
        if (!hit) continue;
        ++hits;
        CHECK(double(h.t) == doctest::Approx(double(t)).epsilon(sizeof(T) == 4 ? 1e-4 : 1e-11));
        CHECK(h.entering == (prism::dot(n, ray.direction) < T(0)));
        const Vec3<T> p = h.b[0] * c[0] + h.b[1] * c[1] + h.b[2] * c[2];
        CHECK(prism::length(p - ray.at(h.t)) < (sizeof(T) == 4 ? 1e-4 : 1e-12) * (1 + std::abs(double(h.t))));
    }
    CHECK(compared > 180000);
    CHECK(hits > 30000);
}

TEST_CASE_TEMPLATE("the four-lane edge test keeps every triangle hit_triangle hits, rejects most others, and equals its lane-by-lane twin", T, float, double)
{
    // Fans of triangles around shared vertices and edges (a ray through one is on the
    // edge of its neighbours), rays aimed at corners, edge points and random points.
    Random rng(17u, 2u);
    int lost = 0, hits = 0, misses = 0, rejected = 0, lanewise_differs = 0;
    for (int i = 0; i < 20000; ++i) {
        const Fan<T> f = fan_and_eye<T>(rng, i);
        const auto& [fan, block, aim, target, aimed_from] = f;
        Vec3<T> eye = aimed_from;
        const Ray<T> ray{eye, target - eye};
        const prism::detail::ShearedRay<T> sheared(ray);
        const unsigned kept = prism::detail::edge_test(sheared, block);
        lanewise_differs += kept != prism::detail::edge_test_lanewise(sheared, block); // the scalar twin: the same bits
        for (std::uint32_t lane = 0; lane < 4; ++lane) {
            prism::detail::TriangleHit<T> h;
            REQUIRE(block.triangle(lane) == fan[lane]);
            if (prism::detail::hit_triangle(sheared, fan[lane], {-prism::infinity<T>, prism::infinity<T>}, h)) {
                ++hits;
                lost += (kept >> lane & 1u) == 0;
            } else {
                ++misses;
                rejected += (kept >> lane & 1u) == 0;
            }
        }
    }
    CHECK(lost == 0);
    CHECK(hits > 10000);
    CHECK(rejected > misses / 2);
    CHECK(lanewise_differs == 0);
}


#if PRISM_VECTOR_EXTENSIONS
TEST_CASE_TEMPLATE("the four-lane full test gives hit_triangle's answer, t, weights and side, bit for bit, over fans, far and near ranges", T, float, double)
{
    // As above: fans around shared vertices and edges, rays at corners, edge points and
    // random points, at unit scale and 10^4 away; ranges that cut hits off at either end
    // (the t bound near 0 as well: rays that start on a triangle's plane).
    Random rng(29u, 3u);
    int hits = 0, redone = 0, differ = 0;
    for (int i = 0; i < 40000; ++i) {
        const Fan<T> f = fan_and_eye<T>(rng, i);
        const auto& [fan, block, aim, target, aimed_from] = f;
        Vec3<T> eye = aimed_from;
        if (i % 11 == 0) eye = aim[1] + T(0.3) * (aim[2] - aim[1]) + T(0.2) * (aim[0] - aim[1]); // on the plane of a triangle
        const Ray<T> ray{eye, target - eye};
        const prism::detail::ShearedRay<T> sheared(ray);
        const prism::Interval<T> range = i % 5 == 0 ? prism::Interval<T>{T(0), T(0.5) + rng.uniform<T>()} : prism::Interval<T>{T(0), prism::infinity<T>};
        const prism::detail::BlockHits<T> block_hits = prism::detail::hit_block(sheared, block, range, 0xfu);
        for (std::uint32_t lane = 0; lane < 4; ++lane) {
            if ((block_hits.redo >> lane) & 1u) {
                ++redone;
                continue;
            }
            prism::detail::TriangleHit<T> h;
            const bool hit = prism::detail::hit_triangle(sheared, fan[lane], range, h);
            hits += hit;
            if (hit != (((block_hits.hit >> lane) & 1u) != 0)) {
                ++differ;
                continue;
            }
            if (!hit) continue;
            differ += h.t != block_hits.t[lane] || h.b[0] != block_hits.b[0][lane] || h.b[1] != block_hits.b[1][lane] || h.b[2] != block_hits.b[2][lane] ||
                      h.entering != (((block_hits.entering >> lane) & 1u) != 0);
        }
    }
    CHECK(differ == 0);
    CHECK(hits > 12000);
    CHECK(redone > 0); // the rays at corners and on edges meet edge functions of 0
}
#endif
