// SPDX-License-Identifier: MIT
// cornell_area: the Cornell box lit by its ceiling light, a rectangle that emits (an area
// light), photon-mapped: soft shadows under the spheres, the glass sphere's caustic, the
// walls' colour bleeding (by default a final gather behind an irradiance cache; --method
// chooses another estimator, --method reference the path tracer with multiple importance
// sampling plus the light tracer). cornell_caustics is the same room under a point light.
#include "cli.hpp"
#include "methods.hpp"
#include "scenes/cornell.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"cornell_area"}; // checked before rendering
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "the Cornell box under its ceiling light (an area light), photon-mapped", {.photons = true})) return 0;
        const auto scene = scenes::cornell_area_scene<float>();
        const examples::Rendered rendered = examples::render_by_method("cornell_area", scene, scenes::cornell_camera<float>(), options);
        examples::save(rendered, options, true);
        return 0;
    });
}
