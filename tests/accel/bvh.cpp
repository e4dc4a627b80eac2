// SPDX-License-Identifier: MIT
// Bvh against brute force: the same nearest hit, at the same t, for every ray.
#include <prism/accel/bvh.hpp>
#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

using namespace prism;

namespace {

template <class T>
struct Ball {
    Vec3<T> center;
    T radius;

    [[nodiscard]] Aabb<T> box() const { return Aabb<T>{center - Vec3<T>(radius), center + Vec3<T>(radius)}.rounded_out(); }

    /// The nearest crossing within range, or infinity; worked out in long double, so
    /// that a ray from far away finds no spurious crossing.
    [[nodiscard]] T hit(const Ray<T>& ray, Interval<T> range) const
    {
        using L = long double;
        const L ox = L(ray.origin.x) - L(center.x), oy = L(ray.origin.y) - L(center.y), oz = L(ray.origin.z) - L(center.z);
        const L dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
        const L a = dx * dx + dy * dy + dz * dz, b = ox * dx + oy * dy + oz * dz, c = ox * ox + oy * oy + oz * oz - L(radius) * L(radius);
        const L disc = b * b - a * c;
        if (disc < 0) return infinity<T>;
        const L root = std::sqrt(disc);
        for (const L t : {(-b - root) / a, (-b + root) / a})
            if (T(t) >= range.min && T(t) <= range.max) return T(t);
        return infinity<T>;
    }
};

template <class T>
bool holds(const Aabb<T>& outer, const Aabb<T>& inner)
{
    return outer.contains(inner.lo) && outer.contains(inner.hi);
}

template <class T>
struct Found {
    T t = infinity<T>;
    std::uint32_t index = std::uint32_t(-1);
    friend bool operator==(const Found&, const Found&) = default;
};

/// The nearest hit, ties to the lower index, by a scene's linear scan: every ball whose
/// box the ray may cross (a naive quadratic in float finds spurious hits from far away,
/// and the box keeps them out, as it does in a scene).
template <class T>
Found<T> brute_force(const std::vector<Ball<T>>& balls, const Ray<T>& ray, Interval<T> range)
{
    Found<T> best;
    for (std::uint32_t i = 0; i < balls.size(); ++i) {
        if (!balls[i].box().may_cross(ray, range)) continue;
        const T t = balls[i].hit(ray, range);
        if (t < best.t || (t == best.t && t < infinity<T> && i < best.index)) best = {t, i};
    }
    return best;
}

template <class T, int W>
Found<T> by_bvh(const Bvh<T, W>& bvh, const std::vector<Ball<T>>& balls, const Ray<T>& ray, Interval<T> range, int* visits = nullptr)
{
    Found<T> best;
    bvh.traverse(ray, range, [&](std::uint32_t i, Interval<T>& r) {
        if (visits) ++*visits;
        const T t = balls[i].hit(ray, r);
        if (t < best.t || (t == best.t && t < infinity<T> && i < best.index)) best = {t, i}, r.max = t;
        return false;
    });
    return best;
}

template <class T>
std::vector<Aabb<T>> boxes_of(const std::vector<Ball<T>>& balls)
{
    std::vector<Aabb<T>> boxes;
    for (const auto& b : balls) boxes.push_back(b.box());
    return boxes;
}

template <class T>
std::vector<Ball<T>> random_balls(int n, Random& rng, T spread, T size)
{
    std::vector<Ball<T>> balls;
    for (int i = 0; i < n; ++i) {
        const Vec3<T> c{rng.uniform<T>(), rng.uniform<T>(), rng.uniform<T>()};
        balls.push_back({(c - Vec3<T>(T(0.5))) * spread, size * (T(0.05) + rng.uniform<T>())});
    }
    return balls;
}

/// Rays of every kind: from inside the cloud, from far away (1e4 times its size),
/// axis-aligned, and with a denormal component.
template <class T>
Vec3<T> random_point_in(Random& rng, T half_size)
{
    return (Vec3<T>{rng.uniform<T>(), rng.uniform<T>(), rng.uniform<T>()} * T(2) - Vec3<T>(T(1))) * half_size;
}

template <class T>
Ray<T> random_ray(Random& rng, T spread, int kind)
{
    const Vec3<T> target = (Vec3<T>{rng.uniform<T>(), rng.uniform<T>(), rng.uniform<T>()} - Vec3<T>(T(0.5))) * spread;
    switch (kind % 4) {
    case 0: return {target, uniform_sphere<T>(rng)};
    case 1: {
        const Vec3<T> from = target - uniform_sphere<T>(rng) * (spread * T(1e4));
        return {from, normalize(target - from)};
    }
    case 2: {
        Vec3<T> d{0};
        d[int(rng.uniform<T>() * T(2.999))] = rng.uniform<T>() < T(0.5) ? T(-1) : T(1);
        return {target - d * spread, d};
    }
    default: {
        Vec3<T> d = uniform_sphere<T>(rng);
        d[int(rng.uniform<T>() * T(2.999))] = std::numeric_limits<T>::denorm_min();
        return {target - d * spread, normalize(d)};
    }
    }
}

} // namespace

