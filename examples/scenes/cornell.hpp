// SPDX-License-Identifier: MIT
// The Cornell-like box of shared/scenes/cornell_caustics.pov, in prism's coordinates.
//
// POV-Ray is left-handed with y up and its camera looks along +z; prism is right-handed
// with y up. Negating z maps one onto the other with the same picture: the camera at
// POV (2.78, 2.73, -8) looking along +z sits at (2.78, 2.73, 8) looking along -z.
//
// Units: POV-Ray's diffuse shading is pigment * diffuse * light colour * cos, with no
// pi. prism's Lambertian BRDF is albedo / pi, so a POV-Ray light of colour c with
// `fade_power 0` is a PointLight of intensity pi * c with Falloff::none.
#pragma once

#include <prism/prism.hpp>

namespace scenes {

template <prism::Scalar T>
prism::Camera<T> cornell_camera()
{
    return {.position = {T(2.78), T(2.73), T(8)}, .look_at = {T(2.78), T(2.73), T(0)}, .up = {T(0), T(1), T(0)}, .fov = T(40)};
}

/// The Cornell box. `physical_light` swaps POV-Ray's no-falloff light for an
/// inverse-square one that gives the same irradiance at distance 4, about the middle of
/// the room (intensity 16 pi): photons thin out as 1 / r^2, so a photon map can only be
/// consistent with a physical light.
/// The five walls: white floor, ceiling and back, red left, green right, albedo 0.75 x
/// kd 0.8 as the .pov's pigment x diffuse; open toward the camera.
template <prism::Scalar T>
auto cornell_walls()
{
    using namespace prism;
    using V = Vec3<T>;
    constexpr T w = T(5.55), t = T(0.1); // interior size, wall thickness
    const auto diffuse = [](T r, T g, T b) { return Diffuse<T>{.albedo = {.color = {r, g, b}}, .kd = T(0.8), .ka = T(0)}; };
    const auto white = diffuse(T(0.75), T(0.75), T(0.75));
    using Wall = Object<Box<T>, Diffuse<T>>;
    return ObjectArray<Box<T>, Diffuse<T>>{{
        Wall{Box<T>(V{-t, -t, 0}, V{w + t, 0, -(w + t)}), white},                             // floor
        Wall{Box<T>(V{-t, w, 0}, V{w + t, w + t, -(w + t)}), white},                          // ceiling
        Wall{Box<T>(V{-t, -t, -w}, V{w + t, w + t, -(w + t)}), white},                        // back
        Wall{Box<T>(V{-t, -t, 0}, V{0, w + t, -(w + t)}), diffuse(T(0.75), T(0.1), T(0.1))},  // left, red
        Wall{Box<T>(V{w, -t, 0}, V{w + t, w + t, -(w + t)}), diffuse(T(0.1), T(0.75), T(0.1))}, // right, green
    }};
}

/// shared/scenes/cornell_diffuse.md: the walls alone under a point light of 20 W/sr,
/// the scene Blender's Cycles renders too (bench/cycles_cornell.py).
template <prism::Scalar T>
auto cornell_diffuse_scene()
{
    using namespace prism;
    return Scene{Lights{PointLight<T>{.position = {T(2.78), T(5.35), T(-2.60)}, .intensity = Rgb<T>(T(20))}}, cornell_walls<T>()};
}

/// The ceiling light of the Cornell box: a rectangle of 1.30 x 1.05 just below the
/// ceiling's centre (the Cornell data's light, in metres), facing down, of radiance 37
/// W/(m^2 sr): L A = 50 W/sr straight down, as the point light's 16 pi sends every way
/// (its power, pi L A = 159 W, is a quarter of the point light's, which sends three
/// quarters of its power at the walls and ceiling).
template <prism::Scalar T>
auto cornell_ceiling_light()
{
    using namespace prism;
    return Object{Quad<T>({T(2.13), T(5.549), T(-3.32)}, {T(1.30), T(0), T(0)}, {T(0), T(0), T(1.05)}), Emissive<T>{.radiance = Rgb<T>(T(37))}};
}

/// The diffuse box lit by its ceiling light instead of the point light (the scene
/// bench/cycles_cornell.py --area renders in Cycles).
template <prism::Scalar T>
auto cornell_diffuse_area_scene()
{
    using namespace prism;
    return Scene{Lights{}, cornell_walls<T>(), cornell_ceiling_light<T>()};
}

template <prism::Scalar T, class Fresnel = prism::ExactFresnel>
auto cornell_scene(bool physical_light = false)
{
    using namespace prism;
    Scene scene{
        Lights{physical_light ? PointLight<T>{.position = {T(2.78), T(5.35), T(-2.60)}, .intensity = Rgb<T>(pi<T> * T(4 * 4))}
                              : PointLight<T>{.position = {T(2.78), T(5.35), T(-2.60)}, .intensity = Rgb<T>(pi<T>), .falloff = Falloff::none}},
        cornell_walls<T>(),
        Object{Sphere<T>({T(3.85), T(1.0), T(-2.0)}, T(1)), Dielectric<T, Fresnel>{.ior = T(1.5)}},
        Object{Sphere<T>({T(1.60), T(1.0), T(-3.6)}, T(1)), Mirror<T>{{.kr = Rgb<T>(T(0.95))}}},
    };
    return scene;
}

/// The Cornell box lit as the original is, by its ceiling light, with the glass and the
/// mirror spheres.
template <prism::Scalar T, class Fresnel = prism::ExactFresnel>
auto cornell_area_scene()
{
    using namespace prism;
    return Scene{
        Lights{},
        cornell_walls<T>(),
        cornell_ceiling_light<T>(),
        Object{Sphere<T>({T(3.85), T(1.0), T(-2.0)}, T(1)), Dielectric<T, Fresnel>{.ior = T(1.5)}},
        Object{Sphere<T>({T(1.60), T(1.0), T(-3.6)}, T(1)), Mirror<T>{{.kr = Rgb<T>(T(0.95))}}},
    };
}

/// The Cornell box under its ceiling light with glossy spheres: rough gold (measured
/// index, roughness 0.3), red plastic under a smooth clear coat, and a blue glossy
/// sphere by the modified Phong model (the classic photon-mapping test surface).
template <prism::Scalar T>
auto cornell_glossy_scene()
{
    using namespace prism;
    return Scene{
        Lights{},
        cornell_walls<T>(),
        cornell_ceiling_light<T>(),
        Object{Sphere<T>({T(1.55), T(1.0), T(-3.5)}, T(1)), rough_metal<T>(metals::gold, Roughness<T>(T(0.3)))},
        Object{Sphere<T>({T(3.95), T(0.85), T(-2.2)}, T(0.85)), CoatedDiffuse<T>({.color = {T(0.7), T(0.08), T(0.06)}}, {.ior = T(1.5), .roughness = T(0)})},
        Object{Sphere<T>({T(2.9), T(0.6), T(-4.6)}, T(0.6)),
               Phong<T>{.diffuse = {.color = {T(0.05), T(0.12), T(0.45)}}, .specular = Rgb<T>(T(0.45)), .exponent = T(60)}},
    };
}

} // namespace scenes
