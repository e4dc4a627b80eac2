// SPDX-License-Identifier: MIT
// csg_quadrics_area: shared/scenes/csg_quadrics.pov with POV-Ray's area_light on both
// lights (area_light <1.5, 0, 0>, <0, 0, 1.5>, 5, 5 adaptive 1): the same CSG and quadrics
// with soft shadows, rendered by Whitted with PointGridLight, POV-Ray's rule for the grid.
// With --povray POV-Ray's picture of the same scene (bench/vs_povray.py writes its .pov),
// also writes prism | POV-Ray | difference.
#include "cli.hpp"
#include "compare.hpp"
#include "scenes/csg_quadrics.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"csg_quadrics_area"}; // checked before rendering, written together after
        if (!examples::parse(argc, argv, options, "csg_quadrics.pov under POV-Ray's area_light: soft shadows", {.povray = true})) return 0;
        const auto scene = scenes::csg_quadrics_scene<float>(scenes::csg_quadrics_area_lights<float>());
        const prism::Whitted integrator(scene, {.max_depth = 5});
        const examples::Rendered rendered = examples::timed_render("csg_quadrics_area", scenes::csg_quadrics_camera<float>(), integrator, options);
        examples::save(rendered, options);
        if (!options.povray.empty())
            examples::write_comparison(rendered.image(), options.povray, examples::output_file(options, "csg_quadrics_area_vs_povray.png"));
        return 0;
    });
}
