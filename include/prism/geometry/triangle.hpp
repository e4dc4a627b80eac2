// SPDX-License-Identifier: MIT
// The ray-triangle test: Woop, Benthin & Wald's watertight one ("Watertight
// Ray/Triangle Intersection", JCGT 2013), with pbrt-v4's bound on t. The vertices are
// moved to the ray's origin and sheared so the ray runs along +z; the three 2D edge
// functions then decide the hit by their signs alone. A vertex shared by two triangles
// is carried through the same arithmetic for both, so a ray through their common edge
// finds at least one of them: no ray slips between the triangles of a closed mesh. An
// edge function that rounds to exactly zero is worked out again in double.
// TriangleBlock keeps four triangles' corners side by side, so that the edge test meets
// four at once (in SIMD where the compiler has vector extensions, lane by lane
// otherwise: the same bits) before those it keeps take the whole test.
#pragma once

#include <prism/core/config.hpp>
#include <prism/core/interval.hpp>
#include <prism/core/lanes.hpp>
#include <prism/core/math.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/ray.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace prism::detail {

/// A ray sheared so that it runs along +z from the origin (Woop et al. 2013): the same
/// for every triangle it is tested against.
template <Scalar T>
struct ShearedRay {
    Vec3<T> origin;
    int kz = 2; ///< the axis the ray runs most along (kx, ky the two after it, cyclically)
    T sx = 0, sy = 0, sz = 0;

#if PRISM_VECTOR_EXTENSIONS
    /// What the four-triangle edge test takes from the ray in every lane, broadcast once
    /// per ray: the origin on the permuted axes kx, ky, kz, and the shear sx, sy.
    typedef T Lanes __attribute__((vector_size(4 * sizeof(T))));
    Lanes lane_origin[3], lane_sx, lane_sy; // (set by the constructor: no zeros stored first)
#endif

    [[gnu::always_inline]] explicit ShearedRay(const Ray<T>& ray) noexcept : origin(ray.origin)
    {
        // (Scalars and arrays indexed by kz: a Vec3's operator[] is a switch.)
        const T d[3] = {ray.direction.x, ray.direction.y, ray.direction.z}, o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
        const T ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
        kz = ax >= ay ? (ax >= az ? 0 : 2) : (ay >= az ? 1 : 2);
        const int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        sz = T(1) / d[kz];
        sx = -d[kx] * sz;
        sy = -d[ky] * sz;
#if PRISM_VECTOR_EXTENSIONS
        splat(lane_origin[0], o[kx]);
        splat(lane_origin[1], o[ky]);
        splat(lane_origin[2], o[kz]);
        splat(lane_sx, sx);
        splat(lane_sy, sy);
#else
        (void)o;
#endif
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
        p[std::size_t(i)] = {q[kx] + rounded(ray.sx * q[Kz]), q[ky] + rounded(ray.sy * q[Kz]), q[Kz]};
    }
    // Plain products, each rounded (never fused into the difference: math.hpp's
    // rounded): an edge shared by two triangles gets exactly opposite values in them (the
    // subtraction rounds symmetrically), so a ray is inside exactly one of them, or on
    // the edge of both.
    T e0 = rounded(p[1].x * p[2].y) - rounded(p[1].y * p[2].x);
    T e1 = rounded(p[2].x * p[0].y) - rounded(p[2].y * p[0].x);
    T e2 = rounded(p[0].x * p[1].y) - rounded(p[0].y * p[1].x);
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
    // That bound grows as the square of the distance (delta_e as max_z), and from 5 10^4
    // times a triangle's size it refuses hits far in front. A triangle whose every corner
    // is in front by more than z's rounding is hit at t > 0 whatever t's own rounding: a
    // hit inside it lies between its corners' z, which are the ray's t there.
    if (!(t > delta_t) && !(std::min(std::min(z0, z1), z2) > delta_z)) return false;
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
/// A block's corners moved to the ray's origin, permuted and sheared, four lanes at once
/// (hit_triangle_along's p[i], lane by lane): px, py, and pz before its scale by sz.
template <int Kz, Scalar T>
[[gnu::always_inline]] inline void sheared_corners(const ShearedRay<T>& ray, const TriangleBlock<T>& block, typename ShearedRay<T>::Lanes (&px)[3],
                                                   typename ShearedRay<T>::Lanes (&py)[3], typename ShearedRay<T>::Lanes (&pz)[3]) noexcept
{
    constexpr int kx = Kz == 2 ? 0 : Kz + 1, ky = kx == 2 ? 0 : kx + 1;
    using Lanes = typename ShearedRay<T>::Lanes;
    static_assert(sizeof(Lanes) == TriangleBlock<T>::width * sizeof(T));
    // (The ray's values broadcast once per ray, ShearedRay's lanes; the corners written out.)
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i) {
        Lanes x, y, z;
        __builtin_memcpy(&x, block.corner[std::size_t(3 * i + kx)].data(), sizeof(Lanes));
        __builtin_memcpy(&y, block.corner[std::size_t(3 * i + ky)].data(), sizeof(Lanes));
        __builtin_memcpy(&z, block.corner[std::size_t(3 * i + Kz)].data(), sizeof(Lanes));
        x -= ray.lane_origin[0], y -= ray.lane_origin[1], z -= ray.lane_origin[2];
        Lanes shear_x = ray.lane_sx * z, shear_y = ray.lane_sy * z;
        keep_rounded(shear_x), keep_rounded(shear_y); // (as hit_triangle_along's, in any build)
        px[i] = x + shear_x;
        py[i] = y + shear_y;
        pz[i] = z;
    }
}

