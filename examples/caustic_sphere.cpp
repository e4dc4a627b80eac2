// SPDX-License-Identifier: MIT
// caustic_sphere: a glass ball on a checkered floor under a point light, photon-mapped:
// the ball focuses the light into a bright caustic inside its own shadow (the classic test of
// photon mapping, Jensen 2001). With --whitted it is rendered instead as Whitted's shadow rays see
// it: light passing straight through the glass, no focus.
#include "cli.hpp"
#include "methods.hpp"

#include <prism/prism.hpp>

#include <cstring>

int main(int argc, char** argv)
{
    // --whitted is this example's own flag; the rest are the shared options.
    bool whitted = false;
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--whitted") == 0) whitted = true;
        else args.push_back(argv[i]);
    }
    return examples::run([&] {
        using namespace prism;
        examples::Options options;
        options.images = {"caustic_sphere"}; // checked before rendering, written together after
        options.render.width = 640;
        options.render.height = 400;
        options.render.spp = 4;
        options.photons = 100000;
        options.caustic_photons = 1000000;
        options.method = "direct"; // one light over an open floor: little indirect light to gather
        if (!examples::parse(int(args.size()), args.data(), options,
                             "a glass ball's caustic on a checkered floor (photon mapping; --whitted: shadow rays through the glass)",
                             {.photons = true}))
            return 0;
        const Scene scene{
            Lights{PointLight<float>{.position = {-3, 7, -1}, .intensity = Rgb<float>(110)}},
            Object{Plane<float>({0, 1, 0}, 0),
                   Diffuse<float, Checker<float>>{.albedo = {.even = Rgb<float>(0.8f), .odd = Rgb<float>(0.45f), .size = 0.5f}, .kd = 1, .ka = 0}},
            Object{Sphere<float>({0, 1, 0}, 1), Dielectric<float>{.ior = 1.5f}},
        };
        const Camera<float> camera{.position = {4.5f, 4.2f, 6.5f}, .look_at = {0.8f, 0.3f, 0.2f}, .up = {0, 1, 0}, .fov = 45};
        if (whitted) {
            const Whitted integrator(scene, {.max_depth = 10});
            examples::save(examples::timed_render("caustic_sphere", camera, integrator, options), options);
            return 0;
        }
        examples::save(examples::render_by_method("caustic_sphere", scene, camera, options), options);
        return 0;
    });
}
