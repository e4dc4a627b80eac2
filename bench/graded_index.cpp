// SPDX-License-Identifier: MIT
// Error against time for the ways of tracing a ray through graded-index air: Sharma's
// Runge-Kutta-Nystrom step with error control (tolerances 1e-2 to 1e-12), the same with
// fixed steps, and the lecture notes' flat layers with Snell at each boundary (10 to
// 10^5 layers). The field is n(y) = 1 + 0.05 y; a ray leaves the origin 0.3 rad above
// the horizon and is followed to the height y = 4, where the exact answer is
//   x = (K / g) (acosh(n(4) / K) - acosh(n(0) / K)),  K = n(0) cos(0.3)
// (the stratified invariant n cos(theta) = K, integrated). Error: |x - exact|. Time: ns
// per ray, the minimum of 5 runs of 2000 rays. Output: results/graded_index.csv.
//
// Then whole pictures: the mirage over a hot road (examples/mirage.cpp's road) at 160 x 60,
// 1 spp, one thread, rendered through GradedAir at tolerances 1e-2 to 1e-7 and through the
// notes' LayeredAir at 10 to 10^4 layers between the road and 4 m, against GradedAir at
// 1e-9: RMSE against seconds. Output: results/graded_index_image.csv.
//   bench_graded_index [results-folder]
#include "common.hpp"

#include <prism/medium/air.hpp>
#include <prism/medium/graded_index.hpp>

#include <cmath>
#include <cstdio>

namespace {

using prism::CurvedRay;
using prism::Vec3;

constexpr double g = 0.05, theta0 = 0.3, top = 4;
const prism::LinearIndex<double> field{.n0 = 1, .slope = g};

double exact_x()
{
    const double k = std::cos(theta0);
    return k / g * (std::acosh(field.index({0, top, 0}) / k) - std::acosh(1.0 / k));
}

CurvedRay<double> start() { return prism::curved_ray(field, prism::Ray<double>{{0, 0, 0}, {std::cos(theta0), std::sin(theta0), 0}}); }

/// From the last state below the top, the step that lands on it: Newton's method on
/// y(dt) = top, with dy/dt = T_y (quadratic convergence, a few Sharma steps).
double land(const CurvedRay<double>& below)
{
    double dt = (top - below.position.y) / below.optical.y;
    CurvedRay<double> at = prism::sharma_step(field, below, dt);
    for (int i = 0; i < 8 && std::abs(at.position.y - top) > 1e-15 * top; ++i) {
        dt -= (at.position.y - top) / at.optical.y;
        at = prism::sharma_step(field, below, dt);
    }
    return at.position.x;
}

double adaptive(double tolerance)
{
    const prism::AdaptiveStepper stepper(field, {.tolerance = tolerance, .first_step = 0.5, .max_step = 100});
    CurvedRay<double> ray = start();
    double dt = 0;
    for (;;) {
        CurvedRay<double> next = ray;
        stepper.step(next, dt);
        if (next.position.y >= top) return land(ray);
        ray = next;
    }
}

double fixed(double dt)
{
    CurvedRay<double> ray = start();
    for (;;) {
        const CurvedRay<double> next = prism::sharma_step(field, ray, dt);
        if (next.position.y >= top) return land(ray);
        ray = next;
    }
}

double layered(int layers)
{
    const prism::LayeredMedium medium(field, 0.0, top, layers);
    Vec3<double> origin{0, 0, 0}, direction{std::cos(theta0), std::sin(theta0), 0};
    int layer = 0;
    while (medium.step(origin, direction, layer)) {
    }
    return origin.x;
}

template <class F>
void measure(bench::Csv& csv, const char* method, double parameter, F&& trace)
{
    const double exact = exact_x();
    double x = 0;
    const int rays = 2000;
    const double seconds = bench::min_seconds(5, [&] {
        for (int i = 0; i < rays; ++i) x = trace();
    });
    const double error = std::abs(x - exact);
    std::printf("%-9s %-10g error %.3e  %9.1f ns per ray\n", method, parameter, error, 1e9 * seconds / rays);
    csv.row("%s,%g,%.6e,%.3f", method, parameter, error, 1e9 * seconds / rays);
}

/// The hot road of examples/mirage.cpp, smaller.
auto road()
{
    using namespace prism;
    using T = double;
    Scene scene{Lights{DirectionalLight<T>{.direction = {T(-0.3), T(-0.6), T(0.4)}, .irradiance = Rgb<T>(T(3))}},
                Object{Plane<T>({0, 1, 0}, 0), Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(T(0.32)), .odd = Rgb<T>(T(0.22)), .size = T(4)}}},
                Object{Sphere<T>({T(420), T(2.2), T(-3)}, T(2.2)), Diffuse<T>{.albedo = {.color = {T(0.8), T(0.12), T(0.08)}}}},
                Object{Sphere<T>({T(560), T(4), T(9)}, T(4)), Diffuse<T>{.albedo = {.color = {T(0.15), T(0.55), T(0.15)}}}}};
    scene.background = {T(0.45), T(0.62), T(0.9)};
    return scene;
}

