// SPDX-License-Identifier: MIT
// A newcomer's second scene, written from the user guide: newcomer_box.cpp's Cornell box in
// fog, rendered by progressive photon mapping. bench/compile_cost.py --translation-units
// times its compile.
#include <prism/prism.hpp>
#include <prism/io/image.hpp>

using namespace prism;

int main()
{
    const Diffuse<float> white{.albedo = {.color = Rgb<float>(0.73f)}};
    const Diffuse<float> red{.albedo = {.color = {0.65f, 0.05f, 0.05f}}};
    const Diffuse<float> green{.albedo = {.color = {0.12f, 0.45f, 0.15f}}};
    const Scene scene{Lights{},
                      Object{Quad<float>({-0.5f, 1.99f, -0.5f}, {0, 0, 1}, {1, 0, 0}), Emissive<float>{.radiance = Rgb<float>(15)}},
                      Object{Quad<float>({-1, 0, -1}, {0, 0, 2}, {2, 0, 0}), white},     // floor
                      Object{Quad<float>({-1, 2, -1}, {2, 0, 0}, {0, 0, 2}), white},     // ceiling
                      Object{Quad<float>({-1, 0, -1}, {2, 0, 0}, {0, 2, 0}), white},     // back
                      Object{Quad<float>({-1, 0, -1}, {0, 2, 0}, {0, 0, 2}), red},       // left
                      Object{Quad<float>({1, 0, -1}, {0, 0, 2}, {0, 2, 0}), green},      // right
                      Object{Sphere<float>({-0.45f, 0.35f, -0.3f}, 0.35f),
                             RoughConductor<float, ComplexIor<float>>{.fresnel = {.eta = {0.18f, 0.42f, 1.37f}, .k = {3.42f, 2.35f, 1.77f}},
                                                                      .roughness = Roughness<float>(0.25f)}},
                      Object{Sphere<float>({0.45f, 0.35f, 0.3f}, 0.35f), Dielectric<float>{.ior = 1.5f}}};
    const Camera<float> camera{.position = {0, 1, 3.4f}, .look_at = {0, 1, 0}, .fov = 40};
    using Scene = std::remove_cvref_t<decltype(scene)>;
    using Air = FilledAir<Fog<float>>;
    const Air fog{.medium = {.absorption = Rgb<float>(0.01f), .scattering = Rgb<float>(0.15f), .phase = {.g = 0.5f}}, .region = {{-1, 0, -1}, {1, 2, 1}}};
    ProgressiveConfig<Scene, Air> config;
    config.pass.tracing = {.global_photons = 100000, .caustic_photons = 100000};
    write_png(render(camera, ProgressivePhotonMapper<Scene, Air>(scene, config, fog), {.width = 256, .height = 256, .spp = 16}), "newcomer_fog.png");
}
