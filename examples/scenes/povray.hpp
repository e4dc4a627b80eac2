// SPDX-License-Identifier: MIT
// From POV-Ray's coordinates to prism's.
//
// POV-Ray is left-handed with y up and its camera looks along +z; prism is right-handed.
// Negating z (the reflection S = diag(1, 1, -1)) maps one onto the other with the same
// picture. A transform written in POV-Ray's coordinates becomes S M S in prism's.
#pragma once

#include <prism/prism.hpp>

namespace scenes::pov {

/// A POV-Ray point or vector in prism's coordinates.
template <prism::Scalar T>
prism::Vec3<T> point(double x, double y, double z)
{
    return {T(x), T(y), T(-z)};
}

/// S itself: moves a shape written in POV-Ray's coordinates (such as a quadric's
/// coefficients) into prism's.
template <prism::Scalar T>
prism::Transform<T> mirror()
{
    return prism::Transform<T>::scale({T(1), T(1), T(-1)});
}

/// A transform written in POV-Ray's coordinates, as prism applies it.
template <prism::Scalar T>
prism::Transform<T> transform(const prism::Transform<T>& in_povray)
{
    return mirror<T>().then(in_povray).then(mirror<T>());
}

/// POV-Ray's `rotate <x, y, z>`: about x, then y, then z, by the standard rotation
/// matrices in POV-Ray's own coordinates (its left-hand rule in a left-handed frame).
template <prism::Scalar T>
prism::Transform<T> rotate(double x, double y, double z)
{
    using X = prism::Transform<T>;
    return X::rotate_x(T(x)).then(X::rotate_y(T(y))).then(X::rotate_z(T(z)));
}

template <prism::Scalar T>
prism::Transform<T> translate(double x, double y, double z)
{
    return prism::Transform<T>::translate({T(x), T(y), T(z)});
}

/// A POV-Ray light of colour c (no fading): POV-Ray's diffuse has no 1/pi, prism's
/// Lambertian BRDF does, so the intensity is pi c with no falloff.
template <prism::Scalar T>
prism::PointLight<T> light(const prism::Vec3<T>& position, const prism::Rgb<T>& colour)
{
    return {.position = position, .intensity = prism::pi<T> * colour, .falloff = prism::Falloff::none};
}

} // namespace scenes::pov
