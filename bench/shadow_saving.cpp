// SPDX-License-Identifier: MIT
// Shadow rays saved by the photons' say (Jensen and Christensen 1995), in the Cornell box
// with its physical point light and under its ceiling light, an area light (200 000
// global photons, the global map read directly; caustics on in the box with glass).
//
// For every pixel's first diffuse point the camera sees, ask the `visibility_k` nearest
// global photons: the fraction of points where they decide (all direct or all shadow) is
// the fraction of shadow rays saved there (one per point for the point light, the
// 4 x 4 = 16 of its grid for the area light), and each decision is checked against what
// the shadow rays it replaces see (for the area light, 32 x 32 rays to its points: a
// decision is wrong where they see between 0.1 % and 99.9 % of it). Then the whole picture
// is rendered with and without the saving (same seed): the time ratio, the image
// difference, and each image's RMSE against a render of 16 times the photons, so that the
// saving's error is set against the error the method has anyway. Output:
// results/shadow_saving.csv.
//   bench_shadow_saving [results-folder]
#include "common.hpp"
#include "scenes/cornell.hpp"

#include <cstdio>
#include <string>

namespace {

template <class SceneT>
void measure(const SceneT& scene, const std::string& name, bool caustics, int shadow_rays, bench::Csv& csv)
{
    constexpr int size = 512;
    using Mapper = prism::PhotonMapper<SceneT>;
    const auto camera = scenes::cornell_camera<float>();
    const prism::RenderConfig config{.width = size, .height = size, .spp = 1, .threads = 2, .seed = 1, .progress = false};
    const std::size_t photons = 200000, caustic_photons = caustics ? 200000 : 0;
    const Mapper plain(scene, {.tracing = {.global_photons = photons, .caustic_photons = caustic_photons, .seed = 1}, .gather_rays = 0});
    prism::Film reference(1, 1), plain_film(1, 1);
    const double plain_seconds = bench::min_seconds(3, [&] { plain_film = prism::render(camera, plain, config); });
    {
        const Mapper fine(scene, {.tracing = {.global_photons = 16 * photons, .caustic_photons = 16 * caustic_photons, .seed = 2}, .gather_rays = 0});
        reference = prism::render(camera, fine, config);
    }
    const double plain_error = bench::rmse(plain_film, reference);
    std::printf("%s %dx%d, shadow rays skipped where the k nearest global photons agree (%d a point otherwise); "
                "without: %.3f s, RMSE %.2e against 16 times the photons:\n",
                name.c_str(), size, size, shadow_rays, plain_seconds, plain_error);
    for (const std::size_t k : {std::size_t(8), std::size_t(16), std::size_t(32), std::size_t(64)}) {
        const Mapper saving(scene, {.tracing = {.global_photons = photons, .caustic_photons = caustic_photons, .seed = 1}, .gather_rays = 0,
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
                // What the shadow rays see: the share of the light's samples (strata centres
                // of a 32 x 32 grid for an area light) that reach the point.
                double seen = 0, all = 0;
                prism::for_each_light_arriving<prism::ShadowsThroughGlass::blocked>(scene, c, prism::LightSampling{nullptr, 32},
                                                                                     [&](const prism::LightSample<float>&, const prism::Rgb<float>& v, float) {
                                                                                         seen += v.x > 0.0f ? 1 : 0;
                                                                                         all += 1;
                                                                                     });
                const double share = all > 0 ? seen / all : 0.0;
                wrong += *said ? share < 0.999 : share > 0.001;
            }
        prism::Film film(1, 1);
        const double seconds = bench::min_seconds(3, [&] { film = prism::render(camera, saving, config); });
        double largest = 0;
        for (std::size_t i = 0; i < film.pixels().size(); ++i)
            for (int ch = 0; ch < 3; ++ch) largest = std::max(largest, double(std::abs(film.pixels()[i][ch] - plain_film.pixels()[i][ch])));
        const double difference = bench::rmse(film, plain_film), error = bench::rmse(film, reference);
        const double saved = double(decided) / double(points);
        std::printf("  k = %2zu: %5.1f %% of %ld first diffuse points decided by photons (%.1f %% of their shadow rays saved), %ld wrongly (%.3f %%); "
                    "render %.3f s against %.3f s (%.2fx); RMSE against the plain render %.2e (largest %.3f), against 16 times the photons %.2e (plain %.2e)\n",
                    k, 100.0 * saved, points, 100.0 * saved, wrong, 100.0 * double(wrong) / double(points), seconds, plain_seconds,
                    seconds / plain_seconds, difference, largest, error, plain_error);
        csv.row("%s,%zu,%d,%.5f,%.5f,%.4f,%.4f,%.6g,%.6g,%.6g,%.6g", name.c_str(), k, shadow_rays, saved, double(wrong) / double(points), seconds,
                plain_seconds, difference, largest, error, plain_error);
    }
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path results = argc > 1 ? argv[1] : "bench/results";
    bench::Csv csv(results / "shadow_saving.csv",
                   "scene,visibility_k,shadow_rays_per_point,decided,wrong,render_seconds,plain_seconds,rmse_vs_plain,max_difference,rmse_vs_fine,plain_rmse_vs_fine");
    measure(scenes::cornell_scene<float>(true), "point light (the box with glass)", true, 1, csv);
    measure(scenes::cornell_diffuse_area_scene<float>(), "area light (the diffuse box)", false, 16, csv);
    return 0;
}
