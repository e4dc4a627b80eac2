// SPDX-License-Identifier: MIT
#include <prism/integrator/bidirectional.hpp>
#include <prism/prism.hpp>
#include <prism/render/render.hpp>

#include "../effort.hpp"
#include "../furnace.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace prism;

namespace {

/// The mean of an image's red channel over pixels [x0, x1) x [y0, y1) (all of it by default).
double mean_red(const Film& film, int x0 = 0, int x1 = -1, int y0 = 0, int y1 = -1)
{
    if (x1 < 0) x1 = film.width();
    if (y1 < 0) y1 = film.height();
    double sum = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += double(film.at(x, y).x);
    return sum / (double(x1 - x0) * double(y1 - y0));
}

const char* method_name(BidirectionalMethod m) { return m == BidirectionalMethod::vcm ? "vcm" : "bdpt"; }

// The area-lit furnace: the inside of the unit sphere of albedo 0.5 around a lamp, a
// sphere of radius 0.3 at its centre that emits L and scatters nothing. The wall's
// irradiance from the lamp is pi L 0.3^2 everywhere, so its direct light (paths of two
// segments) reads 0.5 L 0.09: 1 for L = 1 / 0.045. The camera stands off the centre
// looking at the wall, the lamp behind it.
constexpr float lamp_radius = 0.3f;
constexpr float lamp_radiance = 1.0f / (0.5f * lamp_radius * lamp_radius);

auto lamp_furnace()
{
    return Scene{Lights{}, Object{Sphere<float>({0, 0, 0}, 1), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                 Object{Sphere<float>({0, 0, 0}, lamp_radius), Emissive<float>{.radiance = Rgb<float>(lamp_radiance)}}};
}

const Camera<float> lamp_camera{.position = {0, 0, 0.45f}, .look_at = {0, 0, 1}, .fov = 50};

} // namespace

TEST_CASE("the bidirectional furnace: inside a diffuse sphere of albedo 0.5 lit at its centre the walls read 1.0, by BDPT and by VCM")
{
    const auto scene = test::furnace_scene(false);
    const Camera<float> camera{.position = {0.01f, 0.02f, 0.03f}, .look_at = {0.01f, 0.02f, -1}, .fov = 60};
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
        CAPTURE(std::string(method_name(method)));
        const Bidirectional estimator(scene, {.method = method});
        const Film film = render(camera, estimator, {.width = 32, .height = 32, .spp = int(test::samples(64)), .progress = false});
        CHECK(mean_red(film) == doctest::Approx(1.0).epsilon(test::resolved(0.005)));
    }
}

TEST_CASE("every BDPT strategy alone reads the area-lit furnace's direct light (1.0), and the strategies of longer paths agree with each other")
{
    // Each strategy (s, t) of a path length k, unweighted, is an unbiased estimate of the
    // light carried by paths of k segments: (0, 3) the camera path meets the lamp, (1, 2) a
    // light sample, (2, 1) light tracing. Their MIS-weighted sum is the same light.
    const auto scene = lamp_furnace();
    const RenderConfig config{.width = 16, .height = 16, .spp = int(test::samples(64)), .seed = 3, .progress = false};
    const BidirectionalConfig base{.method = BidirectionalMethod::bdpt, .max_length = 2, .light_paths = 4096};
    // Tolerances of about 4 standard errors, measured over 8 seeds: 0.3 % for (0, 3), 0.9 %
    // for light tracing (2, 1), whose light paths reach the wall the camera sees rarely; the
    // light sample (1, 2) is exact here (the lamp seen whole from every point of the wall).
    for (const Strategy strategy : {Strategy{0, 3}, Strategy{1, 2}, Strategy{2, 1}}) {
        CAPTURE(strategy.s);
        BidirectionalConfig alone = base;
        alone.only = strategy;
        alone.weighted = false;
        CHECK(mean_red(render(lamp_camera, Bidirectional(scene, alone), config)) == doctest::Approx(1.0).epsilon(test::resolved(strategy.t == 1 ? 0.04 : 0.012)));
    }
    const double two = mean_red(render(lamp_camera, Bidirectional(scene, base), config));
    CHECK(two == doctest::Approx(1.0).epsilon(test::resolved(0.005)));
    // Three segments: the four strategies alone agree with the weighted whole's paths of
    // three segments (the render to three less the render to two).
    BidirectionalConfig three = base;
    three.max_length = 3;
    const double longest = mean_red(render(lamp_camera, Bidirectional(scene, three), config)) - two;
    const auto strategy_mean = [&](int s, int t, bool weighted, const RenderConfig& c) {
        BidirectionalConfig one = three;
        one.only = Strategy{s, t};
        one.weighted = weighted;
        return mean_red(render(lamp_camera, Bidirectional(scene, one), c));
    };
    for (int s = 0; s <= 3; ++s) {
        CAPTURE(s);
        CHECK(strategy_mean(s, 4 - s, false, config) == doctest::Approx(longest).epsilon(test::resolved(s == 3 ? 0.04 : 0.02)));
    }
    // The weighted strategies' images add up to the whole, each render taking the same samples.
    RenderConfig few = config;
    few.spp = 4;
    double sum = 0;
    for (int k = 1; k <= 3; ++k)
        for (int s = 0; s <= k; ++s) sum += strategy_mean(s, k + 1 - s, true, few);
    CHECK(sum == doctest::Approx(mean_red(render(lamp_camera, Bidirectional(scene, three), few))).epsilon(1e-5));
}

