// SPDX-License-Identifier: MIT
// CSG against brute force: the crossing list of a nested CSG tree must agree with
// inside/outside found by evaluating the children's implicit functions (contains) at
// points along the ray, away from the boundaries.
#include <prism/csg/csg_node.hpp>
#include <prism/prism.hpp>

#include "../support.hpp"

#include <string>
#include <vector>

using namespace prism;

namespace {

template <Scalar T>
Vec3<T> random_in(Random& rng, T extent)
{
    return test::random_point<T>(rng, extent);
}

template <Scalar T>
Sphere<T> random_sphere(Random& rng)
{
    return Sphere<T>(random_in<T>(rng, T(0.5)), T(0.8) + T(0.8) * rng.uniform<T>());
}

template <Scalar T>
Box<T> random_box(Random& rng)
{
    const Vec3<T> centre = random_in<T>(rng, T(0.5));
    const Vec3<T> half = Vec3<T>{T(0.4) + rng.uniform<T>(), T(0.4) + rng.uniform<T>(), T(0.4) + rng.uniform<T>()};
    return Box<T>(centre - half, centre + half);
}

/// A smaller box, for the part a difference takes away.
template <Scalar T>
Box<T> random_bite(Random& rng)
{
    const Vec3<T> centre = random_in<T>(rng, T(0.8));
    const Vec3<T> half = Vec3<T>{T(0.2) + rng.uniform<T>(), T(0.2) + rng.uniform<T>(), T(0.2) + rng.uniform<T>()} * T(0.6);
    return Box<T>(centre - half, centre + half);
}

template <Scalar T>
Plane<T> random_plane(Random& rng)
{
    return Plane<T>::through(random_in<T>(rng, T(0.5)), test::random_direction<T>(rng));
}

template <Scalar T>
Transform<T> random_placement(Random& rng)
{
    return Transform<T>::rotate(T(360) * rng.uniform<T>(), test::random_direction<T>(rng)).then(Transform<T>::translate(random_in<T>(rng, T(0.4))));
}

/// Every kind of quadric, bounded and not, convex and not, randomly placed.
template <Scalar T>
Quadric<T> random_quadric(Random& rng)
{
    const auto u = [&rng] { return T(0.6) + rng.uniform<T>(); };
    const Vec3<T> o(T(0));
    const Vec3<T> z{T(0), T(0), T(1)};
    switch (static_cast<int>(rng.uniform<float>() * 6)) {
    case 0: return Quadric<T>::ellipsoid(o, {u(), u(), u()}).transformed(random_placement<T>(rng));
    case 1: return Quadric<T>::cylinder(o, z, T(0.5) * u()).transformed(random_placement<T>(rng));
    case 2: return Quadric<T>::cone(o, z, T(15) + T(40) * rng.uniform<T>()).transformed(random_placement<T>(rng));
    case 3: return Quadric<T>::hyperboloid_one_sheet(u(), u(), u()).transformed(random_placement<T>(rng));
    case 4: return Quadric<T>::hyperboloid_two_sheets(u(), u(), u()).transformed(random_placement<T>(rng));
    default: return Quadric<T>::elliptic_paraboloid(u(), u()).transformed(random_placement<T>(rng));
    }
}

// Three tree shapes, depth 3 and 4, using every operation at every level.
template <Scalar T>
auto tree_one(Random& rng) // (S | Q) - (B & Transformed<Q>)
{
    return difference_of(union_of(random_sphere<T>(rng), random_quadric<T>(rng)),
                         intersection_of(random_bite<T>(rng), Transformed(random_quadric<T>(rng), random_placement<T>(rng))));
}

template <Scalar T>
auto tree_two(Random& rng) // (B - (S & Transformed<B>)) | (Q & (S - P))
{
    return union_of(difference_of(random_box<T>(rng), intersection_of(random_sphere<T>(rng), Transformed(random_bite<T>(rng), random_placement<T>(rng)))),
                    intersection_of(random_quadric<T>(rng), difference_of(random_sphere<T>(rng), random_plane<T>(rng))));
}

template <Scalar T>
auto tree_three(Random& rng) // Transformed<S | (B - Q)> & ((S | S) - B)
{
    return intersection_of(Transformed(union_of(random_sphere<T>(rng), difference_of(random_box<T>(rng), random_quadric<T>(rng))),
                                       Transform<T>::scale({T(1.2), T(0.8), T(1)}).then(random_placement<T>(rng))),
                           difference_of(union_of(random_sphere<T>(rng), random_sphere<T>(rng)), random_bite<T>(rng)));
}

struct Tally {
    long rays = 0, rays_crossing = 0, crossings = 0, samples = 0, inside_samples = 0, mismatches = 0, order_errors = 0;
};

/// Check one ray over [0, length]: the flags alternate from inside_at_start, and
/// contains() at points spread over every span, `margin` away from its ends, matches.
template <class Tree, Scalar T>
void check_ray(const Tree& tree, const Ray<T>& ray, T length, T margin, Tally& tally)
{
    const auto c = tree.crossings(ray, {T(0), length});
    ++tally.rays;
    tally.crossings += static_cast<long>(c.size());
    tally.rays_crossing += !c.empty();
    bool state = c.inside_at_start;
    std::vector<T> ends{T(0)};
    std::vector<bool> states{state};
    for (const auto& x : c) {
        if (x.entering == state || x.t < ends.back()) ++tally.order_errors;
        state = x.entering;
        ends.push_back(x.t);
        states.push_back(state);
    }
    ends.push_back(length);
    bool mismatch = false;
    for (std::size_t s = 0; s + 1 < ends.size(); ++s) {
        const T a = ends[s] + margin, b = ends[s + 1] - margin;
        if (!(b > a)) continue;
        constexpr int per_span = 5;
        for (int k = 0; k < per_span; ++k) {
            const T t = a + (b - a) * (T(k) + T(0.5)) / T(per_span);
            ++tally.samples;
            tally.inside_samples += states[s];
            mismatch |= tree.contains(ray.at(t)) != states[s];
        }
    }
    tally.mismatches += mismatch;
}

template <Scalar T, class Make>
Tally brute_force(std::uint64_t seed, int trees, int rays_per_tree, T margin, Make&& make)
{
    Random rng(seed, 77u);
    Tally tally;
    for (int i = 0; i < trees; ++i) {
        const auto tree = make(rng);
        for (int r = 0; r < rays_per_tree; ++r) {
            // Origins in and around the tree, so many rays start inside a child.
            const Vec3<T> origin = random_in<T>(rng, T(1.6));
            check_ray(tree, Ray<T>{origin, test::random_direction<T>(rng)}, T(6), margin, tally);
        }
    }
    return tally;
}

void report(const std::string& name, const Tally& t)
{
    MESSAGE(name << ": " << t.rays << " rays (" << t.rays_crossing << " crossing a boundary), " << t.crossings << " crossings, "
                 << t.samples << " samples (" << t.inside_samples << " inside)");
    CHECK(t.mismatches == 0);
    CHECK(t.order_errors == 0);
    // The test means something: many rays cross the trees, and they are neither all
    // inside nor all outside.
    CHECK(t.rays_crossing > t.rays / 5);
    CHECK(t.inside_samples > t.samples / 10);
    CHECK(t.inside_samples < t.samples * 9 / 10);
}

} // namespace

