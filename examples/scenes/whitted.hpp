// SPDX-License-Identifier: MIT
// The classic Whitted (1980) picture: a glass and a mirror sphere over a checkerboard.
#pragma once

#include <prism/geometry/plane.hpp>
#include <prism/geometry/sphere.hpp>
#include <prism/light/directional_light.hpp>
#include <prism/material/conductor.hpp>
#include <prism/material/dielectric.hpp>
#include <prism/material/diffuse.hpp>
#include <prism/material/texture.hpp>
#include <prism/optics/fresnel.hpp>
#include <prism/scene/camera.hpp>
#include <prism/scene/scene.hpp>

namespace scenes {

template <prism::Scalar T>
prism::Camera<T> whitted_camera()
{
    return {.position = {T(0), T(2.0), T(7.5)}, .look_at = {T(0), T(1.1), T(0)}, .up = {T(0), T(1), T(0)}, .fov = T(50)};
}

template <prism::Scalar T, class Fresnel = prism::ExactFresnel>
auto whitted_scene()
{
    using namespace prism;
    Scene scene{
        // Sunlight from the upper left, behind the camera: E = 3 W/m^2 facing it, so a
        // floor lit at cos = 0.8 shows about 0.76 of its albedo.
        Lights{DirectionalLight<T>{.direction = {T(0.45), T(-0.8), T(-0.4)}, .irradiance = Rgb<T>(T(3))}},
        Object{Plane<T>({T(0), T(1), T(0)}, T(0)),
               Diffuse<T, Checker<T>>{.albedo = {.even = {T(0.85), T(0.15), T(0.1)}, .odd = {T(0.9), T(0.8), T(0.2)}, .size = T(1)},
                                      .kd = T(1), .ka = T(1)}},
        Object{Sphere<T>({T(0.4), T(1.2), T(1.6)}, T(1.2)),
               Dielectric<T, Fresnel>{.ior = T(1.5), .interior = {.absorption = {T(0.05), T(0.02), T(0.01)}}}},
        Object{Sphere<T>({T(-1.9), T(1.1), T(-1.6)}, T(1.1)), Mirror<T>{{.kr = Rgb<T>(T(0.9))}}},
        Object{Sphere<T>({T(2.6), T(0.8), T(-1.2)}, T(0.8)), Diffuse<T>{.albedo = {.color = {T(0.15), T(0.3), T(0.8)}}}},
    };
    scene.background = {T(0.35), T(0.55), T(0.85)};
    scene.ambient = Rgb<T>(T(0.12));
    return scene;
}

} // namespace scenes
