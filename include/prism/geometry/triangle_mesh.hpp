// SPDX-License-Identifier: MIT
// TriangleMesh: a solid (or an open surface) bounded by triangles, with its own Bvh.
//
// The ray-triangle test is Woop, Benthin & Wald's watertight one ("Watertight
// Ray/Triangle Intersection", JCGT 2013), with pbrt-v4's bound on t: the vertices are
// moved to the ray's origin and sheared so the ray runs along +z; the three 2D edge
// functions then decide the hit by their signs alone. A vertex shared by two triangles
// is carried through the same arithmetic for both, so a ray through their common edge
// finds at least one of them: no ray slips between the triangles of a closed mesh. An
// edge function that rounds to exactly zero is worked out again in double.
//
// A mesh is a closed solid when every edge is shared by exactly two triangles that
// run along it in opposite directions (checked at construction): then it has an
// inside, works as a CSG child and as glass, and a ray enters where the triangle's
// normal (right-handed: (b - a) x (c - a), outward) faces against it. Any other mesh is
// an open surface: a ray crosses it wherever it hits it, entering on the normal's side,
// and it is never inside (a shadow ray through an open glass surface meets boundaries
// that do not pair up: use a closed mesh for glass).
//
// Crossings: a ray through an edge or vertex hits every triangle around it at one t.
// Those hits are merged by their orientation: all entering (or all leaving) are one
// crossing; a ray that touches the surface there (as many entering as leaving) is
// reported as both, in the order that keeps the ray outside (or inside) after them.
// At most N crossings are reported, the nearest N: a closed mesh that a ray crosses more
// often within one query's range gives a CSG node or a shadow ray through glass only
// its first N (2 to 64; 8 by default).
//
// Vertex normals and coordinates (optional, one per position): a hit's shading normal
// is its vertex normals interpolated by the barycentric weights (the true normal where
// that leans to the other side of the triangle), and its uv likewise. They change how
// the surface shades (material/scattering.hpp), never where it is or which side is out.
//
// Storage and queries: the corners are kept a leaf at a time, four triangles side by
// side (TriangleBlock), and a leaf's triangles meet the edge test four at once before
// those it keeps take the whole test; the Bvh costs a leaf of up to four as one test.
// The mesh's data (corner blocks, the Bvh) is immutable and shared: copies of a mesh,
// and Transformed meshes in an ObjectArray (instances), hold one copy of it.
#pragma once

#include <prism/accel/bvh.hpp>
#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/geometry/shape.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace prism {

/// Three vertex indices, counter-clockwise seen from outside.
using TriangleIndices = std::array<std::uint32_t, 3>;

/// Positions and triangles, counter-clockwise seen from outside, and optionally a unit
/// normal and surface coordinates per position: what a TriangleMesh is built from.
template <Scalar T>
struct MeshBuffers {
    std::vector<Vec3<T>> positions;
    std::vector<TriangleIndices> triangles;
    std::vector<Vec3<T>> normals; ///< per position, pointing out, or empty (shade flat)
    std::vector<Vec2<T>> uvs;     ///< per position, or empty (uv (0, 0))
};

namespace detail {

/// A ray sheared so that it runs along +z from the origin (Woop et al. 2013): the same
/// for every triangle it is tested against.
template <Scalar T>
struct ShearedRay {
    Vec3<T> origin, direction;
    int kx = 0, ky = 1, kz = 2;
    T sx = 0, sy = 0, sz = 0;

