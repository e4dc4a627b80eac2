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