TEST_CASE_TEMPLATE("SlabRay's three axes at once (run time) equal its loop over the axes (constant evaluation), over hostile directions", T, float, double)
{
    // The loop, written out here as SlabRay's comments state it: the twin of the SIMD path.
    using L = std::numeric_limits<T>;
    const T values[] = {T(1), T(-0.3), T(0), -T(0), L::denorm_min(), -L::denorm_min(), L::min(), T(1e-30), L::max(), -L::max(), T(7.5)};
    const T largest = L::max();
    int checked = 0;
    for (const T x : values)
        for (const T y : values)
            for (const T z : values) {
                const Ray<T> ray{{T(0.25), T(-3), T(1e4)}, {x, y, z}};
                const T magnitude = T(12);
                const detail::SlabRay<T> slab(ray, magnitude);
                const T pad = gamma<T>(20) * (max_component(abs(ray.origin)) + T(2) * magnitude) + L::min();
                for (int axis = 0; axis < 3; ++axis) {
                    const T d = ray.direction[axis];
                    const T inverse = d == T(0) ? (std::signbit(d) ? -L::infinity() : L::infinity()) : std::clamp(T(1) / d, -largest, largest);
                    const bool negative = inverse < T(0);
                    CHECK(std::bit_cast<std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>(slab.inverse[axis]) ==
                          std::bit_cast<std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>(inverse));
                    CHECK(slab.far_inverse[axis] == inverse * detail::SlabRay<T>::far_widening);
                    CHECK(slab.negative[std::size_t(axis)] == negative);
                    CHECK(slab.near_origin[axis] == (negative ? ray.origin[axis] - pad : ray.origin[axis] + pad));
                    CHECK(slab.far_origin[axis] == (negative ? ray.origin[axis] + pad : ray.origin[axis] - pad));
                    ++checked;
                }
            }
    CHECK(checked == 3 * 11 * 11 * 11);
}

TEST_CASE_TEMPLATE("the node test keeps every box Aabb::may_cross keeps, and little more", T, float, double)
{
    Random rng(11u, 3u);
    int culled = 0, crossed = 0, extra = 0;
    for (int i = 0; i < 200000; ++i) {
        const T scale = (i / 4) % 4 == 3 ? T(1e5) : T(10); // and far from the origin
        const Ball<T> ball{(Vec3<T>{rng.uniform<T>(), rng.uniform<T>(), rng.uniform<T>()} - Vec3<T>(T(0.5))) * scale, T(0.01) + rng.uniform<T>()};
        Ray<T> ray = random_ray<T>(rng, scale, i);
        if (i % 8 == 6) ray.direction = -ray.direction; // axis-aligned with -0 components
        const Interval<T> range{T(0), i % 3 == 0 ? infinity<T> : T(2) * scale * rng.uniform<T>()};
        // The tree's magnitude: this box's, or a larger tree's.
        const Aabb<T> box = ball.box();
        const T magnitude = std::max(max_component(abs(box.lo)), max_component(abs(box.hi))) * (i % 2 ? T(1) : T(3));
        const bool slow = box.may_cross(ray, range);
        const bool fast = !detail::SlabRay<T>(ray, magnitude).may_cross(box, range).empty();
        culled += slow && !fast;
        extra += fast && !slow;
        crossed += slow;
    }
    CHECK(culled == 0);
    CHECK(crossed > 1000);
    CHECK(extra < crossed / 50);
}

