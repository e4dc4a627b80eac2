// SPDX-License-Identifier: MIT
// The Cornell box as in examples/cornell: walls, a glass sphere and a mirror sphere.
// Paired with scene_diffuse_only.cpp by compile_cost.py: same geometry and light, so the
// difference in compile time, binary size and render time is what the materials cost.
#include "common.hpp"
#include "scenes/cornell.hpp"

int main()
{
    const auto scene = scenes::cornell_scene<float>();
    static_assert(decltype(scene)::has_transmissive);
    const prism::Whitted integrator(scene);
    prism::Film film(1, 1);
    const double seconds = bench::min_seconds(5, [&] {
        film = prism::render(scenes::cornell_camera<float>(), integrator, {.width = 512, .height = 512, .threads = 1, .progress = false});
    });
    std::printf("render_seconds %.6f\n", seconds);
}
