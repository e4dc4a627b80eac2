// SPDX-License-Identifier: MIT
// prism_rainbow: the project's namesake. A beam of white sunlight through a slit meets a
// 60-degree prism of Schott F2 flint (CSG of five half-spaces) at its minimum deviation,
// and fans out into a spectrum on the floor, by photon mapping: each photon takes one
// wavelength where it first refracts and follows F2's Sellmeier index from then on.
// Beside it, the same prism of a glass that does not disperse (n = n_d): one white beam.
// And the prism in haze (prism_haze): a narrow white beam from a projector (a spot light)
// crosses the hazy room, visible by the light the haze scatters, enters the prism and
// leaves it as a fan of colours in the air down to the floor, by bidirectional path
// tracing: light paths take a wavelength band at the prism's first face and are joined to
// the camera wherever they scatter in the haze or land on the floor (`--method
// progressive` renders it by progressive photon mapping, `--method vcm` by VCM).
#include "cli.hpp"
#include "methods.hpp"
#include "scenes/namesake.hpp"

#include <prism/prism.hpp>

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        using namespace scenes::namesake;
        examples::Options options;
        options.images = {"prism_rainbow", "prism_rainbow_plain", "prism_haze"}; // checked before rendering, written together after
        options.render.width = 640;
        options.render.height = 400;
        options.render.spp = 4;
        options.photons = 20000;
        options.caustic_photons = 1000000;
        options.radius = 0.04;
        options.k = 0;
        options.method = "direct"; // its light is the spectrum's caustic; the global map lights the rest
        if (!examples::parse(argc, argv, options, "white light through a flint prism onto the floor: a spectrum (photon mapping)", {.photons = true}))
            return 0;
        const Camera<T> camera = scenes::namesake::camera();
        const auto scene = rainbow_scene(DispersiveDielectric<T>{.glass = glass::f2<double>});
        examples::save(examples::render_by_method("prism_rainbow", scene, camera, options), options);
        const auto plain = rainbow_scene(Dielectric<T>{.ior = T(glass::f2<double>.index(fraunhofer::d))});
        examples::save(examples::render_by_method("prism_rainbow_plain", plain, camera, options), options);
        // In haze (8 % of the light scattered per unit length, mostly forward).
        const auto hazy = hazy_scene();
        using Air = FilledAir<Fog<T>>;
        const Air haze = scenes::namesake::haze();
        examples::Options haze_options = options;
        haze_options.render.spp = 12 * options.render.spp; // passes
        using H = std::remove_cvref_t<decltype(hazy)>;
        if (options.method == "progressive") {
            // Progressive photon mapping: the white beam is single scattering (equiangular
            // samples kept to the projector's cone: clean at any pass count); the fan in the
            // haze and the spectrum on the floor are the caustic photons' (L S S M, L S S D),
            // which fresh photons each pass and a shrinking radius bring to a clean fan;
            // light scattered more than once, the global photons' at a wider radius.
            ProgressiveConfig<H, Air> config;
            config.pass.tracing = examples::photon_tracer_config(options);
            config.pass.tracing.global_photons = options.photons;                 // a pass's
            config.pass.tracing.caustic_photons = 2 * options.caustic_photons / 5; // aimed at the prism
            config.pass.caustic.radius = float(options.radius);
            config.pass.global.radius = 0.25f;
            config.pass.volume_radius = 0.05f;
            config.pass.indirect_volume_radius = 0.3f;
            config.pass.single_scattering = true;
            const ProgressivePhotonMapper<H, Air> mapper(hazy, config, haze);
            examples::save(examples::timed_render("prism_haze", camera, mapper, haze_options), haze_options);
        } else {
            // Bidirectional path tracing (or VCM, --method vcm): the fan in the haze and the
            // spectrum on the floor are light paths through the prism joined to the camera
            // (light tracing, L S S M E and L S S D E), each keeping the band it took at the
            // first face; the white beam is the haze's light samples of the projector and the
            // light paths' first vertices joined to the camera, weighted together.
            const Bidirectional estimator(hazy, {.method = options.method == "vcm" ? BidirectionalMethod::vcm : BidirectionalMethod::bdpt}, haze);
            examples::save(examples::timed_render("prism_haze", camera, estimator, haze_options), haze_options);
        }
        return 0;
    });
}