namespace {

/// SlabLanes (SIMD, what a traversal runs) and SlabRay's lane loop (what a constant
/// evaluation runs) against SlabRay::may_cross, one box at a time, for a node of W
/// children; unused lanes (empty boxes) are never crossed.
template <class T, int W>
void check_node_test()
{
    CAPTURE(W);
    Random rng(2u, 8u);
    int mismatches = 0, crossed = 0;
    for (int i = 0; i < 50000; ++i) {
        const T scale = i % 4 == 3 ? T(1e5) : T(10);
        BvhNode<T, W> node;
        T magnitude = 0;
        const int used = 1 + i % W;
        for (int c = 0; c < W; ++c) {
            const Ball<T> ball{(Vec3<T>{rng.uniform<T>(), rng.uniform<T>(), rng.uniform<T>()} - Vec3<T>(T(0.5))) * scale, T(0.01) + rng.uniform<T>() * scale / 4};
            const Aabb<T> box = c < used ? ball.box() : Aabb<T>{};
            node.set(c, box, 0, 0);
            if (c < used) magnitude = std::max({magnitude, max_component(abs(box.lo)), max_component(abs(box.hi))});
        }
        Ray<T> ray = random_ray<T>(rng, scale, i);
        if (i % 8 == 6) ray.direction = -ray.direction;
        const Interval<T> range{i % 5 == 0 ? T(0) : scale * rng.uniform<T>(), i % 3 == 0 ? infinity<T> : T(2) * scale * rng.uniform<T>()};
        const detail::SlabRay<T> slab(ray, magnitude);
        std::array<T, W> near{};
#if PRISM_VECTOR_EXTENSIONS
        const unsigned hits = detail::SlabLanes<T, W>(ray, magnitude).may_cross(node, range, near);
#else
        const unsigned hits = slab.may_cross(node, range, near); // a build without vector extensions: the scalar loop alone
#endif
        std::array<T, W> near_scalar{};
        mismatches += slab.may_cross(node, range, near_scalar) != hits;
        for (int c = 0; c < W; ++c) {
            const Interval<T> one = slab.may_cross(node.box(c), range);
            const bool hit = (hits >> c) & 1u;
            mismatches += hit != !one.empty() || (hit && std::bit_cast<std::array<unsigned char, sizeof(T)>>(near[std::size_t(c)]) != std::bit_cast<std::array<unsigned char, sizeof(T)>>(one.min)) || (hit && c >= used);
            crossed += hit;
        }
    }
    CHECK(mismatches == 0);
    CHECK(crossed > 750 * W);
}

} // namespace

TEST_CASE_TEMPLATE("the node test in SIMD is the one-box test in every lane, bit for bit, for 4 and 8 lanes", T, float, double)
{
    check_node_test<T, 4>();
    check_node_test<T, 8>();
}

TEST_CASE_TEMPLATE("the nearest hit through the Bvh is brute force's, same ball and same t, for every ray (4 and 8 wide)", T, float, double)
{
    Random rng(5u, 9u);
    for (const int n : {1, 2, 7, 100, 3000}) {
        const auto balls = random_balls<T>(n, rng, T(10), T(3) / std::cbrt(T(n)));
        for (const BvhSplit split : {BvhSplit::binned, BvhSplit::sweep}) {
            CAPTURE(n);
            CAPTURE(int(split));
            const Bvh<T, 4> four(boxes_of(balls), {.split = split});
            const Bvh<T, 8> eight(boxes_of(balls), {.split = split});
            int mismatches = 0, hits = 0;
            const int rays = n >= 1000 ? 3000 : 40000; // brute force costs n per ray
            for (int i = 0; i < rays; ++i) {
                const Ray<T> ray = random_ray<T>(rng, T(10), i);
                const Interval<T> range{T(0), infinity<T>};
                const Found<T> a = brute_force(balls, ray, range);
                mismatches += !(a == by_bvh(four, balls, ray, range)) + !(a == by_bvh(eight, balls, ray, range));
                hits += a.t < infinity<T>;
            }
            CHECK(mismatches == 0);
            CHECK(hits > rays / 20);
        }
    }
}

