// SPDX-License-Identifier: MIT
// A node of a Bvh (accel/bvh.hpp) and the test a ray makes of it: up to Width children
// whose boxes lie side by side, and a ray prepared once (SlabRay) to test them all at once,
// in SIMD where the compiler has vector extensions (SlabLanes) and lane by lane otherwise,
// the same arithmetic in each lane. Every box is widened by one pad per ray (see Bvh), so
// the test is a plain slab test (Ize 2013) that never culls a box Aabb::may_cross keeps.
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/core/config.hpp>
#include <prism/core/lanes.hpp>
#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace prism {

namespace detail {

/// The node width a Bvh<T> takes unless told: eight children where the target has AVX
/// and T is float (a face's eight coordinates fill one 256-bit register, and the tree
/// has a third fewer levels), else four (one 128-bit register in float, 256 in double).
/// Every translation unit of a program should be compiled for the same target, as with
/// any header-only SIMD library: Bvh<float> names a different tree in each.
template <class T>
inline constexpr int default_bvh_width =
#if defined(__AVX__)
    sizeof(T) == 4 ? 8 : 4;
#else
    4;
#endif

} // namespace detail

/// A node of the Width-wide tree (4 or 8): up to Width children, each a node or a leaf,
/// their boxes side by side (lane c of bounds[axis] is child c's lo[axis], of
/// bounds[3 + axis] its hi[axis]). An unused lane holds the empty box (lo +inf, hi -inf),
/// which every ray misses, and count 0.
template <Scalar T, int Width = detail::default_bvh_width<T>>
struct alignas(64) BvhNode {
    static_assert(Width == 4 || Width == 8, "a BvhNode has 4 or 8 children");
    /// Children per node.
    static constexpr int width = Width;
    std::array<std::array<T, width>, 6> bounds = empty_bounds(); ///< every lane unused until set
    std::array<std::uint32_t, width> first{}; ///< child node, or a leaf's first primitive
    std::array<std::uint32_t, width> count{}; ///< a leaf's primitives; 0 for a node (or unused)

    /// Every lane's box empty (lo +inf, hi -inf): the bounds of a fresh node.
    [[nodiscard]] static constexpr std::array<std::array<T, width>, 6> empty_bounds() noexcept
    {
        std::array<std::array<T, width>, 6> b{};
        for (std::size_t row = 0; row < 6; ++row) b[row].fill(row < 3 ? infinity<T> : -infinity<T>);
        return b;
    }

    /// Whether child `lane` is a leaf.
    [[nodiscard]] constexpr bool leaf(int lane) const noexcept { return count[std::size_t(lane)] != 0; }
    /// Whether child `lane` is in use (its box is not empty).
    [[nodiscard]] constexpr bool used(int lane) const noexcept { return bounds[0][std::size_t(lane)] <= bounds[3][std::size_t(lane)]; }
    /// Child `lane`'s box.
    [[nodiscard]] constexpr Aabb<T> box(int lane) const noexcept
    {
        const auto c = std::size_t(lane);
        return {{bounds[0][c], bounds[1][c], bounds[2][c]}, {bounds[3][c], bounds[4][c], bounds[5][c]}};
    }
    /// Make child `lane` the box `box` over a node (count_ 0, first_ its index) or a leaf (count_ primitives from first_).
    constexpr void set(int lane, const Aabb<T>& box, std::uint32_t first_, std::uint32_t count_) noexcept
    {
        const auto c = std::size_t(lane);
        for (int axis = 0; axis < 3; ++axis) {
            bounds[std::size_t(axis)][c] = box.lo[axis];
            bounds[std::size_t(axis + 3)][c] = box.hi[axis];
        }
        first[c] = first_;
        count[c] = count_;
    }
};

namespace detail {

#if PRISM_VECTOR_EXTENSIONS
/// SlabRay's numbers for the three axes at once, in the first three lanes of a vector
/// each (lane by lane the arithmetic of SlabRay's loop: 1 / +-0 is that infinity already
/// at run time, so one division and a select), for SlabRay and SlabLanes to take apart.
template <Scalar T>
struct SlabAxes {
    typedef T Axes __attribute__((vector_size(4 * sizeof(T))));
    Axes inverse, far_inverse, near_origin, far_origin;
    unsigned negative; ///< a bit per axis the ray runs toward -axis on
    bool finite; ///< no NaN or infinity in the ray's origin or direction

