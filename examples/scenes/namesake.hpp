// SPDX-License-Identifier: MIT
// The project's namesake: a 60-degree prism of Schott F2 flint (CSG of five half-spaces) at
// its minimum deviation, lit through a slit by the sun (rainbow_scene) or, in a dark hazy
// room, by a narrow beam from a projector (hazy_scene): examples/prism_rainbow.cpp renders
// them, bench/prism_haze.cpp times the hazy one by each estimator.
#pragma once

#include <prism/prism.hpp>

#include <cmath>

namespace scenes::namesake {

using T = float;
using prism::Vec3;

/// Rotate (x, y) by `angle` about the z axis.
inline Vec3<T> rotated(const Vec3<T>& v, T angle)
{
    return {v.x * std::cos(angle) - v.y * std::sin(angle), v.x * std::sin(angle) + v.y * std::cos(angle), v.z};
}

constexpr T pi = prism::pi<T>;
constexpr T tilt = T(-34) * pi / T(180); ///< the whole set-up turned so that the sunbeam descends
const Vec3<T> centre{T(0), T(4.2), T(0)};  ///< where the prism's base centre sits

/// A prism of apex 60 degrees and side 2, 3 deep along z, apex up before the tilt.
inline auto prism_solid()
{
    using namespace prism;
    const T half = T(1), height = std::sqrt(T(3));
    const Vec3<T> left = rotated({-std::sqrt(T(3)) / 2, T(0.5), 0}, tilt), right = rotated({std::sqrt(T(3)) / 2, T(0.5), 0}, tilt),
                  base = rotated({0, -1, 0}, tilt);
    const Vec3<T> a = centre + rotated({-half, 0, 0}, tilt), b = centre + rotated({half, 0, 0}, tilt), apex = centre + rotated({0, height, 0}, tilt);
    const Vec3<T> lo = component_min(component_min(a, b), apex) - Vec3<T>(T(0.01)), hi = component_max(component_max(a, b), apex) + Vec3<T>(T(0.01));
    return intersection_of(Plane<T>::through(a, left), Plane<T>::through(b, right), Plane<T>::through(a, base),
                           Box<T>({lo.x, lo.y, T(-1.5)}, {hi.x, hi.y, T(1.5)}));
}

/// Sunlight entering the prism's left face at the minimum-deviation angle for F2's d line.
inline Vec3<T> sunbeam()
{
    const T theta1 = std::asin(T(prism::glass::f2<double>.index(prism::fraunhofer::d)) * T(0.5));
    const Vec3<T> inward = rotated({std::sqrt(T(3)) / 2, T(-0.5), 0}, tilt), along = rotated({T(0.5), std::sqrt(T(3)) / 2, 0}, tilt);
    return std::cos(theta1) * inward + std::sin(theta1) * along;
}

template <class Glass>
auto rainbow_scene(const Glass& glass)
{
    using namespace prism;
    const Vec3<T> beam = sunbeam();
    // A black screen across the beam, 3 before the prism's left face, with a slit 0.25
    // wide aimed at the face's middle: a box with a slot cut out, turned with the beam.
    const Vec3<T> face_middle = centre + rotated({T(-0.5), std::sqrt(T(3)) / 2 * T(0.5), 0}, tilt);
    const Vec3<T> slit = face_middle - T(3) * beam;
    const T screen_degrees = std::atan2(beam.y, beam.x) * T(180) / pi; // the screen is normal to the beam
    const Transform<T> to_screen = Transform<T>::rotate_z(screen_degrees).then(Transform<T>::translate(slit));
    auto screen = Transformed{difference_of(Box<T>({T(-0.05), T(-40), T(-1000)}, {T(0.05), T(40), T(1000)}),
                                            Box<T>({T(-0.1), T(-0.125), T(-1)}, {T(0.1), T(0.125), T(1)})),
                              to_screen};
    // The sun, and a dim lamp high above on this side of the screen, so the room shows.
    Scene scene{Lights{DirectionalLight<T>{.direction = beam, .irradiance = Rgb<T>(T(12))},
                       PointLight<T>{.position = {T(3), T(12), T(8)}, .intensity = Rgb<T>(T(12))}},
                Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.85))}, .kd = 1, .ka = 1}},
                Object{std::move(screen), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.03))}, .kd = 1, .ka = 1}},
                Object{prism_solid(), glass}};
    scene.background = {T(0.01), T(0.01), T(0.015)};
    return scene;
}

/// The prism alone in a dark hazy room, lit by a narrow white beam aimed at its left face at
/// F2's minimum deviation, from a projector 6 away.
inline auto hazy_scene()
{
    using namespace prism;
    const Vec3<T> beam = sunbeam();
    const Vec3<T> face_middle = centre + rotated({T(-0.5), std::sqrt(T(3)) / 2 * T(0.5), 0}, tilt);
    return Scene{Lights{SpotLight<T>{.position = face_middle - T(6) * beam, .direction = beam, .intensity = Rgb<T>(T(50000)), .inner_angle = T(0.6),
                                     .outer_angle = T(0.8)}},
                 Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.85))}, .kd = 1, .ka = 0}},
                 Object{prism_solid(), DispersiveDielectric<T>{.glass = glass::f2<double>}}};
}


/// The camera both scenes are seen by.
inline prism::Camera<T> camera()
{
    return {.position = {T(-1.5), T(8.5), T(9)}, .look_at = {T(1.4), T(2.4), T(0)}, .up = {0, 1, 0}, .fov = 50};
}

/// The hazy room's air: 8 % of the light scattered per unit length, mostly forward, none
/// absorbed; the camera stands outside it.
inline prism::FilledAir<prism::Fog<T>> haze()
{
    return {.medium = {.scattering = prism::Rgb<T>(T(0.08)), .phase = {.g = T(0.5)}}, .region = {{-12, 0, -10}, {14, 7, 6}}};
}

} // namespace scenes::namesake