TEST_CASE_TEMPLATE("an any-hit query stops at its first hit and agrees with brute force on whether there is one", Tree, Bvh<float, 4>, Bvh<float, 8>)
{
    // Nearest first (traverse) and in no order (any_in_leaf_order, a shadow ray's).
    Random rng(7u, 1u);
    const auto balls = random_balls<float>(500, rng, 10.0f, 0.3f);
    const Tree bvh(boxes_of(balls));
    int mismatches = 0, blocked = 0, tests_after_hit = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray<float> ray = random_ray<float>(rng, 10.0f, i);
        const Interval<float> range{0.0f, 5.0f * rng.uniform<float>()};
        const bool truth = brute_force(balls, ray, range).t < infinity<float>;
        for (const bool ordered : {true, false}) {
            Interval<float> r = range;
            bool hit = false;
            const auto visit = [&](std::uint32_t k, Interval<float>& rr) {
                tests_after_hit += hit;
                hit = balls[ordered ? k : bvh.primitives()[k]].hit(ray, rr) < infinity<float>;
                return hit;
            };
            const bool stopped = ordered ? bvh.traverse(ray, r, visit) : bvh.any_in_leaf_order(ray, r, visit);
            mismatches += hit != truth || stopped != hit;
        }
        blocked += truth;
    }
    CHECK(tests_after_hit == 0);
    CHECK(mismatches == 0);
    CHECK(blocked > 500);
}

TEST_CASE_TEMPLATE("a ray with a NaN or an infinity in its origin or direction visits nothing, by every query", Tree, Bvh<float, 4>, Bvh<float, 8>,
                   Bvh<double, 4>)
{
    // Regression: an all-NaN ray passed every node's test, padding lanes (empty boxes,
    // count 0) included, which the walk then took for the root: it pushed without end and
    // wrote past its stack.
    using T = typename Tree::scalar_type;
    Random rng(3u, 3u);
    const auto balls = random_balls<T>(300, rng, T(10), T(0.5));
    const Tree bvh(boxes_of(balls));
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = infinity<T>;
    const Vec3<T> o{T(-20), T(0.1), T(0.2)}, d = normalize(Vec3<T>(1, T(0.01), T(0.02)));
    int visits = 0;
    const auto count = [&](auto&&...) {
        ++visits;
        return false;
    };
    const Ray<T> bad[] = {{Vec3<T>(nan), Vec3<T>(nan)}, {{nan, o.y, o.z}, d}, {o, {d.x, nan, d.z}}, {{-inf, o.y, o.z}, d}, {o, {inf, d.y, d.z}},
                          {{o.x, inf, o.z}, d},           {o, {d.x, d.y, -inf}}};
    for (const Ray<T>& ray : bad) {
        CAPTURE(ray.origin.x);
        CAPTURE(ray.direction.x);
        for (const Interval<T> range : {Interval<T>{T(0), inf}, Interval<T>{T(0), T(100)}}) {
            visits = 0;
            Interval<T> r = range;
            CHECK_FALSE(bvh.traverse(ray, r, count));
            r = range;
            CHECK_FALSE(bvh.any_in_leaf_order(ray, r, count));
            r = range;
            CHECK_FALSE(bvh.traverse_leaves(ray, r, count));
            r = range;
            CHECK_FALSE(bvh.any_leaf(ray, r, count));
            CHECK(visits == 0);
        }
    }
    // The same tree still answers a finite ray.
    CHECK(by_bvh(bvh, balls, Ray<T>{o, d}, Interval<T>{T(0), inf}) == brute_force(balls, Ray<T>{o, d}, Interval<T>{T(0), inf}));
}

