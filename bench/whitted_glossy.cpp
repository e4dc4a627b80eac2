// SPDX-License-Identifier: MIT
// What Whitted's cut costs on a glossy surface: a rough metal ball (constant reflectance 0.9)
// on a lit checker floor, at roughnesses from 0.02 to 0.8. Whitted lights the ball by its
// BSDF toward the light (exact) and replaces the lobe's reflection of the floor by one ray
// along the mirror direction carrying the lobe's albedo there. The reference is the path
// tracer limited to one non-delta bounce (max_diffuse_bounces = 1): the same light (the
// lights at the ball, and the floor's direct light reflected by the whole lobe), with the
// background black for both (a path tracer's background lights nothing after a bounce).
// The error is over the pixels whose centre sees the ball, relative to their mean, leaving
// out the brightest 2 % of them by the reference (the point light's highlight, direct light
// that Whitted finds exactly, and whose few pixels' sampling noise would swamp the rest);
// the reference's own noise, from two seeds, is printed beside it.
//
// usage: bench_whitted_glossy RESULTS_DIR [REFERENCE_SPP]
#include <prism/prism.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

int main(int argc, char** argv)
{
    using namespace prism;
    using T = float;
    const std::string results = argc > 1 ? argv[1] : ".";
    const int reference_spp = argc > 2 ? std::atoi(argv[2]) : 1024;
    constexpr int size = 160;
    const Camera<T> camera{.position = {0, 1.6f, 3.6f}, .look_at = {0, 0.8f, 0}, .fov = 36};
    const std::string path = results + "/whitted_glossy.csv";
    std::FILE* csv = std::fopen(path.c_str(), "w");
    if (!csv) {
        std::fprintf(stderr, "cannot write %s\n", path.c_str());
        return 1;
    }
    std::fprintf(csv, "roughness,whitted_seconds,reference_seconds,whitted_error,reference_noise,pixels\n");
    std::printf("%9s %10s %12s %14s %16s\n", "roughness", "whitted s", "reference s", "Whitted error", "reference noise");
    for (const T roughness : {0.05f, 0.1f, 0.2f, 0.3f, 0.5f, 0.8f}) {
        const Scene scene{Lights{PointLight<T>{.position = {2, 4, 3}, .intensity = Rgb<T>(30)}},
                          Object{Plane<T>({0, 1, 0}, 0), Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(0.8f), .odd = Rgb<T>(0.1f), .size = 0.5f}, .ka = 0}},
                          Object{Sphere<T>({0, 0.8f, 0}, 0.8f), RoughConductor<T>{.fresnel = {.kr = Rgb<T>(0.9f)}, .roughness = roughness}}};
        const RenderConfig config{.width = size, .height = size, .spp = 16, .threads = 2, .seed = 1, .progress = false};
        auto start = std::chrono::steady_clock::now();
        const Film whitted = render(camera, Whitted(scene), config);
        const double whitted_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const PathTracer reference(scene, {.max_diffuse_bounces = 1});
        RenderConfig long_config = config;
        long_config.spp = reference_spp;
        start = std::chrono::steady_clock::now();
        const Film a = render(camera, reference, long_config);
        const double reference_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        long_config.seed = 2;
        const Film b = render(camera, reference, long_config);
        // The ball's pixels: those whose centre ray meets the sphere first, but the brightest 2 %.
        const CameraRays<T> rays = camera.rays(size, size);
        std::vector<std::pair<double, int>> ball;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const auto hit = scene.closest_hit(rays.ray(T(x) + T(0.5), T(y) + T(0.5)), {T(0), infinity<T>});
                if (hit && hit->slot == 1) ball.emplace_back(double(a.at(x, y).x + b.at(x, y).x), y * size + x);
            }
        std::sort(ball.begin(), ball.end());
        ball.resize(ball.size() - ball.size() / 50);
        double sum = 0, squares = 0, noise = 0;
        int pixels = 0;
        for (const auto& [brightness, k] : ball) {
            const int x = k % size, y = k / size;
            for (int c = 0; c < 3; ++c) {
                const double mean = 0.5 * (double(a.at(x, y)[c]) + double(b.at(x, y)[c]));
                sum += mean;
                squares += std::pow(double(whitted.at(x, y)[c]) - mean, 2);
                noise += std::pow(0.5 * (double(a.at(x, y)[c]) - double(b.at(x, y)[c])), 2);
            }
            ++pixels;
        }
        const double mean = sum / (3.0 * pixels);
        const double error = std::sqrt(squares / (3.0 * pixels)) / mean, reference_noise = std::sqrt(noise / (3.0 * pixels)) / mean;
        std::printf("%9.2f %10.3f %12.3f %14.4f %16.4f\n", double(roughness), whitted_seconds, reference_seconds, error, reference_noise);
        std::fprintf(csv, "%.2f,%.4f,%.4f,%.6f,%.6f,%d\n", double(roughness), whitted_seconds, reference_seconds, error, reference_noise, pixels);
    }
    std::fclose(csv);
    std::printf("wrote %s\n", path.c_str());
    return 0;
}
