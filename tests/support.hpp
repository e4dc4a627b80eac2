// SPDX-License-Identifier: MIT
// Helpers shared by the tests: random directions and points from fixed seeds.
#pragma once

#include <prism/prism.hpp>

#include <doctest/doctest.h>

namespace test {

/// Uniform direction on the unit sphere (z = 1 - 2u, phi = 2 pi v).
template <prism::Scalar T>
prism::Vec3<T> random_direction(prism::Pcg32& rng)
{
    const T z = T(1) - T(2) * rng.uniform<T>();
    const T r = std::sqrt(std::max(T(0), T(1) - z * z));
    const T phi = T(2) * prism::pi<T> * rng.uniform<T>();
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// Uniform point in the cube [-extent, extent]^3.
template <prism::Scalar T>
prism::Vec3<T> random_point(prism::Pcg32& rng, T extent)
{
    return {extent * (T(2) * rng.uniform<T>() - T(1)), extent * (T(2) * rng.uniform<T>() - T(1)),
            extent * (T(2) * rng.uniform<T>() - T(1))};
}

/// A direction on the hemisphere around n.
template <prism::Scalar T>
prism::Vec3<T> random_hemisphere(prism::Pcg32& rng, const prism::Vec3<T>& n)
{
    const prism::Vec3<T> d = random_direction<T>(rng);
    return prism::dot(d, n) < T(0) ? -d : d;
}

} // namespace test

namespace test {

/// pbrt-v4's TestReintersectConvex, for any convex shape: `count` times, make(rng)
/// returns a shape and a point inside it; a ray from a random point 5 units from there
/// hits it, and a ray leaving the hit point to the side it came from (the outside of a
/// convex solid) must never cross the shape again. Returns the number of self-hits.
template <class Make>
int reintersections(prism::Pcg32& rng, int count, Make&& make)
{
    using Placed = decltype(make(rng));
    using T = typename decltype(Placed::first)::scalar_type;
    int self_hits = 0;
    for (int i = 0; i < count; ++i) {
        const auto [shape, inside] = make(rng);
        const prism::Vec3<T> eye = inside + random_direction<T>(rng) * T(5);
        const auto crossings = shape.crossings({eye, prism::normalize(inside - eye)}, {T(0), prism::infinity<T>});
        if (crossings.empty()) continue;
        const prism::Crossing<T>& hit = crossings.front();
        const prism::Vec3<T> w = random_hemisphere<T>(rng, hit.facing_normal());
        const prism::Ray<T> leaving = prism::spawn_ray(hit.point, hit.error, hit.normal, w);
        self_hits += !shape.crossings(leaving, {T(0), prism::infinity<T>}).empty();
    }
    return self_hits;
}

} // namespace test
