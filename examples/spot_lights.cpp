// SPDX-License-Identifier: MIT
// spot_lights: three spot lights, red, green and blue, crossing on a floor before a wall,
// where their circles add up to white; a glass ball focuses each into a caustic of its own
// colour, and a white ball casts three coloured shadows. Photon-mapped: the spots' photons
// leave only into their cones, each carrying pbrt-v4's smoothstep falloff toward the
// cone's edge.
#include "cli.hpp"
#include "methods.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        examples::Options options;
        options.images = {"spot_lights"}; // checked before rendering, written together after
        options.render.width = 640;
        options.render.height = 400;
        options.render.spp = 4;
        options.photons = 200000;
        options.caustic_photons = 1000000;
        options.method = "cache"; // the wall and the floor outside the circles are lit by the floor: gathered
        if (!examples::parse(argc, argv, options, "three coloured spot lights and their caustics through a glass ball (photon mapping)", {.photons = true}))
            return 0;
        // Each from 6 m up, aimed at a point of the floor 0.8 m from the middle: 9 degrees
        // of full light and 5 more of falloff, circles of about 1.5 m that overlap in the middle.
        const auto spot = [](const Vec3<float>& from, const Vec3<float>& at, const Rgb<float>& colour) {
            return SpotLight<float>{.position = from, .direction = at - from, .intensity = 160.0f * colour, .inner_angle = 9, .outer_angle = 14};
        };
        const Scene scene{
            Lights{spot({-2.5f, 6, 1.5f}, {-0.7f, 0, 0.4f}, {1, 0.05f, 0.03f}), spot({0, 6, 3.5f}, {0, 0, -0.8f}, {0.04f, 1, 0.06f}),
                   spot({2.5f, 6, 1.5f}, {0.7f, 0, 0.4f}, {0.03f, 0.1f, 1})},
            Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.75f)}, .kd = 1, .ka = 0}},
            Object{Plane<float>({0, 0, 1}, -3.0f), Diffuse<float>{.albedo = {.color = Rgb<float>(0.6f)}, .kd = 1, .ka = 0}},
            Object{Sphere<float>({-0.55f, 0.5f, 0.75f}, 0.5f), Dielectric<float>{.ior = 1.5f}},
            Object{Sphere<float>({0.7f, 0.4f, -0.35f}, 0.4f), Diffuse<float>{.albedo = {.color = Rgb<float>(0.85f)}, .kd = 1, .ka = 0}},
        };
        const Camera<float> camera{.position = {0, 4.8f, 6.5f}, .look_at = {0, 0.2f, -0.1f}, .up = {0, 1, 0}, .fov = 44};
        examples::save(examples::render_by_method("spot_lights", scene, camera, options), options);
        return 0;
    });
}
