// SPDX-License-Identifier: MIT
// sphere_field: a hundred thousand balls on a plain, seen from low down to the horizon,
// with a few large mirror balls among them: two ObjectArray slots, each found through its
// own Bvh, so a ray costs about log N tests, not N (Whitted: sun, sky, mirrors).
#include "cli.hpp"
#include "scenes/sphere_field.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        using T = float;
        examples::Options options;
        options.images = {"sphere_field"}; // checked before rendering, written together after
        options.render.width = 720;
        options.render.height = 360;
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "a field of 10^5 balls and some mirror balls, each array found through its own Bvh (Whitted)")) return 0;
        const auto scene = scenes::sphere_field_scene();
        const Camera<T> camera{.position = {0, T(1.6), T(-6)}, .look_at = {0, T(0.2), T(6)}, .up = {0, 1, 0}, .fov = 50};
        const Whitted integrator(scene, {.max_depth = 6});
        examples::save(examples::timed_render("sphere_field", camera, integrator, options), options);
        return 0;
    });
}
