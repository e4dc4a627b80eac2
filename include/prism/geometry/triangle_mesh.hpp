// SPDX-License-Identifier: MIT
// TriangleMesh: a solid (or an open surface) bounded by triangles, with its own Bvh.
//
// The ray-triangle test is geometry/triangle.hpp's (watertight: no ray slips between
// the triangles of a closed mesh).
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
#include <prism/core/distribution.hpp>
#include <prism/geometry/surface_point.hpp>
#include <prism/geometry/triangle.hpp>

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
    std::vector<Vec3<T>> positions; ///< the vertices
    std::vector<TriangleIndices> triangles; ///< three indices into positions per triangle
    std::vector<Vec3<T>> normals; ///< per position, pointing out, or empty (shade flat)
    std::vector<Vec2<T>> uvs;     ///< per position, or empty (uv (0, 0))
};

namespace detail {

template <Scalar T>
struct MeshData {
    std::vector<TriangleBlock<T>> blocks;        ///< the corners in the Bvh's leaf order (position k: block k / 4, lane k % 4)
    std::vector<std::array<Vec3<T>, 3>> normals; ///< per triangle, its corners' unit normals (or none)
    std::vector<std::array<Vec2<T>, 3>> uvs;     ///< per triangle, its corners' coordinates (or none)
    Bvh<T> bvh;
    Aabb<T> bounds;
    NearBox<T> near; ///< the bounds as brought_near asks them
    bool closed = false;
};

} // namespace detail

/// A mesh of triangles with its own Bvh, reporting the nearest N crossings: a closed solid or an open
/// surface. Copies share the mesh, so Transformed copies are instances.
template <Scalar T = float, std::size_t N = 8>
class TriangleMesh {
    static_assert(N >= 2 && N <= 64, "a TriangleMesh reports 2 to 64 crossings");

public:
    /// The precision of the vertices and the crossings.
    using scalar_type = T;
    /// The most crossings a query reports: the nearest N (a CSG node or a shadow ray through glass sees only those).
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
        data->near = NearBox<T>(data->bounds);
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

    /// The mesh of `positions` and `triangles`, without normals or uvs; throws as the span constructor does.
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

