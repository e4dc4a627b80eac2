// SPDX-License-Identifier: MIT
// light_shafts: sunlight through a four-paned window into a dusty room. The room's air
// is a fog (FilledAir over the room's box: it scatters 8 % and absorbs 1 % per metre,
// forward-scattering, Henyey-Greenstein g = 0.6), so the beams through the panes are
// seen in the air, and the floor they land on lights the haze around it. Path-traced:
// at every point where a path scatters in the fog, a shadow ray to the sun through the
// window, weighed by the phase function and the fog's transmittance.
#include "cli.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        using T = float;
        examples::Options options;
        options.images = {"light_shafts"}; // checked before rendering
        options.render.width = 480;
        options.render.height = 308;
        options.render.spp = 128;
        if (!examples::parse(argc, argv, options, "sunlight through a window into a dusty room: beams in fog (path tracing)")) return 0;
        // The room, 6 x 3 x 8 m, its walls 0.2 m thick; a window of four panes in the left wall.
        const Box<T> inside({-3, 0, -4}, {3, 3, 4});
        const auto pane = [](T y0, T z0) { return Box<T>({-3.5f, y0, z0}, {-2.5f, y0 + 0.7f, z0 + 0.9f}); };
        const auto shell = difference_of(Box<T>({-3.2f, -0.2f, -4.2f}, {3.2f, 3.2f, 4.2f}), inside, pane(1.2f, -1.5f), pane(2.0f, -1.5f),
                                         pane(1.2f, -0.5f), pane(2.0f, -0.5f));
        const Scene scene{Lights{DirectionalLight<T>{.direction = normalize(Vec3<T>(1, -0.75f, 0.35f)), .irradiance = Rgb<T>(10.0f, 9.0f, 7.5f)}},
                          Object{shell, Diffuse<T>{.albedo = {.color = Rgb<T>(0.6f, 0.55f, 0.5f)}, .kd = 1, .ka = 0}},
                          Object{Sphere<T>({0.6f, 0.5f, -0.8f}, 0.5f), Diffuse<T>{.albedo = {.color = Rgb<T>(0.7f, 0.25f, 0.2f)}, .kd = 1, .ka = 0}}};
        const FilledAir<Fog<T>> dust{.medium = {.absorption = Rgb<T>(0.01f), .scattering = Rgb<T>(0.08f), .phase = {.g = 0.6f}}, .region = inside.bounds()};
        const PathTracer tracer(scene, {}, dust);
        const Camera<T> camera{.position = {2.6f, 1.4f, 3.7f}, .look_at = {-1.2f, 1.0f, -1.2f}, .up = {0, 1, 0}, .fov = 62};
        examples::save(examples::timed_render("light_shafts", camera, tracer, options), options);
        return 0;
    });
}
