// SPDX-License-Identifier: MIT
// metals: gold, silver, copper and aluminium spheres from measured spectral indices
// (Johnson & Christy; Palik), reduced to RGB by integration against the CIE observer,
// beside a constant kr of the same normal-incidence colour (Whitted's model).
#include "cli.hpp"
#include "scenes/sphere_row.hpp"

#include <prism/prism.hpp>

#include <tuple>

namespace {

/// Two coloured balls behind the camera, for the metals to reflect.
auto reflected_balls()
{
    using namespace prism;
    using T = float;
    return std::tuple{Object{Sphere<T>({T(-2), T(2), T(11)}, T(2)), Diffuse<T>{.albedo = {.color = {T(0.2), T(0.4), T(0.8)}}}},
                      Object{Sphere<T>({T(2.5), T(1.5), T(10)}, T(1.5)), Diffuse<T>{.albedo = {.color = {T(0.8), T(0.2), T(0.15)}}}}};
}

template <class Material>
auto metal_row(const Material (&materials)[4])
{
    return std::apply([&](auto... balls) { return scenes::sphere_row(materials, balls...); }, reflected_balls());
}

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"metals", "metals_plain"}; // checked before rendering, written together after
        options.render.width = 720;
        options.render.height = 300;
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "gold, silver, copper and aluminium from measured spectral indices, beside constant kr"))
            return 0;
        using T = float;
        namespace metals = prism::metals;
        const prism::Camera<T> camera = scenes::sphere_row_camera();
        using Measured = prism::Conductor<T, prism::MeasuredConductor<T>>;
        const Measured measured[4] = {prism::measured_metal<T>(metals::gold), prism::measured_metal<T>(metals::silver),
                                      prism::measured_metal<T>(metals::copper), prism::measured_metal<T>(metals::aluminium)};
        // Whitted's conductor: a constant kr, here each metal's own normal-incidence RGB.
        prism::Mirror<T> plain[4];
        for (int i = 0; i < 4; ++i) plain[i].fresnel.kr = measured[i].fresnel.reflectance(1);

        const auto scene = metal_row(measured);
        const prism::Whitted integrator(scene);
        examples::save(examples::timed_render("metals", camera, integrator, options), options);
        const auto plain_scene = metal_row(plain);
        const prism::Whitted plain_integrator(plain_scene);
        examples::save(examples::timed_render("metals_plain", camera, plain_integrator, options), options);
        return 0;
    });
}