/// hit_triangle_along's three edge functions, four lanes at once, each product rounded
/// (never fused into the difference), as there.
template <class Lanes>
[[gnu::always_inline]] inline void edge_functions(const Lanes (&px)[3], const Lanes (&py)[3], Lanes& e0, Lanes& e1, Lanes& e2) noexcept
{
    Lanes a[3] = {px[1] * py[2], px[2] * py[0], px[0] * py[1]}, b[3] = {py[1] * px[2], py[2] * px[0], py[0] * px[1]};
    for (int i = 0; i < 3; ++i) keep_rounded(a[i]), keep_rounded(b[i]);
    e0 = a[0] - b[0], e1 = a[1] - b[1], e2 = a[2] - b[2];
}

template <int Kz, Scalar T>
[[nodiscard, gnu::always_inline]] inline unsigned edge_test_along(const ShearedRay<T>& ray, const TriangleBlock<T>& block) noexcept
{
    constexpr int width = TriangleBlock<T>::width;
    using Lanes = typename ShearedRay<T>::Lanes;
    Lanes px[3], py[3], pz[3];
    sheared_corners<Kz>(ray, block, px, py, pz);
    Lanes e0, e1, e2;
    edge_functions(px, py, e0, e1, e2);
    const auto missed = ((e0 < T(0)) | (e1 < T(0)) | (e2 < T(0))) & ((e0 > T(0)) | (e1 > T(0)) | (e2 > T(0))) &
                        ~((e0 == T(0)) | (e1 == T(0)) | (e2 == T(0)));
    return ~lane_bits(missed) & ((1u << width) - 1); // a bit per lane kept
}

/// hit_triangle on a block's four triangles at once: which of the lanes `lanes` (a bit
/// each) the ray hits strictly inside `range`, with their t, barycentric weights and side.
/// Each lane takes hit_triangle_along's operations in the same order, so its answer and
/// numbers are hit_triangle's, bit for bit (tests/geometry/triangle.cpp checks it over
/// random rays), but for a lane with an edge function of exactly 0, which hit_triangle
/// works out again in double: those are left in `redo` for it. The edge test comes first
/// and ends it where every lane misses (most blocks an incoherent ray meets), and the
/// bound on t's own rounding is worked out only where a lane's triangle is not wholly in
/// front of the ray (one the ray starts on, or behind it).
template <Scalar T>
struct BlockHits {
    unsigned hit = 0;  ///< a bit per lane hit within the range
    unsigned redo = 0; ///< a bit per lane hit_triangle must decide
    std::array<T, 4> t{};                ///< t[lane]
    std::array<std::array<T, 4>, 3> b{}; ///< b[i][lane]: corner i's weight
    unsigned entering = 0;               ///< a bit per lane the ray enters by
};

