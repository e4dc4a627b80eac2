// SPDX-License-Identifier: MIT
// sun_caustic: the sun's caustic through a glass ball on a floor, seen directly and in a
// mirror beside the ball, by vertex connection and merging (--method chooses another
// estimator). Seen in the mirror the caustic is the path E S D S S L: the camera's ray
// leaves by the mirror, the sun's light arrives by the glass, and every segment of the
// path has a delta end, so no connection can join it. Only merging finds it: under
// --method bdpt or reference the caustic is in the floor but not in its mirror image.
#include "cli.hpp"
#include "methods.hpp"

#include <prism/prism.hpp>

namespace {

auto sun_caustic_scene()
{
    using namespace prism;
    using V = Vec3<float>;
    const auto floor = Diffuse<float>{.albedo = {.color = {0.75f, 0.72f, 0.66f}}, .kd = 1, .ka = 0};
    return Scene{Lights{DirectionalLight<float>{.direction = normalize(V{0.35f, -1.0f, 0.45f}), .irradiance = Rgb<float>(3.0f)},
                        EnvironmentLight<float>{.radiance = {0.05f, 0.07f, 0.11f}}},
                 Object{Plane<float>({0, 1, 0}, 0), floor},
                 Object{Sphere<float>({-0.6f, 1.0f, -0.6f}, 1.0f), Dielectric<float>{.ior = 1.5f}},
                 // The mirror, a slab standing to the ball's left.
                 Object{Box<float>(V{-3.2f, 0.0f, -4.0f}, V{-3.0f, 3.0f, 4.0f}), Mirror<float>{{.kr = Rgb<float>(0.9f)}}}};
}

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"sun_caustic"}; // checked before rendering
        options.method = "vcm";
        options.render.width = 512;
        options.render.height = 320;
        options.render.spp = 128;
        if (!examples::parse(argc, argv, options, "the sun's caustic through a glass ball, seen directly and in a mirror (E S D S S L), by vertex connection and merging",
                             {.photons = true}))
            return 0;
        const auto scene = sun_caustic_scene();
        const prism::Camera<float> camera{.position = {3.6f, 2.6f, 6.0f}, .look_at = {-1.6f, 0.5f, 0.0f}, .fov = 55};
        examples::save(examples::render_by_method("sun_caustic", scene, camera, options), options, true);
        return 0;
    });
}