TEST_CASE("the bidirectional sky furnace: under a uniform sky a diffuse ball reads its albedo and a clear glass ball the sky, by BDPT and by VCM")
{
    // The camera sees nothing but the ball: a window of 0.2 on a ball of radius 1.
    const Camera<float> camera{.position = {0, 0, 6}, .look_at = {0, 0, 0}, .fov = 2};
    const auto diffuse = Scene{Lights{EnvironmentLight<float>{.radiance = Rgb<float>(1)}},
                               Object{Sphere<float>({0, 0, 0}, 1), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}}};
    const auto glass = Scene{Lights{EnvironmentLight<float>{.radiance = Rgb<float>(1)}}, Object{Sphere<float>({0, 0, 0}, 1), Dielectric<float>{.ior = 1.5f}}};
    const RenderConfig config{.width = 8, .height = 8, .spp = int(test::samples(256)), .progress = false};
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
        CAPTURE(std::string(method_name(method)));
        CHECK(mean_red(render(camera, Bidirectional(diffuse, {.method = method, .light_paths = 2000}), config)) == doctest::Approx(0.5).epsilon(test::resolved(0.005)));
        CHECK(mean_red(render(camera, Bidirectional(glass, {.method = method, .light_paths = 2000}), config)) == doctest::Approx(1.0).epsilon(test::resolved(0.005)));
    }
}

namespace {

// A diffuse floor y = 0 (albedo 0.5) beside a vertical mirror x in [-0.1, 0] of
// reflectance R, under a point light at (1, 2, 0) of intensity I (light_tracer.cpp's
// scene): the floor reads L(p) = 0.5 / pi (I cos / d^2 + R I cos' / d'^2), the light's
// term and its mirror image's at (-1, 2, 0). Seen in the mirror, the floor reads R L(p):
// the image's term is the path E S D S L, which no connection finds (each of its
// segments has a delta end) and merging does.
constexpr float floor_light = 10, floor_mirror = 0.8f;

auto floor_and_mirror()
{
    return Scene{Lights{PointLight<float>{.position = {1, 2, 0}, .intensity = Rgb<float>(floor_light)}},
                 Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                 Object{Box<float>({-0.1f, 0, -3}, {0, 4, 3}), Mirror<float>{{.kr = Rgb<float>(floor_mirror)}}}};
}

/// The floor's radiance at p: from the light, and (with the image) from its mirror image.
double floor_and_image(const Vec3<double>& p, bool image)
{
    const auto term = [&](const Vec3<double>& light, double i) {
        const Vec3<double> v = light - p;
        return 0.5 / pi<double> * i * v.y / std::pow(length(v), 3.0);
    };
    return term({1, 2, 0}, floor_light) + (image ? term({-1, 2, 0}, floor_mirror * floor_light) : 0.0);
}

} // namespace

TEST_CASE("a floor lit by a point light and its mirror image, seen in the mirror: VCM reads the closed form (E S D S L), BDPT all but the image's light")
{
    const auto scene = floor_and_mirror();
    // The camera looks at the mirror from the floor's side and sees the floor near it.
    const Camera<float> camera{.position = {1.2f, 0.6f, 0}, .look_at = {0, 0.3f, 0}, .fov = 12};
    const int width = 6, height = 6;
    const RenderConfig config{.width = width, .height = height, .spp = int(test::samples(64)), .seed = 2, .progress = false};
    // The closed form at each pixel's centre: the ray reflected by the mirror (x = 0) meets the floor.
    const CameraRays<float> rays = camera.rays(width, height);
    double direct = 0, both = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Ray<float> r = rays.ray(float(x) + 0.5f, float(y) + 0.5f);
            Vec3<double> o(r.origin), d(r.direction);
            REQUIRE(d.x < 0);
            o += (-o.x / d.x) * d; // on the mirror
            d.x = -d.x;
            REQUIRE(d.y < 0);
            const Vec3<double> p = o + (-o.y / d.y) * d;
            direct += floor_mirror * floor_and_image(p, false);
            both += floor_mirror * floor_and_image(p, true);
        }
    direct /= width * height;
    both /= width * height;
    CHECK(both > 1.2 * direct); // the image's light is a large part
    const double bdpt = mean_red(render(camera, Bidirectional(scene, {.method = BidirectionalMethod::bdpt, .light_paths = 20000}), config));
    const double vcm = mean_red(render(camera, Bidirectional(scene, {.method = BidirectionalMethod::vcm, .radius = 0.02, .light_paths = 20000}), config));
    CHECK(bdpt == doctest::Approx(direct).epsilon(test::resolved(0.01)));
    CHECK(vcm == doctest::Approx(both).epsilon(test::resolved(0.02)));
}

