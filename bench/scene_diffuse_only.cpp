// SPDX-License-Identifier: MIT
// The Cornell box of scene_full.cpp with both spheres made diffuse: no material
// reflects or transmits, so the Whitted integrator compiles no reflection, refraction,
// Fresnel or Beer-Lambert code (Scene::has_specular is false).
#include "common.hpp"
#include "scenes/cornell.hpp"

int main()
{
    using namespace prism;
    const auto walls = prism::get<0>(scenes::cornell_scene<float>().slots);
    const Scene scene{Lights{PointLight<float>{.position = {2.78f, 5.35f, -2.60f}, .intensity = Rgb<float>(pi<float>), .falloff = Falloff::none}},
                      walls,
                      Object{Sphere<float>({3.85f, 1.0f, -2.0f}, 1.0f), Diffuse<float>{.albedo = {.color = Rgb<float>(0.75f)}, .kd = 0.8f, .ka = 0}},
                      Object{Sphere<float>({1.60f, 1.0f, -3.6f}, 1.0f), Diffuse<float>{.albedo = {.color = Rgb<float>(0.75f)}, .kd = 0.8f, .ka = 0}}};
    static_assert(!decltype(scene)::has_transmissive && !decltype(scene)::has_specular);
    const Whitted integrator(scene);
    Film film(1, 1);
    const double seconds = bench::min_seconds(5, [&] {
        film = render(scenes::cornell_camera<float>(), integrator, {.width = 512, .height = 512, .threads = 1, .progress = false});
    });
    std::printf("render_seconds %.6f\n", seconds);
}