    /// Whether every directed edge is matched by its reverse once (a closed solid with an inside), found at construction.
    [[nodiscard]] bool closed() const noexcept { return data_->closed; }
    /// Whether the mesh has vertex normals (smooth shading).
    [[nodiscard]] bool has_normals() const noexcept { return !data_->normals.empty(); }
    /// Whether the mesh has surface coordinates.
    [[nodiscard]] bool has_uvs() const noexcept { return !data_->uvs.empty(); }
    /// The number of triangles.
    [[nodiscard]] std::size_t triangle_count() const noexcept { return data_->bvh.size(); }
    /// The corners of the triangle at position k of the mesh's own (leaf) order, which
    /// repeats a leaf's last triangle to fill its last block of four (Bvh::primitives()):
    /// k < bvh().primitives().size().
    [[nodiscard]] std::array<Vec3<T>, 3> corners(std::uint32_t k) const noexcept
    {
        PRISM_ASSERT(k < data_->bvh.primitives().size());
        constexpr std::uint32_t width = detail::TriangleBlock<T>::width;
        return data_->blocks[k / width].triangle(k % width);
    }
    /// The mesh's own Bvh over its triangles.
    [[nodiscard]] const Bvh<T>& bvh() const noexcept { return data_->bvh; }
    /// The box around every vertex.
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
    [[nodiscard]] T first_crossing(const Ray<T>& far_ray, Interval<T> far_range, SurfaceHint<T>& hint) const noexcept
    {
        const NearRay<T> near = brought_near(far_ray, data_->near);
        const Ray<T>& ray = near.ray_for(far_ray);
        Interval<T> range = near.range(far_range);
        detail::TriangleHit<T> nearest{infinity<T>, {}, false};
        std::uint32_t triangle = 0;
        // (The leaf's visit holds the sheared ray and the blocks itself, not by reference:
        // each leaf then starts its loads one pointer away, not four.)
        data_->bvh.traverse_leaves(ray, range, [&nearest, &triangle, sheared = detail::ShearedRay<T>(ray), blocks = data_->blocks.data()](
                                                   std::uint32_t first, std::uint32_t count, Interval<T>& r) __attribute__((always_inline)) {
            return for_each_hit(sheared, blocks, first, count, r, [&](std::uint32_t k, const detail::TriangleHit<T>& h) {
                nearest = h, r.max = h.t, triangle = k;
                return false;
            });
        });
        if (!(nearest.t < infinity<T>)) return infinity<T>;
        const T t = near.back(nearest.t);
        // (Field by field: a whole struct built on the stack and copied is read back with
        // a wider load than its stores, which stalls.)
        hint.index = triangle, hint.t = t, hint.b = nearest.b, hint.entering = nearest.entering;
        return t;
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
    [[nodiscard]] bool any_crossing(const Ray<T>& far_ray, Interval<T> far_range) const noexcept
    {
        const NearRay<T> near = brought_near(far_ray, data_->near);
        const Ray<T>& ray = near.ray_for(far_ray);
        Interval<T> range = near.range(far_range);
        return data_->bvh.any_leaf(ray, range, [sheared = detail::ShearedRay<T>(ray), blocks = data_->blocks.data()](std::uint32_t first, std::uint32_t count, Interval<T>& r)
                                                   __attribute__((always_inline)) {
            return for_each_hit(sheared, blocks, first, count, r, [](std::uint32_t, const detail::TriangleHit<T>&) { return true; });
        });
    }

    /// Every crossing of `ray` within `range` (at most N), sorted, by the watertight ray-triangle test.
    template <bool Surface = true>
    [[nodiscard]] Crossings<T, N> crossings(const Ray<T>& far_ray, Interval<T> far_range) const noexcept
    {
        const NearRay<T> near = brought_near(far_ray, data_->near);
        const Ray<T>& ray = near.ray_for(far_ray);
        Interval<T> range = near.range(far_range);
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
        if (near.shift != 0)
            for (std::size_t k = 0; k < out.count; ++k) out.items[k].t = near.back(out.items[k].t);
        return out;
    }

private:
    /// Calls take(k, hit) for each triangle of the leaf [first, first + count) that the ray
    /// hits within `range` (which take may shrink), in order, until take returns true (and
    /// then returns true): what hit_triangle finds, lane by lane, but a block's lanes
    /// tested at once (hit_block: the same numbers).
    template <class Take>
    [[gnu::always_inline]] static bool for_each_hit(const detail::ShearedRay<T>& ray, const detail::TriangleBlock<T>* blocks, std::uint32_t first, std::uint32_t count,
                                                    Interval<T>& range, Take&& take) noexcept
    {
#if PRISM_VECTOR_EXTENSIONS
        constexpr std::uint32_t width = detail::TriangleBlock<T>::width;
        const detail::TriangleBlock<T>* block = blocks + first / width; // a leaf starts a block
        for (std::uint32_t k = first; k < first + count; k += width, ++block) {
            const std::uint32_t lanes = std::min(width, first + count - k);
            const detail::BlockHits<T> hits = detail::hit_block(ray, *block, range, (1u << lanes) - 1);
            for (unsigned maybe = hits.hit | hits.redo; maybe != 0; maybe &= maybe - 1) {
                const auto lane = std::uint32_t(std::countr_zero(maybe));
                detail::TriangleHit<T> h;
                if ((hits.redo >> lane) & 1u) {
                    if (!detail::hit_triangle(ray, block->triangle(lane), range, h)) continue;
                } else {
                    // (Tested against the range as it was: a hit before may have shrunk it.)
                    if (!(hits.t[lane] < range.max)) continue;
                    h = {hits.t[lane], {hits.b[0][lane], hits.b[1][lane], hits.b[2][lane]}, ((hits.entering >> lane) & 1u) != 0};
                }
                if (take(k + lane, h)) return true;
            }
        }
        return false;
#else
        return for_each_maybe_hit(ray, blocks, first, count, [&](std::uint32_t k, const std::array<Vec3<T>, 3>& tri) {
            detail::TriangleHit<T> h;
            return detail::hit_triangle(ray, tri, range, h) && take(k, h);
        });
#endif
    }

    /// Calls test(k, corners) for each triangle of the leaf [first, first + count) that
    /// the edge test keeps, in order, until one returns true (and then returns true).
    template <class Test>
    [[gnu::always_inline]] static bool for_each_maybe_hit(const detail::ShearedRay<T>& ray, const detail::TriangleBlock<T>* blocks, std::uint32_t first, std::uint32_t count,
                                                          Test&& test) noexcept
    {
        constexpr std::uint32_t width = detail::TriangleBlock<T>::width;
        const detail::TriangleBlock<T>* block = blocks + first / width; // a leaf starts a block
        for (std::uint32_t k = first; k < first + count; k += width, ++block) {
            const std::uint32_t lanes = std::min(width, first + count - k);
            for (unsigned maybe = detail::edge_test(ray, *block) & ((1u << lanes) - 1); maybe != 0; maybe &= maybe - 1) {
                const auto lane = std::uint32_t(std::countr_zero(maybe));
                if (test(k + lane, block->triangle(lane))) return true;
            }
        }
        return false;
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
            // dp/du and dp/dv of the triangle's linear map from uv to space (pbrt-v4,
            // Triangle::InteractionFromIntersection); none where its uvs are collinear.
            const Vec2<T> d02 = uv[0] - uv[2], d12 = uv[1] - uv[2];
            const Vec3<T> p02 = c[0] - c[2], p12 = c[1] - c[2];
            const T det = d02.x * d12.y - d02.y * d12.x;
            if (std::abs(det) > T(1e-9) * std::max(d02.x * d02.x + d02.y * d02.y, d12.x * d12.x + d12.y * d12.y)) {
                const T inv = T(1) / det;
                out.dpdu = (d12.y * p02 - d02.y * p12) * inv;
                out.dpdv = (d02.x * p12 - d12.x * p02) * inv;
            }
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

/// A mesh's surface, to draw points on (an emitting mesh's): a triangle chosen by its
/// area, in O(1) (an alias table), and a point uniform in it, so every point of the mesh
/// has density 1 / area.
template <Scalar T, std::size_t N>
class MeshSurface {
public:
    /// The precision.
    using scalar_type = T;

    /// The surface of `mesh`; throws std::invalid_argument for a mesh of no area.
    explicit MeshSurface(TriangleMesh<T, N> mesh) : mesh_(std::move(mesh))
    {
        // Each triangle once: the leaf order repeats a leaf's last triangle as padding.
        const auto order = mesh_.bvh().primitives();
        std::vector<double> areas;
        double total = 0;
        for (std::size_t k = 0; k < order.size(); ++k) {
            if (k > 0 && order[k] == order[k - 1]) continue;
            const auto [a, b, c] = mesh_.corners(std::uint32_t(k));
            const Vec3<double> e1 = Vec3<double>(b) - Vec3<double>(a), e2 = Vec3<double>(c) - Vec3<double>(a);
            positions_.push_back(std::uint32_t(k));
            areas.push_back(0.5 * length(cross(e1, e2)));
            total += areas.back();
        }
        PRISM_ASSERT(positions_.size() == mesh_.triangle_count());
        if (!(total > 0) || !is_finite(total)) detail::throw_invalid("an emitting TriangleMesh must have a finite, positive area, got ", total);
        triangles_ = AliasTable<T>(areas, "TriangleMesh triangle area");
        area_ = T(total);
    }

    /// The mesh's area.
    [[nodiscard]] T area() const noexcept { return area_; }

    /// A point uniform over the mesh for u in the unit square, its triangle's unit normal
    /// (by its winding: outward on a closed mesh), density 1 / area.
    [[nodiscard]] SurfacePoint<T> sample_area(const Vec2<T>& u) const noexcept
    {
        const AliasPick<T> pick = triangles_.pick(u.x);
        const auto [a, b, c] = mesh_.corners(positions_[pick.index]);
        // Uniform in the triangle: (1 - sqrt(u)) a + sqrt(u) (1 - v) b + sqrt(u) v c.
        const T su = prism::sqrt(pick.rest);
        return {a + (su * (T(1) - u.y)) * (b - a) + (su * u.y) * (c - a), normalize(cross(b - a, c - a)), T(1) / area_};
    }

private:
    TriangleMesh<T, N> mesh_;
    std::vector<std::uint32_t> positions_; ///< each triangle's leaf-order position, once
    AliasTable<T> triangles_;              ///< over positions_, by area
    T area_ = T(0);
};

/// What points are drawn on when a mesh emits: its MeshSurface.
template <Scalar T, std::size_t N>
[[nodiscard]] MeshSurface<T, N> surface_of(const TriangleMesh<T, N>& mesh)
{
    return MeshSurface<T, N>(mesh);
}

} // namespace prism