TEST_CASE_TEMPLATE("the tree's shape: every primitive once, children inside their parent, leaves within max_leaf_size and starting a block", Tree, Bvh<float, 4>,
                   Bvh<float, 8>)
{
    Random rng(3u, 3u);
    for (const auto& [leaf, block] : {std::pair{1, 1}, {4, 1}, {8, 1}, {8, 3}, {16, 4}}) {
        for (const BvhSplit split : {BvhSplit::binned, BvhSplit::sweep}) {
            const auto balls = random_balls<float>(5000, rng, 10.0f, 0.1f);
            const auto boxes = boxes_of(balls);
            const Tree bvh(boxes, {.max_leaf_size = leaf, .leaf_block = block, .split = split});
            std::vector<int> seen(balls.size(), 0), parents(bvh.nodes().size(), 0);
            bool inside = true, small = true, packed = true, blocked = true;
            std::size_t positions = 0; // the leaves' positions, padded to whole blocks
            for (const auto& node : bvh.nodes()) {
                int used = 0;
                for (int c = 0; c < Tree::width; ++c) {
                    if (!node.used(c)) {
                        packed = packed && node.count[std::size_t(c)] == 0;
                        continue;
                    }
                    ++used;
                    if (node.leaf(c)) {
                        const std::uint32_t first = node.first[std::size_t(c)], count = node.count[std::size_t(c)];
                        small = small && count <= std::uint32_t(leaf);
                        // A leaf starts a block; its last primitive fills the block's rest.
                        const std::uint32_t padded = (count + std::uint32_t(block) - 1) / std::uint32_t(block) * std::uint32_t(block);
                        blocked = blocked && first % std::uint32_t(block) == 0;
                        for (std::uint32_t k = first + count; k < first + padded; ++k) blocked = blocked && bvh.primitives()[k] == bvh.primitives()[first + count - 1];
                        positions += padded;
                        for (std::uint32_t k = node.first[std::size_t(c)]; k < node.first[std::size_t(c)] + node.count[std::size_t(c)]; ++k) {
                            const std::uint32_t p = bvh.primitives()[k];
                            ++seen[p];
                            inside = inside && holds(node.box(c), boxes[p]);
                        }
                    } else {
                        const auto& child = bvh.nodes()[node.first[std::size_t(c)]];
                        ++parents[node.first[std::size_t(c)]];
                        for (int g = 0; g < Tree::width; ++g)
                            if (child.used(g)) inside = inside && holds(node.box(c), child.box(g));
                    }
                }
                // Two children at least: a node of one would be a wasted level.
                packed = packed && used >= 2;
            }
            CHECK(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
            CHECK(blocked);
            CHECK(positions == bvh.primitives().size());
            CHECK(bvh.size() == balls.size());
            if (block == 1) CHECK(bvh.primitives().size() == balls.size());
            CHECK(parents[0] == 0);
            CHECK(std::all_of(parents.begin() + 1, parents.end(), [](int p) { return p == 1; }));
            CHECK(inside);
            CHECK(small);
            CHECK(packed);
            // A binary tree has n - 1 inner nodes at most; a 4-wide one about a third of
            // that, and an 8-wide one (whose nodes near the leaves are partly filled)
            // about two thirds of the 4-wide one's.
            CHECK(bvh.nodes().size() <= balls.size() / 2);
            if (Tree::width == 8) CHECK(bvh.nodes().size() <= Bvh<float, 4>(boxes, {.max_leaf_size = leaf, .split = split}).nodes().size() * 3 / 4);
            Aabb<float> all;
            for (const auto& box : boxes) all = all.merged(box);
            CHECK((bvh.bounds().lo == all.lo && bvh.bounds().hi == all.hi));
        }
    }
}

namespace {

/// A random binary tree of `leaves` leaves laid out as the build lays one out (children
/// side by side, after their parent), with random boxes, and leaves of 1 to 4 primitives.
template <int W>
std::vector<typename Bvh<double, W>::BinaryNode> random_binary_tree(Random& rng, int leaves)
{
    using Node = typename Bvh<double, W>::BinaryNode;
    std::vector<Node> tree(1);
    std::uint32_t primitive = 0;
    const auto grow = [&](auto& self, std::size_t at, int n) -> void {
        if (n == 1) {
            const Vec3<double> lo = random_point_in<double>(rng, 10.0);
            const auto count = std::uint32_t(1 + int(rng.uniform<double>() * 3.999));
            tree[at] = {{lo, lo + Vec3<double>{rng.uniform<double>(), rng.uniform<double>(), rng.uniform<double>()} * 5.0}, primitive, count};
            primitive += count;
            return;
        }
        const auto child = std::uint32_t(tree.size());
        tree.resize(tree.size() + 2);
        const int left = 1 + int(rng.uniform<double>() * (n - 1 - 1e-9));
        self(self, child, left);
        self(self, child + 1, n - left);
        tree[at] = {tree[child].box.merged(tree[child + 1].box), child, 0};
    };
    grow(grow, 0, leaves);
    return tree;
}

/// The least wide-node area of any collapse of `tree` into nodes of at most W lanes, by
/// trying every set of inner nodes to keep (the root always is).
template <int W>
double least_node_area(const std::vector<typename Bvh<double, W>::BinaryNode>& tree)
{
    std::vector<std::uint32_t> inner;
    for (std::uint32_t n = 1; n < tree.size(); ++n)
        if (tree[n].count == 0) inner.push_back(n);
    double least = infinity<double>;
    for (std::uint32_t keep = 0; keep < (1u << inner.size()); ++keep) {
        std::vector<bool> kept(tree.size(), false);
        kept[0] = true;
        for (std::size_t i = 0; i < inner.size(); ++i) kept[inner[i]] = (keep >> i) & 1u;
        // Lanes of a kept node: its binary children, a dropped inner one replaced by its own.
        const auto lanes = [&](auto& self, std::uint32_t n) -> int {
            return tree[n].count != 0 || kept[n] ? 1 : self(self, tree[n].first) + self(self, tree[n].first + 1);
        };
        bool fits = true;
        double area = 0;
        for (std::uint32_t n = 0; n < tree.size(); ++n)
            if (tree[n].count == 0 && kept[n]) {
                fits = fits && lanes(lanes, tree[n].first) + lanes(lanes, tree[n].first + 1) <= W;
                area += detail::half_area(tree[n].box);
            }
        if (fits) least = std::min(least, area);
    }
    return least;
}

template <int W>
void check_collapse_is_least()
{
    CAPTURE(W);
    Random rng(6u, 6u);
    int mismatches = 0, lost = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int leaves = 2 + trial % 13;
        const auto tree = random_binary_tree<W>(rng, leaves);
        const auto wide = Bvh<double, W>::collapse(tree, {});
        // Its node area (the root's box, and every lane that is a node), and its leaves.
        double area = detail::half_area(tree[0].box);
        std::vector<std::pair<std::uint32_t, std::uint32_t>> found, expected;
        for (const auto& node : wide)
            for (int c = 0; c < W; ++c) {
                if (!node.used(c)) continue;
                if (node.leaf(c)) found.emplace_back(node.first[std::size_t(c)], node.count[std::size_t(c)]);
                else area += detail::half_area(node.box(c));
            }
        for (const auto& b : tree)
            if (b.count != 0) expected.emplace_back(b.first, b.count);
        std::sort(found.begin(), found.end());
        std::sort(expected.begin(), expected.end());
        lost += found != expected;
        const double least = least_node_area<W>(tree);
        mismatches += !(std::abs(area - least) <= 1e-9 * least);
    }
    CHECK(lost == 0);
    CHECK(mismatches == 0);
}

} // namespace

