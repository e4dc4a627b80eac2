// SPDX-License-Identifier: MIT
// The scene prism and Blender's Cycles both render under the photographed sky of
// assets/sky/sunrise.exr (bench/cycles_sky.py builds Cycles' copy): a white and a mirror
// sphere on a grey floor, lit by the environment map alone. Writes the path tracer's
// picture as PFM and prints "seconds S", 2 threads.
//
// usage: bench_sky OUT.pfm SPP [SIZE] [SEED] [glossy | frosted | plain] [sobol | independent] [path | bdpt | vcm]
//
// `glossy`: the spheres rough metals of constant reflectance 0.9 (RoughConductor with
// ConstantKr, as Cycles' Glossy BSDF: GGX without Fresnel), roughness 0.4 (left) and 0.15
// (right). `frosted`: the left one frosted glass instead (RoughDielectric, index 1.5,
// roughness 0.3, against Cycles' Glass BSDF). `plain` is the white and mirror spheres.
// `independent`: independent samples instead of Owen-scrambled Sobol points. `bdpt`, `vcm`:
// Bidirectional's passes instead of the path tracer's samples (SPP counts the passes).
#include <prism/io/exr.hpp>
#include <prism/io/image.hpp>
#include <prism/prism.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: bench_sky OUT.pfm SPP [SIZE] [SEED] [glossy | frosted | plain] [sobol | independent] [path | bdpt | vcm]\n");
        return 2;
    }
    using namespace prism;
    using T = float;
    const int size = argc > 3 ? std::atoi(argv[3]) : 256;
    const Film image = read_exr(PRISM_ASSET_DIR "/sky/sunrise.exr").film(NegativeValues::to_zero);
    // Turned 150 degrees about +y: the sun low at the left, behind the camera.
    const EnvironmentMap<T> sky(image.width(), image.height(), image.pixels(), {.rotation_degrees = 150});
    const Object floor{Quad<T>({-5, 0, 5}, {10, 0, 0}, {0, 0, -10}), Diffuse<T>{.albedo = {.color = Rgb<T>(0.5f)}, .kd = 1, .ka = 0}};
    const Camera<T> camera{.position = {0, 1.5f, 5}, .look_at = {0, 0.5f, 0}, .up = {0, 1, 0}, .fov = 50};
    const std::string variant = argc > 5 ? argv[5] : "plain", sampler = argc > 6 ? argv[6] : "sobol", method = argc > 7 ? argv[7] : "path";
    if ((variant != "plain" && variant != "glossy" && variant != "frosted") || (sampler != "sobol" && sampler != "independent") ||
        (method != "path" && method != "bdpt" && method != "vcm")) {
        std::fprintf(stderr, "bench_sky: unknown variant '%s', sampler '%s' or method '%s'\n", variant.c_str(), sampler.c_str(), method.c_str());
        return 2;
    }
    const RenderConfig config{.width = size, .height = size, .spp = std::atoi(argv[2]),
                              .sampler = sampler == "independent" ? SamplerKind::independent : SamplerKind::sobol, .threads = 2,
                              .seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 0, .progress = false};
    const auto start = std::chrono::steady_clock::now();
    Film film(1, 1);
    const auto by_method = [&](const auto& scene) {
        if (method == "path") return render(camera, PathTracer(scene), config);
        return render(camera, Bidirectional(scene, {.method = method == "vcm" ? BidirectionalMethod::vcm : BidirectionalMethod::bdpt}), config);
    };
    if (variant == "frosted") {
        const Scene scene{Lights{sky}, floor, Object{Sphere<T>({-0.8f, 0.6f, 0}, 0.6f), RoughDielectric<T>{.ior = 1.5f, .roughness = 0.3f}},
                          Object{Sphere<T>({0.8f, 0.6f, 0}, 0.6f), RoughConductor<T>{.fresnel = {.kr = Rgb<T>(0.9f)}, .roughness = 0.15f}}};
        film = by_method(scene);
    } else if (variant == "glossy") {
        const Scene scene{Lights{sky}, floor,
                          Object{Sphere<T>({-0.8f, 0.6f, 0}, 0.6f), RoughConductor<T>{.fresnel = {.kr = Rgb<T>(0.9f)}, .roughness = 0.4f}},
                          Object{Sphere<T>({0.8f, 0.6f, 0}, 0.6f), RoughConductor<T>{.fresnel = {.kr = Rgb<T>(0.9f)}, .roughness = 0.15f}}};
        film = by_method(scene);
    } else {
        const Scene scene{Lights{sky}, floor, Object{Sphere<T>({-0.8f, 0.6f, 0}, 0.6f), Diffuse<T>{.albedo = {.color = Rgb<T>(0.8f)}, .kd = 1, .ka = 0}},
                          Object{Sphere<T>({0.8f, 0.6f, 0}, 0.6f), Mirror<T>{{.kr = Rgb<T>(0.9f)}}}};
        film = by_method(scene);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_pfm(film, argv[1]);
    std::printf("seconds %.3f\n", seconds);
    return 0;
}
