// SPDX-License-Identifier: MIT
// smoke: a plume of smoke rising from the floor of a dim room, lit from the side by a warm
// spot light and from above by a cool sky. The smoke is a medium of varying density
// (VaryingFog) over a 48 x 80 x 48 density grid made here: a column that drifts and
// widens as it rises and thins toward the top, broken up by three octaves of value
// noise. Path-traced: free flights by delta (spectral) tracking against the grid's
// majorants, shadow rays through the smoke by residual ratio tracking, so the plume
// shadows itself and the floor.
#include "cli.hpp"

#include <prism/prism.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

/// A value in [0, 1) at each point of the integer lattice (a hash of its coordinates).
float lattice_value(int x, int y, int z)
{
    std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(z) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return float(h & 0xffffffu) / float(1u << 24);
}

/// Value noise: the lattice's values, smoothly interpolated (in [0, 1)).
float value_noise(float x, float y, float z)
{
    const int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
    const auto smooth = [](float t) { return t * t * (3 - 2 * t); };
    const float fx = smooth(x - float(ix)), fy = smooth(y - float(iy)), fz = smooth(z - float(iz));
    const auto mix = [](float a, float b, float t) { return a + t * (b - a); };
    const auto row = [&](int y0, int z0) { return mix(lattice_value(ix, y0, z0), lattice_value(ix + 1, y0, z0), fx); };
    const auto plane = [&](int z0) { return mix(row(iy, z0), row(iy + 1, z0), fy); };
    return mix(plane(iz), plane(iz + 1), fz);
}

/// The plume's density at a point.
float plume(const prism::Vec3<float>& p)
{
    if (p.y < 0) return 0;
    const float cx = 0.3f * std::sin(1.6f * p.y), cz = 0.25f * std::cos(1.2f * p.y) - 0.25f; // it drifts as it rises
    const float radius = 0.1f + 0.16f * p.y;                                                 // and widens
    const float dx = p.x - cx, dz = p.z - cz;
    const float column = std::exp(-(dx * dx + dz * dz) / (radius * radius));
    float noise = 0, amplitude = 0.5f, frequency = 4;
    for (int octave = 0; octave < 3; ++octave, amplitude *= 0.5f, frequency *= 2.1f)
        noise += amplitude * value_noise(frequency * p.x, frequency * (p.y - 0.4f * float(octave)), frequency * p.z);
    const float fade = std::exp(-0.6f * p.y) * std::min(1.0f, p.y / 0.15f);
    return 14.0f * fade * column * std::max(0.0f, 2.6f * noise - 0.85f);
}

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        using T = float;
        examples::Options options;
        options.images = {"smoke"}; // checked before rendering
        options.render.width = 400;
        options.render.height = 400;
        options.render.spp = 128;
        if (!examples::parse(argc, argv, options, "a plume of smoke lit by a spot light: a medium of varying density (path tracing)")) return 0;
        // The density grid: 48 x 80 x 48 points over the plume's box.
        const Aabb<T> box{{-1.2f, 0, -1.2f}, {1.2f, 3.2f, 1.2f}};
        const int nx = 48, ny = 80, nz = 48;
        std::vector<float> values;
        values.reserve(std::size_t(nx) * ny * nz);
        for (int z = 0; z < nz; ++z)
            for (int y = 0; y < ny; ++y)
                for (int x = 0; x < nx; ++x)
                    values.push_back(plume(box.lo + Vec3<T>(T(x) / T(nx - 1), T(y) / T(ny - 1), T(z) / T(nz - 1)) * (box.hi - box.lo)));
        // Grey smoke: per unit density 6 scattered and 0.6 absorbed per metre, slightly forward.
        using Smoke = VaryingFog<DensityGrid<T>>;
        const FilledAir<Smoke> smoke{.medium = Smoke(DensityGrid<T>(nx, ny, nz, box, std::move(values)), Rgb<T>(0.6f), Rgb<T>(6.0f), {.g = 0.3f})};
        const Scene scene{Lights{SpotLight<T>{.position = {-4, 3.5f, 1.5f}, .direction = Vec3<T>(4, -2.4f, -1.7f), .intensity = Rgb<T>(80, 60, 38),
                                              .inner_angle = 17, .outer_angle = 22},
                                 EnvironmentLight<T>{.radiance = Rgb<T>(0.06f, 0.08f, 0.12f)}},
                          Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(0.55f, 0.52f, 0.5f)}, .kd = 1, .ka = 0}},
                          Object{Plane<T>({0, 0, 1}, -2.5f), Diffuse<T>{.albedo = {.color = Rgb<T>(0.45f, 0.47f, 0.5f)}, .kd = 1, .ka = 0}}};
        const PathTracer tracer(scene, {}, smoke);
        const Camera<T> camera{.position = {0.4f, 1.6f, 6.0f}, .look_at = {0, 1.4f, 0}, .up = {0, 1, 0}, .fov = 40};
        examples::save(examples::timed_render("smoke", camera, tracer, options), options);
        return 0;
    });
}