    explicit ShearedRay(const Ray<T>& ray) noexcept : origin(ray.origin), direction(ray.direction)
    {
        const Vec3<T> a = prism::abs(ray.direction);
        kz = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        sz = T(1) / direction[kz];
        sx = -direction[kx] * sz;
        sy = -direction[ky] * sz;
    }
};

/// Where a ray hits a triangle: t and the barycentric weights of its three corners.
template <Scalar T>
struct TriangleHit {
    T t;
    std::array<T, 3> b;
    bool entering;
};

/// hit_triangle for a ray whose largest direction component is on axis Kz (the
/// permutation known at compile time).
template <int Kz, Scalar T>
[[nodiscard, gnu::always_inline]] inline bool hit_triangle_along(const ShearedRay<T>& ray, const std::array<Vec3<T>, 3>& corner, Interval<T> range,
                                                                 TriangleHit<T>& out) noexcept
{
    constexpr int kx = Kz == 2 ? 0 : Kz + 1, ky = kx == 2 ? 0 : kx + 1;
    // Translate to the ray's origin, permute and shear.
    std::array<Vec3<T>, 3> p;
    for (int i = 0; i < 3; ++i) {
        const Vec3<T> q = corner[std::size_t(i)] - ray.origin;
        p[std::size_t(i)] = {q[kx] + ray.sx * q[Kz], q[ky] + ray.sy * q[Kz], q[Kz]};
    }
    // Plain products: an edge shared by two triangles gets exactly opposite values in
    // them (the subtraction rounds symmetrically), so a ray is inside exactly one of
    // them, or on the edge of both.
    T e0 = p[1].x * p[2].y - p[1].y * p[2].x;
    T e1 = p[2].x * p[0].y - p[2].y * p[0].x;
    T e2 = p[0].x * p[1].y - p[0].y * p[1].x;
    if constexpr (sizeof(T) < sizeof(double)) {
        // On an edge to float precision: decide it in double.
        if (e0 == T(0) || e1 == T(0) || e2 == T(0)) {
            e0 = T(double(p[1].x) * double(p[2].y) - double(p[1].y) * double(p[2].x));
            e1 = T(double(p[2].x) * double(p[0].y) - double(p[2].y) * double(p[0].x));
            e2 = T(double(p[0].x) * double(p[1].y) - double(p[0].y) * double(p[1].x));
        }
    }
    // One branch, not six (the signs are as good as random over incoherent rays).
    const bool below = (e0 < T(0)) | (e1 < T(0)) | (e2 < T(0)), above = (e0 > T(0)) | (e1 > T(0)) | (e2 > T(0));
    if (below & above) return false;
    const T det = e0 + e1 + e2;
    if (det == T(0)) return false; // edge-on, or a degenerate triangle
    const T z0 = p[0].z * ray.sz, z1 = p[1].z * ray.sz, z2 = p[2].z * ray.sz;
    const T t_scaled = e0 * z0 + e1 * z1 + e2 * z2;
    const T inv_det = T(1) / det;
    const T t = t_scaled * inv_det;
    if (!range.surrounds(t)) return false;
    // t is above zero by more than its rounding (pbrt-v4, Triangle::Intersect).
    const T max_z = max_component(Vec3<T>(std::abs(z0), std::abs(z1), std::abs(z2)));
    const T max_x = max_component(Vec3<T>(std::abs(p[0].x), std::abs(p[1].x), std::abs(p[2].x)));
    const T max_y = max_component(Vec3<T>(std::abs(p[0].y), std::abs(p[1].y), std::abs(p[2].y)));
    const T delta_z = gamma<T>(3) * max_z;
    const T delta_x = gamma<T>(5) * (max_x + max_z), delta_y = gamma<T>(5) * (max_y + max_z);
    const T delta_e = T(2) * (gamma<T>(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    const T max_e = max_component(Vec3<T>(std::abs(e0), std::abs(e1), std::abs(e2)));
    const T delta_t = T(3) * (gamma<T>(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * std::abs(inv_det);
    if (!(t > delta_t)) return false;
    // det is the sheared normal's z, dot(direction, normal) / direction[kz] (the
    // permutation is cyclic, the shear of determinant 1): it enters where that is < 0.
    out = {t, {e0 * inv_det, e1 * inv_det, e2 * inv_det}, (det < T(0)) != (ray.sz < T(0))};
    return true;
}

/// The watertight test. Hits with t strictly inside `range` (and beyond the bound of
/// t's own rounding, so never the triangle a ray was spawned from) are returned.
template <Scalar T>
[[nodiscard, gnu::always_inline]] inline bool hit_triangle(const ShearedRay<T>& ray, const std::array<Vec3<T>, 3>& corner, Interval<T> range,
                                                           TriangleHit<T>& out) noexcept
{
    // The same branch for every triangle a ray meets: predicted.
    switch (ray.kz) {
    case 0: return hit_triangle_along<0>(ray, corner, range, out);
    case 1: return hit_triangle_along<1>(ray, corner, range, out);
    default: return hit_triangle_along<2>(ray, corner, range, out);
    }
}

/// Up to four triangles of a leaf, their corners side by side: lane j of row 3 c + axis
/// is triangle j's corner c on that axis. (A leaf of fewer fills the rest with its last.)
template <Scalar T>
struct TriangleBlock {
    static constexpr int width = 4;
    std::array<std::array<T, width>, 9> corner{};

    /// Lane `lane`'s three corners.
    [[nodiscard]] std::array<Vec3<T>, 3> triangle(std::uint32_t lane) const noexcept
    {
        std::array<Vec3<T>, 3> t;
        for (std::size_t i = 0; i < 3; ++i) t[i] = {corner[3 * i][lane], corner[3 * i + 1][lane], corner[3 * i + 2][lane]};
        return t;
    }
};

/// hit_triangle's edge test on a block's four triangles at once: a bit per lane that may
/// be hit, for hit_triangle to decide. Each lane's edge functions are hit_triangle's, the
/// same operations in the same order, so a lane whose signs differ is one hit_triangle
/// rejects; a lane with an edge function of 0 (which hit_triangle decides again in
/// double) is kept. Over incoherent rays most triangles a leaf offers are missed, and
/// this rejects four in about the time hit_triangle takes for one.
#if PRISM_VECTOR_EXTENSIONS
template <int Kz, Scalar T>
[[nodiscard, gnu::always_inline]] inline unsigned edge_test_along(const ShearedRay<T>& ray, const TriangleBlock<T>& block) noexcept
{
    constexpr int kx = Kz == 2 ? 0 : Kz + 1, ky = kx == 2 ? 0 : kx + 1;
    constexpr int width = TriangleBlock<T>::width;
    typedef T Lanes __attribute__((vector_size(width * sizeof(T))));
    Lanes px[3], py[3];
    for (int i = 0; i < 3; ++i) {
        Lanes x, y, z;
        __builtin_memcpy(&x, block.corner[std::size_t(3 * i + kx)].data(), sizeof(Lanes));
        __builtin_memcpy(&y, block.corner[std::size_t(3 * i + ky)].data(), sizeof(Lanes));
        __builtin_memcpy(&z, block.corner[std::size_t(3 * i + Kz)].data(), sizeof(Lanes));
        x -= ray.origin[kx], y -= ray.origin[ky], z -= ray.origin[Kz];
        px[i] = x + ray.sx * z;
        py[i] = y + ray.sy * z;
    }
    const Lanes e0 = px[1] * py[2] - py[1] * px[2];
    const Lanes e1 = px[2] * py[0] - py[2] * px[0];
    const Lanes e2 = px[0] * py[1] - py[0] * px[1];
    const auto missed = ((e0 < T(0)) | (e1 < T(0)) | (e2 < T(0))) & ((e0 > T(0)) | (e1 > T(0)) | (e2 > T(0))) &
                        ~((e0 == T(0)) | (e1 == T(0)) | (e2 == T(0)));
    unsigned maybe = 0;
    for (int lane = 0; lane < width; ++lane) maybe |= missed[lane] ? 0u : 1u << lane;
    return maybe;
}
#endif

/// edge_test_along one lane at a time, with the same arithmetic: where the compiler has
/// no vector extensions, and the twin the SIMD test is checked against.
template <int Kz, Scalar T>
[[nodiscard]] inline unsigned edge_test_lanewise_along(const ShearedRay<T>& ray, const TriangleBlock<T>& block) noexcept
{
    constexpr int kx = Kz == 2 ? 0 : Kz + 1, ky = kx == 2 ? 0 : kx + 1;
    unsigned maybe = 0;
    for (std::size_t lane = 0; lane < std::size_t(TriangleBlock<T>::width); ++lane) {
        T px[3], py[3];
        for (std::size_t i = 0; i < 3; ++i) {
            const T x = block.corner[3 * i + kx][lane] - ray.origin[kx], y = block.corner[3 * i + ky][lane] - ray.origin[ky],
                    z = block.corner[3 * i + Kz][lane] - ray.origin[Kz];
            px[i] = x + ray.sx * z;
            py[i] = y + ray.sy * z;
        }
        const T e0 = px[1] * py[2] - py[1] * px[2];
        const T e1 = px[2] * py[0] - py[2] * px[0];
        const T e2 = px[0] * py[1] - py[0] * px[1];
        const bool missed = (e0 < T(0) || e1 < T(0) || e2 < T(0)) && (e0 > T(0) || e1 > T(0) || e2 > T(0)) &&
                            !(e0 == T(0) || e1 == T(0) || e2 == T(0));
        maybe |= missed ? 0u : 1u << lane;
    }
    return maybe;
}

/// edge_test_lanewise_along for the ray's axis.
template <Scalar T>
[[nodiscard]] inline unsigned edge_test_lanewise(const ShearedRay<T>& ray, const TriangleBlock<T>& block) noexcept
{
    switch (ray.kz) {
    case 0: return edge_test_lanewise_along<0>(ray, block);
    case 1: return edge_test_lanewise_along<1>(ray, block);
    default: return edge_test_lanewise_along<2>(ray, block);
    }
}

/// edge_test_along for the ray's axis.
template <Scalar T>
[[nodiscard, gnu::always_inline]] inline unsigned edge_test(const ShearedRay<T>& ray, const TriangleBlock<T>& block) noexcept
{
#if !PRISM_VECTOR_EXTENSIONS
    return edge_test_lanewise(ray, block);
#else
    switch (ray.kz) {
    case 0: return edge_test_along<0>(ray, block);
    case 1: return edge_test_along<1>(ray, block);
    default: return edge_test_along<2>(ray, block);
    }
#endif
}

template <Scalar T>
struct MeshData {
    std::vector<TriangleBlock<T>> blocks;        ///< the corners in the Bvh's leaf order (position k: block k / 4, lane k % 4)
    std::vector<std::array<Vec3<T>, 3>> normals; ///< per triangle, its corners' unit normals (or none)
    std::vector<std::array<Vec2<T>, 3>> uvs;     ///< per triangle, its corners' coordinates (or none)
    Bvh<T> bvh;
    Aabb<T> bounds;
    bool closed = false;
};

} // namespace detail

template <Scalar T = float, std::size_t N = 8>
class TriangleMesh {
    static_assert(N >= 2 && N <= 64, "a TriangleMesh reports 2 to 64 crossings");

public:
    using scalar_type = T;
    static constexpr std::size_t max_crossings = N;

    /// The Bvh settings a mesh is built with unless given others: its leaves are tested
    /// a block of four triangles at a time, and the build costs them so.
    [[nodiscard]] static constexpr BvhConfig bvh_config() noexcept
    {
        BvhConfig config;
        config.leaf_block = detail::TriangleBlock<T>::width;
        return config;
    }

    /// A mesh of `triangles` over `positions`, with a normal and coordinates per position
    /// where `normals` and `uvs` are not empty; throws std::invalid_argument for no
    /// triangle, an index past the positions, a non-finite position, a closed mesh whose
    /// triangles wind inward (negative volume: reverse each triangle's order), normals or
    /// uvs not one per position, a normal that is not finite and non-zero, a non-finite
    /// uv, a triangle whose three normals all point against its winding, or a
    /// config.leaf_block that is not a multiple of four (bvh_config() is the default).
    TriangleMesh(std::span<const Vec3<T>> positions, std::span<const TriangleIndices> triangles, BvhConfig config = bvh_config(),
                 std::span<const Vec3<T>> normals = {}, std::span<const Vec2<T>> uvs = {})
    {
        if (triangles.empty()) detail::throw_invalid("TriangleMesh triangles must not be empty");
        if (config.leaf_block < 1 || config.leaf_block % detail::TriangleBlock<T>::width != 0)
            detail::throw_invalid("TriangleMesh BvhConfig leaf_block must be a multiple of ", detail::TriangleBlock<T>::width, " (its triangles are tested in blocks), got ",
                                  config.leaf_block);
        for (std::size_t i = 0; i < positions.size(); ++i)
            if (!is_finite(positions[i])) detail::throw_invalid("TriangleMesh position ", i, " must be finite, got ", detail::describe(positions[i]));
        for (std::size_t f = 0; f < triangles.size(); ++f)
            for (const std::uint32_t v : triangles[f])
                if (v >= positions.size()) detail::throw_invalid("TriangleMesh triangle ", f, " has vertex index ", v, ", past the ", positions.size(), " positions");
        std::vector<Vec3<T>> unit_normals(normals.size());
        validate_attributes(positions, triangles, normals, uvs, unit_normals);
        auto data = std::make_shared<detail::MeshData<T>>();
        data->closed = is_closed(triangles);
        if (data->closed) {
            // Six times the signed volume (the divergence theorem over the faces, about
            // the first vertex so that a mesh far from the origin loses nothing to
            // cancellation), in double: a closed mesh must wind outward.
            double volume6 = 0;
            const Vec3<double> r(positions[triangles[0][0]]);
            for (const TriangleIndices& f : triangles)
                volume6 += dot(Vec3<double>(positions[f[0]]) - r, cross(Vec3<double>(positions[f[1]]) - r, Vec3<double>(positions[f[2]]) - r));
            if (volume6 < 0) detail::throw_invalid("TriangleMesh is closed but its triangles wind inward (volume ", volume6 / 6, "): reverse each triangle's vertex order");
        }
        std::vector<Aabb<T>> boxes(triangles.size());
        for (std::size_t f = 0; f < triangles.size(); ++f) {
            Aabb<T> box;
            for (const std::uint32_t v : triangles[f]) box = box.merged({positions[v], positions[v]});
            boxes[f] = box.rounded_out();
            data->bounds = data->bounds.merged(boxes[f]);
        }
        data->bvh = Bvh<T>(boxes, config);
        const auto order = data->bvh.primitives();
        make_blocks(*data, positions, triangles);
        if (!normals.empty()) {
            data->normals.resize(order.size());
            for (std::size_t k = 0; k < order.size(); ++k) {
                const TriangleIndices& f = triangles[order[k]];
                data->normals[k] = {unit_normals[f[0]], unit_normals[f[1]], unit_normals[f[2]]};
            }
        }
        if (!uvs.empty()) {
            data->uvs.resize(order.size());
            for (std::size_t k = 0; k < order.size(); ++k) {
                const TriangleIndices& f = triangles[order[k]];
                data->uvs[k] = {uvs[f[0]], uvs[f[1]], uvs[f[2]]};
            }
        }
        data_ = std::move(data);
    }

    TriangleMesh(const std::vector<Vec3<T>>& positions, const std::vector<TriangleIndices>& triangles, BvhConfig config = bvh_config())
        : TriangleMesh(std::span<const Vec3<T>>(positions), std::span<const TriangleIndices>(triangles), config)
    {
    }

    /// The mesh of `mesh`'s buffers, with its normals and uvs where it has them.
    explicit TriangleMesh(const MeshBuffers<T>& mesh, BvhConfig config = bvh_config())
        : TriangleMesh(std::span<const Vec3<T>>(mesh.positions), std::span<const TriangleIndices>(mesh.triangles), config,
                       std::span<const Vec3<T>>(mesh.normals), std::span<const Vec2<T>>(mesh.uvs))
    {
    }

    [[nodiscard]] bool closed() const noexcept { return data_->closed; }
    [[nodiscard]] bool has_normals() const noexcept { return !data_->normals.empty(); }
    [[nodiscard]] bool has_uvs() const noexcept { return !data_->uvs.empty(); }
    [[nodiscard]] std::size_t triangle_count() const noexcept { return data_->bvh.size(); }
    [[nodiscard]] const Bvh<T>& bvh() const noexcept { return data_->bvh; }
    [[nodiscard]] Aabb<T> bounds() const noexcept { return data_->bounds; }
    /// Bytes held by the shared data (corner blocks, normals, uvs, Bvh), for every
    /// copy together.
    [[nodiscard]] std::size_t memory_bytes() const noexcept
    {
        const auto& d = *data_;
        return sizeof(d) + d.blocks.size() * sizeof(d.blocks[0]) + d.normals.size() * sizeof(d.normals[0]) +
               d.uvs.size() * sizeof(d.uvs[0]) + d.bvh.nodes().size() * sizeof(typename Bvh<T>::Node) + d.bvh.primitives().size() * sizeof(std::uint32_t);
    }

    /// Inside a closed mesh: the first crossing along a fixed direction from p leaves it.
    [[nodiscard]] bool contains(const Vec3<T>& p) const noexcept
    {
        if (!data_->closed || !data_->bounds.contains(p)) return false;
        // An irrational-looking direction, unlikely to run along an edge.
        return inside_before(Ray<T>{p, Vec3<T>(T(0.5773502), T(0.5773503), T(0.5773504))}, T(0));
    }

    /// The t of the first crossing strictly inside `range`, or infinity: what
    /// crossings<false>(ray, range).front().t gives, found by a closest-hit query alone.
    [[nodiscard]] T first_crossing(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        SurfaceHint<T> hint;
        return first_crossing(ray, range, hint);
    }

    /// first_crossing, keeping the triangle hit and where (for surface_crossing).
    [[nodiscard]] T first_crossing(const Ray<T>& ray, Interval<T> range, SurfaceHint<T>& hint) const noexcept
    {
        const detail::ShearedRay<T> sheared(ray);
        detail::TriangleHit<T> nearest{infinity<T>, {}, false};
        std::uint32_t triangle = 0;
        data_->bvh.traverse_leaves(ray, range, [&](std::uint32_t first, std::uint32_t count, Interval<T>& r) {
            for_each_maybe_hit(sheared, first, count, [&](std::uint32_t k, const std::array<Vec3<T>, 3>& tri) {
                detail::TriangleHit<T> h;
                if (detail::hit_triangle(sheared, tri, r, h)) nearest = h, r.max = h.t, triangle = k;
                return false;
            });
            return false;
        });
        if (nearest.t < infinity<T>) hint = {triangle, nearest.t, nearest.b, nearest.entering};
        return nearest.t;
    }

    /// crossings(ray, range).front(), from the hit first_crossing kept (the same ray
    /// tested against the same triangle, so the same numbers): a hit inside it (off its
    /// edges) is the only one at its t, but where two triangles not sharing an edge meet
    /// the ray at the same float t (a self-intersecting mesh). A hit on an edge, or
    /// outside `range`, takes the search.
    [[nodiscard]] std::optional<Crossing<T>> surface_crossing(const Ray<T>& ray, Interval<T> range, const SurfaceHint<T>& hint) const noexcept
    {
        if (hint.index < data_->bvh.primitives().size() && range.surrounds(hint.t) && hint.b[0] > T(0) && hint.b[1] > T(0) && hint.b[2] > T(0))
            return surface_at({hint.t, hint.index, hint.b, hint.entering}, hint.entering);
        const auto all = crossings(ray, range);
        if (all.empty()) return std::nullopt;
        return all.front();
    }

    /// Whether any crossing lies strictly inside `range` (a shadow ray's query).
    [[nodiscard]] bool any_crossing(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        const detail::ShearedRay<T> sheared(ray);
        return data_->bvh.any_leaf(ray, range, [&](std::uint32_t first, std::uint32_t count, Interval<T>& r) {
            return for_each_maybe_hit(sheared, first, count, [&](std::uint32_t, const std::array<Vec3<T>, 3>& tri) {
                detail::TriangleHit<T> h;
                return detail::hit_triangle(sheared, tri, r, h);
            });
        });
    }

    template <bool Surface = true>
    [[nodiscard]] Crossings<T, N> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        Crossings<T, N> out;
        const Hits hits = gather(ray, range);
        const bool closed = data_->closed;
        // Inside at the start of a closed mesh: its first crossing (not a touch) leaves it.
        bool inside = false;
        if (closed) {
            int net = 0;
            for (std::size_t i = 0; i < hits.count && net == 0; i = group_end(hits, i)) net = net_of(hits, i, group_end(hits, i));
            inside = net != 0 ? net < 0 : inside_before(ray, range.min);
        }
        out.inside_at_start = inside;
        for (std::size_t i = 0; i < hits.count && out.count < N;) {
            const std::size_t end = group_end(hits, i);
            const int net = net_of(hits, i, end);
            const Hit& h = hits.items[i];
            if (net == 0) {
                // A touch: in and out again (or out and in), on the first hit's triangle.
                if (out.count + 2 > N) break;
                push<Surface>(out, h, !inside);
                push<Surface>(out, h, inside);
            } else if (!closed || (net > 0) != inside) {
                // (A closed mesh's hits that agree with where the ray already is, which
                // only rounding at a near-touch can give, cross nothing.)
                push<Surface>(out, h, net > 0);
                if (closed) inside = net > 0;
            }
            i = end;
        }
        return out;
    }

private:
    /// Calls test(k, corners) for each triangle of the leaf [first, first + count) that
    /// the edge test keeps, in order, until one returns true (and then returns true).
    template <class Test>
    [[gnu::always_inline]] bool for_each_maybe_hit(const detail::ShearedRay<T>& ray, std::uint32_t first, std::uint32_t count, Test&& test) const noexcept
    {
        constexpr std::uint32_t width = detail::TriangleBlock<T>::width;
        const detail::TriangleBlock<T>* block = &data_->blocks[first / width]; // a leaf starts a block
        for (std::uint32_t k = first; k < first + count; k += width, ++block) {
            const std::uint32_t lanes = std::min(width, first + count - k);
            for (unsigned maybe = detail::edge_test(ray, *block) & ((1u << lanes) - 1); maybe != 0; maybe &= maybe - 1) {
                const auto lane = std::uint32_t(std::countr_zero(maybe));
                if (test(k + lane, block->triangle(lane))) return true;
            }
        }
        return false;
    }

    /// The corners of the triangle at leaf-order position k.
    [[nodiscard]] std::array<Vec3<T>, 3> corners(std::uint32_t k) const noexcept
    {
        constexpr std::uint32_t width = detail::TriangleBlock<T>::width;
        return data_->blocks[k / width].triangle(k % width);
    }

    /// The corners in blocks of four in the Bvh's leaf order, where each leaf starts a
    /// block and its last triangle fills its last block (Bvh::primitives()).
    static void make_blocks(detail::MeshData<T>& data, std::span<const Vec3<T>> positions, std::span<const TriangleIndices> triangles)
    {
        constexpr std::uint32_t width = detail::TriangleBlock<T>::width;
        const auto order = data.bvh.primitives(); // the triangle at each leaf-order position
        PRISM_ASSERT(order.size() % width == 0);
        data.blocks.resize(order.size() / width);
        for (std::size_t k = 0; k < order.size(); ++k) {
            const TriangleIndices& f = triangles[order[k]];
            for (std::size_t i = 0; i < 3; ++i)
                for (int axis = 0; axis < 3; ++axis) data.blocks[k / width].corner[3 * i + std::size_t(axis)][k % width] = positions[f[i]][axis];
        }
    }

    struct Hit {
        T t;
        std::uint32_t triangle; ///< leaf order
        std::array<T, 3> b;
        bool entering;
    };
    /// The nearest N hits, sorted by t then triangle.
    struct Hits {
        std::array<Hit, N> items;
        std::size_t count = 0;
    };

    [[nodiscard]] Hits gather(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        const detail::ShearedRay<T> sheared(ray);
        Hits hits;
        data_->bvh.traverse_in_leaf_order(ray, range, [&](std::uint32_t k, Interval<T>& r) {
            detail::TriangleHit<T> h;
            if (!detail::hit_triangle(sheared, corners(k), r, h)) return false;
            const Hit hit{h.t, k, h.b, h.entering};
            const auto before = [](const Hit& a, const Hit& b) { return a.t < b.t || (a.t == b.t && a.triangle < b.triangle); };
            if (hits.count == N) {
                if (!before(hit, hits.items[N - 1])) return false;
                --hits.count;
            }
            std::size_t j = hits.count++;
            for (; j > 0 && before(hit, hits.items[j - 1]); --j) hits.items[j] = hits.items[j - 1];
            hits.items[j] = hit;
            // Full: nothing beyond the last kept hit can enter (ties are kept by the
            // next float up).
            if (hits.count == N) r.max = std::min(r.max, next_float_up(hits.items[N - 1].t));
            return false;
        });
        return hits;
    }

    [[nodiscard]] static std::size_t group_end(const Hits& hits, std::size_t i) noexcept
    {
        std::size_t end = i + 1;
        while (end < hits.count && hits.items[end].t == hits.items[i].t) ++end;
        return end;
    }

    [[nodiscard]] static int net_of(const Hits& hits, std::size_t begin, std::size_t end) noexcept
    {
        int net = 0;
        for (std::size_t k = begin; k < end; ++k) net += hits.items[k].entering ? 1 : -1;
        return net;
    }

    /// Whether ray.at(t) is inside the closed mesh: the first crossing group after t that
    /// is not a touch leaves it.
    [[nodiscard]] bool inside_before(const Ray<T>& ray, T t) const noexcept
    {
        for (int guard = 0; guard < 64; ++guard) {
            const T first = first_crossing(ray, {t, infinity<T>});
            if (!(first < infinity<T>)) return false;
            const Hits at = gather(ray, {next_float_down(first), next_float_up(first)});
            const int net = at.count ? net_of(at, 0, group_end(at, 0)) : 0;
            if (net != 0) return net < 0;
            t = first;
        }
        return false;
    }

    template <bool Surface>
    void push(Crossings<T, N>& out, const Hit& h, bool entering) const noexcept
    {
        if constexpr (!Surface) out.push_back(Crossing<T>::without_surface(h.t, entering));
        else out.push_back(surface_at(h, entering));
    }

    /// The crossing at a hit, with its surface.
    [[nodiscard]] Crossing<T> surface_at(const Hit& h, bool entering) const noexcept
    {
        const std::array<Vec3<T>, 3> c = corners(h.triangle);
        // The point from the barycentric weights, exact to the triangle's own scale
        // (pbrt-v4: an error of gamma(7) of the weighted corners).
        const Vec3<T> a = h.b[0] * c[0], b = h.b[1] * c[1], d = h.b[2] * c[2];
        const Vec3<T> point = a + b + d;
        const Vec3<T> error = gamma<T>(7) * (prism::abs(a) + prism::abs(b) + prism::abs(d));
        // The outward normal as the triangle winds (non-zero: a degenerate triangle is
        // never hit).
        const Vec3<T> normal = normalize(cross(c[1] - c[0], c[2] - c[0]));
        Crossing<T> out = Crossing<T>::flat(h.t, point, error, normal, entering);
        if (!data_->normals.empty()) {
            const auto& n = data_->normals[h.triangle];
            const Vec3<T> shading = h.b[0] * n[0] + h.b[1] * n[1] + h.b[2] * n[2];
            // Leaning over the triangle's edge (opposed normals across a fold): flat.
            if (dot(shading, normal) > T(0)) out.shading = normalize(shading);
        }
        if (!data_->uvs.empty()) {
            const auto& uv = data_->uvs[h.triangle];
            out.uv = h.b[0] * uv[0] + h.b[1] * uv[1] + h.b[2] * uv[2];
        }
        return out;
    }

    static void validate_attributes(std::span<const Vec3<T>> positions, std::span<const TriangleIndices> triangles, std::span<const Vec3<T>> normals,
                                    std::span<const Vec2<T>> uvs, std::vector<Vec3<T>>& unit_normals)
    {
        if (!normals.empty() && normals.size() != positions.size())
            detail::throw_invalid("TriangleMesh normals must be one per position (", positions.size(), "), got ", normals.size());
        if (!uvs.empty() && uvs.size() != positions.size())
            detail::throw_invalid("TriangleMesh uvs must be one per position (", positions.size(), "), got ", uvs.size());
        for (std::size_t i = 0; i < uvs.size(); ++i)
            if (!std::isfinite(uvs[i].x) || !std::isfinite(uvs[i].y))
                detail::throw_invalid("TriangleMesh uv ", i, " must be finite, got (", uvs[i].x, ", ", uvs[i].y, ")");
        for (std::size_t i = 0; i < normals.size(); ++i) {
            const Vec3<double> n(normals[i]);
            const double len = length(n);
            if (!is_finite(normals[i]) || !(len > 0) || !std::isfinite(len))
                detail::throw_invalid("TriangleMesh normal ", i, " must be finite and non-zero, got ", detail::describe(normals[i]));
            unit_normals[i] = Vec3<T>(n / len);
        }
        if (normals.empty()) return;
        for (std::size_t f = 0; f < triangles.size(); ++f) {
            const TriangleIndices& v = triangles[f];
            const Vec3<double> a(positions[v[0]]), face = cross(Vec3<double>(positions[v[1]]) - a, Vec3<double>(positions[v[2]]) - a);
            if (dot(face, Vec3<double>(unit_normals[v[0]])) < 0 && dot(face, Vec3<double>(unit_normals[v[1]])) < 0 &&
                dot(face, Vec3<double>(unit_normals[v[2]])) < 0)
                detail::throw_invalid("TriangleMesh triangle ", f, " has all three normals pointing against its winding: reverse the normals or the vertex order");
        }
    }

    [[nodiscard]] static bool is_closed(std::span<const TriangleIndices> triangles)
    {
        // Every directed edge once, and its reverse once.
        std::vector<std::uint64_t> edges;
        edges.reserve(3 * triangles.size());
        for (const TriangleIndices& f : triangles)
            for (int i = 0; i < 3; ++i) {
                const std::uint32_t a = f[std::size_t(i)], b = f[std::size_t((i + 1) % 3)];
                if (a == b) return false;
                edges.push_back(std::uint64_t(a) << 32 | b);
            }
        std::sort(edges.begin(), edges.end());
        if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
        for (const std::uint64_t e : edges)
            if (!std::binary_search(edges.begin(), edges.end(), (e << 32) | (e >> 32))) return false;
        return true;
    }

    std::shared_ptr<const detail::MeshData<T>> data_;
};

static_assert(Shape<TriangleMesh<float>>);
static_assert(Shape<TriangleMesh<double>>);

} // namespace prism