TEST_CASE("CSG trees of depth 3 and 4 against brute-force inside tests: 0 mismatches over 1.5e5 rays (double)")
{
    // 3 tree shapes x 1000 trees x 50 rays = 150 000 rays.
    report("(S | Q) - (B & xQ)", brute_force<double>(1, 1000, 50, 1e-7, [](Random& r) { return tree_one<double>(r); }));
    report("(B - (S & xB)) | (Q & (S - P))", brute_force<double>(2, 1000, 50, 1e-7, [](Random& r) { return tree_two<double>(r); }));
    report("x(S | (B - Q)) & ((S | S) - B)", brute_force<double>(3, 1000, 50, 1e-7, [](Random& r) { return tree_three<double>(r); }));
}

TEST_CASE("the same in float, with a margin for float's rounding")
{
    report("(S | Q) - (B & xQ)", brute_force<float>(4, 200, 50, 2e-3f, [](Random& r) { return tree_one<float>(r); }));
    report("(B - (S & xB)) | (Q & (S - P))", brute_force<float>(5, 200, 50, 2e-3f, [](Random& r) { return tree_two<float>(r); }));
    report("x(S | (B - Q)) & ((S | S) - B)", brute_force<float>(6, 200, 50, 2e-3f, [](Random& r) { return tree_three<float>(r); }));
}

