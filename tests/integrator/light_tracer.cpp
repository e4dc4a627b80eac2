// SPDX-License-Identifier: MIT
#include <prism/integrator/light_tracer.hpp>
#include <prism/integrator/path_tracer.hpp>
#include <prism/prism.hpp>
#include <prism/render/render.hpp>

#include "../airlight.hpp"
#include "../effort.hpp"
#include "../furnace.hpp"
#include "../glossy_scenes.hpp"

#include <doctest/doctest.h>

#include <algorithm>

#include <cmath>

using namespace prism;

namespace {

/// A diffuse floor y = 0 (albedo 0.5) beside a vertical mirror x in [-0.1, 0] of
/// reflectance R, under a point light at (1, 2, 0) of intensity I. The floor cannot see
/// its own image (coplanar), so it has no indirect light: it reads
///     L = 0.5 / pi (I cos / d^2 + R I cos' / d'^2),
/// the light's term from the path tracer (E D L) and the mirror image's, from (-1, 2, 0),
/// from the light tracer (L S D E). The camera looks straight down at the floor and
/// does not see the mirror.
constexpr float mirror_light_intensity = 10, mirror_reflectance = 0.8f; // unique names: tests share unity files

auto mirror_scene()
{
    return Scene{Lights{PointLight<float>{.position = {1, 2, 0}, .intensity = Rgb<float>(mirror_light_intensity)}},
                 Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                 Object{Box<float>({-0.1f, 0, -3}, {0, 4, 3}), Mirror<float>{{.kr = Rgb<float>(mirror_reflectance)}}}};
}

double floor_radiance(const Vec3<double>& p, const Vec3<double>& light, double i)
{
    const Vec3<double> v = light - p;
    return 0.5 / pi<double> * i * v.y / std::pow(length(v), 3.0);
}

} // namespace

TEST_CASE("light tracing: a mirror's image of a point light on a floor, L S D E, against the closed form; the path tracer adds the rest")
{
    const auto scene = mirror_scene();
    const Camera<float> camera{.position = {1.5f, 3, 0}, .look_at = {1.5f, 0, 0}, .up = {0, 0, -1}, .fov = 40};
    constexpr int size = 16;
    // (Under a sanitizer, here and below, an eighth of the paths, and what they resolve
    // widened by sqrt(8): tests/effort.hpp.)
    const Film traced = render(camera, LightTracer(scene, {.paths = std::size_t(test::samples(8000000))}), {.width = size, .height = size, .threads = 2, .seed = 3, .progress = false});
    const Film pathed = render(camera, PathTracer(scene), {.width = size, .height = size, .spp = 16, .threads = 2, .progress = false});
    const CameraRays<float> rays = camera.rays(size, size);
    double mirror_sum = 0, mirror_expected = 0, worst_direct = 0, squares = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            // The closed forms averaged over the pixel (8 x 8 points).
            double direct = 0, image = 0;
            for (int j = 0; j < 64; ++j) {
                const Ray<float> ray = rays.ray(float(x) + (float(j % 8) + 0.5f) / 8, float(y) + (float(j / 8) + 0.5f) / 8);
                const Vec3<double> p = Vec3<double>(ray.origin) + Vec3<double>(ray.direction) * (-double(ray.origin.y) / double(ray.direction.y));
                direct += floor_radiance(p, {1, 2, 0}, mirror_light_intensity) / 64;
                image += floor_radiance(p, {-1, 2, 0}, mirror_reflectance * mirror_light_intensity) / 64;
            }
            mirror_sum += traced.at(x, y).x;
            mirror_expected += image;
            squares += std::pow(traced.at(x, y).x / image - 1, 2);
            worst_direct = std::max(worst_direct, std::abs(pathed.at(x, y).x / direct - 1));
        }
    CHECK(mirror_sum / mirror_expected == doctest::Approx(1.0).epsilon(test::resolved(0.005)));
    // Noise alone: 4.0 % per pixel at 2 million paths, 1.9 % at 8 million.
    MESSAGE("relative RMS per pixel ", std::sqrt(squares / (size * size)));
    CHECK(std::sqrt(squares / (size * size)) < test::resolved(0.025));
    CHECK(worst_direct < 0.02); // the light's own term, by shadow rays (16 samples over the pixel)
}

