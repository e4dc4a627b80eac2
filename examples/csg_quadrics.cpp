// SPDX-License-Identifier: MIT
// csg_quadrics: shared/scenes/csg_quadrics.pov in prism (CSG of spheres and quadrics,
// a general quadric, a checkered floor, two lights). With --povray POV-Ray's picture of
// the same scene, also writes prism | POV-Ray | difference.
#include "cli.hpp"
#include "compare.hpp"
#include "scenes/csg_quadrics.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"csg_quadrics"}; // checked before rendering, written together after
        if (!examples::parse(argc, argv, options, "CSG and general quadrics, as in shared/scenes/csg_quadrics.pov", {.povray = true})) return 0;
        const auto scene = scenes::csg_quadrics_scene<float>();
        const prism::Whitted integrator(scene, {.max_depth = 5});
        const examples::Rendered rendered = examples::timed_render("csg_quadrics", scenes::csg_quadrics_camera<float>(), integrator, options);
        examples::save(rendered, options);
        if (!options.povray.empty()) examples::write_comparison(rendered.image(), options.povray, examples::output_file(options, "csg_quadrics_vs_povray.png"));
        return 0;
    });
}
