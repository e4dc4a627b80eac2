// SPDX-License-Identifier: MIT
// The sphere field: a hundred thousand balls on a plain, on a jittered 316 x 316 grid,
// with twelve large mirror balls among them (sphere_field, depth_of_field).
#pragma once

#include <prism/prism.hpp>

#include <cmath>
#include <cstddef>
#include <utility>

namespace scenes {

/// The field under a low sun and a blue sky, with a little ambient light (Whitted's).
inline auto sphere_field_scene()
{
    using namespace prism;
    using T = float;
    // Balls on a jittered 316 x 316 grid, 0.25 apart, resting on the plain.
    Random rng(2026u, 14u);
    ObjectArray<Sphere<T>, Diffuse<T>> balls;
    constexpr int side = 316;
    balls.items.reserve(std::size_t(side) * side);
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const T r = T(0.04) + T(0.06) * rng.uniform<T>();
            const T x = T(0.25) * (T(i) - T(side) / 2 + T(0.6) * rng.uniform<T>() - T(0.3));
            const T z = T(0.25) * (T(j) + T(0.6) * rng.uniform<T>() - T(0.3)) - T(4);
            const T hue = rng.uniform<T>();
            const Rgb<T> albedo{T(0.5) + T(0.35) * std::cos(T(6.283) * hue), T(0.5) + T(0.35) * std::cos(T(6.283) * (hue - T(0.33))),
                                T(0.5) + T(0.35) * std::cos(T(6.283) * (hue - T(0.67)))};
            balls.items.emplace_back(Sphere<T>({x, r, z}, r), Diffuse<T>{.albedo = {.color = albedo}});
        }
    ObjectArray<Sphere<T>, Mirror<T>> mirrors;
    for (int k = 0; k < 12; ++k) {
        const T r = T(0.5) + T(0.5) * rng.uniform<T>();
        mirrors.items.emplace_back(Sphere<T>({T(14) * rng.uniform<T>() - T(7), r, T(3) + T(30) * rng.uniform<T>()}, r), Mirror<T>{.fresnel = {.kr = Rgb<T>(T(0.85))}});
    }
    Scene scene{Lights{DirectionalLight<T>{.direction = {T(-0.4), T(-0.7), T(0.5)}, .irradiance = Rgb<T>(T(2.6))}},
                Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.35), T(0.33), T(0.3))}}}, std::move(balls), std::move(mirrors)};
    scene.background = Rgb<T>(T(0.55), T(0.7), T(0.95));
    scene.ambient = Rgb<T>(T(0.08));
    return scene;
}

} // namespace scenes
