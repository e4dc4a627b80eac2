// SPDX-License-Identifier: MIT
// mirage: a hot road seen through a telephoto lens, by Whitted ray tracing through
// graded-index air. Air over a road 30 K hotter than the air above has an index lower by
// 3e-5 at the road, recovering over 0.3 m (HeatedLayer); rays looking down at less than
// about 0.44 degrees turn before they reach the road and rise again, so the sky shows on
// the road like water and distant objects stand on their own upside-down images (the
// inferior mirage). Then a superior mirage over a cold sea: warm air above 25 m (an
// index 1.2e-5 lower, over about 3 m) bends rising rays back down, so a ship 8 km away
// looms higher and taller, and a band of distant sea shows in the sky. Each beside the
// same scene in uniform air. Last, the hot road in haze: fog filling the graded air, the
// sun's light scattered once along every curved ray, so the haze itself is mirrored in the
// road with the sky.
#include "cli.hpp"

#include <prism/prism.hpp>

#include <cmath>

namespace {

using T = double; // metres over kilometres, and an index 3e-5 below 1.000293

template <class... Extra>
auto road_scene()
{
    using namespace prism;
    Scene scene{Lights{DirectionalLight<T>{.direction = {T(-0.3), T(-0.6), T(0.4)}, .irradiance = Rgb<T>(T(3))}},
                Object{Plane<T>({0, 1, 0}, 0), Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(T(0.32)), .odd = Rgb<T>(T(0.22)), .size = T(4)}}},
                Object{Sphere<T>({T(420), T(2.2), T(-3)}, T(2.2)), Diffuse<T>{.albedo = {.color = {T(0.8), T(0.12), T(0.08)}}}},
                Object{Sphere<T>({T(560), T(4), T(9)}, T(4)), Diffuse<T>{.albedo = {.color = {T(0.15), T(0.55), T(0.15)}}}},
                Object{Box<T>({T(320), T(0), T(6)}, {T(321), T(7), T(7)}), Diffuse<T>{.albedo = {.color = Rgb<T>(T(0.9))}}},
                Object{Box<T>({T(700), T(0), T(-20)}, {T(720), T(9), T(-4)}), Diffuse<T>{.albedo = {.color = {T(0.75), T(0.65), T(0.45)}}}}};
    scene.background = {T(0.45), T(0.62), T(0.9)};
    scene.ambient = Rgb<T>(T(0.25));
    return scene;
}

/// The index over a cold sea under an inversion: warmer, thinner air above about 25 m.
struct Inversion {
    T operator()(const prism::Vec3<T>& p) const { return T(1.000293) - T(1.2e-5) * (T(1) + std::tanh((p.y - T(25)) / T(3))) / T(2); }
};

auto sea_scene()
{
    using namespace prism;
    Scene scene{Lights{DirectionalLight<T>{.direction = {T(-0.3), T(-0.5), T(0.4)}, .irradiance = Rgb<T>(T(3))}},
                Object{Plane<T>({0, 1, 0}, 0),
                       Diffuse<T, Checker<T>>{.albedo = {.even = {T(0.05), T(0.12), T(0.2)}, .odd = {T(0.06), T(0.14), T(0.24)}, .size = T(20)}}},
                Object{Box<T>({T(8000), T(0), T(-60)}, {T(8100), T(12), T(60)}), Diffuse<T>{.albedo = {.color = {T(0.8), T(0.8), T(0.75)}}}},
                Object{Box<T>({T(8030), T(12), T(-15)}, {T(8060), T(30), T(15)}), Diffuse<T>{.albedo = {.color = {T(0.7), T(0.2), T(0.1)}}}}};
    scene.background = {T(0.5), T(0.65), T(0.9)};
    scene.ambient = Rgb<T>(T(0.25));
    return scene;
}

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        examples::Options options;
        options.images = {"mirage", "mirage_plain", "superior_mirage", "superior_mirage_plain", "mirage_haze"}; // checked before rendering, written together after
        options.render.width = 640;
        options.render.height = 240;
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "an inferior mirage over a hot road and a superior mirage over a cold sea (graded-index air), beside uniform air; the road in haze"))
            return 0;
        const Camera<T> camera{.position = {0, T(1.5), 0}, .look_at = {T(500), T(1.0), T(2)}, .up = {0, 1, 0}, .fov = T(5)};
        const auto scene = road_scene();
        const GradedAir<HeatedLayer<T>> hot_air{.field = {.n_air = T(1.000293), .drop = T(3e-5), .thickness = T(0.3)},
                                                .region = {{T(-5000), T(-1), T(-5000)}, {T(5000), T(4), T(5000)}},
                                                .stepping = {.tolerance = T(1e-5), .first_step = T(1), .max_step = T(25)}};
        const Whitted integrator(scene, {}, hot_air);
        examples::save(examples::timed_render("mirage", camera, integrator, options), options);
        const Whitted straight(scene);
        examples::save(examples::timed_render("mirage_plain", camera, straight, options), options);

        const Camera<T> sea_camera{.position = {0, T(3), 0}, .look_at = {T(8000), T(14), T(0)}, .up = {0, 1, 0}, .fov = T(2)};
        const auto sea = sea_scene();
        const GradedAir<IndexFunction<T, Inversion>> inversion{.field = {.function = Inversion{}, .h = T(0.01)},
                                                               .region = {{T(-1000), T(-1), T(-9000)}, {T(9000), T(60), T(9000)}},
                                                               .stepping = {.tolerance = T(1e-3), .first_step = T(5), .max_step = T(400)}};
        const Whitted looming(sea, {}, inversion);
        examples::save(examples::timed_render("superior_mirage", sea_camera, looming, options), options);
        const Whitted sea_straight(sea);
        examples::save(examples::timed_render("superior_mirage_plain", sea_camera, sea_straight, options), options);

        // Haze over the road, bluish and scattering forward, to 1.2 km: the air it fills is
        // the hot air above, so it scatters along the same curved rays.
        const FilledAir<Fog<T>, GradedAir<HeatedLayer<T>>> haze{
            .medium = {.scattering = {T(0.45e-3), T(0.6e-3), T(0.85e-3)}, .phase = {.g = T(0.6)}},
            .region = {{T(-10), T(-1), T(-600)}, {T(1200), T(120), T(600)}},
            .base = hot_air};
        const Whitted hazy(scene, {.march_steps = 4}, haze);
        examples::save(examples::timed_render("mirage_haze", camera, hazy, options), options);
        return 0;
    });
}
