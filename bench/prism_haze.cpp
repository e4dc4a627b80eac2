// SPDX-License-Identifier: MIT
// The namesake in haze (examples/prism_rainbow.cpp's prism_haze) by the estimators that can
// render it: bidirectional path tracing, vertex connection and merging, and progressive
// photon mapping as the example configured it before BDPT took its place. Error: RMSE in
// the display range (each channel clamped to [0, 1], what a picture shows) against a long
// BDPT render of another seed, over the whole image and over four regions (the fan of
// colours in the haze, its spot on the floor, the white beam, the prism's lit face). Time:
// seconds per render, the minimum of 2 interleaved runs. Output: results/prism_haze.csv.
//   bench_prism_haze [results-folder] [width] [reference passes]
#include "common.hpp"
#include "scenes/namesake.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace prism;
using T = float;

/// A region of the image in fractions of its width and height: [x0, x1) x [y0, y1).
struct Region {
    const char* name;
    double x0, x1, y0, y1;
};

/// The regions, placed on the 320 x 200 picture and scaled with it.
constexpr std::array<Region, 5> regions{{{"all", 0, 1, 0, 1},
                                         {"fan", 150.0 / 320, 215.0 / 320, 70.0 / 200, 150.0 / 200},
                                         {"spot", 190.0 / 320, 220.0 / 320, 135.0 / 200, 155.0 / 200},
                                         {"beam", 0, 95.0 / 320, 20.0 / 200, 40.0 / 200},
                                         {"prism face", 85.0 / 320, 160.0 / 320, 20.0 / 200, 90.0 / 200}}};

/// Display-range RMSE of `a` against `reference` over a region.
double display_rmse(const Film& a, const Film& reference, const Region& r)
{
    const int x0 = int(r.x0 * a.width()), x1 = int(r.x1 * a.width()), y0 = int(r.y0 * a.height()), y1 = int(r.y1 * a.height());
    double sum = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) {
                const double d = std::clamp(double(a.at(x, y)[c]), 0.0, 1.0) - std::clamp(double(reference.at(x, y)[c]), 0.0, 1.0);
                sum += d * d;
            }
    return std::sqrt(sum / (3.0 * double(x1 - x0) * double(y1 - y0)));
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    const int width = argc > 2 ? std::stoi(argv[2]) : 320, height = width * 5 / 8;
    const int reference_passes = argc > 3 ? std::stoi(argv[3]) : 1024;
    const auto scene = scenes::namesake::hazy_scene();
    using S = std::remove_cvref_t<decltype(scene)>;
    using Air = FilledAir<Fog<T>>;
    const Air haze = scenes::namesake::haze();
    const Camera<T> camera = scenes::namesake::camera();
    const auto config = [&](int passes, std::uint64_t seed) { return RenderConfig{.width = width, .height = height, .spp = passes, .seed = seed, .progress = false}; };
    const auto bidirectional = [&](BidirectionalMethod method, int passes, std::uint64_t seed) {
        return render(camera, Bidirectional(scene, {.method = method}, haze), config(passes, seed));
    };
    const auto progressive = [&](int passes, std::uint64_t seed) {
        ProgressiveConfig<S, Air> pc;
        pc.pass.tracing.global_photons = 20000;
        pc.pass.tracing.caustic_photons = 400000;
        pc.pass.tracing.seed = seed;
        pc.pass.caustic.radius = 0.04f;
        pc.pass.global.radius = 0.25f;
        pc.pass.volume_radius = 0.05f;
        pc.pass.indirect_volume_radius = 0.3f;
        pc.pass.single_scattering = true;
        return render(camera, ProgressivePhotonMapper<S, Air>(scene, pc, haze), config(passes, seed));
    };
    std::printf("prism_haze: the reference, BDPT %d passes at %d x %d\n", reference_passes, width, height);
    const Film reference = bidirectional(BidirectionalMethod::bdpt, reference_passes, 100);
    struct Run {
        std::string method;
        int passes;
    };
    const std::array<Run, 10> runs{{{"bdpt", 8}, {"bdpt", 16}, {"bdpt", 32}, {"bdpt", 64}, {"progressive", 6}, {"progressive", 12}, {"progressive", 24}, {"progressive", 48}, {"vcm", 16}, {"vcm", 64}}};
    std::array<double, runs.size()> seconds;
    seconds.fill(1e300);
    std::vector<std::optional<Film>> films(runs.size());
    for (int round = 0; round < 2; ++round)
        for (std::size_t i = 0; i < runs.size(); ++i) {
            const Run& r = runs[i];
            const auto start = std::chrono::steady_clock::now();
            Film f = r.method == "progressive" ? progressive(r.passes, 1)
                                               : bidirectional(r.method == "vcm" ? BidirectionalMethod::vcm : BidirectionalMethod::bdpt, r.passes, 1);
            seconds[i] = std::min(seconds[i], std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            films[i] = std::move(f);
        }
    std::string header = "method,passes,seconds";
    for (const Region& r : regions) header += std::string(",rmse_") + r.name;
    bench::Csv csv(out / "prism_haze.csv", header);
    for (std::size_t i = 0; i < runs.size(); ++i) {
        std::array<double, regions.size()> e{};
        for (std::size_t k = 0; k < regions.size(); ++k) e[k] = display_rmse(*films[i], reference, regions[k]);
        std::printf("%-12s %3d passes %7.2f s   all %.4f  fan %.4f  spot %.4f  beam %.4f  prism face %.4f\n", runs[i].method.c_str(), runs[i].passes, seconds[i], e[0], e[1], e[2],
                    e[3], e[4]);
        csv.row("%s,%d,%.3f,%.5f,%.5f,%.5f,%.5f,%.5f", runs[i].method.c_str(), runs[i].passes, seconds[i], e[0], e[1], e[2], e[3], e[4]);
    }
    return 0;
}