template <int Kz, Scalar T>
[[nodiscard, gnu::always_inline]] inline BlockHits<T> hit_block_along(const ShearedRay<T>& ray, const TriangleBlock<T>& block, Interval<T> range,
                                                                     unsigned lanes) noexcept
{
    using Lanes = typename ShearedRay<T>::Lanes;
    using Bits = std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>;
    typedef Bits BitLanes __attribute__((vector_size(sizeof(Lanes))));
    // |v| by its sign bit, as std::abs.
    const auto abs = [](const Lanes& v, Lanes& out) {
        BitLanes bits;
        __builtin_memcpy(&bits, &v, sizeof(Lanes));
        bits &= ~(BitLanes{} + Bits(std::uint64_t(1) << (8 * sizeof(T) - 1)));
        __builtin_memcpy(&out, &bits, sizeof(Lanes));
    };
    const auto max3 = [&abs](const Lanes& v0, const Lanes& v1, const Lanes& v2, Lanes& out) {
        Lanes a0, a1, a2;
        abs(v0, a0), abs(v1, a1), abs(v2, a2);
        const Lanes m = a0 > a1 ? a0 : a1;
        out = m > a2 ? m : a2;
    };
    Lanes px[3], py[3], pz[3];
    sheared_corners<Kz>(ray, block, px, py, pz);
    Lanes e0, e1, e2;
    edge_functions(px, py, e0, e1, e2);
    const BitLanes below = (e0 < T(0)) | (e1 < T(0)) | (e2 < T(0)), above = (e0 > T(0)) | (e1 > T(0)) | (e2 > T(0));
    const BitLanes zero = (e0 == T(0)) | (e1 == T(0)) | (e2 == T(0));
    BlockHits<T> out;
    if ((~lane_bits(below & above & ~zero) & lanes) == 0) return out; // edge_test_along's answer: all missed
    out.redo = lane_bits(zero) & lanes;
    const Lanes det = e0 + e1 + e2;
    Lanes sz, range_min, range_max;
    splat(sz, ray.sz), splat(range_min, range.min), splat(range_max, range.max);
    const Lanes z0 = pz[0] * sz, z1 = pz[1] * sz, z2 = pz[2] * sz;
    const Lanes t_scaled = e0 * z0 + e1 * z1 + e2 * z2;
    const Lanes inv_det = T(1) / det;
    const Lanes t = t_scaled * inv_det;
    out.hit = lane_bits(~(below & above) & (det != T(0)) & (range_min < t) & (t < range_max)) & lanes & ~out.redo;
    // t above zero by more than its rounding: hit_triangle_along's bound, lane by lane,
    // where it can decide.
    Lanes max_z;
    max3(z0, z1, z2, max_z);
    const Lanes delta_z = gamma<T>(3) * max_z;
    const Lanes min01 = z1 < z0 ? z1 : z0;
    const Lanes min_z = z2 < min01 ? z2 : min01;
    unsigned in_front = lane_bits(min_z > delta_z);
    if ((out.hit & ~in_front) != 0) {
        Lanes max_x, max_y, max_e, abs_inv_det;
        max3(px[0], px[1], px[2], max_x);
        max3(py[0], py[1], py[2], max_y);
        const Lanes delta_x = gamma<T>(5) * (max_x + max_z), delta_y = gamma<T>(5) * (max_y + max_z);
        const Lanes delta_e = T(2) * (gamma<T>(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
        max3(e0, e1, e2, max_e);
        abs(inv_det, abs_inv_det);
        const Lanes delta_t = T(3) * (gamma<T>(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * abs_inv_det;
        in_front |= lane_bits(t > delta_t);
    }
    out.hit &= in_front;
    out.entering = lane_bits((det < T(0)) != (sz < T(0)));
    const Lanes b0 = e0 * inv_det, b1 = e1 * inv_det, b2 = e2 * inv_det;
    __builtin_memcpy(out.t.data(), &t, sizeof(Lanes));
    __builtin_memcpy(out.b[0].data(), &b0, sizeof(Lanes));
    __builtin_memcpy(out.b[1].data(), &b1, sizeof(Lanes));
    __builtin_memcpy(out.b[2].data(), &b2, sizeof(Lanes));
    return out;
}

/// hit_block_along for the ray's axis.
template <Scalar T>
[[nodiscard, gnu::always_inline]] inline BlockHits<T> hit_block(const ShearedRay<T>& ray, const TriangleBlock<T>& block, Interval<T> range, unsigned lanes) noexcept
{
    switch (ray.kz) {
    case 0: return hit_block_along<0>(ray, block, range, lanes);
    case 1: return hit_block_along<1>(ray, block, range, lanes);
    default: return hit_block_along<2>(ray, block, range, lanes);
    }
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
            px[i] = x + rounded(ray.sx * z);
            py[i] = y + rounded(ray.sy * z);
        }
        const T e0 = rounded(px[1] * py[2]) - rounded(py[1] * px[2]);
        const T e1 = rounded(px[2] * py[0]) - rounded(py[2] * px[0]);
        const T e2 = rounded(px[0] * py[1]) - rounded(py[0] * px[1]);
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

} // namespace prism::detail