TEST_CASE("the collapse to wide nodes has the least node area of every collapse of the binary tree, tried one by one")
{
    // Leaf costs are the same in every collapse, so the SAH cost differs only by the
    // wide nodes' areas. Random trees of 2 to 14 leaves (up to 2^12 sets of nodes to keep).
    check_collapse_is_least<4>();
    check_collapse_is_least<8>();
}

TEST_CASE("the sweep's tree costs less than the binned one by the surface area heuristic, and both far less than one leaf")
{
    // Clustered balls of very different sizes, where 16 bins place planes coarsely.
    Random rng(4u, 4u);
    std::vector<Ball<float>> balls;
    for (int cluster = 0; cluster < 20; ++cluster) {
        const Vec3<float> c = random_point_in<float>(rng, 100.0f);
        for (int i = 0; i < 500; ++i) balls.push_back({c + random_point_in<float>(rng, 3.0f), 0.01f + 0.5f * rng.uniform<float>() * rng.uniform<float>()});
    }
    const double binned = Bvh<float>(boxes_of(balls)).sah_cost(), sweep = Bvh<float>(boxes_of(balls), {.split = BvhSplit::sweep}).sah_cost();
    const double coarse = Bvh<float>(boxes_of(balls), {.bins = 4}).sah_cost();
    MESSAGE("SAH cost: 4 bins ", coarse, ", 16 bins ", binned, ", sweep ", sweep, " (one leaf: ", balls.size(), ")");
    CHECK(sweep < binned);
    CHECK(binned < coarse);
    CHECK(sweep < 0.01 * double(balls.size()));
}

