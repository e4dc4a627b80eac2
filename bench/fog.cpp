// SPDX-License-Identifier: MIT
// The foggy scene of issue 36 that prism and Blender's Cycles both render
// (bench/cycles_fog.py builds Cycles' copy): a spot light shines down through haze onto
// a rough glass ball, which focuses it into a volumetric caustic in the air below and a
// caustic on the floor; a wall behind. One render by one method; writes the image as PFM
// and prints "seconds S" (the whole render), 2 threads.
//
// usage: bench_fog METHOD EFFORT OUT.pfm [WIDTH] [SEED]   (the height is 3/4 of WIDTH)
//   METHOD, and what EFFORT is:
//     path         the path tracer (samples per pixel)
//     direct       the photon mapper, maps read directly (global photons; twice as many caustic)
//     progressive  progressive photon mapping, 25000 global and 50000 caustic photons a pass (passes)
//     bdpt, vcm    bidirectional path tracing, vertex connection and merging (passes of one
//                  camera and one light path a pixel)
//   each with ":independent" after it for independent samples instead of Owen-scrambled
//   Sobol points (camera samples and photons alike).
//
// The glass is rough (GGX, roughness 0.1) so that a path tracer can find the volumetric
// caustic at all: through smooth glass, no path from a point in the haze reaches a point
// light (a shadow ray stops at the glass, and a refracted ray never hits the point).
// Cycles' spot light is not prism's SpotLight: its intensity falls as cos(angle from the
// axis) inside the cone, besides the smoothstep at its edge. CyclesSpot puts that factor
// on prism's spot (both the light samples and the photons), so the two scenes are one.
#include "common.hpp"

#include <prism/io/image.hpp>
#include <prism/prism.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <type_traits>

namespace {

using T = float;
using namespace prism;

/// prism's SpotLight with Cycles 3.4's extra factor: the intensity I cos(angle) falloff.
struct CyclesSpot {
    using scalar_type = T;
    static constexpr bool delta = true;
    SpotLight<T> spot;

    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p, const Vec2<T>& uv) const noexcept
    {
        LightSample<T> s = spot.sample(p, uv);
        s.irradiance *= std::max(T(0), dot(-s.wi, normalize(spot.direction)));
        return s;
    }
    /// An upper bound still: the factor is at most 1.
    [[nodiscard]] Rgb<T> photon_power(const PhotonAim<T>& aim) const noexcept { return spot.photon_power(aim); }
    [[nodiscard]] EmittedPhoton<T> emit_photon(const PhotonAim<T>& aim, T u, T v) const noexcept
    {
        EmittedPhoton<T> photon = spot.emit_photon(aim, u, v);
        photon.weight *= std::max(T(0), dot(photon.ray.direction, normalize(spot.direction)));
        return photon;
    }
    /// The light paths of Bidirectional: the spot's, the factor on what they carry (their densities the spot's).
    [[nodiscard]] EmissionSample<T> emission(const BoundingSphere<T>& sphere, const Vec2<T>& u_area, const Vec2<T>& u_direction) const noexcept
    {
        EmissionSample<T> e = spot.emission(sphere, u_area, u_direction);
        e.radiance *= std::max(T(0), dot(e.ray.direction, normalize(spot.direction)));
        return e;
    }
    [[nodiscard]] EmissionPdf<T> emission_pdf(const Vec3<T>& leaving, const BoundingSphere<T>& sphere) const noexcept { return spot.emission_pdf(leaving, sphere); }
    void validate() const { spot.validate(); }
};
static_assert(Light<CyclesSpot>);

const Camera<T> fog_camera{.position = {0, 2.0f, 6.5f}, .look_at = {0, 1.3f, 0}, .up = {0, 1, 0}, .fov = 45};

/// Haze over the floor, in front of the wall: 12 % scattered and 1 % absorbed per metre.
const FilledAir<Fog<T>> haze{.medium = {.absorption = Rgb<T>(0.01f), .scattering = Rgb<T>(0.12f), .phase = {.g = 0.3f}}, .region = {{-5, 0, -3}, {5, 6, 6}}};

auto fog_scene()
{
    return Scene{Lights{CyclesSpot{{.position = {0, 4.5f, 0}, .direction = {0, -1, 0}, .intensity = Rgb<T>(60), .inner_angle = 9, .outer_angle = 12}}},
                 Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(0.7f)}, .kd = 1, .ka = 0}},
                 Object{Plane<T>({0, 0, 1}, -3), Diffuse<T>{.albedo = {.color = Rgb<T>(0.5f)}, .kd = 1, .ka = 0}},
                 Object{Sphere<T>({0, 1.6f, 0}, 0.6f), RoughDielectric<T>{.ior = 1.5f, .roughness = 0.1f}}};
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_fog path|direct|progressive|bdpt|vcm EFFORT OUT.pfm [WIDTH] [SEED]\n");
        return 2;
    }
    std::string method = argv[1];
    const std::string out = argv[3];
    const SamplerKind sampler = bench::take_sampler(method);
    const double effort = std::atof(argv[2]);
    const int width = argc > 4 ? std::atoi(argv[4]) : 256;
    RenderConfig config{.width = width, .height = width * 3 / 4, .spp = 1, .threads = 2, .progress = false};
    config.seed = argc > 5 ? std::strtoull(argv[5], nullptr, 10) : 0;
    config.sampler = sampler;
    const auto scene = fog_scene();
    using S = std::remove_cvref_t<decltype(scene)>;
    using Air = FilledAir<Fog<T>>;
    PhotonMapper<S, Air>::Config mapping;
    mapping.tracing.seed = config.seed;
    mapping.tracing.sampler = sampler;
    mapping.caustic.radius = 0.05f;
    mapping.global.radius = 0.15f;
    mapping.gather_rays = 0;
    mapping.volume_radius = 0.04f;
    const auto start = std::chrono::steady_clock::now();
    Film film(1, 1);
    if (method == "path") {
        config.spp = int(effort);
        film = render(fog_camera, PathTracer(scene, {}, haze), config);
    } else if (method == "direct") {
        mapping.tracing.global_photons = std::size_t(effort);
        mapping.tracing.caustic_photons = 2 * std::size_t(effort);
        config.spp = 2;
        film = render(fog_camera, PhotonMapper<S, Air>(scene, mapping, haze), config);
    } else if (method == "progressive") {
        ProgressiveConfig<S, Air> progressive{.pass = mapping};
        progressive.pass.tracing.global_photons = 25000;
        progressive.pass.tracing.caustic_photons = 50000;
        progressive.pass.caustic.radius = 0.1f;
        progressive.pass.global.radius = 0.25f;
        progressive.pass.volume_radius = 0.08f;
        config.spp = int(effort);
        film = render(fog_camera, ProgressivePhotonMapper<S, Air>(scene, progressive, haze), config);
    } else if (method == "bdpt" || method == "vcm") {
        config.spp = int(effort);
        const BidirectionalConfig bidirectional{.method = method == "vcm" ? BidirectionalMethod::vcm : BidirectionalMethod::bdpt};
        film = render(fog_camera, Bidirectional(scene, bidirectional, haze), config);
    } else {
        std::fprintf(stderr, "bench_fog: unknown METHOD '%s'\n", method.c_str());
        return 2;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_pfm(film, out);
    std::printf("seconds %.4f\n", seconds);
    return 0;
}
