// SPDX-License-Identifier: MIT
// Shadow rays saved by the photons' say (Jensen and Christensen 1995), in the Cornell box
// with its physical light (200 000 global photons, caustics on, global map read directly).
//
// For every pixel's first diffuse point the camera sees, ask the `visibility_k` nearest
// global photons: the fraction of points where they decide (all direct or all shadow) is
// the fraction of shadow rays saved there, and each decision is checked against the
// shadow ray it replaces. Then the whole picture is rendered with and without the saving
// (same seed): the time ratio and the image difference. Output: results/shadow_saving.csv.
//   bench_shadow_saving [results-folder]
#include "common.hpp"
#include "scenes/cornell.hpp"

#include <cstdio>

int main(int argc, char** argv)
{
    const std::filesystem::path results = argc > 1 ? argv[1] : "bench/results";
    constexpr int size = 512;
    const auto scene = scenes::cornell_scene<float>(true);
    using Scene = std::remove_cvref_t<decltype(scene)>;
    using Mapper = prism::PhotonMapper<Scene>;
    const auto camera = scenes::cornell_camera<float>();
    const prism::RenderConfig config{.width = size, .height = size, .spp = 1, .threads = 2, .seed = 1, .progress = false};
    const Mapper plain(scene, {.tracing = {.global_photons = 200000, .caustic_photons = 200000, .seed = 1}, .gather_rays = 0});
    bench::Csv csv(results / "shadow_saving.csv", "visibility_k,decided,wrong,render_seconds,plain_seconds,rmse,max_difference");
    prism::Film reference(1, 1);
    const double plain_seconds = bench::min_seconds(3, [&] { reference = prism::render(camera, plain, config); });
    std::printf("Cornell box %dx%d, shadow rays skipped where the k nearest global photons agree:\n", size, size);
    for (const std::size_t k : {std::size_t(8), std::size_t(16), std::size_t(32), std::size_t(64)}) {
        const Mapper saving(scene, {.tracing = {.global_photons = 200000, .caustic_photons = 200000, .seed = 1}, .gather_rays = 0,
                                    .visibility_k = k});
        const prism::CameraRays<float> rays = camera.rays(size, size);
        long points = 0, decided = 0, wrong = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const auto hit = scene.closest_hit(rays.ray(float(x) + 0.5f, float(y) + 0.5f), {0.0f, prism::infinity<float>});
                if (!hit) continue;
                const bool diffuse = scene.visit_material(*hit, []<class M>(const M&) { return prism::has_diffuse<M>; });
                if (!diffuse) continue;
                const prism::Crossing<float>& c = hit->crossing;
                const prism::Vec3<float> n = c.facing_normal();
                ++points;
                const auto said = saving.visibility_from_photons(c.point, n);
                if (!said) continue;
                ++decided;
                bool lit = false;
                prism::for_each_light_arriving<prism::ShadowsThroughGlass::blocked>(scene, c, [&](const prism::LightSample<float>&, const prism::Rgb<float>& v, float) {
                    lit = v.x > 0.0f;
                });
                wrong += *said != lit;
            }
        prism::Film film(1, 1);
        const double seconds = bench::min_seconds(3, [&] { film = prism::render(camera, saving, config); });
        double largest = 0;
        for (std::size_t i = 0; i < film.pixels().size(); ++i)
            for (int ch = 0; ch < 3; ++ch) largest = std::max(largest, double(std::abs(film.pixels()[i][ch] - reference.pixels()[i][ch])));
        const double rmse = bench::rmse(film, reference);
        std::printf("  k = %2zu: %5.1f %% of %ld first diffuse points decided by photons (shadow ray saved), %ld wrongly (%.3f %%); "
                    "render %.3f s against %.3f s (%.2fx); image RMSE %.2e, largest difference %.3f (linear radiance)\n",
                    k, 100.0 * double(decided) / double(points), points, wrong, 100.0 * double(wrong) / double(points), seconds,
                    plain_seconds, seconds / plain_seconds, rmse, largest);
        csv.row("%zu,%.5f,%.5f,%.4f,%.4f,%.6g,%.6g", k, double(decided) / double(points), double(wrong) / double(points), seconds,
                plain_seconds, rmse, largest);
    }
    return 0;
}