TEST_CASE("a CSG tree is a Shape of the summed capacity, nested to any depth")
{
    using Deep = Difference<Intersection<Sphere<float>, Quadric<float>>, Union<Box<float>, Transformed<Quadric<float>>>>;
    static_assert(Shape<Deep>);
    static_assert(Deep::max_crossings == 8);
    using Deeper = Union<Deep, Transformed<Deep>, Plane<float>>;
    static_assert(Deeper::max_crossings == 17);
    CHECK(Deeper::max_crossings == 17);
}

TEST_CASE("a ray leaving a CSG surface starts on the side it leaves by")
{
    // For every crossing of random rays through random trees, a ray spawned from it
    // into the solid must start inside, and one spawned out of it must start outside;
    // directions within 0.2 of the tangent plane, where an edge may be in the way, are left out.
    Random rng(8u, 8u);
    long checked = 0, wrong = 0;
    const auto probe = [&](const auto& tree) {
        for (int r = 0; r < 40; ++r) {
            const Vec3<double> origin = random_in<double>(rng, 1.6);
            const auto c = tree.crossings({origin, test::random_direction<double>(rng)}, {0.0, 6.0});
            for (const auto& x : c) {
                const Vec3<double> w = test::random_direction<double>(rng);
                const double along = dot(w, x.normal);
                if (std::abs(along) < 0.2) continue;
                const auto again = tree.crossings(spawn_ray(x.point, x.error, x.normal, w), {0.0, infinity<double>});
                ++checked;
                if (again.inside_at_start != (along < 0)) {
                    const auto o = spawn_ray(x.point, x.error, x.normal, w).origin;
                    MESSAGE("wrong start: point " << x.point.x << " " << x.point.y << " " << x.point.z << " normal " << x.normal.x << " "
                            << x.normal.y << " " << x.normal.z << " along " << along << " contains(origin) " << tree.contains(o)
                            << " err " << x.error.x << " " << x.error.y << " " << x.error.z);
                }
                wrong += again.inside_at_start != (along < 0);
            }
        }
    };
    for (int i = 0; i < 1000; ++i) {
        probe(tree_one<double>(rng));
        probe(tree_two<double>(rng));
        probe(tree_three<double>(rng));
    }
    MESSAGE(checked << " spawned rays");
    CHECK(checked > 10000);
    CHECK(wrong == 0);
}

