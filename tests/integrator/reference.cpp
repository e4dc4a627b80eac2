// SPDX-License-Identifier: MIT
#include <prism/integrator/reference.hpp>
#include <prism/prism.hpp>

#include "../effort.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace prism;

namespace {

/// The irradiance at p (on the floor y = 0, facing up) from the rectangle [x0, x1] x [z0, z1]
/// at height h of radiance L, facing down: the corner form factor of a parallel rectangle,
/// odd in both sides, summed with signs over the four corners.
double rectangle_irradiance(const Vec3<double>& p, double x0, double x1, double z0, double z1, double h, double radiance)
{
    const auto corner = [&](double a, double b) {
        const double x = a / h, y = b / h;
        return radiance / 2 *
               (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) + y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)));
    };
    const double a0 = x0 - p.x, a1 = x1 - p.x, b0 = z0 - p.z, b1 = z1 - p.z;
    return corner(a1, b1) - corner(a0, b1) - corner(a1, b0) + corner(a0, b0);
}

} // namespace

// The path tracer alone finds a mirror's image of an area light on a floor (E D S L: its
// diffuse bounce meets the light through the mirror); the reference's light tracer finds
// it too (L S D E), so the reference's path tracer must leave it out. It did not at
// first: the reference read the image twice (0.5 / pi (E + 2 R E') on this floor).
TEST_CASE("an area light's image in a mirror on a floor: the path tracer alone and the reference each count it once, against the closed form")
{
    constexpr double radiance = 4, reflectance = 0.8, h = 4; // above the camera, which must not see its back
    // The light [0.5, 1.5] x [-0.5, 0.5] at height 4, facing down; a vertical mirror x in [-0.1, 0].
    const Scene scene{Lights{}, Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .kd = 1, .ka = 0}},
                      Object{Box<double>({-0.1, 0, -5}, {0, 6, 5}), Mirror<double>{{.kr = Rgb<double>(reflectance)}}},
                      Object{Quad<double>({0.5, h, -0.5}, {1, 0, 0}, {0, 0, 1}), Emissive<double>{.radiance = Rgb<double>(radiance)}}};
    const Camera<double> camera{.position = {1.5, 3, 0}, .look_at = {1.5, 0, 0}, .up = {0, 0, -1}, .fov = 40};
    constexpr int size = 8;
    // (Under a sanitizer an eighth of the samples, and 2.8 %: tests/effort.hpp.)
    const RenderConfig config{.width = size, .height = size, .spp = int(test::samples(16384)), .threads = 2, .seed = 5, .progress = false};
    const Film alone = render(camera, PathTracer(scene), config);
    const Film both = render(camera, Reference(scene), config);
    const CameraRays<double> rays = camera.rays(size, size);
    double expected = 0, mean_alone = 0, mean_both = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            // The closed form over the pixel (8 x 8 points): the light, and its image at x in [-1.5, -0.5].
            for (int j = 0; j < 64; ++j) {
                const Ray<double> ray = rays.ray(x + (j % 8 + 0.5) / 8, y + (j / 8 + 0.5) / 8);
                const Vec3<double> p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
                const double e = rectangle_irradiance(p, 0.5, 1.5, -0.5, 0.5, h, radiance) + reflectance * rectangle_irradiance(p, -1.5, -0.5, -0.5, 0.5, h, radiance);
                expected += 0.5 / pi<double> * e / 64;
            }
            mean_alone += alone.at(x, y).x;
            mean_both += both.at(x, y).x;
        }
    MESSAGE("floor: closed form ", expected / 64, ", path tracer ", mean_alone / 64, ", reference ", mean_both / 64);
    CHECK(mean_alone == doctest::Approx(expected).epsilon(test::resolved(0.01)));
    CHECK(mean_both == doctest::Approx(expected).epsilon(test::resolved(0.01)));
}

