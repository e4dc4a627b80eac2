// SPDX-License-Identifier: MIT
// The scene of issue 35's surfaces that prism and Blender's Cycles both render
// (bench/cycles_surfaces.py builds Cycles' copy): a rough gold sphere and a rough glass
// sphere on a varnished tile floor with an image texture and a normal map, seen through
// a thin lens focused on the gold, lit by a point light (which the glass focuses into a
// caustic on the tiles) and a dim uniform sky. One render by one method; writes the
// image as PFM and prints "seconds S" (the whole render), 2 threads.
//
// usage: bench_surfaces METHOD EFFORT OUT.pfm [SIZE] [SEED]
//   METHOD, and what EFFORT is:
//     path         the path tracer alone (samples per pixel)
//     reference    path tracing plus light tracing (samples per pixel, as many light paths)
//     direct       the global map read at the point, caustic map (photons of each kind)
//     gather       final gathering, 2e5 photons of each kind (gather rays)
//     progressive  progressive photon mapping, 5e4 + 5e4 photons a pass (passes)
//     bdpt, vcm    bidirectional path tracing, vertex connection and merging (passes)
//   each with ":independent" after it for independent samples instead of Owen-scrambled
//   Sobol points (camera samples and photons alike).
//
// The floor is what Cycles 3.4 can express exactly: a Mix of a Lambertian (the tiles,
// weight 0.7) and a dielectric's microfacet reflection (n = 1.5, roughness 0.2, weight
// 0.3: Cycles' Principled BSDF with a black base and specular 0.5), both shaded by the
// normal map. Cycles 3.4 has no layered coat with its energy accounted as prism's
// CoatedDiffuse, so that material is not in the shared scene. Textures are read by
// nearest texel, as Cycles' "Closest": Cycles interpolates an 8-bit sRGB picture before
// decoding it and keeps no mipmaps, so any filter but the nearest texel differs.
#include "common.hpp"
#include "methods.hpp"

#include <prism/io/image.hpp>
#include <prism/io/texture.hpp>
#include <prism/prism.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using T = float;
using namespace prism;

/// The camera: 40 degrees across, a lens of radius 4 cm focused 3.74 m ahead (the gold sphere).
Camera<T> surfaces_camera()
{
    return {.position = {0, 2.0f, 3.6f}, .look_at = {0, 0.35f, 0}, .up = {0, 1, 0}, .fov = 40, .aperture_radius = 0.04f, .focus_distance = 3.74f};
}

auto surfaces_scene()
{
    const TextureSampling nearest{.wrap = Wrap::repeat, .filter = TextureFilter::nearest};
    const ImageTexture<T> tiles = load_texture<T>(PRISM_ASSET_DIR "/surfaces/tiles.png", {.encoding = TextureEncoding::srgb, .sampling = nearest});
    const ImageTexture<T> normals = load_texture<T>(PRISM_ASSET_DIR "/surfaces/tiles_normal.png", {.encoding = TextureEncoding::linear, .sampling = nearest});
    using Tiles = Diffuse<T, ImageTexture<T>>;
    using Varnish = RoughConductor<T, ComplexIor<T>>;
    const Mix<T, Tiles, Varnish> glazed{.first = {.albedo = tiles, .kd = 1, .ka = 0},
                                        .second = {.fresnel = {.eta = Rgb<T>(1.5f), .k = Rgb<T>(0)}, .roughness = 0.2f},
                                        .weight = 0.3f};
    return Scene{Lights{PointLight<T>{.position = {-1.3f, 2.8f, -1.4f}, .intensity = Rgb<T>(25)}, EnvironmentLight<T>{.radiance = {0.1f, 0.12f, 0.16f}}},
                 Object{Quad<T>({-2, 0, 2}, {4, 0, 0}, {0, 0, -4}), NormalMapped(glazed, normals)},
                 Object{Sphere<T>({0.7f, 0.45f, 0.2f}, 0.45f), RoughConductor<T>{.fresnel = {.kr = {0.95f, 0.75f, 0.33f}}, .roughness = 0.3f}},
                 Object{Sphere<T>({-0.6f, 0.5f, 0}, 0.5f), RoughDielectric<T>{.ior = 1.5f, .roughness = 0.15f}}};
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_surfaces path|reference|direct|gather|progressive|bdpt|vcm EFFORT OUT.pfm [SIZE] [SEED]\n");
        return 2;
    }
    std::string method = argv[1];
    const std::string out = argv[3];
    const double effort = std::atof(argv[2]);
    examples::Options options;
    options.render.sampler = bench::take_sampler(method);
    options.render.width = options.render.height = argc > 4 ? std::atoi(argv[4]) : 256;
    options.render.threads = 2;
    options.render.seed = argc > 5 ? std::strtoull(argv[5], nullptr, 10) : 0;
    options.render.progress = false;
    options.render.spp = 4;
    options.method = method;
    options.photons = options.caustic_photons = 200000;
    options.radius = 0.05;
    options.global_radius = 0.1;
    if (method == "direct") {
        options.photons = options.caustic_photons = std::size_t(effort);
    } else if (method == "gather") {
        options.gather = int(effort);
    } else if (method == "progressive") {
        options.passes = std::size_t(effort);
        options.photons = options.caustic_photons = 50000;
        options.render.spp = 1;
    } else if (method == "path" || method == "reference" || method == "bdpt" || method == "vcm") {
        options.render.spp = int(effort);
    } else {
        std::fprintf(stderr, "bench_surfaces: unknown METHOD '%s'\n", method.c_str());
        return 2;
    }
    const auto scene = surfaces_scene();
    const auto start = std::chrono::steady_clock::now();
    Film film(1, 1);
    if (method == "path") film = render(surfaces_camera(), PathTracer(scene), options.render);
    else film = examples::render_by_method("surfaces", scene, surfaces_camera(), options).image();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_pfm(film, out);
    std::printf("seconds %.4f\n", seconds);
    return 0;
}
