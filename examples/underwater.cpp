// SPDX-License-Identifier: MIT
// underwater: the sun through a wavy sea surface into murky water. The waves focus the
// sunlight into a net of caustics on the sandy floor, and the water scatters and tints the
// light on its way. The camera is in the water (Scene::media_at starts its
// rays there), and rays that leave through the surface see the sky within Snell's window.
// Rendered by progressive photon mapping: each pass traces fresh photons (the caustic
// pass aimed at the water) and shrinks the radii of the floor's and the beams' estimates,
// so the floor's caustic sharpens as the passes add up. Light scattered more than once in
// the water is read with a wider beam than the light scattered once
// (indirect_volume_radius): its photons are few, and at the narrow radius each one near
// the camera showed as a bright disk.
#include "cli.hpp"

#include <prism/prism.hpp>

#include <cmath>

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        using T = float;
        examples::Options options;
        options.images = {"underwater"}; // checked before rendering
        options.render.width = 400;
        options.render.height = 225;
        options.render.spp = 64; // passes
        options.photons = 60000;
        options.caustic_photons = 150000;
        options.radius = 0.08;
        if (!examples::parse(argc, argv, options, "sunlight through waves into murky water: caustics on the floor, seen from in the water (progressive photon mapping)",
                             {.photons = true}))
            return 0;
        // The water: a solid under a sum of waves, from y = -0.5 (under the sand) up to about 3.
        const auto waves = [](T x, T z) {
            return T(3) + T(0.06) * std::sin(T(4.1) * x + T(1.3) * z) + T(0.05) * std::sin(T(-1.9) * x + T(4.4) * z + T(1.3)) +
                   T(0.02) * std::sin(T(7.1) * x - T(5.3) * z + T(0.4));
        };
        const TriangleMesh<T> sea(height_field_solid<T>(-6, 6, -10, 6, 192, T(-0.5), waves));
        // Clear-ish sea water: red absorbed most, blue least; scattering forward.
        const Fog<T> water{.absorption = {T(0.25), T(0.05), T(0.035)}, .scattering = Rgb<T>(T(0.15)), .phase = {.g = T(0.8)}};
        Scene scene{Lights{DirectionalLight<T>{.direction = normalize(Vec3<T>(T(0.2), T(-1), T(-0.25))), .irradiance = Rgb<T>(T(4))}},
                    Object{sea, Dielectric<T, ExactFresnel, Fog<T>>{.ior = T(1.33), .interior = water}},
                    Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = {T(0.75), T(0.68), T(0.5)}}, .kd = 1, .ka = 0}},
                    Object{Sphere<T>({T(-1.2), T(0.1), T(-2.5)}, T(0.6)), Diffuse<T>{.albedo = {.color = {T(0.35), T(0.33), T(0.3)}}, .kd = 1, .ka = 0}},
                    Object{Sphere<T>({T(1.6), T(0.0), T(-4.0)}, T(0.9)), Diffuse<T>{.albedo = {.color = {T(0.4), T(0.36), T(0.3)}}, .kd = 1, .ka = 0}}};
        scene.background = {T(0.55), T(0.75), T(1.0)};
        using S = decltype(scene);
        ProgressiveConfig<S> config;
        config.pass.tracing.global_photons = options.photons;
        config.pass.tracing.caustic_photons = options.caustic_photons;
        config.pass.tracing.seed = options.render.seed;
        config.pass.caustic.radius = float(options.radius);
        config.pass.global.radius = 0.3f;
        config.pass.volume_radius = 0.05f;          // the shafts: light scattered once
        config.pass.indirect_volume_radius = 0.2f; // light scattered more than once: smooth, and wider
        config.samples = 1;
        const ProgressivePhotonMapper<S> mapper(scene, config);
        const Camera<T> camera{.position = {0, T(1.2), T(5)}, .look_at = {0, T(1.4), T(-3)}, .up = {0, 1, 0}, .fov = 60};
        examples::save(examples::timed_render("underwater", camera, mapper, options), options);
        return 0;
    });
}
