// SPDX-License-Identifier: MIT
// volumetric_caustic: a spot light shines down through haze onto a glass ball, which
// focuses it: below the ball the light narrows to a bright point in the air and widens
// again to the floor's caustic. Photon-mapped (volumetric_caustic.png): photons that
// scatter in the haze are stored as volume photons, and camera rays gather them by the
// beam radiance estimate; a volumetric caustic (light, glass, haze) is traced by the
// caustic pass, aimed at the ball. Beside it the path tracer (volumetric_caustic_path.png)
// with the same time or more: from a point in the haze, a shadow ray to a point light
// cannot pass the glass, so the path tracer sees the beam and its shadow but not the
// focused light. Last, vertex connection and merging (volumetric_caustic_vcm.png): light
// paths through the ball scatter in the haze and are joined to the camera, so the focused
// light is found with no photon map; the haze seen through the ball, which no connection
// joins (camera, glass, haze, glass, light), by merging.
#include "cli.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        using T = float;
        examples::Options options;
        options.images = {"volumetric_caustic", "volumetric_caustic_path", "volumetric_caustic_vcm"}; // checked before rendering
        options.render.width = 480;
        options.render.height = 360;
        options.render.spp = 2;
        options.photons = 1000000;
        options.caustic_photons = 2000000;
        options.radius = 0.05;
        if (!examples::parse(argc, argv, options, "a glass ball focuses a spot light in haze: a volumetric caustic (photon mapping; the path tracer beside it)",
                             {.photons = true}))
            return 0;
        const Scene scene{Lights{SpotLight<T>{.position = {0, 4.5f, 0}, .direction = {0, -1, 0}, .intensity = Rgb<T>(60), .inner_angle = 9, .outer_angle = 12}},
                          Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(0.7f)}, .kd = 1, .ka = 0}},
                          Object{Plane<T>({0, 0, 1}, -3), Diffuse<T>{.albedo = {.color = Rgb<T>(0.5f)}, .kd = 1, .ka = 0}},
                          Object{Sphere<T>({0, 1.6f, 0}, 0.6f), Dielectric<T>{.ior = 1.5f}}};
        // Haze over the floor, in front of the wall: 12 % scattered and 1 % absorbed per metre.
        const FilledAir<Fog<T>> haze{.medium = {.absorption = Rgb<T>(0.01f), .scattering = Rgb<T>(0.12f), .phase = {.g = 0.3f}},
                                     .region = {{-5, 0, -3}, {5, 6, 6}}};
        const Camera<T> camera{.position = {0, 2.0f, 6.5f}, .look_at = {0, 1.3f, 0}, .up = {0, 1, 0}, .fov = 45};
        PhotonMapper<std::remove_cvref_t<decltype(scene)>, FilledAir<Fog<T>>>::Config config;
        config.tracing.global_photons = options.photons;
        config.tracing.caustic_photons = options.caustic_photons;
        config.tracing.seed = options.render.seed;
        config.caustic.radius = float(options.radius);
        config.gather_rays = 0; // the global map read directly: the haze's light on the floor is dim and even
        config.volume_radius = 0.04f;
        const PhotonMapper mapper(scene, config, haze);
        std::printf("volumetric_caustic: %zu volume, %zu global and %zu caustic photons\n", mapper.maps().volume.size(), mapper.maps().global.size(),
                    mapper.maps().caustic.size());
        examples::save(examples::timed_render("volumetric_caustic", camera, mapper, options), options);
        examples::Options path = options;
        path.render.spp = 16 * options.render.spp;
        const PathTracer tracer(scene, {}, haze);
        examples::save(examples::timed_render("volumetric_caustic_path", camera, tracer, path), path);
        examples::Options passes = options;
        passes.render.spp = 16 * options.render.spp;
        const Bidirectional vcm(scene, {.method = BidirectionalMethod::vcm}, haze);
        examples::save(examples::timed_render("volumetric_caustic_vcm", camera, vcm, passes), passes);
        return 0;
    });
}