// The same scene held to paths of 2 and 3 segments: the image in the mirror (E D S L) is
// a path of 3, which the path tracer finds by its bounce and the reference by its light
// tracer, while at 2 the floor has its direct light alone, the light samples' and the
// bounces' that meet the light (MIS at the limit: a light met at the last vertex counts
// with its weight against the light sample the vertex before took).
TEST_CASE("the reference and the path tracer held to 2 or 3 segments: the area light's image in a mirror is a path of 3, against the closed form")
{
    constexpr double radiance = 4, reflectance = 0.8, h = 4;
    const Scene scene{Lights{}, Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .kd = 1, .ka = 0}},
                      Object{Box<double>({-0.1, 0, -5}, {0, 6, 5}), Mirror<double>{{.kr = Rgb<double>(reflectance)}}},
                      Object{Quad<double>({0.5, h, -0.5}, {1, 0, 0}, {0, 0, 1}), Emissive<double>{.radiance = Rgb<double>(radiance)}}};
    const Camera<double> camera{.position = {1.5, 3, 0}, .look_at = {1.5, 0, 0}, .up = {0, 0, -1}, .fov = 40};
    constexpr int size = 8;
    const RenderConfig config{.width = size, .height = size, .spp = int(test::samples(4096)), .threads = 2, .seed = 9, .progress = false};
    const CameraRays<double> rays = camera.rays(size, size);
    double direct = 0, image = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            for (int j = 0; j < 64; ++j) {
                const Ray<double> ray = rays.ray(x + (j % 8 + 0.5) / 8, y + (j / 8 + 0.5) / 8);
                const Vec3<double> p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
                direct += 0.5 / pi<double> * rectangle_irradiance(p, 0.5, 1.5, -0.5, 0.5, h, radiance) / 64;
                image += 0.5 / pi<double> * reflectance * rectangle_irradiance(p, -1.5, -0.5, -0.5, 0.5, h, radiance) / 64;
            }
    MESSAGE("floor: direct ", direct / 64, ", the image ", image / 64);
    for (const int length : {2, 3}) {
        CAPTURE(length);
        const double expected = length == 2 ? direct : direct + image;
        const auto sum = [&](const Film& film) {
            double total = 0;
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) total += film.at(x, y).x;
            return total;
        };
        CHECK(sum(render(camera, PathTracer(scene, {.max_length = length}), config)) == doctest::Approx(expected).epsilon(test::resolved(0.01)));
        CHECK(sum(render(camera, Reference(scene, {.max_length = length}), config)) == doctest::Approx(expected).epsilon(test::resolved(0.01)));
    }
}

// The same for a sky: a floor's diffuse bounce meets the environment through the mirror
// (E D S Env), which the reference leaves to its light tracer (Env S D E), its photons
// entering through the disk over the scene. Counted twice, the floor by the mirror would
// read its mirrored sky twice.
TEST_CASE("a sky's image in a mirror on a floor: the reference counts it once, as the path tracer alone does")
{
    // A sky brighter toward -x, so that the mirror facing -x sends the floor more of it.
    std::vector<Rgb<float>> pixels;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) pixels.push_back(Rgb<float>(y < 4 ? 1.0f + 3.0f * float(std::abs(x - 4) < 3) : 0.0f));
    const Scene scene{Lights{EnvironmentMap<double>(16, 8, pixels)},
                      Object{Quad<double>({-5, 0, 5}, {10, 0, 0}, {0, 0, -10}), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .kd = 1, .ka = 0}},
                      Object{Box<double>({-0.1, 0, -2}, {0, 3, 2}), Mirror<double>{{.kr = Rgb<double>(0.9)}}}};
    const Camera<double> camera{.position = {-1, 3, 0}, .look_at = {-1, 0, 0}, .up = {0, 0, -1}, .fov = 40};
    constexpr int size = 8;
    // (Under a sanitizer an eighth of the samples, and 4.2 %: tests/effort.hpp.)
    const RenderConfig config{.width = size, .height = size, .spp = int(test::samples(4096)), .threads = 2, .seed = 3, .progress = false};
    const Film alone = render(camera, PathTracer(scene), config);
    const Film both = render(camera, Reference(scene), config);
    const Film direct = render(camera, PathTracer(scene, {.max_diffuse_bounces = 1, .caustics_of_area_lights = false}), config);
    double mean_alone = 0, mean_both = 0, mean_direct = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) mean_alone += alone.at(x, y).x / 64, mean_both += both.at(x, y).x / 64, mean_direct += direct.at(x, y).x / 64;
    MESSAGE("floor by the mirror: path tracer ", mean_alone, ", reference ", mean_both, ", without the mirrored sky ", mean_direct);
    CHECK(mean_both == doctest::Approx(mean_alone).epsilon(test::resolved(0.015)));
    // The mirrored sky is a share of the floor's light the test can see.
    CHECK(mean_alone > 1.2 * mean_direct);
}

