// SPDX-License-Identifier: MIT
// Four spheres of four materials in a row over a checkerboard, in sunlight from behind the
// camera: the metals and the anodised titanium of the gallery, each beside its plain version.
#pragma once

#include <prism/prism.hpp>

namespace scenes {

/// The camera that frames the row.
inline prism::Camera<float> sphere_row_camera()
{
    return {.position = {0, 2.4f, 8.5f}, .look_at = {0, 0.9f, 0}, .up = {0, 1, 0}, .fov = 62};
}

/// Spheres of `materials` 2.2 apart, and the `extra` objects (something for them to reflect).
template <class Material, class... Extra>
auto sphere_row(const Material (&materials)[4], Extra... extra)
{
    using namespace prism;
    using T = float;
    Scene scene{Lights{DirectionalLight<T>{.direction = {T(0.35), T(-0.8), T(0.5)}, .irradiance = Rgb<T>(T(3))}},
                Object{Plane<T>({T(0), T(1), T(0)}, T(0)),
                       Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(T(0.85)), .odd = Rgb<T>(T(0.12)), .size = T(1)}}},
                Object{Sphere<T>({T(-3.3), T(1), T(0)}, T(1)), materials[0]},
                Object{Sphere<T>({T(-1.1), T(1), T(0)}, T(1)), materials[1]},
                Object{Sphere<T>({T(1.1), T(1), T(0)}, T(1)), materials[2]},
                Object{Sphere<T>({T(3.3), T(1), T(0)}, T(1)), materials[3]},
                std::move(extra)...};
    scene.background = {T(0.5), T(0.65), T(0.9)};
    scene.ambient = Rgb<T>(T(0.15));
    return scene;
}

} // namespace scenes
