// SPDX-License-Identifier: MIT
// cornell_glossy: the Cornell box under its ceiling light with glossy spheres (rough
// gold, red plastic under a clear coat, a modified-Phong blue), photon-mapped: the
// glossy surfaces' lights and caustics weighed by their BSDFs, their indirect light by a
// final gather drawn from the lobe (--method chooses another estimator; --method
// reference is the path tracer with multiple importance sampling plus the light tracer).
#include "cli.hpp"
#include "methods.hpp"
#include "scenes/cornell.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"cornell_glossy"}; // checked before rendering
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "the Cornell box with glossy spheres (rough gold, coated plastic, Phong) under its ceiling light",
                             {.photons = true}))
            return 0;
        const auto scene = scenes::cornell_glossy_scene<float>();
        const examples::Rendered rendered = examples::render_by_method("cornell_glossy", scene, scenes::cornell_camera<float>(), options);
        examples::save(rendered, options, true);
        return 0;
    });
}
