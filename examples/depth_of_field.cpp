// SPDX-License-Identifier: MIT
// depth_of_field: the sphere field through a thin lens focused 6 units ahead, so the balls
// there are sharp and the nearer and farther ones blur by the thin-lens formula's circle
// of confusion (Whitted; each sample draws its own lens point, hence the 64 samples).
#include "cli.hpp"
#include "scenes/sphere_field.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        using T = float;
        examples::Options options;
        options.images = {"depth_of_field"}; // checked before rendering
        options.render.width = 720;
        options.render.height = 360;
        options.render.spp = 64;
        if (!examples::parse(argc, argv, options, "the sphere field through a thin lens: depth of field (Whitted)")) return 0;
        const auto scene = scenes::sphere_field_scene();
        const Camera<T> camera{.position = {0, T(0.9), T(-5)},
                               .look_at = {0, T(0.1), T(6)},
                               .up = {0, 1, 0},
                               .fov = 45,
                               .aperture_radius = T(0.06),
                               .focus_distance = T(6)};
        const Whitted integrator(scene, {.max_depth = 6});
        examples::save(examples::timed_render("depth_of_field", camera, integrator, options), options);
        return 0;
    });
}
