// SPDX-License-Identifier: MIT
// cornell_diffuse: shared/scenes/cornell_diffuse.md, the diffuse Cornell box that
// Blender's Cycles renders too (bench/cycles_cornell.py): five walls, colour bleeding,
// a point light of 20 W/sr. By default a final gather behind an irradiance cache;
// --method reference renders prism's unbiased path tracer instead.
#include "cli.hpp"
#include "methods.hpp"
#include "scenes/cornell.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"cornell_diffuse"}; // checked before rendering, written together after
        options.render.spp = 4;
        options.caustic_photons = 0; // nothing specular
        if (!examples::parse(argc, argv, options, "the diffuse Cornell box shared with Blender's Cycles (colour bleeding)", {.photons = true})) return 0;
        const auto scene = scenes::cornell_diffuse_scene<float>();
        examples::save(examples::render_by_method("cornell_diffuse", scene, scenes::cornell_camera<float>(), options), options, true);
        return 0;
    });
}