void images(const std::filesystem::path& out)
{
    using namespace prism;
    using T = double;
    const auto scene = road();
    const HeatedLayer<T> hot{.n_air = T(1.000293), .drop = T(3e-5), .thickness = T(0.3)};
    const Aabb<T> region{{T(-5000), T(-1), T(-5000)}, {T(5000), T(4), T(5000)}};
    const Camera<T> camera{.position = {0, T(1.5), 0}, .look_at = {T(500), T(1.0), T(2)}, .up = {0, 1, 0}, .fov = T(5)};
    const RenderConfig config{.width = 160, .height = 60, .spp = 1, .threads = 1, .progress = false};
    const auto graded = [&](T tolerance) {
        return GradedAir<HeatedLayer<T>>{.field = hot, .region = region, .stepping = {.tolerance = tolerance, .first_step = T(1), .max_step = T(25)}};
    };
    const Film reference = render(camera, Whitted(scene, {}, graded(T(1e-9))), config);
    bench::Csv csv(out / "graded_index_image.csv", "method,parameter,rmse,seconds");
    std::printf("\nthe hot road, 160x60, 1 spp: RMSE against GradedAir at tolerance 1e-9\n");
    const auto measure_image = [&](const char* method, double parameter, const auto& integrator) {
        Film film = reference;
        const double seconds = bench::min_seconds(3, [&] { film = render(camera, integrator, config); });
        const double error = bench::rmse(film, reference);
        std::printf("%-9s %-8g RMSE %.2e  %.3f s\n", method, parameter, error, seconds);
        csv.row("%s,%g,%.6e,%.4f", method, parameter, error, seconds);
    };
    for (const T tolerance : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) measure_image("adaptive", tolerance, Whitted(scene, {}, graded(tolerance)));
    for (const int layers : {10, 30, 100, 300, 1000, 3000, 10000})
        measure_image("layers", layers, Whitted(scene, {}, LayeredAir<HeatedLayer<T>>{.field = hot, .bottom = T(0), .top = T(4), .layers = layers}));
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    bench::Csv csv(out / "graded_index.csv", "method,parameter,error,ns_per_ray");
    std::printf("n(y) = 1 + %g y, a ray at %g rad to y = %g: exact x = %.15f\n", g, theta0, top, exact_x());
    for (const double tolerance : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) measure(csv, "adaptive", tolerance, [&] { return adaptive(tolerance); });
    for (const double dt : {4.0, 2.0, 1.0, 0.5, 0.25, 0.1, 0.05, 0.02}) measure(csv, "fixed", dt, [&] { return fixed(dt); });
    for (const int layers : {10, 30, 100, 300, 1000, 3000, 10000, 100000}) measure(csv, "layers", layers, [&] { return layered(layers); });
    images(out);
    return 0;
}