TEST_CASE("regression: the reference in a furnace of a white mix with a mirror part, in a ball of smoke, reads 1 (the light tracer follows a mix's mirror from the light)")
{
    // A ball of radius 0.5 of a white two-lobe mix (Lambert and a mirror, half and half)
    // inside a ball of smoke that does not absorb (radius 0.8, index 1), under a sky of
    // radiance 1, seen from inside the smoke: every pixel reads 1. Light from the sky that
    // leaves the ball by its mirror part and then scatters in the smoke (L S M E) is the
    // light tracer's: the reference's path tracer leaves the paths whose last vertex
    // before the sky is a mirror (D S L) to it. The light tracer aimed its paths at
    // mirrors and glass only, never at a glossy lobe (a mix's mirror part, a smooth coat),
    // and ended a path at a first hit on one: it added nothing here, and the image read
    // 0.965, 0.954, 0.946 (found by the consistency matrix, tests/matrix.hpp).
    using T = float;
    using Shiny = RoughConductor<T>; // at roughness 0, a mirror: the mix's delta part
    const Fog<T> fog{.scattering = {0.6f, 0.9f, 1.2f}, .phase = {.g = 0.3f}};
    const Scene scene{Lights{EnvironmentLight<T>{}},
                      Object{Sphere<T>({0, 0, 0}, 0.5f), Mix<T, Diffuse<T>, Shiny>{.first = {.albedo = {.color = Rgb<T>(1)}},
                                                                                    .second = {.fresnel = {.kr = Rgb<T>(1)}, .roughness = Roughness<T>(0)},
                                                                                    .weight = 0.5f}},
                      Object{Sphere<T>({0, 0, 0}, 0.8f), Dielectric<T, ExactFresnel, Fog<T>>{.ior = 1, .interior = fog}}};
    const Camera<T> camera{.position = {0, 0.2f, 0.72f}, .look_at = {0, -0.1f, 0}, .fov = 70};
    // The light tracer's part (the reference less its path tracer's, the same bits) is
    // heavy-tailed: 0.033 to 0.083 of the 0.049 it must add, over six renders of 2048
    // passes. Eight renders of 1024: their mean within 3 % (4.5 standard errors).
    Rgb<double> mean{0}, lights{0};
    const int renders = 8;
    for (int k = 0; k < renders; ++k) {
        const RenderConfig config{.width = 8, .height = 8, .spp = int(test::samples(1024)), .threads = 2, .seed = std::uint64_t(k + 1), .progress = false};
        const Film both = render(camera, Reference(scene), config);
        const Film paths = render(camera, PathTracer(scene, {.caustics_of_area_lights = false}), config);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                mean += Rgb<double>(both.at(x, y)) / (64.0 * renders);
                lights += (Rgb<double>(both.at(x, y)) - Rgb<double>(paths.at(x, y))) / (64.0 * renders);
            }
    }
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        MESSAGE("channel ", c, ": ", mean[c], ", of which the light tracer's ", lights[c]);
        CHECK(mean[c] == doctest::Approx(1).epsilon(test::resolved(0.03)).scale(0));
        CHECK(lights[c] > 0.02);
    }
}
