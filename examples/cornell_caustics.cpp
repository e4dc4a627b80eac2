// SPDX-License-Identifier: MIT
// cornell_caustics: the Cornell box of shared/scenes/cornell_caustics.pov, photon-mapped:
// the glass sphere's caustic and the walls' colour bleeding (by default a final gather
// behind an irradiance cache; --method chooses another estimator), and pictures of where
// the global and the caustic photons landed.
//
// With --light povray it renders what POV-Ray does: its no-falloff light, direct light
// and caustics only (POV-Ray's scene has no radiosity, so no global map, and the
// reference takes no diffuse bounce). --povray PNG (POV-Ray's picture with
// Declare=PHOTONS=1) implies it and writes prism | POV-Ray | difference.
#include "cli.hpp"
#include "compare.hpp"
#include "methods.hpp"
#include "scenes/cornell.hpp"

#include <prism/prism.hpp>
#include <prism/io/image.hpp>

#include <chrono>

namespace {

/// Every photon of a map drawn as a dot where the camera sees it, in its own colour.
template <class T>
prism::Film photon_picture(const prism::PhotonMap& map, const prism::Camera<T>& camera, int width, int height, float gain)
{
    prism::Film film(width, height);
    std::vector<prism::Rgb<float>> sum(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), prism::Rgb<float>(0.0f));
    const prism::Vec3<T> forward = prism::normalize(camera.look_at - camera.position);
    const prism::Vec3<T> right = prism::normalize(prism::cross(forward, camera.up));
    const prism::Vec3<T> up = prism::cross(right, forward);
    const T half_width = std::tan(T(0.5) * camera.fov * prism::pi<T> / T(180));
    const T half_height = half_width * T(height) / T(width);
    for (const prism::Photon& photon : map.photons()) {
        if (photon.flags & prism::Photon::shadow) continue;
        const prism::Vec3<T> v = prism::Vec3<T>(photon.position) - camera.position;
        const T depth = prism::dot(v, forward);
        if (depth <= T(0)) continue;
        const T sx = prism::dot(v, right) / (depth * half_width), sy = prism::dot(v, up) / (depth * half_height);
        const int x = static_cast<int>((sx + T(1)) * T(0.5) * T(width)), y = static_cast<int>((T(1) - sy) * T(0.5) * T(height));
        if (x < 0 || y < 0 || x >= width || y >= height) continue;
        sum[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] += photon.power() * gain;
    }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) film.set(x, y, sum[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]);
    return film;
}

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"cornell_caustics", "cornell_global_photons", "cornell_caustic_photons"}; // checked before rendering, written together after
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "the Cornell box with photon-mapped caustics and colour bleeding", {.povray = true, .photons = true})) return 0;
        if (!options.povray.empty()) {
            options.povray_light = true;
            if (options.method == "gather" || options.method == "cache") options.method = "direct";
        }
        if (options.povray_light) {
            // POV-Ray's scene has no radiosity: its light is direct light and caustics only,
            // so no global map (render_by_method: no diffuse bounce for the reference).
            if (options.method == "gather" || options.method == "cache")
                throw std::invalid_argument("--light povray (POV-Ray's model: direct light and caustics, no global light) renders with --method direct, "
                                            "progressive or reference, got '" + options.method + "'");
            options.photons = 0;
        }
        const auto scene = scenes::cornell_scene<float>(!options.povray_light);
        const auto camera = scenes::cornell_camera<float>();
        const examples::Rendered rendered = examples::render_by_method("cornell_caustics", scene, camera, options);
        examples::save(rendered, options, true);
        if (!options.povray.empty()) examples::write_comparison(rendered.image(), options.povray, examples::output_file(options, "cornell_caustics_vs_povray.png"));
        if (options.part) return 0; // the photon pictures below are of the whole image, for one machine to draw
        // Where the photons landed: each photon's power, summed per pixel (one photon per
        // pixel of the global map reads as mid-grey).
        const prism::PhotonMaps maps = prism::trace_photons(scene, examples::photon_tracer_config(options));
        const float gain = float(options.photons) / 200000.0f * 40.0f;
        examples::save_png(photon_picture(maps.global, camera, options.render.width, options.render.height, gain), options, "cornell_global_photons");
        examples::save_png(photon_picture(maps.caustic, camera, options.render.width, options.render.height, gain), options, "cornell_caustic_photons");
        return 0;
    });
}
