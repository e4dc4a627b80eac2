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

#include <prism/prism.hpp>

#include <cmath>

namespace {

using T = float;
using prism::Vec3;

/// Rotate (x, y) by `angle` about the z axis.
Vec3<T> rotated(const Vec3<T>& v, T angle)
{
    return {v.x * std::cos(angle) - v.y * std::sin(angle), v.x * std::sin(angle) + v.y * std::cos(angle), v.z};
}

constexpr T pi = prism::pi<T>;
constexpr T tilt = T(-34) * pi / T(180); ///< the whole set-up turned so that the sunbeam descends
const Vec3<T> centre{T(0), T(4.2), T(0)};  ///< where the prism's base centre sits

/// A prism of apex 60 degrees and side 2, 3 deep along z, apex up before the tilt.
auto prism_solid()
{
    using namespace prism;
    const T half = T(1), height = std::sqrt(T(3));
    const Vec3<T> left = rotated({-std::sqrt(T(3)) / 2, T(0.5), 0}, tilt), right = rotated({std::sqrt(T(3)) / 2, T(0.5), 0}, tilt),
                  base = rotated({0, -1, 0}, tilt);
    const Vec3<T> a = centre + rotated({-half, 0, 0}, tilt), b = centre + rotated({half, 0, 0}, tilt), apex = centre + rotated({0, height, 0}, tilt);
    const Vec3<T> lo = component_min(component_min(a, b), apex) - Vec3<T>(T(0.01)), hi = component_max(component_max(a, b), apex) + Vec3<T>(T(0.01));
    return intersection_of(Plane<T>::through(a, left), Plane<T>::through(b, right), Plane<T>::through(a, base),
                           Box<T>({lo.x, lo.y, T(-1.5)}, {hi.x, hi.y, T(1.5)}));
}

/// Sunlight entering the prism's left face at the minimum-deviation angle for F2's d line.
Vec3<T> sunbeam()
{
    const T theta1 = std::asin(T(prism::glass::f2<double>.index(prism::fraunhofer::d)) * T(0.5));
    const Vec3<T> inward = rotated({std::sqrt(T(3)) / 2, T(-0.5), 0}, tilt), along = rotated({T(0.5), std::sqrt(T(3)) / 2, 0}, tilt);
    return std::cos(theta1) * inward + std::sin(theta1) * along;
}

template <class Glass>
auto rainbow_scene(const Glass& glass)
{
    using namespace prism;
    const Vec3<T> beam = sunbeam();
    // A black screen across the beam, 3 before the prism's left face, with a slit 0.25
    // wide aimed at the face's middle: a box with a slot cut out, turned with the beam.
    const Vec3<T> face_middle = centre + rotated({T(-0.5), std::sqrt(T(3)) / 2 * T(0.5), 0}, tilt);
    const Vec3<T> slit = face_middle - T(3) * beam;
    const T screen_degrees = std::atan2(beam.y, beam.x) * T(180) / pi; // the screen is normal to the beam
    const Transform<T> to_screen = Transform<T>::rotate_z(screen_degrees).then(Transform<T>::translate(slit));
    auto screen = Transformed{difference_of(Box<T>({T(-0.05), T(-40), T(-1000)}, {T(0.05), T(40), T(1000)}),
                                            Box<T>({T(-0.1), T(-0.125), T(-1)}, {T(0.1), T(0.125), T(1)})),
                              to_screen};
    // The sun, and a dim lamp high above on this side of the screen, so the room shows.
    Scene scene{Lights{DirectionalLight<T>{.direction = beam, .irradiance = Rgb<T>(T(12))},
                       PointLight<T>{.position = {T(3), T(12), T(8)}, .intensity = Rgb<T>(T(12))}},
                Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.85))}, .kd = 1, .ka = 1}},
                Object{std::move(screen), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.03))}, .kd = 1, .ka = 1}},
                Object{prism_solid(), glass}};
    scene.background = {T(0.01), T(0.01), T(0.015)};
    return scene;
}

/// The prism alone in a dark hazy room, lit by a narrow white beam aimed at its left face at
/// F2's minimum deviation, from a projector 6 away.
auto hazy_scene()
{
    using namespace prism;
    const Vec3<T> beam = sunbeam();
    const Vec3<T> face_middle = centre + rotated({T(-0.5), std::sqrt(T(3)) / 2 * T(0.5), 0}, tilt);
    return Scene{Lights{SpotLight<T>{.position = face_middle - T(6) * beam, .direction = beam, .intensity = Rgb<T>(T(50000)), .inner_angle = T(0.6),
                                     .outer_angle = T(0.8)}},
                 Object{Plane<T>({0, 1, 0}, 0), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.85))}, .kd = 1, .ka = 0}},
                 Object{prism_solid(), DispersiveDielectric<T>{.glass = glass::f2<double>}}};
}

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
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
        const Camera<T> camera{.position = {T(-1.5), T(8.5), T(9)}, .look_at = {T(1.4), T(2.4), T(0)}, .up = {0, 1, 0}, .fov = 50};
        const auto scene = rainbow_scene(DispersiveDielectric<T>{.glass = glass::f2<double>});
        examples::save(examples::render_by_method("prism_rainbow", scene, camera, options), options);
        const auto plain = rainbow_scene(Dielectric<T>{.ior = T(glass::f2<double>.index(fraunhofer::d))});
        examples::save(examples::render_by_method("prism_rainbow_plain", plain, camera, options), options);
        // In haze: 8 % of the light scattered per unit length, mostly forward, none absorbed;
        // the camera stands outside it.
        const auto hazy = hazy_scene();
        using Air = FilledAir<Fog<T>>;
        const Air haze{.medium = {.scattering = Rgb<T>(T(0.08)), .phase = {.g = T(0.5)}}, .region = {{-12, 0, -10}, {14, 7, 6}}};
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
