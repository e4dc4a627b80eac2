// SPDX-License-Identifier: MIT
// shared/scenes/csg_quadrics.pov in prism: a sphere bored by a quadric cylinder, a
// two-sphere lens, a three-sphere union and a rotated general-quadric ellipsoid on a
// checkered floor, two lights. Every number below is the .pov file's, in POV-Ray's
// coordinates, converted by scenes/povray.hpp.
#pragma once

#include "povray.hpp"

#include <prism/prism.hpp>

namespace scenes {

template <prism::Scalar T>
prism::Camera<T> csg_quadrics_camera()
{
    return {.position = pov::point<T>(0, 3.2, -7.5), .look_at = pov::point<T>(0, 0.9, 0.5), .up = {T(0), T(1), T(0)}, .fov = T(50)};
}

/// The .pov file's two lights: point lights of colour 0.9 and 0.4.
template <prism::Scalar T>
auto csg_quadrics_lights()
{
    return prism::Lights{pov::light<T>(pov::point<T>(-4, 8, -6), prism::Rgb<T>(T(0.9))), pov::light<T>(pov::point<T>(5, 6, -3), prism::Rgb<T>(T(0.4)))};
}

/// The same lights as POV-Ray's area lights (bench/vs_povray.py writes the .pov file's
/// copy): `area_light <1.5, 0, 0>, <0, 0, 1.5>, 5, 5 adaptive 1` on each, no jitter.
template <prism::Scalar T>
auto csg_quadrics_area_lights()
{
    const auto grid = [](const prism::PointLight<T>& light) {
        return prism::PointGridLight<T>{.light = light, .axis1 = pov::point<T>(1.5, 0, 0), .axis2 = pov::point<T>(0, 0, 1.5), .size1 = 5, .size2 = 5,
                                        .adaptive = 1};
    };
    return prism::Lights{grid(pov::light<T>(pov::point<T>(-4, 8, -6), prism::Rgb<T>(T(0.9)))),
                         grid(pov::light<T>(pov::point<T>(5, 6, -3), prism::Rgb<T>(T(0.4))))};
}

/// The scene under `lights` (by default the .pov file's own).
template <prism::Scalar T, class LightList = decltype(csg_quadrics_lights<T>())>
auto csg_quadrics_scene(LightList lights = csg_quadrics_lights<T>())
{
    using namespace prism;
    // finish { ambient 0 diffuse 0.7 phong 0.5 phong_size 40 }
    const auto plastic = [](T r, T g, T b) {
        return Diffuse<T>{.albedo = {.color = {r, g, b}}, .kd = T(0.7), .ka = T(0), .phong = T(0.5), .phong_size = T(40)};
    };

    // Shapes inside pov::transform are in the object's own coordinates, z negated like
    // the world's; the sphere, the z-axis cylinder and the lens are symmetric in z.

    // 1) unit sphere minus the quadric cylinder x^2 + y^2 = 0.45^2, rotate <-30,-20,0>, translate <-2.3,1,0.4>
    const auto bead = Transformed(difference_of(Sphere<T>({T(0), T(0), T(0)}, T(1)), Quadric<T>::from_povray(1, 1, 0, 0, 0, 0, 0, 0, 0, T(-0.2025))),
                                  pov::transform(pov::rotate<T>(-30, -20, 0).then(pov::translate<T>(-2.3, 1.0, 0.4))));
    // 2) two spheres of radius 1.1, centres 1.2 apart: a lens; rotate <0,0,65>, rotate <0,30,0>, translate <0,0.95,0>
    const auto lens = Transformed(intersection_of(Sphere<T>({T(-0.6), T(0), T(0)}, T(1.1)), Sphere<T>({T(0.6), T(0), T(0)}, T(1.1))),
                                  pov::transform(pov::rotate<T>(0, 0, 65).then(pov::rotate<T>(0, 30, 0)).then(pov::translate<T>(0, 0.95, 0))));
    // 3) the snowman, translate <0.2, 0, 2.8>
    const auto snowman = union_of(Sphere<T>(pov::point<T>(0.2, 0.80, 2.8), T(0.80)), Sphere<T>(pov::point<T>(0.2, 1.90, 2.8), T(0.55)),
                                  Sphere<T>(pov::point<T>(0.2, 2.60, 2.8), T(0.35)));
    // 4) the rotated ellipsoid, as the general quadric the file writes out.
    const auto ellipsoid = Quadric<T>::from_povray(T(1.423437), T(2.678336), T(1.460957), T(-2.173548), T(-0.483221), T(-0.278988),
                                                   T(-5.469745), T(1.477484), T(0.310799), T(5.457516))
                               .transformed(pov::mirror<T>());

    // The floor's checker: negating z moves every cell across an odd number of cell
    // faces, so POV-Ray's first colour is prism's odd one.
    Scene scene{
        std::move(lights),
        Object{Plane<T>({T(0), T(1), T(0)}, T(0)),
               Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(T(0.35)), .odd = Rgb<T>(T(0.8)), .size = T(1)}, .kd = T(0.8), .ka = T(0)}},
        Object{bead, plastic(T(0.85), T(0.35), T(0.15))},
        Object{lens, plastic(T(0.2), T(0.45), T(0.85))},
        Object{snowman, plastic(T(0.9), T(0.9), T(0.85))},
        Object{ellipsoid, plastic(T(0.25), T(0.75), T(0.3))},
    };
    scene.background = {T(0.15), T(0.18), T(0.25)};
    return scene;
}

} // namespace scenes