// Regression: seen from 10^3, a CSG node of size 10^-3 is 16 steps of float t deep, and
// its children's crossings fell within a step of each other: a ball's exit and its
// hole's merged in the wrong order left slivers where there is nothing (122 hits lost
// and 72 gained of 32 000 rays, 261 of 49 796 spawned rays on the wrong side). The node
// now asks its children from a point near itself. What float t cannot hold is left out:
// a chord shorter than a step of t (6 10^-5, near the bead's rims or grazing it) enters
// and leaves at one t, and whether it is there at all is decided on a line moved by half
// a step of the coordinates near the node.
TEST_CASE("a float CSG node seen from 10^3 keeps its children's crossings in order")
{
    Random rng(33u, 12u);
    long spawned = 0, wrong_side = 0, lost = 0, phantom = 0, hits = 0, short_chords = 0;
    for (int shape = 0; shape < 16; ++shape) {
        // The bead of csg_quadrics at 10^-3: a ball bored by a quadric cylinder, and its
        // double twin from the float shape's own numbers.
        const Vec3<float> centre(test::random_point<double>(rng, 1.0));
        const auto size = float(1e-3), hole = float(1e-3 * (0.2 + 0.5 * rng.uniform<double>()));
        const Vec3<float> axis(test::random_direction<double>(rng));
        auto bead = difference_of(Sphere<float>(centre, size), Quadric<float>::cylinder(centre, axis, hole));
        test::through_memory(bead); // the twin from the float shapes' own numbers (see test::through_memory)
        const Sphere<float>& ball = bead.first();
        const Quadric<float>& cylinder = bead.second();
        const auto k = cylinder.coefficients();
        const auto twin = difference_of(Sphere<double>{Vec3<double>(ball.center()), double(ball.radius())},
                                        Quadric<double>({k.a, k.b, k.c, k.d, k.e, k.f, k.g, k.h, k.i, k.j}, Vec3<double>(cylinder.origin())));
        for (int i = 0; i < 2000; ++i) {
            const Vec3<double> dir = test::random_direction<double>(rng);
            const Vec3<double> from = Vec3<double>(centre) + 1.2e-3 * test::random_direction<double>(rng) * std::cbrt(rng.uniform<double>()) - 1e3 * dir;
            Ray<float> ray{Vec3<float>(from), Vec3<float>(dir)};
            test::through_memory(ray);
            const auto c = bead.crossings(ray, {0.0f, infinity<float>});
            const auto exact = twin.crossings({Vec3<double>(ray.origin), Vec3<double>(ray.direction)}, {0.0, infinity<double>});
            // A chord less than a step of t long, in either.
            const double step = double(next_float_up(1e3f) - 1e3f);
            bool short_chord = c.size() >= 2 && c[1].t == c[0].t;
            for (std::size_t e = 0; e + 1 < exact.size(); e += 2) short_chord |= exact[e + 1].t - exact[e].t < step;
            short_chords += short_chord;
            if (!short_chord) {
                hits += !exact.empty();
                lost += !exact.empty() && c.empty();
                phantom += exact.empty() && !c.empty();
            }
            if (c.empty() || short_chord) continue;
            const Vec3<float> d1 = normalize(ray.direction);
            for (const Vec3<float>& w : {d1, reflect(d1, c[0].facing_normal())}) {
                const float cos = dot(w, c[0].normal);
                if (!(std::abs(cos) > 1e-3f)) continue;
                ++spawned;
                wrong_side += bead.crossings<false>(spawn_ray(c[0].point, c[0].error, c[0].normal, w), {0.0f, infinity<float>}).inside_at_start != (cos < 0);
            }
        }
    }
    MESSAGE(hits, " hits of 32000 rays: lost ", lost, ", phantom ", phantom, "; ", wrong_side, " of ", spawned, " spawned rays on the wrong side; ",
            short_chords, " rays with a chord shorter than a step of t left out");
    CHECK(hits > 20000);
    CHECK(lost == 0);
    CHECK(phantom == 0);
    CHECK(spawned > 20000);
    CHECK(wrong_side == 0);
    CHECK(short_chords < 1600);
}

namespace {

/// Of the rays spawned (straight on and mirrored) from the first crossing of rays from 1000
/// sizes away at the bead of `size` placed 10^3 from the origin, how many start on the
/// wrong side of it, and how many were spawned.
template <Scalar T>
std::pair<long, long> bead_wrong_side_spawns(double size)
{
    Random rng(33u, 14u);
    long spawned = 0, wrong_side = 0;
    for (int shape = 0; shape < 8; ++shape) {
        const Vec3<T> centre(Vec3<double>(1e3, 0, 0) + test::random_point<double>(rng, 1.0));
        const T radius = T(size), hole = T(size * (0.2 + 0.5 * rng.uniform<double>()));
        const auto bead = difference_of(Sphere<T>(centre, radius), Quadric<T>::cylinder(centre, Vec3<T>(test::random_direction<double>(rng)), hole));
        for (int i = 0; i < 2000; ++i) {
            const Vec3<double> dir = test::random_direction<double>(rng);
            const Vec3<double> from = Vec3<double>(centre) + 1.2 * size * std::cbrt(rng.uniform<double>()) * test::random_direction<double>(rng) - 1e3 * size * dir;
            const Ray<T> ray{Vec3<T>(from), Vec3<T>(dir)};
            const auto c = bead.crossings(ray, {T(0), infinity<T>});
            if (c.empty()) continue;
            const Vec3<T> d = normalize(ray.direction);
            for (const Vec3<T>& w : {d, reflect(d, c[0].facing_normal())}) {
                const T cos = dot(w, c[0].normal);
                if (!(std::abs(cos) > T(1e-3))) continue;
                ++spawned;
                wrong_side += bead.template crossings<false>(spawn_ray(c[0].point, c[0].error, c[0].normal, w), {T(0), infinity<T>}).inside_at_start != (cos < 0);
            }
        }
    }
    return {wrong_side, spawned};
}

} // namespace

