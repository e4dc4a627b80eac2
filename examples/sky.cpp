// SPDX-License-Identifier: MIT
// sky: glass, gold and white clay spheres on a pale floor under a photographed sky at
// sunrise (Blender's CC0 studio light, an HDR latitude-longitude image read from EXR, its
// sun 70 000 times the sky's mean), rendered by the reference estimator: the path tracer
// draws the sky pixel by pixel by what each sends and combines those samples with its
// bounces by multiple importance sampling; the light tracer carries the sun's caustics
// through the glass and off the gold onto the floor. The low sun casts long shadows.
#include "cli.hpp"

#include <prism/io/exr.hpp>
#include <prism/prism.hpp>

#include <cstdio>

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"sky"}; // checked before rendering
        options.render.width = 640;
        options.render.height = 360;
        options.render.spp = 128;
        if (!examples::parse(argc, argv, options, "spheres under a photographed sky at sunrise (an HDR environment map), path-traced")) return 0;
        using namespace prism;
        using T = float;
        // Blender's DWA-compressed EXR holds 596 values a little below 0 (at worst -0.004,
        // its lossy compression's noise): stored as 0, and said so.
        const Film image = read_exr(PRISM_ASSET_DIR "/sky/sunrise.exr").film(NegativeValues::to_zero);
        std::printf("sky: %s, %d x %d pixels, %llu negative values (lossy compression) set to 0\n", "assets/sky/sunrise.exr", image.width(),
                    image.height(), static_cast<unsigned long long>(image.rejected()));
        // Turned so that the sun stands to the left, behind the spheres.
        const EnvironmentMap<T> sunrise(image.width(), image.height(), image.pixels(), {.rotation_degrees = -50});
        const Scene scene{Lights{sunrise},
                          Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.5), T(0.48), T(0.45))}}},
                          Object{Sphere<T>({-1.25f, 0.6f, 0.3f}, 0.6f), Dielectric<T>{.ior = 1.5f}},
                          Object{Sphere<T>({0.1f, 0.6f, -0.6f}, 0.6f), measured_metal<T>(metals::gold)},
                          Object{Sphere<T>({1.35f, 0.6f, 0.4f}, 0.6f), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.8))}}}};
        const Camera<T> camera{.position = {0, 1.1f, 7.5f}, .look_at = {0, 0.9f, 0}, .up = {0, 1, 0}, .fov = 40};
        const Reference integrator(scene);
        examples::save(examples::timed_render("sky", camera, integrator, options), options);
        return 0;
    });
}
