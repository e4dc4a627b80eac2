// SPDX-License-Identifier: MIT
// Helpers shared by the tests: random directions and points from fixed seeds.
#pragma once

#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include "effort.hpp"
#include "through_memory.hpp"

namespace test {

/// Uniform direction on the unit sphere (z = 1 - 2u, phi = 2 pi v).
template <prism::Scalar T>
prism::Vec3<T> random_direction(prism::Random& rng)
{
    const T z = T(1) - T(2) * rng.uniform<T>();
    const T r = std::sqrt(std::max(T(0), T(1) - z * z));
    const T phi = T(2) * prism::pi<T> * rng.uniform<T>();
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// Uniform point in the cube [-extent, extent]^3.
template <prism::Scalar T>
prism::Vec3<T> random_point(prism::Random& rng, T extent)
{
    return {extent * (T(2) * rng.uniform<T>() - T(1)), extent * (T(2) * rng.uniform<T>() - T(1)),
            extent * (T(2) * rng.uniform<T>() - T(1))};
}

/// A direction on the hemisphere around n.
template <prism::Scalar T>
prism::Vec3<T> random_hemisphere(prism::Random& rng, const prism::Vec3<T>& n)
{
    const prism::Vec3<T> d = random_direction<T>(rng);
    return prism::dot(d, n) < T(0) ? -d : d;
}

} // namespace test

namespace test {

/// One try of pbrt-v4's TestReintersectConvex, for any convex shape with a point inside
/// it: a ray from a random point 5 units from there hits it, and a ray leaving the hit
/// point to the side it came from (the outside of a convex solid) must never cross the
/// shape again. Whether it does.
template <class S, prism::Scalar T>
bool reintersects(prism::Random& rng, const S& shape, const prism::Vec3<T>& inside)
{
    const prism::Vec3<T> eye = inside + random_direction<T>(rng) * T(5);
    const auto crossings = shape.crossings({eye, prism::normalize(inside - eye)}, {T(0), prism::infinity<T>});
    if (crossings.empty()) return false;
    const prism::Crossing<T>& hit = crossings.front();
    const prism::Vec3<T> w = random_hemisphere<T>(rng, hit.facing_normal());
    const prism::Ray<T> leaving = prism::spawn_ray(hit.point, hit.error, hit.normal, w);
    return !shape.crossings(leaving, {T(0), prism::infinity<T>}).empty();
}

/// reintersects, `count` times: make(rng) returns a shape and a point inside it, and
/// `rays_per_shape` tries go to each (more for shapes slow to build, as meshes).
/// Returns the number of self-hits.
template <class Make>
int reintersections(prism::Random& rng, int count, Make&& make, int rays_per_shape = 1)
{
    int self_hits = 0;
    for (int i = 0; i < count; ++i) {
        const auto [shape, inside] = make(rng);
        for (int j = 0; j < rays_per_shape; ++j) self_hits += reintersects(rng, shape, inside);
    }
    return self_hits;
}

} // namespace test

namespace test {

/// Where a float shape and the same shape evaluated in double disagree on whether a ray
/// crosses it at all: a hit the float shape loses, or one it reports where there is none.
struct Disagreements {
    int lost = 0;    ///< the double evaluation crosses, the float shape does not
    int phantom = 0; ///< the float shape crosses, the double evaluation does not
    int hits = 0;    ///< rays the double evaluation says cross
};

/// `rays` float rays from `distance` away, aimed at points within 1.2 `size` of `centre`,
/// at `shape` (float) and its exact `twin` (double, built from the float shape's own
/// numbers, so the same surface), each given the float ray's exact values.
template <class F, class D>
Disagreements far_disagreements(const F& shape, const D& twin, prism::Vec3<double> centre, double size, double distance, int rays, prism::Random& rng)
{
    Disagreements out;
    for (int i = 0; i < rays; ++i) {
        const prism::Vec3<double> dir = random_direction<double>(rng);
        const prism::Vec3<double> target = centre + 1.2 * size * random_direction<double>(rng) * std::cbrt(rng.uniform<double>());
        const prism::Vec3<double> from = target - distance * dir;
        prism::Ray<float> ray{{float(from.x), float(from.y), float(from.z)}, {float(dir.x), float(dir.y), float(dir.z)}};
        through_memory(ray);
        const bool f = !shape.crossings(ray, {0.0f, prism::infinity<float>}).empty();
        const bool d = !twin.crossings(prism::Ray<double>{prism::Vec3<double>(ray.origin), prism::Vec3<double>(ray.direction)}, {0.0, prism::infinity<double>}).empty();
        out.hits += d;
        out.lost += d && !f;
        out.phantom += f && !d;
    }
    return out;
}

} // namespace test

#include <exception>
#include <new>
#include <string>

namespace test {

/// The mean of test::samples(n) estimates integrator.radiance(ray, rng).x from one stream
/// (an eighth of n under a sanitizer: tests/effort.hpp).
template <class Integrator, class Ray>
double mean_radiance(const Integrator& integrator, const Ray& ray, long n, prism::Random rng)
{
    n = samples(n);
    double sum = 0;
    for (long i = 0; i < n; ++i) sum += integrator.radiance(ray, rng).x;
    return sum / double(n);
}

/// Whether this build runs under a sanitizer, which keeps its own operator new (so
/// tests/main.cpp does not replace it, and allocation_budget has no effect).
constexpr bool sanitized = PRISM_TEST_SANITIZED;

/// Bytes that operator new may still hand out on this thread before it throws
/// std::bad_alloc, or -1 for no limit (tests/main.cpp replaces operator new to count; a
/// refusal leaves 1 MiB for what follows, as a machine out of memory has for a message).
inline thread_local long long allocation_budget = -1;

/// Run `reader` with only `budget` bytes to allocate, and say what it threw:
/// "allocation_error: <what>" for prism's, "bad_alloc: <what>" for a bare one, "other:
/// <what>" for anything else, "returned" if it returned.
template <class F>
std::string thrown_with_memory_short(std::size_t budget, F&& reader)
{
    std::exception_ptr thrown;
    allocation_budget = static_cast<long long>(budget);
    try {
        reader();
    } catch (...) {
        thrown = std::current_exception();
    }
    allocation_budget = -1; // before anything here allocates
    if (!thrown) return "returned";
    try {
        std::rethrow_exception(thrown);
    } catch (const prism::allocation_error& e) {
        return std::string("allocation_error: ") + e.what();
    } catch (const std::bad_alloc& e) {
        return std::string("bad_alloc: ") + e.what();
    } catch (const std::exception& e) {
        return std::string("other: ") + e.what();
    }
}

} // namespace test
