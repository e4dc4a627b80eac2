// SPDX-License-Identifier: MIT
// csg_figures: the classic quadric and CSG figures: an ellipsoid from a general quadric;
// two spheres in union, intersection and difference; a CSG of a CSG; and a glass lens
// made by intersection, refracting through both of its faces. One image each,
// figure_*.png.
#include "cli.hpp"

#include <prism/prism.hpp>

#include <string>

namespace {

using namespace prism;
using T = float;

/// One figure: the shape on a checkered floor in sunlight from the upper left. No
/// ambient: Whitted's rule (ambient only where every light is occluded) would draw a
/// dark line along each terminator, where a surface turning away from the light is
/// still lit, faintly, and so gets no ambient.
template <Shape S, Material M>
void figure(const std::string& name, S shape, M material, const examples::Options& options)
{
    Scene scene{Lights{DirectionalLight<T>{.direction = {0.55f, -0.7f, -0.45f}, .irradiance = Rgb<T>(3.2f)}},
                Object{Plane<T>({0, 1, 0}, 0), Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(0.85f), .odd = Rgb<T>(0.3f), .size = 0.5f}, .ka = 0}},
                Object{std::move(shape), material}};
    scene.background = {0.55f, 0.65f, 0.8f};
    const Camera<T> camera{.position = {0, 2.2f, 5.5f}, .look_at = {0, 1, 0}, .fov = 45};
    const Whitted integrator(scene);
    examples::save(examples::timed_render("figure_" + name, camera, integrator, options), options);
}

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"figure_ellipsoid", "figure_union", "figure_intersection", "figure_difference", "figure_csg_of_csg", "figure_glass_lens"}; // checked before rendering, written together after
        options.render.width = 480;
        options.render.height = 360;
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "quadric and CSG figures: an ellipsoid, union, intersection, difference, a CSG of a CSG, a lens")) return 0;

        const auto red = Diffuse<T>{.albedo = {.color = {0.8f, 0.2f, 0.15f}}, .ka = 0, .phong = 0.4f};
        const auto gold = Diffuse<T>{.albedo = {.color = {0.85f, 0.6f, 0.15f}}, .ka = 0, .phong = 0.4f};
        const Sphere<T> left({-0.45f, 1.0f, 0}, 0.8f), right({0.45f, 1.0f, 0}, 0.8f);

        // An ellipsoid written as a general quadric: semi-axes (1.3, 0.6, 0.7), tilted 25 degrees.
        const auto tilt = Mat3<T>(Transform<T>::rotate_z(25).matrix());
        figure("ellipsoid", Quadric<T>::ellipsoid({0, 1, 0}, {1.3f, 0.6f, 0.7f}, tilt), red, options);
        figure("union", union_of(left, right), red, options);
        figure("intersection", intersection_of(left, right), red, options);
        figure("difference", difference_of(left, right), red, options);
        // A CSG of a CSG: the union of the two spheres, bored through by a cylinder and
        // cut flat by a box from above.
        figure("csg_of_csg",
               difference_of(union_of(left, right), Quadric<T>::cylinder({0, 1, 0}, {0, 0, 1}, 0.35f), Box<T>({-2, 1.5f, -2}, {2, 3, 2})),
               gold, options);
        // A biconvex glass lens stood on its rim and turned 35 degrees: the floor seen
        // through it, refracted by both faces, is turned upside down.
        const auto lens = Transformed(intersection_of(Sphere<T>({0, 0, -1.2f}, 1.5f), Sphere<T>({0, 0, 1.2f}, 1.5f)),
                                      Transform<T>::rotate_y(35).then(Transform<T>::translate({0, 1.0f, 0})));
        figure("glass_lens", lens, Dielectric<T>{.ior = 1.5f, .interior = {.absorption = {0.02f, 0.01f, 0.0f}}}, options);
        return 0;
    });
}