TEST_CASE_TEMPLATE("a build on several threads makes one thread's tree, node for node", T, float, double)
{
    // Clusters and a uniform spread, 17 000 boxes (a threaded build needs 2^14): the build
    // leaves a dozen subtrees to its threads. Compared with the one-thread build (the
    // serial twin), bit for bit.
    Random rng(8u, 3u);
    std::vector<Ball<T>> balls = random_balls<T>(12000, rng, T(50), T(0.3));
    for (int cluster = 0; cluster < 20; ++cluster) {
        const Vec3<T> c = random_point_in<T>(rng, T(50));
        for (int i = 0; i < 250; ++i) balls.push_back({c + random_point_in<T>(rng, T(1)), T(0.01) + T(0.2) * rng.uniform<T>()});
    }
    const auto boxes = boxes_of(balls);
    for (const BvhSplit split : {BvhSplit::binned, BvhSplit::sweep}) {
        const Bvh<T> one(boxes, {.split = split, .threads = 1});
        for (const unsigned threads : {2u, 3u}) {
            CAPTURE(threads);
            const Bvh<T> many(boxes, {.split = split, .threads = threads});
            REQUIRE(many.nodes().size() == one.nodes().size());
            CHECK(std::equal(many.primitives().begin(), many.primitives().end(), one.primitives().begin(), one.primitives().end()));
            bool same = true;
            for (std::size_t i = 0; i < one.nodes().size(); ++i) {
                const auto &a = many.nodes()[i], &b = one.nodes()[i];
                same = same && a.first == b.first && a.count == b.count && std::memcmp(a.bounds.data(), b.bounds.data(), sizeof a.bounds) == 0;
            }
            CHECK(same);
            CHECK(many.depth() == one.depth());
        }
    }
}

TEST_CASE("degenerate sets: identical boxes, one box, exponentially spaced boxes; depth stays bounded")
{
    // 1000 copies of one ball: centroids coincide, so the tree splits by count.
    const std::vector<Ball<double>> same(1000, Ball<double>{{1, 2, 3}, 0.5});
    const Bvh<double> bvh(boxes_of(same));
    CHECK(bvh.depth() <= 12);
    const Ray<double> ray{{1, 2, -5}, {0, 0, 1}};
    CHECK(by_bvh(bvh, same, ray, {0, infinity<double>}) == Found<double>{7.5, 0});
    // One ball.
    const std::vector<Ball<double>> one{{{0, 0, 0}, 1}};
    CHECK(by_bvh(Bvh<double>(boxes_of(one)), one, {{0, 0, -5}, {0, 0, 1}}, {0, infinity<double>}).t == doctest::Approx(4.0));
    // Balls at 2^k along x, k = 0..200: the SAH would cut one off at each level; past
    // depth 48 the tree splits by count.
    std::vector<Ball<double>> spaced;
    for (int k = 0; k < 200; ++k) spaced.push_back({{std::ldexp(1.0, k), 0, 0}, std::ldexp(0.25, k)});
    const Bvh<double> deep(boxes_of(spaced));
    CHECK(deep.depth() <= Bvh<double>::max_depth);
    Random rng(1u, 1u);
    int mismatches = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray<double> r{{std::ldexp(1.0, int(rng.uniform<double>() * 190)), 0, -1}, normalize(uniform_sphere<double>(rng) + Vec3<double>(0, 0, 1))};
        mismatches += !(by_bvh(deep, spaced, r, {0, infinity<double>}) == brute_force(spaced, r, {0, infinity<double>}));
    }
    CHECK(mismatches == 0);
    // No primitives: no hit.
    CHECK(by_bvh(Bvh<double>(std::span<const Aabb<double>>{}), same, ray, {0, infinity<double>}).t == infinity<double>);
}

TEST_CASE("work per ray grows as log N: nodes visited from 10^2 to 10^4 balls")
{
    Random rng(9u, 2u);
    double visits_per_ray[2] = {0, 0};
    for (int j = 0; j < 2; ++j) {
        const int n = j == 0 ? 100 : 10000;
        const auto balls = random_balls<float>(n, rng, 10.0f, 2.0f / std::cbrt(float(n)));
        const Bvh<float> bvh(boxes_of(balls));
        int visits = 0;
        for (int i = 0; i < 20000; ++i) (void)by_bvh(bvh, balls, {{-20, 0, 0}, normalize(Vec3<float>(20, 10 * rng.uniform<float>() - 5, 10 * rng.uniform<float>() - 5))}, {0, infinity<float>}, &visits);
        visits_per_ray[j] = visits / 20000.0;
    }
    MESSAGE("primitives tested per ray: ", visits_per_ray[0], " at 10^2, ", visits_per_ray[1], " at 10^4");
    CHECK(visits_per_ray[0] > 0.2);
    CHECK(visits_per_ray[1] < 4 * visits_per_ray[0]); // a linear scan: 100x
}

