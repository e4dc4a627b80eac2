// SPDX-License-Identifier: MIT
// The photon stage on 1 and 2 threads: tracing the Cornell box's global and caustic
// maps, building their trees, and precomputing the final gather's irradiance. Runs
// alternate between the thread counts (these machines are shared and noisy) and the
// ratio of min and median times is reported; every run's maps must be the same bits.
//
// usage: bench_photon_stage [RESULTS_DIR] [photons per map] [runs]   (default bench/results, 1000000, 5)
#include "common.hpp"
#include "scenes/cornell.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <vector>

namespace {

struct Times {
    double trace_and_build = 0, precompute = 0;
};

Times photon_stage(std::size_t photons, unsigned threads, prism::PhotonMaps& maps)
{
    const auto scene = scenes::cornell_scene<float>(true);
    Times t;
    auto start = std::chrono::steady_clock::now();
    maps = prism::trace_photons(scene, {.global_photons = photons, .caustic_photons = photons, .threads = threads});
    auto now = std::chrono::steady_clock::now();
    t.trace_and_build = std::chrono::duration<double>(now - start).count();
    start = now;
    maps.global.precompute_irradiance<64>(4, threads);
    t.precompute = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return t;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path results = argc > 1 ? argv[1] : "bench/results";
    const std::size_t photons = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1000000;
    const int runs = argc > 3 ? std::atoi(argv[3]) : 5;
    std::vector<double> trace[2], pre[2];
    prism::PhotonMaps reference;
    bool same = true;
    for (int run = 0; run < runs; ++run)
        for (unsigned threads : {1u, 2u}) {
            prism::PhotonMaps maps;
            const Times t = photon_stage(photons, threads, maps);
            trace[threads - 1].push_back(t.trace_and_build);
            pre[threads - 1].push_back(t.precompute);
            if (run == 0 && threads == 1) reference = std::move(maps);
            else same = same && maps.global.photons() == reference.global.photons() && maps.caustic.photons() == reference.caustic.photons();
        }
    bench::Csv csv(results / "photon_stage.csv", "stage,threads,min_s,median_s");
    for (int i = 0; i < 2; ++i) {
        csv.row("trace_and_build,%d,%.4f,%.4f", i + 1, *std::min_element(trace[i].begin(), trace[i].end()), median(trace[i]));
        csv.row("precompute_irradiance,%d,%.4f,%.4f", i + 1, *std::min_element(pre[i].begin(), pre[i].end()), median(pre[i]));
    }
    const auto total = [&](int i, bool use_min) {
        std::vector<double> sums;
        for (std::size_t r = 0; r < trace[i].size(); ++r) sums.push_back(trace[i][r] + pre[i][r]);
        return use_min ? *std::min_element(sums.begin(), sums.end()) : median(sums);
    };
    std::printf("photon stage, %zu global + %zu caustic photons, %d interleaved runs each:\n", photons, photons, runs);
    std::printf("  trace + build trees: 1 thread %.3f s, 2 threads %.3f s (min): %.2fx (median %.2fx)\n", *std::min_element(trace[0].begin(), trace[0].end()),
                *std::min_element(trace[1].begin(), trace[1].end()), *std::min_element(trace[0].begin(), trace[0].end()) / *std::min_element(trace[1].begin(), trace[1].end()),
                median(trace[0]) / median(trace[1]));
    std::printf("  precompute irradiance: %.2fx (min), %.2fx (median)\n", *std::min_element(pre[0].begin(), pre[0].end()) / *std::min_element(pre[1].begin(), pre[1].end()),
                median(pre[0]) / median(pre[1]));
    std::printf("  whole stage: %.2fx (min), %.2fx (median); maps identical for 1 and 2 threads: %s\n", total(0, true) / total(1, true), total(0, false) / total(1, false),
                same ? "yes" : "NO");
    return same ? 0 : 1;
}