// What is left of a loss near a rim: near a rim, where the ball's surface and its hole's meet, a
// spawned ray leaves the surface it hit by that point's error bound along its normal, and
// may land past the other surface. In float the error is a coordinate step, so the share
// of spawns that do falls as the bead's size in steps grows; in double it is nil. (Stepping
// a wrong origin ahead along the new direction, checked against the node, was tried: it
// mends 58 % of them at the size of 10^-3, for a second node query on every CSG spawn.)
TEST_CASE("a bead placed 10^3 from the origin: spawned rays start on their side in double, and in float the more often the larger it is")
{
    const auto [wrong_double, spawned_double] = bead_wrong_side_spawns<double>(1e-3);
    MESSAGE("double, size 1e-3: ", wrong_double, " of ", spawned_double, " spawned rays on the wrong side");
    CHECK(spawned_double > 20000);
    CHECK(wrong_double == 0);
    long previous = 0;
    for (const double size : {1e-3, 1e-2, 1e-1}) {
        const auto [wrong, spawned] = bead_wrong_side_spawns<float>(size);
        MESSAGE("float, size ", size, ": ", wrong, " of ", spawned, " spawned rays on the wrong side");
        CHECK(spawned > 20000);
        CHECK(double(wrong) < 0.05 * double(spawned));
        if (size > 1e-3) CHECK(wrong * 5 < previous);
        previous = wrong;
    }
}

TEST_CASE("a CSG crossing's surface coordinates are those of the child it came from, through nesting and a transform")
{
    // A ball with a box bitten out of it, inside a union with a plane, moved: each
    // crossing's uv must be what its own primitive gives at that point.
    const Sphere<double> ball({0, 0, 0}, 1);
    const Box<double> bite({0.2, -2, -2}, {2, 2, 2});
    const Plane<double> floor({0, 1, 0}, -3);
    const auto place = Transform<double>::rotate_y(20).then(Transform<double>::translate({0.5, 0, 0}));
    using Bitten = Difference<Sphere<double>, Box<double>>;
    const Union<Transformed<Bitten>, Plane<double>> shape(Transformed<Bitten>(Bitten(ball, bite), place), floor);
    Random rng(8, 1);
    int from_ball = 0, from_bite = 0, from_floor = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3<double> target = Vec3<double>{0.5, -1, 0} + 2.0 * test::random_direction<double>(rng) * rng.uniform<double>();
        const Vec3<double> origin = target + 8.0 * test::random_direction<double>(rng);
        const auto all = shape.crossings({origin, target - origin}, {0, infinity<double>});
        if (all.empty()) continue;
        Crossing<double> c = all.front();
        add_coordinates(shape, c);
        REQUIRE(c.has_uv());
        // Which primitive's surface is it on? Ask each, in its own frame.
        const Vec3<double> local = place.inverse_point(c.point);
        Crossing<double> own = c;
        if (std::abs(c.point.y + 3) < 1e-9) {
            floor.coordinates(own);
            ++from_floor;
        } else if (std::abs(length(local) - 1) < 1e-9) {
            own.point = local;
            own.normal = normalize(local);
            ball.coordinates(own);
            ++from_ball;
        } else {
            own.point = local;
            own.normal = {-1, 0, 0}; // the bite's face x = 0.2, its own normal outward of the box
            bite.coordinates(own);
            ++from_bite;
        }
        CHECK(length(c.uv - own.uv) < 1e-9);
    }
    CHECK(from_ball > 100);
    CHECK(from_bite > 30);
    CHECK(from_floor > 100);
}