TEST_CASE("bad input is refused, naming it")
{
    std::vector<Aabb<float>> boxes{{{0, 0, 0}, {1, 1, 1}}, Aabb<float>::universe()};
    CHECK_THROWS_WITH_AS(Bvh<float>{boxes}, doctest::Contains("Bvh primitive 1 has no finite box"), std::invalid_argument);
    boxes[1] = {{0, std::nanf(""), 0}, {1, 1, 1}};
    CHECK_THROWS_WITH_AS(Bvh<float>{boxes}, doctest::Contains("Bvh primitive 1 has no finite box"), std::invalid_argument);
    boxes[1] = Aabb<float>{};
    CHECK_THROWS_WITH_AS(Bvh<float>{boxes}, doctest::Contains("Bvh primitive 1"), std::invalid_argument);
    boxes.pop_back();
    CHECK_THROWS_WITH_AS((Bvh<float>{boxes, {.max_leaf_size = 0}}), doctest::Contains("max_leaf_size must be >= 1, got 0"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((Bvh<float>{boxes, {.bins = 1}}), doctest::Contains("bins must be in [2, 256], got 1"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((Bvh<float>{boxes, {.split = BvhSplit(7)}}), doctest::Contains("split must be binned or sweep, got 7"), std::invalid_argument);
    CHECK_THROWS_WITH_AS((Bvh<float>{boxes, {.leaf_block = 0}}), doctest::Contains("leaf_block must be >= 1, got 0"), std::invalid_argument);
}

TEST_CASE("a leaf of up to leaf_block primitives costs one test: four cubes far apart make one leaf with blocks of four, four leaves without")
{
    // Unit cubes at x = 0, 10, 20, 30. The root's box has half area 31 + 1 + 31 = 63,
    // each half's 11 + 1 + 11 = 23. One test at a time, a leaf of four costs 4 and the
    // split 1 + (23 * 2 + 23 * 2) / 63 = 2.46 (and a pair 2 against 1 + (3 + 3) / 23):
    // four leaves of one. A block of four costs 1, the split 1 + (23 + 23) / 63: a leaf.
    std::vector<Aabb<float>> cubes;
    for (int i = 0; i < 4; ++i) cubes.push_back({{10.0f * float(i), 0, 0}, {10.0f * float(i) + 1, 1, 1}});
    for (const int block : {1, 4}) {
        const Bvh<float> bvh(cubes, {.max_leaf_size = 4, .leaf_block = block});
        std::vector<std::uint32_t> leaves;
        for (const auto& node : bvh.nodes())
            for (int c = 0; c < BvhNode<float>::width; ++c)
                if (node.used(c) && node.leaf(c)) leaves.push_back(node.count[std::size_t(c)]);
        CHECK(leaves == (block == 1 ? std::vector<std::uint32_t>{1, 1, 1, 1} : std::vector<std::uint32_t>{4}));
        // The root node, and four leaves of area 3 / 63 and one test each, or one leaf of
        // the root's area and one test.
        CHECK(bvh.sah_cost() == doctest::Approx(block == 1 ? 1 + 4 * 3.0 / 63 : 2.0));
    }
}

namespace {

/// Built and queried at compile time: 8 unit cubes along x, a ray down the row.
template <int W>
constexpr int constexpr_query()
{
    std::array<Aabb<double>, 8> boxes{};
    for (int i = 0; i < 8; ++i) boxes[std::size_t(i)] = {{2.0 * i, 0, 0}, {2.0 * i + 1, 1, 1}};
    const Bvh<double, W> bvh(boxes, {.max_leaf_size = 1});
    Interval<double> range{0, infinity<double>};
    int first = -1;
    bvh.traverse({{-1, 0.5, 0.5}, {1, 0, 0}}, range, [&](std::uint32_t i, Interval<double>& r) {
        const double t = 2.0 * i + 1; // where the ray enters cube i
        if (t < r.max) r.max = t, first = int(i);
        return false;
    });
    return first;
}
// libstdc++ 12 default-fills a new vector of a trivial type through storage whose
// lifetime has not begun, which clang's constant evaluation refuses (g++'s and libc++'s
// are fine): there the same query is checked at run time below.
#if !(defined(__clang__) && defined(__GLIBCXX__))
static_assert(constexpr_query<4>() == 0);
static_assert(constexpr_query<8>() == 0);
#endif

} // namespace

TEST_CASE("the compile-time query's answer, at run time")
{
    CHECK(constexpr_query<4>() == 0);
    CHECK(constexpr_query<8>() == 0);
}
