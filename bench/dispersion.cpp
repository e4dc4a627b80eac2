// SPDX-License-Identifier: MIT
// Dispersion in Whitted: error against time for the number of wavelength bands white
// light splits into at a dispersive interface. The scene: a 60-degree prism of Schott
// F2 flint seen side-on over a black-and-white checkered floor and wall, so every edge
// seen through it fans into colours. Error: RMSE against the same render with 64 bands.
// Time: seconds per render, the minimum of 3. Output: results/dispersion.csv, and the
// 1-band and 64-band pictures as dispersion_1.png and dispersion_64.png.
//   bench_dispersion [results-folder]
#include "common.hpp"

#include <prism/io/image.hpp>

#include <cmath>
#include <cstdio>

namespace {

using T = float;
using namespace prism;

auto scene()
{
    // Prism along x: apex up, base on y = 0.3, side 1.6.
    const T s = T(1.6), y0 = T(0.3), h = s * std::sqrt(T(3)) / 2;
    const Vec3<T> front{0, T(0.5), std::sqrt(T(3)) / 2}, back{0, T(0.5), -std::sqrt(T(3)) / 2};
    auto solid = intersection_of(Plane<T>::through({0, y0, s / 2}, front), Plane<T>::through({0, y0, -s / 2}, back),
                                 Plane<T>({0, -1, 0}, -y0), Box<T>({T(-2), y0 - T(0.01), -s / 2 - T(0.01)}, {T(2), y0 + h + T(0.01), s / 2 + T(0.01)}));
    Scene scene{Lights{DirectionalLight<T>{.direction = {T(0.2), T(-0.6), T(-1)}, .irradiance = Rgb<T>(T(3))}},
                Object{Plane<T>({0, 0, 1}, T(-3)), Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(T(0.95)), .odd = Rgb<T>(T(0.02)), .size = T(0.25)}}},
                Object{Plane<T>({0, 1, 0}, 0), Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(T(0.95)), .odd = Rgb<T>(T(0.02)), .size = T(0.25)}}},
                Object{std::move(solid), DispersiveDielectric<T>{.glass = glass::f2<double>}}};
    scene.background = Rgb<T>(T(0.6));
    scene.ambient = Rgb<T>(T(0.2));
    return scene;
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    const auto s = scene();
    const Camera<T> camera{.position = {T(0.3), T(1.2), T(4.5)}, .look_at = {0, T(0.95), 0}, .up = {0, 1, 0}, .fov = 30};
    const RenderConfig config{.width = 320, .height = 240, .spp = 1, .threads = 1, .progress = false};
    const Film reference = render(camera, Whitted(s, {.dispersion_bands = 64}), config);
    bench::Csv csv(out / "dispersion.csv", "bands,rmse,seconds");
    std::printf("F2 prism over a checkered floor, 320x240, 1 spp, 1 thread; error against 64 bands\n");
    for (const int bands : {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64}) {
        const Whitted integrator(s, {.dispersion_bands = bands});
        Film film = reference;
        const double seconds = bench::min_seconds(3, [&] { film = render(camera, integrator, config); });
        const double error = bench::rmse(film, reference);
        std::printf("%3d bands: RMSE %.5f  %.3f s\n", bands, error, seconds);
        csv.row("%d,%.6e,%.4f", bands, error, seconds);
        if (bands == 1 || bands == 64) write_png(film, out / ("dispersion_" + std::to_string(bands) + ".png"));
    }
    return 0;
}
