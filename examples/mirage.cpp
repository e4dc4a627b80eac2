// SPDX-License-Identifier: MIT
// mirage: a hot road seen through a telephoto lens, by Whitted ray tracing through
// graded-index air. Air over a road 30 K hotter than the air above has an index lower by
// 3e-5 at the road, recovering over 0.3 m (HeatedLayer); rays looking down at less than
// about 0.44 degrees turn before they reach the road and rise again, so the sky shows on
// the road like water and distant objects stand on their own upside-down images (the
// inferior mirage). Beside it, the same scene in uniform air.
#include "cli.hpp"

#include <prism/io/image.hpp>

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

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        examples::Options options;
        options.render.width = 640;
        options.render.height = 240;
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "an inferior mirage over a hot road (graded-index air), beside uniform air"))
            return 0;
        const Camera<T> camera{.position = {0, T(1.5), 0}, .look_at = {T(500), T(1.0), T(2)}, .up = {0, 1, 0}, .fov = T(5)};
        const auto scene = road_scene();
        const GradedAir<HeatedLayer<T>> hot_air{.field = {.n_air = T(1.000293), .drop = T(3e-5), .thickness = T(0.3)},
                                                .region = {{T(-5000), T(-1), T(-5000)}, {T(5000), T(4), T(5000)}},
                                                .stepping = {.tolerance = T(1e-5), .first_step = T(1), .max_step = T(25)}};
        const Whitted integrator(scene, {}, hot_air);
        write_png(examples::timed_render("mirage", camera, integrator, options.render), options.out / "mirage.png");
        const Whitted straight(scene);
        write_png(examples::timed_render("mirage_plain", camera, straight, options.render), options.out / "mirage_plain.png");
        return 0;
    });
}
