// SPDX-License-Identifier: MIT
// still_life: a textured, multi-material OBJ model read with its .mtl (load_obj_model,
// io/obj_model.hpp): a plank floor (an sRGB image), a brick pedestal (an image and a bump
// map of its mortar), a painted ball with a glossy coat of dimples (an image, Phong's
// specular lobe and a tangent-space normal map), and a glass cube whose caustic falls on
// the planks; photon-mapped under a point light. The model and its pictures are made by
// tools/make_still_life.py (assets/still_life/).
#include "cli.hpp"
#include "methods.hpp"

#include <prism/prism.hpp>
#include <prism/io/obj_model.hpp>

#include <cstdio>

#ifndef PRISM_ASSET_DIR
#error "PRISM_ASSET_DIR names the folder that holds still_life/ (examples/CMakeLists.txt sets it)"
#endif

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        examples::Options options;
        options.images = {"still_life"}; // checked before rendering
        options.render.width = 640;
        options.render.height = 400;
        options.render.spp = 16;
        options.photons = 100000;
        options.caustic_photons = 500000;
        options.method = "direct"; // one light over an open floor: little indirect light to gather
        if (!examples::parse(argc, argv, options, "a textured, multi-material OBJ model with its .mtl: planks, bricks with a bump map, a dimpled ball, a glass cube",
                             {.photons = true}))
            return 0;
        ObjModel<float> model = load_obj_model<float>(std::filesystem::path(PRISM_ASSET_DIR) / "still_life" / "still_life.obj");
        for (const std::string& note : model.notes) std::printf("still_life: %s\n", note.c_str());
        const Scene scene{
            Lights{PointLight<float>{.position = {-2.5f, 5.5f, 3.5f}, .intensity = Rgb<float>(80)}},
            std::move(model.opaque),
            std::move(model.glass),
        };
        const Camera<float> camera{.position = {1.3f, 2.5f, 5.6f}, .look_at = {0.45f, 0.8f, 0.2f}, .up = {0, 1, 0}, .fov = 42};
        examples::save(examples::render_by_method("still_life", scene, camera, options), options);
        return 0;
    });
}
