// SPDX-License-Identifier: MIT
// glass_of_water: a glass of water with a pencil in it, by Whitted ray tracing with
// nested dielectrics. The water is modelled to overlap the glass's inner wall by 1 mm
// (no coincident surfaces); the glass has the higher priority, so inside the wall the
// medium is glass and the water-glass interface refracts at 1.33 / 1.5. Beside it, what
// a renderer without nesting must do instead: leave a thin air gap between water and
// glass, which adds two air interfaces (reflections, total internal reflection at the
// wall) that a real glass of water does not have.
#include "cli.hpp"

#include <prism/prism.hpp>

namespace {

using T = float;

/// A tumbler: outer radius 1, wall 0.08, base 0.15 thick, 2.6 tall, on the table at y = 0.
auto tumbler()
{
    using namespace prism;
    const Vec3<T> up{0, 1, 0};
    auto outer = intersection_of(Quadric<T>::cylinder({0, 0, 0}, up, T(1)), Box<T>({T(-1.01), T(0), T(-1.01)}, {T(1.01), T(2.6), T(1.01)}));
    auto inner = intersection_of(Quadric<T>::cylinder({0, 0, 0}, up, T(0.92)), Box<T>({T(-1), T(0.15), T(-1)}, {T(1), T(2.7), T(1)}));
    return difference_of(outer, inner);
}

/// The water: a cylinder of radius r from the base's top (minus `sink`) to y = 1.9.
auto water(T radius, T bottom)
{
    using namespace prism;
    return intersection_of(Quadric<T>::cylinder({0, 0, 0}, {0, 1, 0}, radius), Box<T>({-radius - T(0.01), bottom, -radius - T(0.01)}, {radius + T(0.01), T(1.9), radius + T(0.01)}));
}

template <class Water>
auto scene_with(Water liquid)
{
    using namespace prism;
    // A pencil leaning in the glass: a thin yellow box, turned 25 degrees from the vertical.
    const Transform<T> lean = Transform<T>::rotate_z(T(-25)).then(Transform<T>::translate({T(0.1), T(1.3), T(0)}));
    Scene scene{Lights{DirectionalLight<T>{.direction = {T(-0.4), T(-1), T(-0.6)}, .irradiance = Rgb<T>(T(3))}},
                Object{Plane<T>({0, 1, 0}, 0), Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(T(0.85)), .odd = Rgb<T>(T(0.25)), .size = T(0.5)}}},
                Object{Plane<T>({0, 0, 1}, T(-3)), Diffuse<T>{.albedo = {.color = {T(0.7), T(0.75), T(0.8)}}}},
                Object{tumbler(), Dielectric<T>{.ior = T(1.5), .priority = 2}},
                Object{std::move(liquid), Dielectric<T>{.ior = T(1.33), .interior = {.absorption = {T(0.08), T(0.03), T(0.02)}}, .priority = 1}},
                Object{Transformed{Box<T>({T(-0.06), T(-1.5), T(-0.06)}, {T(0.06), T(1.5), T(0.06)}), lean},
                       Diffuse<T>{.albedo = {.color = {T(0.95), T(0.7), T(0.1)}}}}};
    scene.background = {T(0.6), T(0.7), T(0.85)};
    scene.ambient = Rgb<T>(T(0.2));
    return scene;
}

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        examples::Options options;
        options.images = {"glass_of_water", "glass_of_water_air_gap"}; // checked before rendering, written together after
        options.render.width = 480;
        options.render.height = 480;
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "a glass of water with a pencil in it (nested dielectrics), beside it with an air gap"))
            return 0;
        const Camera<T> camera{.position = {T(0.4), T(2.6), T(6.5)}, .look_at = {T(0), T(1.1), T(0)}, .up = {0, 1, 0}, .fov = 36};
        // Nested: the water overlaps the glass's inner wall and base by 1 mm.
        const auto nested = scene_with(water(T(0.921), T(0.149)));
        const Whitted integrator(nested, {.max_depth = 16});
        examples::save(examples::timed_render("glass_of_water", camera, integrator, options), options);
        // Without nesting: the water stops 1 mm short of the glass, leaving an air gap.
        const auto gap = scene_with(water(T(0.919), T(0.151)));
        const Whitted gap_integrator(gap, {.max_depth = 16});
        examples::save(examples::timed_render("glass_of_water_air_gap", camera, gap_integrator, options), options);
        return 0;
    });
}