    /// `pad`: SlabRay::padding; `far_widening`: SlabRay::far_widening.
    [[gnu::always_inline]] constexpr SlabAxes(const Ray<T>& ray, T pad, T far_widening) noexcept
    {
        constexpr T largest = std::numeric_limits<T>::max();
        const Axes d{ray.direction.x, ray.direction.y, ray.direction.z, T(1)}, o{ray.origin.x, ray.origin.y, ray.origin.z, T(0)};
        const Axes r = T(1) / d;
        Axes most, least;
        splat(most, largest), splat(least, -largest);
        const Axes below = r < largest ? r : most;
        const Axes clamped = r > -largest ? below : least;
        inverse = d == T(0) ? r : clamped;
        far_inverse = inverse * far_widening;
        const auto neg = inverse < T(0);
        near_origin = neg ? o - pad : o + pad;
        far_origin = neg ? o + pad : o - pad;
        negative = lane_bits(neg) & 7u;
        finite = lane_bits((o - o) + (d - d) == T(0)) == 15u; // (x - x is 0 but for a NaN or an infinity)
    }
};
#endif

/// A ray prepared for many box tests: its slabs' reciprocals, which face of each slab
/// it meets first, and its origin moved by one padding for every box of a tree (see
/// Bvh::traverse).
template <Scalar T>
struct SlabRay {
    Vec3<T> inverse{T(0)}; // (initialized: clang's constant evaluation assigns no inactive union member of GLM's vectors)
    /// inverse * far_widening: the far face's distance, widened by the one product.
    /// (Infinite for a denormal d: the far face is then at +-inf, or NaN, which the test
    /// ignores; never a miss.)
    Vec3<T> far_inverse{T(0)};
    /// The origin moved by the pad, for the near and far faces of each slab: the widened
    /// face lo - pad is at (lo - (o + pad)) / d from the origin.
    Vec3<T> near_origin{T(0)}, far_origin{T(0)};
    std::array<bool, 3> negative{}; ///< the ray runs toward -axis: it meets hi first

    /// The far slab's widening: rounding never reports a miss for a ray that touches a
    /// box (pbrt-v4, Bounds3::IntersectP). Folded into far_inverse, the far distance
    /// takes four roundings (o - pad, 1 / d, the widening, the product) where pbrt's takes
    /// three and the widening's own, and 2 gamma(3) covers both.
    static constexpr T far_widening = T(1) + T(2) * gamma<T>(3);

    /// `magnitude`: the largest coordinate magnitude of every box to be tested.
    constexpr SlabRay(const Ray<T>& ray, T magnitude) noexcept
    {
        const T pad = padding(ray, magnitude);
        constexpr T largest = std::numeric_limits<T>::max();
#if PRISM_VECTOR_EXTENSIONS
        if (!std::is_constant_evaluated()) {
            const SlabAxes<T> axes(ray, pad, far_widening);
            for (int axis = 0; axis < 3; ++axis) {
                inverse[axis] = axes.inverse[axis];
                far_inverse[axis] = axes.far_inverse[axis];
                negative[std::size_t(axis)] = ((axes.negative >> axis) & 1u) != 0;
                near_origin[axis] = axes.near_origin[axis];
                far_origin[axis] = axes.far_origin[axis];
            }
            return;
        }
#endif
        for (int axis = 0; axis < 3; ++axis) {
            const T d = ray.direction[axis];
            // 1/d, kept finite for a denormal d (no 0 * inf: no NaN); a zero d gives an
            // infinite reciprocal of its sign, so the slab is all or nothing (NaN only
            // for an origin exactly on a widened face, which the test then ignores).
            inverse[axis] = d == T(0) ? (negative_zero(d) ? -infinity<T> : infinity<T>) : clamp(T(1) / d, -largest, largest);
            far_inverse[axis] = inverse[axis] * far_widening;
            negative[std::size_t(axis)] = inverse[axis] < T(0);
            near_origin[axis] = negative[std::size_t(axis)] ? ray.origin[axis] - pad : ray.origin[axis] + pad;
            far_origin[axis] = negative[std::size_t(axis)] ? ray.origin[axis] + pad : ray.origin[axis] - pad;
        }
    }