TEST_CASE("light tracing with no diffuse bounce, or paths of 3 segments, keeps L S D E alone: a ceiling added, the floor still reads the mirror image's closed form")
{
    // A diffuse ceiling at y = 4 the camera cannot see: it adds L S D(ceiling) D(floor) E
    // paths, which a limit of 0 diffuse bounces leaves out (as POV-Ray's caustic photons),
    // and so does one of 3 segments (max_length); 2 leaves nothing to the light tracer.
    const auto scene = Scene{Lights{PointLight<float>{.position = {1, 2, 0}, .intensity = Rgb<float>(mirror_light_intensity)}},
                             Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                             Object{Plane<float>({0, 1, 0}, 4), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                             Object{Box<float>({-0.1f, 0, -3}, {0, 4, 3}), Mirror<float>{{.kr = Rgb<float>(mirror_reflectance)}}}};
    const Camera<float> camera{.position = {1.5f, 3, 0}, .look_at = {1.5f, 0, 0}, .up = {0, 0, -1}, .fov = 40};
    constexpr int size = 8;
    const RenderConfig render_config{.width = size, .height = size, .threads = 2, .seed = 3, .progress = false};
    const Film first = render(camera, LightTracer(scene, {.paths = std::size_t(test::samples(2000000)), .max_diffuse_bounces = 0}), render_config);
    const Film all = render(camera, LightTracer(scene, {.paths = std::size_t(test::samples(2000000))}), render_config);
    const Film three = render(camera, LightTracer(scene, {.paths = std::size_t(test::samples(2000000)), .max_length = 3}), render_config);
    const Film two = render(camera, LightTracer(scene, {.paths = 1000, .max_length = 2}), render_config);
    const CameraRays<float> rays = camera.rays(size, size);
    double first_sum = 0, all_sum = 0, three_sum = 0, two_sum = 0, expected = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            for (int j = 0; j < 64; ++j) {
                const Ray<float> ray = rays.ray(float(x) + (float(j % 8) + 0.5f) / 8, float(y) + (float(j / 8) + 0.5f) / 8);
                const Vec3<double> p = Vec3<double>(ray.origin) + Vec3<double>(ray.direction) * (-double(ray.origin.y) / double(ray.direction.y));
                expected += floor_radiance(p, {-1, 2, 0}, mirror_reflectance * mirror_light_intensity) / 64;
            }
            first_sum += first.at(x, y).x;
            all_sum += all.at(x, y).x;
            three_sum += three.at(x, y).x;
            two_sum += two.at(x, y).x;
        }
    CHECK(first_sum / expected == doctest::Approx(1.0).epsilon(test::resolved(0.01)));
    CHECK(three_sum / expected == doctest::Approx(1.0).epsilon(test::resolved(0.01)));
    CHECK(two_sum == 0);
    MESSAGE("with the ceiling's bounce: ", all_sum / expected);
    CHECK(all_sum / expected > 1.05);
    CHECK_THROWS_WITH_AS(LightTracer(scene, {.max_diffuse_bounces = -1}), doctest::Contains("LightTracerConfig max_diffuse_bounces must be >= 0, got -1"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(LightTracer(scene, {.paths = 0}), doctest::Contains("LightTracerConfig paths must be >= 1, got 0"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(LightTracer(scene, {.max_length = 0}), doctest::Contains("LightTracerConfig max_length must be >= 1, got 0"), std::invalid_argument);
}

TEST_CASE("the light tracer's image is the same bits for any thread count, and bad sizes are refused")
{
    const auto scene = mirror_scene();
    const Camera<float> camera{.position = {1.5f, 3, 0}, .look_at = {1.5f, 0, 0}, .up = {0, 0, -1}, .fov = 40};
    const LightTracer tracer(scene, {.paths = 40000});
    const RenderConfig config{.width = 12, .height = 9, .threads = 1, .seed = 5, .progress = false};
    RenderConfig two = config;
    two.threads = 2;
    CHECK(render(camera, tracer, config).pixels() == render(camera, tracer, two).pixels());
    RenderConfig bad = config;
    bad.width = 0;
    CHECK_THROWS_WITH_AS((void)render(camera, tracer, bad), doctest::Contains("image size must be positive"), std::invalid_argument);
    bad = config;
    bad.spp = 4;
    bad.passes = {3, 5};
    CHECK_THROWS_WITH_AS((void)render(camera, tracer, bad), doctest::Contains("RenderConfig passes [3, 5) must be a non-empty range of the spp = 4"),
                         std::invalid_argument);
    bad = config;
    bad.crop = {0, 0, 13, 9};
    CHECK_THROWS_WITH_AS((void)render(camera, tracer, bad), doctest::Contains("crop [0, 13) x [0, 9)"), std::invalid_argument);
}

TEST_CASE("the light tracer's ranges of passes and crops add up to the whole image, bit for bit")
{
    const auto scene = mirror_scene();
    const Camera<float> camera{.position = {1.5f, 3, 0}, .look_at = {1.5f, 0, 0}, .up = {0, 0, -1}, .fov = 40};
    // Ten passes of 10000 paths.
    const LightTracer tracer(scene, {.paths = 10000});
    const RenderConfig config{.width = 12, .height = 9, .spp = 10, .threads = 2, .seed = 5, .progress = false};
    const Accumulation whole = render_sums(camera, tracer, config);
    // Passes [0, 3) and [3, 10), the second in two crops.
    Accumulation parts(12, 9, PixelWindow::whole(12, 9));
    RenderConfig part = config;
    part.passes = {3, 10};
    part.crop = {0, 0, 12, 4};
    render_into(parts, camera, tracer, part);
    part.crop = {0, 4, 12, 9};
    render_into(parts, camera, tracer, part);
    part.crop = {};
    part.passes = {0, 3};
    part.threads = 1;
    render_into(parts, camera, tracer, part);
    int lit = 0;
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x) {
            REQUIRE(parts.sums(x, y) == whole.sums(x, y));
            CHECK(parts.weight(x, y) == 10);
            lit += whole.sum(x, y, 0).value() > 0;
        }
    CHECK(lit > 20); // the test sees the caustic
    // Ten passes of 10000 paths are one of 100000: the same paths, each splat weighed alike.
    const Film one = render(camera, LightTracer(scene, {.paths = 100000}), {.width = 12, .height = 9, .threads = 2, .seed = 5, .progress = false});
    const Film ten = whole.image();
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x) CHECK(ten.at(x, y).x == doctest::Approx(one.at(x, y).x).epsilon(1e-5));
    // A crop of the image is those pixels of the whole image.
    part = config;
    part.crop = {3, 2, 9, 7};
    const Film crop = render(camera, tracer, part), image = render(camera, tracer, config);
    for (int y = 2; y < 7; ++y)
        for (int x = 3; x < 9; ++x) CHECK(crop.at(x - 3, y - 2) == image.at(x, y));
}

TEST_CASE("the light tracer in the two-lobe furnace: the paths that leave the light by the coat's mirror, seen directly, within 1 %")
{
    const auto scene = test::coated_furnace_scene();
    const Camera<float> camera{.position = {0.01f, 0.02f, 0.03f}, .look_at = {0.3f, 0.2f, 1}, .fov = 90};
    constexpr int size = 8;
    // (Under a sanitizer an eighth of the paths, and 2.8 %: tests/effort.hpp.)
    const Film traced = render(camera, LightTracer(scene, {.paths = std::size_t(test::samples(4000000))}),
                               {.width = size, .height = size, .threads = 2, .seed = 5, .progress = false});
    const double mean = test::image_mean(traced);
    MESSAGE("light tracer ", mean, " (closed form ", test::CoatedFurnace::light_tracer, ")");
    CHECK(mean == doctest::Approx(test::CoatedFurnace::light_tracer).epsilon(test::resolved(0.01)));
}

TEST_CASE("light tracing onto a glossy floor through a mirror (L S G E) reads the mirror image's light, weighed by the floor's BSDF")
{
    // Joined to the camera at its first glossy surface only, the light tracer's image of
    // the floor is the light of the light's mirror image, which Whitted finds exactly.
    const auto check = [](const auto& floor) {
        const Camera<float> camera = test::floor_camera();
        constexpr int size = 8;
        const RenderConfig config{.width = size, .height = size, .spp = 1, .threads = 2, .seed = 3, .progress = false};
        const auto with_mirror = test::floor_by_mirror(floor);
        const auto with_image = test::floor_by_image(floor);
        // 500 000 paths: each pixel within 1.7 % RMS of the exact image (measured), the mean
        // of 64 such pixels a standard error of 0.2 %, so 1 % is 5 of them. (An eighth of
        // them, 9 % RMS, would leave 2.5: the count stays under a sanitizer.)
        const Film traced = render(camera, LightTracer(with_mirror, {.paths = 500000, .max_diffuse_bounces = 0}), config);
        const RenderConfig exact_config{.width = size, .height = size, .spp = 64, .threads = 2, .seed = 3, .progress = false};
        const Film exact = render(camera, Whitted(with_image), exact_config);
        double traced_sum = 0, exact_sum = 0, squares = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                traced_sum += traced.at(x, y).x + traced.at(x, y).y;
                exact_sum += exact.at(x, y).x + exact.at(x, y).y;
                squares += std::pow((traced.at(x, y).x + traced.at(x, y).y) / (exact.at(x, y).x + exact.at(x, y).y) - 1, 2);
            }
        MESSAGE("relative RMS per pixel ", std::sqrt(squares / (size * size)), ", whole image ", traced_sum / exact_sum);
        CHECK(traced_sum / exact_sum == doctest::Approx(1.0).epsilon(0.01));
    };
    check(RoughConductor<float, ComplexIor<float>>{.fresnel = {.eta = {0.2f, 0.9f, 1.1f}, .k = {3.9f, 2.4f, 2.2f}}, .roughness = 0.5f});
    check(Phong<float>{.diffuse = {.color = {0.3f, 0.2f, 0.1f}}, .specular = Rgb<float>(0.5f), .exponent = 10});
    check(CoatedDiffuse<float>({.color = {0.6f, 0.3f, 0.2f}}, {.ior = 1.5f, .roughness = 0.4f}));
}

TEST_CASE("light tracing through a thin lens, out of focus, reads the closed form blurred by the lens (L S D E)")
{
    // A narrow mirror (z in [-0.3, 0.3]) lights a strip of the floor with the light's image,
    // sharp-edged. Looking straight down at it from 3 up through a lens of radius 0.3
    // focused at 1.5, the strip blurs. What each pixel reads is the floor's closed form
    // (Lambertian: the same radiance every way) averaged over the pixel and the lens, along
    // the lens's rays (8 x 8 pixel positions by 8 x 8 lens points); the light tracer joins
    // each path to a lens point drawn at its vertex and must read the same.
    const auto scene = Scene{Lights{PointLight<float>{.position = {1, 2, 0}, .intensity = Rgb<float>(mirror_light_intensity)}},
                             Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                             Object{Quad<float>({0, 0, -0.3f}, {0, 4, 0}, {0, 0, 0.6f}), Mirror<float>{{.kr = Rgb<float>(mirror_reflectance)}}}};
    const auto strip = [](const Vec3<double>& p) {
        // Lit by the image at (-1, 2, 0) where the way to it crosses x = 0 within the mirror.
        const Vec3<double> image{-1, 2, 0};
        const double t = p.x / (p.x - image.x);
        const Vec3<double> q = p + t * (image - p);
        return q.z >= -0.3 && q.z <= 0.3 && q.y >= 0 && q.y <= 4 ? floor_radiance(p, image, mirror_reflectance * mirror_light_intensity) : 0.0;
    };
    const Camera<float> camera{.position = {1.5f, 3, 0}, .look_at = {1.5f, 0, 0}, .up = {0, 0, -1}, .fov = 40, .aperture_radius = 0.3f,
                               .focus_distance = 1.5f};
    constexpr int size = 8;
    const Film traced = render(camera, LightTracer(scene, {.paths = std::size_t(test::samples(8000000)), .max_diffuse_bounces = 0}),
                               {.width = size, .height = size, .threads = 2, .seed = 3, .progress = false});
    const CameraRays<float> rays = camera.rays(size, size);
    double sum = 0, expected = 0, squares = 0, sharp_squares = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            double blurred = 0, sharp = 0;
            for (int j = 0; j < 64; ++j)
                for (int l = 0; l < 64; ++l) {
                    const float px = float(x) + (float(j % 8) + 0.5f) / 8, py = float(y) + (float(j / 8) + 0.5f) / 8;
                    const Ray<float> ray = rays.ray(px, py, (float(l % 8) + 0.5f) / 8, (float(l / 8) + 0.5f) / 8);
                    blurred += strip(Vec3<double>(ray.origin) + Vec3<double>(ray.direction) * (-double(ray.origin.y) / double(ray.direction.y))) / 4096;
                    if (l == 0) {
                        const Ray<float> pin = rays.ray(px, py);
                        sharp += strip(Vec3<double>(pin.origin) + Vec3<double>(pin.direction) * (-double(pin.origin.y) / double(pin.direction.y))) / 64;
                    }
                }
            sum += traced.at(x, y).x;
            expected += blurred;
            squares += std::pow(traced.at(x, y).x - blurred, 2);
            sharp_squares += std::pow(sharp - blurred, 2);
        }
    const double mean = expected / (size * size);
    CHECK(sum / expected == doctest::Approx(1.0).epsilon(test::resolved(0.01)));
    MESSAGE("RMS per pixel over the mean ", std::sqrt(squares / (size * size)) / mean, "; the pinhole's picture differs by ",
            std::sqrt(sharp_squares / (size * size)) / mean);
    // Noise alone: 2.2 % at 8 million paths; a pinhole's picture would be 17.7 % away.
    CHECK(std::sqrt(squares / (size * size)) < test::resolved(0.05) * mean);
    CHECK(std::sqrt(sharp_squares / (size * size)) > 0.15 * mean); // the blur is there to be found
}