namespace {

/// The children's crossings merged by Roth's rule, written out plainly (no early end):
/// the slow twin of CsgNode::merged.
template <class Op, Shape A, Shape B, bool Surface>
Crossings<typename A::scalar_type, A::max_crossings + B::max_crossings> plain_merge(const A& a, const B& b, const Ray<typename A::scalar_type>& ray,
                                                                                 Interval<typename A::scalar_type> range)
{
    using T = typename A::scalar_type;
    const auto ca = a.template crossings<Surface>(ray, range);
    const auto cb = b.template crossings<Surface>(ray, range);
    Crossings<T, A::max_crossings + B::max_crossings> out;
    bool in_a = ca.inside_at_start, in_b = cb.inside_at_start;
    out.inside_at_start = Op::combine(in_a, in_b);
    bool inside = out.inside_at_start;
    std::size_t i = 0, j = 0;
    while (i < ca.size() || j < cb.size()) {
        const T t = j == cb.size() || (i < ca.size() && ca[i].t <= cb[j].t) ? ca[i].t : cb[j].t;
        const Crossing<T>* from_a = nullptr;
        const Crossing<T>* from_b = nullptr;
        for (; i < ca.size() && ca[i].t == t; ++i) in_a = ca[i].entering, from_a = &ca[i];
        for (; j < cb.size() && cb[j].t == t; ++j) in_b = cb[j].entering, from_b = &cb[j];
        if (Op::combine(in_a, in_b) == inside) continue;
        inside = !inside;
        Crossing<T> c = from_a != nullptr ? *from_a : *from_b;
        if (from_a == nullptr && Op::flips_second) c.normal = -c.normal, c.shading = -c.shading;
        if constexpr (Surface) c.path = c.path << 1 | (from_a == nullptr ? 1u : 0u);
        c.entering = inside;
        out.push_back(c);
    }
    return out;
}

template <class Op, Shape A, Shape B>
int merge_mismatches(Random& rng, const A& a, const B& b, int rays)
{
    using T = typename A::scalar_type;
    const CsgNode<Op, A, B> node(a, b);
    int differ = 0;
    for (int i = 0; i < rays; ++i) {
        const Vec3<T> eye = random_in<T>(rng, T(3));
        const Ray<T> ray{eye, normalize(random_in<T>(rng, T(1.2)) - eye)};
        const Interval<T> range{T(2) * rng.uniform<T>() - T(1), T(1) + T(4) * rng.uniform<T>()};
        const auto lean = node.template crossings<false>(ray, range), lean_twin = plain_merge<Op, A, B, false>(a, b, ray, range);
        const auto full = node.crossings(ray, range), full_twin = plain_merge<Op, A, B, true>(a, b, ray, range);
        bool same = lean.size() == lean_twin.size() && lean.inside_at_start == lean_twin.inside_at_start && full.size() == full_twin.size() &&
                    full.inside_at_start == full_twin.inside_at_start;
        for (std::size_t k = 0; same && k < lean.size(); ++k) same = lean[k].t == lean_twin[k].t && lean[k].entering == lean_twin[k].entering;
        for (std::size_t k = 0; same && k < full.size(); ++k)
            same = full[k].t == full_twin[k].t && full[k].entering == full_twin[k].entering && full[k].path == full_twin[k].path &&
                   full[k].normal == full_twin[k].normal;
        differ += !same;
    }
    return differ;
}

} // namespace

TEST_CASE("an intersection or a difference ends early for a ray outside its first child, with the plain merge's answer")
{
    // Near the origin, where the node asks its children directly: the early end (nothing
    // of the second child is asked when the ray stays outside the first) must give the
    // plain merge's crossings, bit for bit, and the same inside-at-start, for rays that
    // miss the first child, start in it, or graze it.
    Random rng(29u, 4u);
    int differ = 0, missed_first = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const auto ball = random_sphere<double>(rng);
        const auto bite = random_quadric<double>(rng);
        differ += merge_mismatches<DifferenceOp>(rng, ball, bite, 50);
        differ += merge_mismatches<IntersectionOp>(rng, random_box<double>(rng), bite, 50);
        differ += merge_mismatches<DifferenceOp>(rng, random_sphere<float>(rng), random_bite<float>(rng), 50);
        for (int i = 0; i < 50; ++i) {
            const Vec3<double> eye = random_in<double>(rng, 3.0);
            const auto c = ball.crossings<false>(Ray<double>{eye, normalize(random_in<double>(rng, 1.2) - eye)}, {0.0, infinity<double>});
            missed_first += c.empty() && !c.inside_at_start;
        }
    }
    CHECK(differ == 0);
    CHECK(missed_first > 1000); // (the early end is taken)
}
