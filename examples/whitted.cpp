// SPDX-License-Identifier: MIT
// whitted: a glass and a mirror sphere over a checkered plane, Whitted-style.
#include "cli.hpp"
#include "scenes/whitted.hpp"

#include <prism/integrator/whitted.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"whitted"}; // checked before rendering, written together after
        options.render.width = 640;
        options.render.height = 480;
        options.render.spp = 16;
        if (!examples::parse(argc, argv, options, "a glass and a mirror sphere over a checkered plane (Whitted 1980)"))
            return 0;
        const auto scene = scenes::whitted_scene<float>();
        const prism::Whitted integrator(scene);
        examples::save(examples::timed_render("whitted", scenes::whitted_camera<float>(), integrator, options), options);
        return 0;
    });
}