TEST_CASE("the bidirectional estimators' images are the same bits for any thread count, crop and range of passes")
{
    const auto scene = floor_and_mirror();
    const Camera<float> camera{.position = {1.5f, 3, 0}, .look_at = {1.5f, 0, 0}, .up = {0, 0, -1}, .fov = 60};
    // Light paths a pixel's own (drawn from its sampler, joined to its camera paths), or
    // a number of their own (independent streams, joined at random).
    for (const std::size_t paths : {std::size_t(0), std::size_t(3000)})
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
        CAPTURE(std::string(method_name(method)));
        CAPTURE(paths);
        const Bidirectional estimator(scene, {.method = method, .radius = 0.05, .light_paths = paths});
        const RenderConfig config{.width = 12, .height = 9, .spp = 6, .threads = 2, .seed = 5, .progress = false};
        const Accumulation whole = render_sums(camera, estimator, config);
        RenderConfig one = config;
        one.threads = 1;
        CHECK(render(camera, estimator, one).pixels() == whole.image().pixels());
        // Passes [0, 2) and [2, 6), the second in two crops.
        Accumulation parts(12, 9, PixelWindow::whole(12, 9));
        RenderConfig part = config;
        part.passes = {2, 6};
        part.crop = {0, 0, 12, 4};
        render_into(parts, camera, estimator, part);
        part.crop = {0, 4, 12, 9};
        render_into(parts, camera, estimator, part);
        part.crop = {};
        part.passes = {0, 2};
        render_into(parts, camera, estimator, part);
        for (int y = 0; y < 9; ++y)
            for (int x = 0; x < 12; ++x) {
                REQUIRE(parts.sums(x, y) == whole.sums(x, y));
                CHECK(parts.weight(x, y) == 6);
            }
        const Film image = whole.image();
        for (const Rgb<float>& p : image.pixels()) CHECK((std::isfinite(p.x) && p.x > 0));
    }
}

TEST_CASE("bad bidirectional settings are refused, naming the parameter; lights that emit nothing render black")
{
    const auto scene = floor_and_mirror();
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.max_length = 0}), doctest::Contains("max_length must be >= 1, got 0"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.roulette_length = -1}), doctest::Contains("roulette_length must be >= 0"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.radius = -1}), doctest::Contains("radius must be finite and >= 0, got -1"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.alpha = 1}), doctest::Contains("alpha must be in (0, 1), got 1"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.footprints = 0}), doctest::Contains("footprints must be in (0, 1e6), got 0"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.merge_weight = 1.5}), doctest::Contains("merge_weight must be in (0, 1], got 1.5"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.only = Strategy{0, 0}}), doctest::Contains("only must have s >= 0 and t >= 1, got (0, 0)"), std::invalid_argument);
    const auto povray = Scene{Lights{PointLight<float>{.position = {0, 1, 0}, .falloff = Falloff::none}}, Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{}}};
    CHECK_THROWS_WITH_AS(Bidirectional(povray, {}), doctest::Contains("without falloff"), std::invalid_argument);
    // Lights that emit nothing are no error: the image is black.
    const auto dark = Scene{Lights{PointLight<float>{.position = {0, 1, 0}, .intensity = Rgb<float>(0)}}, Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{}}};
    const Camera<float> camera{.position = {0, 2, 2}, .look_at = {0, 0, 0}};
    const Film black = render(camera, Bidirectional(dark, {}), {.width = 4, .height = 4, .spp = 2, .progress = false});
    for (const Rgb<float>& p : black.pixels()) CHECK(p == Rgb<float>(0));
}

TEST_CASE("regression: under the sun, a floor beyond the disk its light paths enter by reads its direct light (rho E cos / pi), by BDPT and by VCM")
{
    // The scene's bounded part is a small ball far from where the camera looks: the sun's
    // light paths enter through the disk over the ball, so the floor seen has light
    // samples only, and their weight must be 1 there (it was shared with light paths that
    // cannot reach it: the floor read dark).
    const Vec3<float> sun = normalize(Vec3<float>{0.3f, -1, 0.2f});
    const auto scene = Scene{Lights{DirectionalLight<float>{.direction = sun, .irradiance = Rgb<float>(2)}},
                             Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}},
                             Object{Sphere<float>({0, 1, 0}, 0.5f), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}}};
    const Camera<float> camera{.position = {20, 3, 20}, .look_at = {20, 0, 19}, .fov = 20};
    const double expected = 0.5 / pi<double> * 2 * double(-sun.y);
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
        CAPTURE(std::string(method_name(method)));
        const double floor = mean_red(render(camera, Bidirectional(scene, {.method = method, .light_paths = 1000}), {.width = 8, .height = 8, .spp = 4, .progress = false}));
        CHECK(floor == doctest::Approx(expected).epsilon(1e-4));
    }
}
