// SPDX-License-Identifier: MIT
// Whitted's single scattering of a point light in fog: marching (stratified jittered
// steps, a shadow ray at each) against the airlight (Gauss-Legendre nodes in the angle
// seen from the light, no shadow rays), error against time. The scene is tests/airlight.hpp's
// (a point light in unbounded coloured fog, nothing to cast a shadow, so both sum the same
// integral); 48 x 32 camera rays pass the light at every distance and angle. The reference
// for each ray is that integral by Simpson's rule in double (20000 intervals over 60
// units), computed without prism's integrators. The error is the RMS over rays and
// channels of the relative error of one evaluation per ray (marching's includes its noise).
//
// usage: bench_airlight [RESULTS_DIR]   writes RESULTS_DIR/airlight.csv (bench/results by default)
#include "../tests/airlight.hpp"
#include "common.hpp"

#include <prism/prism.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    using namespace prism;
    using T = float;
    const std::string results = argc > 1 ? argv[1] : "bench/results";
    const auto scene = test::airlight_scene();
    const Camera<T> camera{.position = {-3, 0.3f, 2.5f}, .look_at = {0, 0.5f, 0}, .up = {0, 1, 0}, .fov = 60};
    const int width = 48, height = 32;
    const CameraRays<T> grid = camera.rays(width, height);
    std::vector<Ray<T>> rays;
    std::vector<Rgb<double>> reference;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            Ray<T> ray = grid.ray(T(x) + T(0.5), T(y) + T(0.5));
            ray.direction = normalize(ray.direction);
            rays.push_back(ray);
            Rgb<double> r;
            for (int c = 0; c < 3; ++c) r[c] = test::airlight_along(c, Vec3<double>(ray.origin), Vec3<double>(ray.direction), {0, 1, 0}, 60.0, 20000);
            reference.push_back(r);
        }
    bench::Csv csv(results + "/airlight.csv", "method,setting,nanoseconds_per_ray,rms_relative_error");
    std::printf("%-9s %8s %14s %14s\n", "method", "setting", "ns per ray", "RMS rel. error");
    const auto measure = [&](const char* method, int setting, const Whitted<std::remove_cvref_t<decltype(scene)>, FilledAir<Fog<T>>>& whitted) {
        std::vector<Rgb<T>> found(rays.size());
        const int rounds = 20;
        const double seconds = bench::min_seconds(3, [&] {
            for (int round = 0; round < rounds; ++round) {
                Random rng(7, std::uint64_t(round));
                for (std::size_t i = 0; i < rays.size(); ++i) found[i] = whitted.radiance(rays[i], rng);
            }
        });
        double squares = 0;
        for (std::size_t i = 0; i < rays.size(); ++i)
            for (int c = 0; c < 3; ++c) squares += std::pow(double(found[i][c]) / reference[i][c] - 1, 2);
        const double error = std::sqrt(squares / (3.0 * double(rays.size())));
        const double ns = 1e9 * seconds / (rounds * double(rays.size()));
        std::printf("%-9s %8d %14.1f %14.3g\n", method, setting, ns, error);
        csv.row("%s,%d,%.2f,%.6g", method, setting, ns, error);
    };
    for (const int steps : {4, 8, 16, 32, 64, 128, 256, 1024})
        measure("march", steps, Whitted(scene, {.march_steps = steps}, test::airlight_fog()));
    for (const int nodes : {1, 2, 4, 8, 16, 32, 64})
        measure("airlight", nodes, Whitted(scene, {.in_scattering = InScattering::airlight, .airlight_nodes = nodes}, test::airlight_fog()));
    return 0;
}