    /// The pad every box of a tree is widened by for `ray` (`magnitude`: the largest
    /// coordinate magnitude of every box to be tested). Aabb::may_cross widens a box by
    /// gamma(16) (|o - c| + h) (c its center, h its half size, as max components), which is
    /// at most gamma(16) (|o| + 2 magnitude). gamma(20) covers that and the rounding of
    /// o +- pad (two ulps of |o| or |lo|), so that every box is at least as wide here as there.
    [[nodiscard, gnu::always_inline]] static constexpr T padding(const Ray<T>& ray, T magnitude) noexcept
    {
        return gamma<T>(20) * (max_component(prism::abs(ray.origin)) + T(2) * magnitude) + std::numeric_limits<T>::min();
    }

    [[nodiscard]] static constexpr bool negative_zero(T zero) noexcept
    {
        using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
        return (std::bit_cast<Bits>(zero) >> (8 * sizeof(T) - 1)) != 0;
    }

    /// The part of `range` in which the ray may be inside the widened box (empty if
    /// none): never empty where Aabb::may_cross is true. (Inlined by force: it is most
    /// of a traversal's work, and a call per node costs a quarter of it.)
    [[nodiscard, gnu::always_inline]] constexpr Interval<T> may_cross(const Aabb<T>& box, Interval<T> range) const noexcept
    {
        std::array<T, 3> t_near{}, t_far{};
        for (int axis = 0; axis < 3; ++axis) {
            const bool n = negative[std::size_t(axis)];
            t_near[std::size_t(axis)] = ((n ? box.hi[axis] : box.lo[axis]) - near_origin[axis]) * inverse[axis];
            t_far[std::size_t(axis)] = ((n ? box.lo[axis] : box.hi[axis]) - far_origin[axis]) * far_inverse[axis];
        }
        range.min = later(later(t_near[0], t_near[1]), later(t_near[2], range.min));
        range.max = sooner(sooner(t_far[0], t_far[1]), sooner(t_far[2], range.max));
        return range.min <= range.max ? range : Interval<T>{};
    }

    /// max and min, paired as a tree (two steps deep instead of three), in the form of
    /// SSE's maxps and minps: a NaN (0 * inf, an axis-parallel ray starting on a widened
    /// face) in the first argument gives the second. A NaN in the second drops its pair,
    /// which only widens the test.
    [[nodiscard, gnu::always_inline]] static constexpr T later(T a, T b) noexcept { return a > b ? a : b; }
    [[nodiscard, gnu::always_inline]] static constexpr T sooner(T a, T b) noexcept { return a < b ? a : b; }

    /// may_cross for the children of a node at once: a bit per child the ray may
    /// cross, and in `near` where its part of the range begins (for compile time; at run
    /// time SlabLanes does the same in SIMD).
    template <int Width>
    [[nodiscard]] constexpr unsigned may_cross(const BvhNode<T, Width>& node, Interval<T> range, std::array<T, std::size_t(Width)>& near) const noexcept
    {
        unsigned hits = 0;
        for (int lane = 0; lane < Width; ++lane) {
            const Interval<T> r = may_cross(node.box(lane), range);
            near[std::size_t(lane)] = r.min;
            hits |= r.empty() ? 0u : 1u << lane;
        }
        return hits;
    }
};

#if PRISM_VECTOR_EXTENSIONS
/// SlabRay's test of a node's children in SIMD (GCC's vector extensions, which clang
/// shares): the same arithmetic in each lane as SlabRay::may_cross, with the ray's values
/// broadcast and the faces it meets first chosen once per ray.
template <Scalar T, int Width>
struct SlabLanes {
    static constexpr int width = Width;
    typedef T Lanes __attribute__((vector_size(width * sizeof(T))));
    Lanes near_origin[3], far_origin[3], inverse[3], far_inverse[3];
    std::size_t near_face[3], far_face[3]; ///< byte offsets in BvhNode::bounds of the rows the ray meets first and last on each axis
    bool finite; ///< no NaN or infinity in the ray (Bvh's walk then visits nothing)