TEST_CASE("light tracing in fog: a mirror's image of a point light, scattered once in the air (L S M E), is the airlight integral of the image")
{
    // tests/airlight.hpp's light and fog under a mirror whose face is y = 2: its image of
    // the light, at (0, 3, 0) with intensity R, lights the fog by paths L S M E, which the
    // path tracer cannot find (from a point in the fog no shadow ray reaches the light by
    // the mirror). max_diffuse_bounces = 0 keeps the paths that scatter once. The camera
    // looks along the airlight ray, 90 degrees across; each pixel's quadrature is averaged over
    // 8 x 8 points, up to the mirror for a ray that rises. Measured within 0.6 % over seeds 5 to 7.
    using namespace prism;
    constexpr float reflectance = 0.8f;
    const Scene scene{Lights{PointLight<float>{.position = {0, 1, 0}, .intensity = Rgb<float>(1)}},
                      Object{Box<float>({-60, 2, -60}, {60, 2.1f, 60}), Mirror<float>{{.kr = Rgb<float>(reflectance)}}}};
    const Camera<float> camera{.position = {-2, 0, 0}, .look_at = {0, 0, 0}, .up = {0, 1, 0}, .fov = 90};
    constexpr int size = 4;
    const RenderConfig config{.width = size, .height = size, .threads = 2, .seed = 7, .progress = false};
    // The fog starts 1 before the camera (x = -1): near the camera a light path's splat
    // grows as 1 / d^2, and its noise with it.
    FilledAir<Fog<float>> fog = test::airlight_fog();
    fog.region = {{-1, -60, -60}, {60, 60, 60}};
    const Film traced = render(camera, LightTracer(scene, {.paths = std::size_t(test::samples(8000000)), .max_diffuse_bounces = 0}, fog), config);
    const CameraRays<float> rays = camera.rays(size, size);
    for (int c = 0; c < 3; ++c) {
        double sum = 0, expected = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                for (int j = 0; j < 64; ++j) {
                    const Ray<float> ray = rays.ray(float(x) + (float(j % 8) + 0.5f) / 8, float(y) + (float(j / 8) + 0.5f) / 8);
                    // A ray that rises meets the mirror: the fog beyond it is out of its sight.
                    const Vec3<double> w = normalize(Vec3<double>(ray.direction));
                    const double reach = w.y > 0 ? std::min(60.0, 2 / w.y) : 60.0;
                    expected += reflectance * test::airlight_along(c, Vec3<double>(ray.origin), w, {0, 3, 0}, reach, 6000, 1 / w.x) / 64;
                }
                sum += traced.at(x, y)[c];
            }
        CAPTURE(c);
        MESSAGE("channel ", c, ": light tracer ", sum / (size * size), ", airlight of the mirror image ", expected / (size * size));
        CHECK(sum / expected == doctest::Approx(1.0).epsilon(test::resolved(0.01)));
    }
}
