// SPDX-License-Identifier: MIT
// Accuracy against time: float vs double, Schlick vs exact Fresnel, samples per pixel.
//
// Each configuration renders the whitted and cornell scenes at 256 x 256 on one thread;
// its error is the RMSE of linear radiance against a double-precision, exact-Fresnel,
// 1024-spp reference of the same scene (sampling and method error together), and
// separately against the double, exact-Fresnel render with the same samples (what the
// scalar type or the Fresnel policy alone changes). Output: results/accuracy.csv.
//   bench_accuracy [results-folder]
#include "common.hpp"
#include "scenes/cornell.hpp"
#include "scenes/whitted.hpp"

#include <array>
#include <cstdio>
#include <vector>

namespace {

constexpr int size = 256;
constexpr int reference_spp = 1024;

template <prism::Scalar T, class Fresnel>
prism::Film render_scene(const char* name, int spp, int threads)
{
    const prism::RenderConfig config{.width = size, .height = size, .spp = spp, .threads = unsigned(threads), .seed = 1, .progress = false};
    if (std::string(name) == "cornell") {
        const auto scene = scenes::cornell_scene<T, Fresnel>();
        return prism::render(scenes::cornell_camera<T>(), prism::Whitted(scene), config);
    }
    const auto scene = scenes::whitted_scene<T, Fresnel>();
    return prism::render(scenes::whitted_camera<T>(), prism::Whitted(scene), config);
}

constexpr std::array spps{1, 4, 16, 64};

template <prism::Scalar T, class Fresnel>
void measure(bench::Csv& csv, const char* scene, const char* scalar, const char* fresnel, const prism::Film& reference,
             const std::vector<prism::Film>& same_samples)
{
    for (std::size_t i = 0; i < spps.size(); ++i) {
        prism::Film film(1, 1);
        const double seconds = bench::min_seconds(3, [&] { film = render_scene<T, Fresnel>(scene, spps[i], 1); });
        const double error = bench::rmse(film, reference);
        const double method_error = bench::rmse(film, same_samples[i]);
        csv.row("%s,%s,%s,%d,%.6f,%.8g,%.8g", scene, scalar, fresnel, spps[i], seconds, error, method_error);
        std::printf("%-8s %-6s %-7s spp %3d  %8.4f s  rmse %.3e  vs double exact, same samples %.3e\n", scene, scalar, fresnel,
                    spps[i], seconds, error, method_error);
    }
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    bench::Csv csv(out / "accuracy.csv", "scene,scalar,fresnel,spp,seconds,rmse,rmse_same_samples");
    for (const char* scene : {"whitted", "cornell"}) {
        std::printf("%s: rendering the %d-spp double reference...\n", scene, reference_spp);
        const prism::Film reference = render_scene<double, prism::ExactFresnel>(scene, reference_spp, 0);
        std::vector<prism::Film> same_samples;
        for (int spp : spps) same_samples.push_back(render_scene<double, prism::ExactFresnel>(scene, spp, 0));
        measure<float, prism::ExactFresnel>(csv, scene, "float", "exact", reference, same_samples);
        measure<double, prism::ExactFresnel>(csv, scene, "double", "exact", reference, same_samples);
        measure<float, prism::SchlickFresnel>(csv, scene, "float", "schlick", reference, same_samples);
        measure<double, prism::SchlickFresnel>(csv, scene, "double", "schlick", reference, same_samples);
    }
    return 0;
}