    /// `magnitude`: the largest coordinate magnitude of every box to be tested (as SlabRay's).
    [[gnu::always_inline]] SlabLanes(const Ray<T>& ray, T magnitude) noexcept
    {
        // SlabRay's numbers, each axis's broadcast from its lane (never stored as scalars),
        // and the rows' offsets from a table.
        const SlabAxes<T> axes(ray, SlabRay<T>::padding(ray, magnitude), SlabRay<T>::far_widening);
        set_axis<0>(axes);
        set_axis<1>(axes);
        set_axis<2>(axes);
        __builtin_memcpy(near_face, faces[axes.negative].data(), sizeof(near_face));
        __builtin_memcpy(far_face, faces[axes.negative].data() + 3, sizeof(far_face));
        finite = axes.finite;
    }

    template <int Axis>
    [[gnu::always_inline]] void set_axis(const SlabAxes<T>& axes) noexcept
    {
        splat_lane<Axis>(near_origin[Axis], axes.near_origin);
        splat_lane<Axis>(far_origin[Axis], axes.far_origin);
        splat_lane<Axis>(inverse[Axis], axes.inverse);
        splat_lane<Axis>(far_inverse[Axis], axes.far_inverse);
    }

    /// For each octant (SlabAxes::negative), the byte offsets of the rows a ray meets
    /// first on each axis, then last: lo (row axis) where it runs toward +axis, else hi.
    static constexpr std::array<std::array<std::size_t, 6>, 8> faces = [] {
        std::array<std::array<std::size_t, 6>, 8> f{};
        for (std::size_t octant = 0; octant < 8; ++octant)
            for (std::size_t axis = 0; axis < 3; ++axis) {
                const std::size_t n = (octant >> axis) & 1u;
                f[octant][axis] = (axis + 3 * n) * sizeof(Lanes);
                f[octant][axis + 3] = (axis + 3 - 3 * n) * sizeof(Lanes);
            }
        return f;
    }();

    [[nodiscard, gnu::always_inline]] unsigned may_cross(const BvhNode<T, Width>& node, Interval<T> range, std::array<T, width>& near) const noexcept
    {
        // The three axes written out, each row found by its byte offset (a loop over the
        // axes kept its results in memory, and took twice the instructions).
        static_assert(sizeof(node.bounds[0]) == sizeof(Lanes));
        const char* rows = reinterpret_cast<const char*>(node.bounds.data());
        // (Loaded into variables: a function returning a vector wider than the target's
        // registers changes the ABI, and GCC says so.)
        Lanes n0, n1, n2, f0, f1, f2;
        __builtin_memcpy(&n0, rows + near_face[0], sizeof(Lanes));
        __builtin_memcpy(&n1, rows + near_face[1], sizeof(Lanes));
        __builtin_memcpy(&n2, rows + near_face[2], sizeof(Lanes));
        __builtin_memcpy(&f0, rows + far_face[0], sizeof(Lanes));
        __builtin_memcpy(&f1, rows + far_face[1], sizeof(Lanes));
        __builtin_memcpy(&f2, rows + far_face[2], sizeof(Lanes));
        const Lanes t_near[3] = {(n0 - near_origin[0]) * inverse[0], (n1 - near_origin[1]) * inverse[1], (n2 - near_origin[2]) * inverse[2]};
        const Lanes t_far[3] = {(f0 - far_origin[0]) * far_inverse[0], (f1 - far_origin[1]) * far_inverse[1], (f2 - far_origin[2]) * far_inverse[2]};
        // SlabRay::later and sooner, written out (a function returning a vector wider
        // than the target's registers changes the ABI, and GCC says so).
        Lanes min, max;
        splat(min, range.min), splat(max, range.max);
        const Lanes near01 = t_near[0] > t_near[1] ? t_near[0] : t_near[1], near2 = t_near[2] > min ? t_near[2] : min;
        const Lanes far01 = t_far[0] < t_far[1] ? t_far[0] : t_far[1], far2 = t_far[2] < max ? t_far[2] : max;
        const Lanes lo = near01 > near2 ? near01 : near2, hi = far01 < far2 ? far01 : far2;
        __builtin_memcpy(near.data(), &lo, sizeof(Lanes));
        return lane_bits(lo <= hi);
    }
};
#endif

} // namespace detail

} // namespace prism
