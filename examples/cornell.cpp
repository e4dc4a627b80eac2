// SPDX-License-Identifier: MIT
// cornell: the Whitted part of shared/scenes/cornell_caustics.pov (POV-Ray with
// Declare=PHOTONS=0): a red/green box, a glass and a mirror sphere, one point light.
#include "cli.hpp"
#include "compare.hpp"
#include "scenes/cornell.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"cornell"}; // checked before rendering, written together after
        if (!examples::parse(argc, argv, options, "Cornell box with glass and mirror spheres, Whitted ray tracing", {.povray = true}))
            return 0;
        const auto scene = scenes::cornell_scene<float>();
        const prism::Whitted integrator(scene, {.max_depth = 10});
        const examples::Rendered rendered = examples::timed_render("cornell", scenes::cornell_camera<float>(), integrator, options);
        examples::save(rendered, options, true);
        if (!options.povray.empty()) examples::write_comparison(rendered.image(), options.povray, examples::output_file(options, "cornell_vs_povray.png"));
        return 0;
    });
}
