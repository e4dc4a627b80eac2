// SPDX-License-Identifier: MIT
#include <prism/integrator/bidirectional.hpp>
#include <prism/prism.hpp>
#include <prism/render/render.hpp>

#include "../effort.hpp"
#include "../furnace.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

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

std::string method_name(BidirectionalMethod m)
{
    return m == BidirectionalMethod::vcm ? "vcm" : m == BidirectionalMethod::merging ? "merging" : "bdpt";
}

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
        CAPTURE(method_name(method));
        const Bidirectional estimator(scene, {.method = method});
        const Film film = render(camera, estimator, {.width = 32, .height = 32, .spp = int(test::samples(64)), .progress = false});
        CHECK(mean_red(film) == doctest::Approx(1.0).epsilon(test::resolved(0.005)));
    }
    // With connections for a share of the camera paths (and fewer light paths), the
    // weights counting them that share of the time: still 1.0. (At 0.25 and 1/16 with 64
    // light paths, 0.9996 to 1.0005 over the methods and shares.)
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm})
        for (const double share : {0.25, 0.0625}) {
            CAPTURE(method_name(method));
            CAPTURE(share);
            const Bidirectional estimator(scene, {.method = method, .light_paths = 64, .connections = share});
            const Film film = render(camera, estimator, {.width = 32, .height = 32, .spp = int(test::samples(64)), .progress = false});
            MESSAGE(method_name(method), " connections ", share, ": ", mean_red(film));
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
    // A connection made for a quarter of the camera paths, over its probability, alone.
    {
        BidirectionalConfig quarter = three;
        quarter.only = Strategy{2, 2};
        quarter.weighted = false;
        quarter.connections = 0.25;
        CHECK(mean_red(render(lamp_camera, Bidirectional(scene, quarter), config)) == doctest::Approx(longest).epsilon(test::resolved(0.04)));
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
        CAPTURE(method_name(method));
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

namespace {

/// That the estimator renders `scene` (in `air`) to the same bits on 1 thread and 2, and
/// in parts (passes [0, 2) whole and [2, 6) in two crops), with light paths a pixel's own
/// (drawn from its sampler, joined to its camera paths), a number of their own
/// (independent streams, joined at random) or as many as a pilot chooses (of the whole
/// image, whatever the crop); and every pixel finite, and lit where `lit`.
template <class SceneT, class Air = StraightAir>
void check_same_bits(const SceneT& scene, const Camera<float>& camera, bool lit, const Air& air = {})
{
    for (const std::size_t paths : {std::size_t(0), std::size_t(12 * 9), std::size_t(3000)})
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
        CAPTURE(method_name(method));
        CAPTURE(paths);
        const Bidirectional estimator(scene, {.method = method, .radius = 0.05, .light_paths = paths}, air);
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
        for (const Rgb<float>& p : image.pixels()) CHECK((std::isfinite(p.x) && (p.x > 0 || !lit)));
    }
}

} // namespace

TEST_CASE("the bidirectional estimators' images are the same bits for any thread count, crop and range of passes")
{
    const auto scene = floor_and_mirror();
    check_same_bits(scene, {.position = {1.5f, 3, 0}, .look_at = {1.5f, 0, 0}, .up = {0, 0, -1}, .fov = 60}, true);
}

namespace {

/// The variance of a pass's image from pass to pass (a pixel's red, over `passes` passes,
/// averaged over the pixels), brute force: each pass rendered on its own.
template <class SceneT>
double pass_variance(const SceneT& scene, const Camera<float>& camera, BidirectionalConfig settings, const RenderConfig& config, int passes)
{
    const Bidirectional estimator(scene, settings);
    std::vector<double> first(std::size_t(config.width * config.height)), second(first.size());
    for (int k = 0; k < passes; ++k) {
        RenderConfig one = config;
        one.spp = passes;
        one.passes = {std::uint64_t(k), std::uint64_t(k) + 1};
        const Film film = render(camera, estimator, one);
        for (std::size_t i = 0; i < first.size(); ++i) {
            const double v = double(film.pixels()[i].x);
            first[i] += v;
            second[i] += v * v;
        }
    }
    double variance = 0;
    for (std::size_t i = 0; i < first.size(); ++i) variance += (second[i] - first[i] * first[i] / passes) / (passes - 1);
    return variance / double(first.size());
}

} // namespace

namespace {

/// A box of white walls 5.55 wide, open at the front (z = 0), red on the left and green
/// on the right: the Cornell box's walls (bench/methods.cpp's).
auto box_walls()
{
    using V = Vec3<float>;
    constexpr float w = 5.55f, t = 0.1f;
    const auto diffuse = [](float r, float g, float b) { return Diffuse<float>{.albedo = {.color = {r, g, b}}, .kd = 0.8f, .ka = 0}; };
    const auto white = diffuse(0.75f, 0.75f, 0.75f);
    using Wall = Object<Box<float>, Diffuse<float>>;
    return ObjectArray<Box<float>, Diffuse<float>>{{
        Wall{Box<float>(V{-t, -t, 0}, V{w + t, 0, -(w + t)}), white},
        Wall{Box<float>(V{-t, w, 0}, V{w + t, w + t, -(w + t)}), white},
        Wall{Box<float>(V{-t, -t, -w}, V{w + t, w + t, -(w + t)}), white},
        Wall{Box<float>(V{-t, -t, 0}, V{0, w + t, -(w + t)}), diffuse(0.75f, 0.1f, 0.1f)},
        Wall{Box<float>(V{w, -t, 0}, V{w + t, w + t, -(w + t)}), diffuse(0.1f, 0.75f, 0.1f)},
    }};
}

const Camera<float> box_camera{.position = {2.78f, 2.73f, 8}, .look_at = {2.78f, 2.73f, 0}, .fov = 40};

} // namespace

TEST_CASE("the light paths a pass, chosen by a pilot: fewer in a box lit by a ceiling lamp, one a pixel under a point light close to the ceiling")
{
    const RenderConfig config{.width = 24, .height = 24, .progress = false};
    const std::size_t pixels = 24 * 24;
    const int passes = int(test::samples(64));
    // Under an area light in the ceiling the camera's strategies (a light sample, a bounce
    // meeting the lamp) find nearly all the light: the pilot takes fewer light paths, and a
    // brute-force variance says they lose nothing a pass, for a fraction of the work.
    {
        const auto scene = Scene{Lights{}, box_walls(),
                                 Object{Quad<float>({2.13f, 5.549f, -3.32f}, {1.30f, 0, 0}, {0, 0, 1.05f}), Emissive<float>{.radiance = Rgb<float>(37)}}};
        for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
            CAPTURE(method_name(method));
            const auto plan = Bidirectional(scene, {.method = method}).light_path_plan(box_camera, config);
            CHECK(plan.light_paths < pixels);
            CHECK(plan.connections == 1);
            const double all = pass_variance(scene, box_camera, {.method = method, .light_paths = pixels}, config, passes);
            const double fewer = pass_variance(scene, box_camera, {.method = method, .light_paths = plan.light_paths}, config, passes);
            CHECK(fewer < 1.2 * all);
        }
    }
    // A point light 0.2 below the ceiling: the bright patch above it, seen by the camera and
    // from every wall, is the light paths' first vertex and light tracing's to draw. Under a
    // delta light the light paths stay one a pixel, and a quarter as many has 1.8 to 2.4
    // times its variance (over 4 seeds, at this size; 9 times at 256 x 256).
    {
        const auto scene = Scene{Lights{PointLight<float>{.position = {2.78f, 5.35f, -2.60f}, .intensity = Rgb<float>(20)}}, box_walls()};
        for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
            CAPTURE(method_name(method));
            const auto plan = Bidirectional(scene, {.method = method}).light_path_plan(box_camera, config);
            CHECK(plan.light_paths == pixels);
            CHECK(plan.connections == 1);
            const double all = pass_variance(scene, box_camera, {.method = method, .light_paths = pixels}, config, passes);
            const double quarter = pass_variance(scene, box_camera, {.method = method, .light_paths = pixels / 4}, config, passes);
            CHECK(quarter > 1.5 * all);
        }
    }
    // With dispersion a light path's wavelength band is its camera paths': the light paths
    // stay one a pixel, or a square's pixels would share one band's colour in a pass (and
    // the image's colour rest on a sixteenth of the bands drawn: a dispersive ball under a
    // sky read 6 % off in a channel at 16 passes).
    {
        const auto scene = Scene{Lights{EnvironmentLight<float>{.radiance = Rgb<float>(1)}},
                                 Object{Sphere<float>({0, 0, 0}, 1), DispersiveDielectric<float>{.glass = glass::f2<double>}}};
        const Camera<float> camera{.position = {0, 0, 6}, .look_at = {0, 0, 0}, .fov = 20};
        for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
            CAPTURE(method_name(method));
            const auto plan = Bidirectional(scene, {.method = method}).light_path_plan(camera, config);
            CHECK(plan.light_paths == pixels);
            CHECK(plan.connections == 1);
        }
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
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.volume_radius = -0.5}), doctest::Contains("volume_radius must be finite and >= 0, got -0.5"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.merge_weight = 1.5}), doctest::Contains("merge_weight must be in (0, 1], got 1.5"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.connections = 0}), doctest::Contains("connections must be in (0, 1], got 0"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.connections = 1.5}), doctest::Contains("connections must be in (0, 1], got 1.5"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.only = Strategy{0, 0}}), doctest::Contains("only must have s >= 0 and t >= 1, got (0, 0)"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Bidirectional(scene, {.dispersion_bands = 82}), doctest::Contains("dispersion_bands must be in [1, 81], got 82"), std::invalid_argument);
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
        CAPTURE(method_name(method));
        const double floor = mean_red(render(camera, Bidirectional(scene, {.method = method, .light_paths = 1000}), {.width = 8, .height = 8, .spp = 4, .progress = false}));
        CHECK(floor == doctest::Approx(expected).epsilon(1e-4));
    }
}

namespace {

/// A random path of k segments, v_0 on the light to v_k at the camera, given by the
/// numbers every strategy's density is made of: segment i (v_i to v_(i+1)) has squared
/// length d2[i] and cosines a[i] at v_i and b[i] at v_(i+1); inner vertex v_i's lobe
/// draws v_(i+1) coming from v_(i-1) with fw[i] per steradian and v_(i-1) coming from
/// v_(i+1) with rv[i] (1 both ways at a delta vertex); the light is chosen with q, draws
/// v_0 with density pa per area and the way to v_1 with pw, and a light sample from v_1
/// finds v_0 with `direct` per steradian; the camera draws its ray with pc per steradian.
struct RandomPath {
    int k = 0;
    std::vector<double> d2, a, b, fw, rv;
    std::vector<bool> delta;
    double q = 0, pa = 0, pw = 0, direct = 0, pc = 0;
    bool point_light = false; ///< a point light (no area: pa = 1, direct d^2, a[0] = 1)
    /// Inner vertex v_i's merging kernel over a surface's (1 on a surface; in a medium,
    /// where the cosines each side are 1, another).
    std::vector<double> ratio;
};

RandomPath random_path(Random& rng, int k, bool point_light, bool with_delta)
{
    const auto in = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform<double>(); };
    RandomPath p;
    p.k = k;
    p.point_light = point_light;
    for (int i = 0; i < k; ++i) {
        p.d2.push_back(in(0.2, 5));
        p.a.push_back(i == 0 && point_light ? 1.0 : in(0.05, 1));
        p.b.push_back(in(0.05, 1));
    }
    p.delta.assign(std::size_t(k + 1), false);
    p.fw.assign(std::size_t(k + 1), 0.0);
    p.rv.assign(std::size_t(k + 1), 0.0);
    for (int i = 1; i < k; ++i) {
        p.delta[std::size_t(i)] = with_delta && rng.uniform<double>() < 0.35;
        p.fw[std::size_t(i)] = p.delta[std::size_t(i)] ? 1.0 : in(0.02, 3);
        p.rv[std::size_t(i)] = p.delta[std::size_t(i)] ? 1.0 : in(0.02, 3);
    }
    p.ratio.assign(std::size_t(k + 1), 1.0);
    for (int i = 1; i < k; ++i)
        if (!p.delta[std::size_t(i)] && rng.uniform<double>() < 0.3) {
            p.ratio[std::size_t(i)] = std::exp(in(-3, 3));
            p.a[std::size_t(i)] = p.b[std::size_t(i - 1)] = 1.0;
        }
    p.q = in(0.1, 1);
    p.pa = point_light ? 1.0 : in(0.1, 4);
    p.pw = in(0.05, 2);
    p.direct = point_light ? p.d2[0] : in(0.05, 3);
    p.pc = in(0.2, 6);
    return p;
}

/// Every strategy's weight of a path by the balance heuristic over its densities, written
/// out: strategy s of the connections (s light vertices; the light tracer's, s = k,
/// counted N times a camera path; those with s >= 2 and t >= 2 `connect` times) and merge i
/// at inner vertex v_i, each the product of the densities per area of the vertices each
/// side gives (v_0 by the light's emission, or by its light sample for s = 1), a merge's
/// vertex given by both and counted eta times.
struct Balance {
    std::vector<double> connect; ///< by s, 0 to k
    std::vector<double> merge;   ///< by i, 1 to k - 1 (0 where none)
};

Balance balance(const RandomPath& p, double light_paths, double eta, double connect)
{
    const int k = p.k;
    const auto s_ = [](int i) { return std::size_t(i); };
    // Densities per area: from the light (forward) and from the camera (backward).
    std::vector<double> fwd(s_(k + 1), 0.0), bwd(s_(k + 1), 0.0);
    fwd[0] = p.q * p.pa;
    fwd[1] = p.pw * p.b[0] / p.d2[0];
    for (int i = 1; i + 1 <= k; ++i) fwd[s_(i + 1)] = p.fw[s_(i)] * p.b[s_(i)] / p.d2[s_(i)];
    bwd[s_(k - 1)] = p.pc * p.a[s_(k - 1)] / p.d2[s_(k - 1)];
    for (int i = k - 1; i >= 1; --i) bwd[s_(i - 1)] = p.rv[s_(i)] * p.a[s_(i - 1)] / p.d2[s_(i - 1)];
    const double direct_area = p.point_light ? 1.0 : p.direct * p.a[0] / p.d2[0];
    const auto delta = [&](int i) { return i >= 1 && i <= k - 1 && p.delta[s_(i)]; };
    Balance out;
    double total = 0;
    for (int s = 0; s <= k; ++s) {
        // Impossible: a connection at a delta vertex, a point light met by a bounce.
        bool possible = !(s == 0 && p.point_light);
        if (s >= 1 && delta(s - 1)) possible = false;
        if (s <= k - 1 && delta(s)) possible = false;
        double density = possible ? 1.0 : 0.0;
        for (int i = 0; i < s; ++i) density *= i == 0 && s == 1 ? direct_area : fwd[s_(i)];
        for (int i = s; i <= k - 1; ++i) density *= bwd[s_(i)];
        if (s == k) density *= light_paths;
        if (s >= 2 && s <= k - 1) density *= connect;
        out.connect.push_back(density);
        total += density;
    }
    out.merge.assign(s_(k), 0.0);
    for (int i = 1; i <= k - 1 && eta > 0; ++i) {
        if (delta(i)) continue;
        double density = eta * p.ratio[s_(i)];
        for (int j = 0; j <= i; ++j) density *= fwd[s_(j)];
        for (int j = i; j <= k - 1; ++j) density *= bwd[s_(j)];
        out.merge[s_(i)] = density;
        total += density;
    }
    for (double& w : out.connect) w /= total;
    for (double& w : out.merge) w /= total;
    return out;
}

/// The same weights as Bidirectional computes them: each subpath's VcmMis quantities
/// vertex by vertex, and each strategy's weight from those and the densities where the
/// subpaths meet (surface.connect the connections' share of the camera paths).
Balance recursive(const RandomPath& p, double light_paths, VcmMis<double>::Pass surface)
{
    const int k = p.k;
    const auto s_ = [](int i) { return std::size_t(i); };
    using Mis = VcmMis<double>;
    // Each vertex's: a surface's, or eta times its ratio.
    const auto at = [&](int i) {
        const double r = surface.vm > 0 ? p.ratio[s_(i)] : 1.0;
        return Mis::Pass{.vm = surface.vm * r, .vc = surface.vc, .ratio = r, .connect = surface.connect};
    };
    const Mis::Pass pass = surface;
    // The light subpath: its quantities at v_0 .. v_(k-1).
    std::vector<Mis> light(s_(k));
    Mis l = Mis::light_start(p.q, p.pa, p.pw, p.a[0], false, p.point_light, pass);
    for (int i = 1; i <= k - 1; ++i) {
        if (i == 1 && !p.point_light) l.first_hit_of_area_light(p.direct, p.a[0], p.b[0]);
        else l.arrive(p.d2[s_(i - 1)], p.b[s_(i - 1)]);
        light[s_(i)] = l;
        l.scattered(p.a[s_(i)], p.fw[s_(i)], p.rv[s_(i)], p.delta[s_(i)], at(i));
    }
    // The camera subpath: its quantities at v_(k-1) .. v_0.
    std::vector<Mis> camera(s_(k));
    Mis c = Mis::camera_start(light_paths, p.pc, pass.connect);
    for (int i = k - 1; i >= 0; --i) {
        c.arrive(p.d2[s_(i)], p.a[s_(i)]);
        camera[s_(i)] = c;
        if (i >= 1) c.scattered(p.b[s_(i - 1)], p.rv[s_(i)], p.fw[s_(i)], p.delta[s_(i)], at(i));
    }
    const double emission = p.q * p.pa * p.pw;
    Balance out;
    out.connect.assign(s_(k + 1), 0.0);
    out.merge.assign(s_(k), 0.0);
    const auto delta = [&](int i) { return i >= 1 && i <= k - 1 && p.delta[s_(i)]; };
    if (!p.point_light) out.connect[0] = camera[0].met_light_weight(p.direct * p.a[0] / p.d2[0], emission, pass.connect);
    if (!delta(1) || k == 1)
        out.connect[1] = camera[1].light_sample_weight(p.direct, p.point_light, emission, p.b[0], p.a[0], p.rv[1], p.fw[1], at(1));
    for (int s = 2; s <= k - 1; ++s) {
        if (delta(s - 1) || delta(s)) continue;
        out.connect[s_(s)] = Mis::connection_weight(light[s_(s - 1)], camera[s_(s)], p.d2[s_(s - 1)], p.a[s_(s - 1)], p.b[s_(s - 1)], p.fw[s_(s - 1)],
                                                    p.rv[s_(s - 1)], p.rv[s_(s)], p.fw[s_(s)], at(s - 1), at(s));
    }
    if (!delta(k - 1)) out.connect[s_(k)] = light[s_(k - 1)].splat_weight(p.pc * p.a[s_(k - 1)] / p.d2[s_(k - 1)], light_paths, p.rv[s_(k - 1)], at(k - 1));
    for (int i = 1; i <= k - 1 && pass.vm > 0; ++i)
        if (!delta(i)) out.merge[s_(i)] = Mis::merge_weight(light[s_(i)], camera[s_(i)], p.rv[s_(i)], p.fw[s_(i)], at(i));
    return out;
}

} // namespace

TEST_CASE("the MIS weights of every strategy of random paths are the balance heuristic over the paths' densities, and sum to 1 (BDPT and VCM)")
{
    // Paths of 2 to 7 segments with random lengths, cosines and lobe densities, an area
    // or a point light, some vertices delta; VcmMis's recursive weights against the
    // balance heuristic written out over every strategy's density (connections between
    // inner vertices counted `connect` times, light tracing N times, merges eta times).
    Random rng(11, 3);
    const double light_paths = 4096;
    int paths = 0;
    double worst = 0, worst_sum = 0;
    for (const bool vcm : {false, true})
        for (const bool point_light : {false, true})
            for (const bool with_delta : {false, true})
                for (int k = 2; k <= 7; ++k)
                    for (int n = 0; n < 50; ++n) {
                        const RandomPath p = random_path(rng, k, point_light, with_delta);
                        const double eta = vcm ? 0.05 * 3.14159 * 0.01 * light_paths * (0.2 + rng.uniform<double>()) : 0.0;
                        // Connections for every camera path, a quarter, or a share at random.
                        const double connect = n % 3 == 0 ? 1.0 : n % 3 == 1 ? 0.25 : 0.05 + 0.95 * rng.uniform<double>();
                        const VcmMis<double>::Pass pass{.vm = eta / connect, .vc = vcm ? connect / eta : connect / (0.05 * 3.14159 * 0.01 * light_paths), .connect = connect};
                        const Balance expected = balance(p, light_paths, eta, connect);
                        const Balance got = recursive(p, light_paths, pass);
                        double sum = 0;
                        for (std::size_t s = 0; s < expected.connect.size(); ++s) {
                            worst = std::max(worst, std::abs(got.connect[s] - expected.connect[s]));
                            sum += got.connect[s];
                        }
                        for (std::size_t i = 0; i < expected.merge.size(); ++i) {
                            worst = std::max(worst, std::abs(got.merge[i] - expected.merge[i]));
                            sum += got.merge[i];
                        }
                        // (A path no strategy finds, every vertex but the ends delta: no weights.)
                        double any = 0;
                        for (const double w : expected.connect) any += w;
                        for (const double w : expected.merge) any += w;
                        if (any > 0) worst_sum = std::max(worst_sum, std::abs(sum - 1));
                        ++paths;
                    }
    MESSAGE(paths, " paths: largest difference from the balance heuristic ", worst, ", of a sum from 1 ", worst_sum);
    CHECK(worst < 1e-9);
    CHECK(worst_sum < 1e-9);
}

namespace {

/// Fog of scattering `sigma` (absorbing nothing) filling the box [-1, 1]^3 of the air.
using FogAir = FilledAir<Fog<float>>;

FogAir fog_box(const Rgb<float>& sigma, float g)
{
    return {.medium = {.scattering = sigma, .phase = {.g = g}}, .region = {Vec3<float>(-1), Vec3<float>(1)}};
}

/// The mean of each channel of an image.
Rgb<double> mean_of(const Film& film)
{
    Rgb<double> sum(0);
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) sum += Rgb<double>(film.at(x, y));
    return sum / double(film.width() * film.height());
}

} // namespace

TEST_CASE("the bidirectional volume furnace: a box of coloured fog that absorbs nothing, under a uniform sky, reads the sky, by BDPT and by VCM")
{
    // Radiance 1 from every direction around a box of fog of optical depths 1, 2 and 4
    // across in the three channels that scatters forward (g = 0.6) and absorbs nothing:
    // every camera ray, through the fog or past it, reads 1. Light paths from the sky and
    // camera paths scatter in the fog up to dozens of times; joined and merged there.
    // (The scene's one object is a speck above the box.)
    const auto sky = Scene{Lights{EnvironmentLight<float>{.radiance = Rgb<float>(1)}}, Object{Sphere<float>({0, 1.2f, 0}, 1e-3f), Diffuse<float>{}}};
    const FogAir air = fog_box({0.5f, 1, 2}, 0.6f);
    const Camera<float> camera{.position = {0.1f, 0.2f, 4}, .look_at = {0, 0, 0}, .fov = 25};
    // At 1024 passes every channel read within 0.05 % of 1 (at 256 passes within 0.8 %),
    // with a light path a pixel. (The pilot takes one a square of 4 x 4 pixels here, for
    // a pixel's noise as low for less work; but the image's mean then rests on 16 light
    // paths a pass, and read within 0.6 %.)
    const RenderConfig config{.width = 16, .height = 16, .spp = int(test::samples(1024)), .progress = false};
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
        CAPTURE(method_name(method));
        const Rgb<double> mean = mean_of(render(camera, Bidirectional(sky, {.method = method, .max_length = 1024, .light_paths = 16 * 16}, air), config));
        MESSAGE(method_name(method), ": ", mean.x, " ", mean.y, " ", mean.z);
        for (int c = 0; c < 3; ++c) CHECK(mean[c] == doctest::Approx(1.0).epsilon(test::resolved(0.005)).scale(0));
    }
}

TEST_CASE("the bidirectional furnace of a ball of smoke (fog inside an index-1 ball) under a uniform sky reads the sky, by BDPT and by VCM")
{
    // The fog of the box furnace inside an object: the ball's boundary is no vertex
    // (index-matched), and the vertices inside are in the object's medium, joined and
    // merged there. Read within 0.3 % of 1 at 1024 passes.
    const Fog<float> fog{.scattering = {0.5f, 1, 2}, .phase = {.g = 0.6f}};
    const auto ball = Scene{Lights{EnvironmentLight<float>{.radiance = Rgb<float>(1)}},
                            Object{Sphere<float>({0, 0, 0}, 1), Dielectric<float, ExactFresnel, Fog<float>>{.ior = 1, .interior = fog}}};
    const Camera<float> camera{.position = {0.1f, 0.2f, 4}, .look_at = {0, 0, 0}, .fov = 25};
    const RenderConfig config{.width = 16, .height = 16, .spp = int(test::samples(1024)), .progress = false};
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm}) {
        CAPTURE(method_name(method));
        const Rgb<double> mean = mean_of(render(camera, Bidirectional(ball, {.method = method, .max_length = 1024}), config));
        MESSAGE(method_name(method), ": ", mean.x, " ", mean.y, " ", mean.z);
        for (int c = 0; c < 3; ++c) CHECK(mean[c] == doctest::Approx(1.0).epsilon(test::resolved(0.005)).scale(0));
    }
}

namespace {

// A floor (y = -1, albedo 0.5) in a box of grey haze [-1, 1]^3 (scattering 0.4, absorbing
// 0.1, g = 0.3), lit by a point light above the haze (a light in it makes every light
// sample's 1 / d^2 heavy-tailed); the camera outside the box.
auto hazy_floor()
{
    return Scene{Lights{PointLight<float>{.position = {0.2f, 1.6f, 0.1f}, .intensity = Rgb<float>(5)}},
                 Object{Plane<float>({0, 1, 0}, -1), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}}};
}

const FogAir hazy_air{.medium = {.absorption = Rgb<float>(0.1f), .scattering = Rgb<float>(0.4f), .phase = {.g = 0.3f}}, .region = {Vec3<float>(-1), Vec3<float>(1)}};
const Camera<float> hazy_camera{.position = {0, 0.3f, 3.5f}, .look_at = {0, -0.3f, 0}, .fov = 40};

/// The mean red of the path tracer's image of the hazy floor with paths of at most `length` segments.
double hazy_path_traced(int length, const RenderConfig& config)
{
    using Tracer = PathTracer<std::remove_cvref_t<decltype(hazy_floor())>, FogAir>;
    typename Tracer::Config c;
    c.max_length = length;
    const auto scene = hazy_floor();
    return mean_red(render(hazy_camera, Tracer(scene, c, hazy_air), config));
}

} // namespace

TEST_CASE("in haze, every BDPT strategy alone reads the path tracer's light of its path length, vertices in the haze and on the floor")
{
    // Paths of 2 segments (camera, a vertex in the haze or on the floor, the light): a
    // light sample (1, 2) and light tracing (2, 1); of 3, also a connection (2, 2). Each
    // alone, unweighted, is an unbiased estimate of the light those paths carry, which the
    // path tracer's image to that length less its image to one less measures (its noise
    // 0.1 % at 4096 samples a pixel). Over seeds 0 to 7 at 1024 passes the strategies
    // spread by 0.1 % (1, 2), 0.8 % (2, 1) and (1, 3), 1.6 % (3, 1) about the path
    // tracer's; held at about three times that. A connection between two vertices in the
    // haze has 1 / d^2 and nothing to cancel it: (2, 2) is heavy-tailed, at 4096 passes
    // within -8 % and +10 % over those seeds (their mean 1.5 % low, its own error 1.8 %),
    // held at 15 %.
    const auto scene = hazy_floor();
    const RenderConfig traced{.width = 16, .height = 16, .spp = int(test::samples(4096)), .seed = 6, .progress = false};
    const double two = hazy_path_traced(2, traced), three = hazy_path_traced(3, traced) - two;
    MESSAGE("path tracer: 2 segments ", two, ", 3 segments ", three);
    const auto alone = [&](Strategy strategy, int passes) {
        const BidirectionalConfig config{.method = BidirectionalMethod::bdpt, .max_length = strategy.s + strategy.t - 1, .only = strategy, .weighted = false};
        const double mean = mean_red(render(hazy_camera, Bidirectional(scene, config, hazy_air), {.width = 16, .height = 16, .spp = int(test::samples(passes)), .seed = 5, .progress = false}));
        MESSAGE("(", strategy.s, ", ", strategy.t, "): ", mean);
        return mean;
    };
    CHECK(alone({1, 2}, 1024) == doctest::Approx(two).epsilon(test::resolved(0.005)).scale(0));
    CHECK(alone({2, 1}, 1024) == doctest::Approx(two).epsilon(test::resolved(0.025)).scale(0));
    CHECK(alone({1, 3}, 1024) == doctest::Approx(three).epsilon(test::resolved(0.025)).scale(0));
    CHECK(alone({3, 1}, 1024) == doctest::Approx(three).epsilon(test::resolved(0.05)).scale(0));
    CHECK(alone({2, 2}, 4096) == doctest::Approx(three).epsilon(test::resolved(0.15)).scale(0));
}

TEST_CASE("VCM's merging alone (progressive photon mapping by its light paths) reads the path tracer's light in haze, as progressive photon mapping does")
{
    // The hazy floor, all path lengths: merges alone at each camera path's first vertex
    // in the haze or on the floor (BidirectionalMethod::merging: VCM's merging part,
    // unweighted), 64 passes of 20 000 light paths from a radius of 0.1; prism's
    // progressive photon mapper with as many photons and the same radius; the path
    // tracer at 4096 samples a pixel. Over seeds 1 to 4 merging read within 3.7 % of the
    // path tracer (at a radius of 0.05; their mean 0.5 % above it), progressive photon
    // mapping 0.2 % to 2.4 % below it, and VCM with its default weights within 0.6 %.
    const auto scene = hazy_floor();
    using S = std::remove_cvref_t<decltype(scene)>;
    const RenderConfig config{.width = 16, .height = 16, .spp = 64, .seed = 2, .progress = false};
    const double traced = mean_red(render(hazy_camera, PathTracer(scene, {}, hazy_air), {.width = 16, .height = 16, .spp = int(test::samples(4096)), .seed = 3, .progress = false}));
    const std::size_t paths = std::size_t(test::samples(20000));
    const double merged = mean_red(render(hazy_camera, Bidirectional(scene, {.method = BidirectionalMethod::merging, .radius = 0.1, .light_paths = paths}, hazy_air), config));
    const double vcm = mean_red(render(hazy_camera, Bidirectional(scene, {.method = BidirectionalMethod::vcm, .radius = 0.1, .light_paths = paths}, hazy_air), config));
    ProgressiveConfig<S, FogAir> progressive;
    progressive.pass.tracing = {.global_photons = paths, .caustic_photons = 0, .seed = 2};
    progressive.pass.volume_radius = 0.1f;
    progressive.pass.global.radius = 0.1f;
    const double ppm = mean_red(render(hazy_camera, ProgressivePhotonMapper<S, FogAir>(scene, progressive, hazy_air), config));
    MESSAGE("path tracer ", traced, ", merging ", merged, ", progressive photon mapping ", ppm, ", VCM ", vcm);
    CHECK(merged == doctest::Approx(traced).epsilon(test::resolved(0.06)).scale(0));
    CHECK(merged == doctest::Approx(ppm).epsilon(test::resolved(0.08)).scale(0));
    CHECK(vcm == doctest::Approx(traced).epsilon(test::resolved(0.02)).scale(0));
    // A ball of its own in the haze (volume_radius), twice the surfaces' radius: the same
    // light; and a volume_radius equal to the radius is the default, bit for bit.
    const double wide = mean_red(render(hazy_camera, Bidirectional(scene, {.method = BidirectionalMethod::merging, .radius = 0.05, .volume_radius = 0.2, .light_paths = paths}, hazy_air), config));
    const Film vcm_wide = render(hazy_camera, Bidirectional(scene, {.method = BidirectionalMethod::vcm, .radius = 0.05, .volume_radius = 0.2, .light_paths = paths}, hazy_air), config);
    MESSAGE("volume_radius 0.2: merging ", wide, ", VCM ", mean_red(vcm_wide));
    CHECK(wide == doctest::Approx(traced).epsilon(test::resolved(0.06)).scale(0));
    CHECK(mean_red(vcm_wide) == doctest::Approx(traced).epsilon(test::resolved(0.02)).scale(0));
    const RenderConfig few{.width = 8, .height = 8, .spp = 4, .seed = 2, .progress = false};
    CHECK(render(hazy_camera, Bidirectional(scene, {.radius = 0.1, .volume_radius = 0.1, .light_paths = 500}, hazy_air), few).pixels() ==
          render(hazy_camera, Bidirectional(scene, {.radius = 0.1, .light_paths = 500}, hazy_air), few).pixels());
}

TEST_CASE("VCM's connections are BDPT's: as merging counts for nothing in the weights, VCM's image becomes BDPT's")
{
    // merge_weight scales every merge's weight against the connections; at 1e-7 the
    // merges' share is of that order where a connection finds the path too, and the
    // connections' weights are BDPT's. On scenes with no path that only merging finds (no
    // mirror or glass): the area-lit furnace, in clear air, and the hazy floor.
    const RenderConfig config{.width = 16, .height = 16, .spp = 16, .seed = 4, .progress = false};
    const BidirectionalConfig bdpt{.method = BidirectionalMethod::bdpt, .light_paths = 2000};
    BidirectionalConfig vcm = bdpt;
    vcm.method = BidirectionalMethod::vcm;
    vcm.merge_weight = 1e-7;
    const auto furnace = lamp_furnace();
    const double clear = mean_red(render(lamp_camera, Bidirectional(furnace, bdpt), config));
    CHECK(mean_red(render(lamp_camera, Bidirectional(furnace, vcm), config)) == doctest::Approx(clear).epsilon(1e-4).scale(0));
    const auto scene = hazy_floor();
    const double hazy = mean_red(render(hazy_camera, Bidirectional(scene, bdpt, hazy_air), config));
    CHECK(mean_red(render(hazy_camera, Bidirectional(scene, vcm, hazy_air), config)) == doctest::Approx(hazy).epsilon(1e-4).scale(0));
}

TEST_CASE("in haze, the bidirectional estimators' images are the same bits for any thread count, crop and range of passes")
{
    // Free flights, vertices in the haze, merges within a ball: the hazy floor in parts.
    const auto scene = hazy_floor();
    check_same_bits(scene, hazy_camera, false, hazy_air);
}

TEST_CASE("fog inside a glass ball under a spot light (E S M S L): VCM reads what progressive photon mapping does, BDPT none of it")
{
    // The camera sees the fog through the glass, and the fog is lit through it (a spot
    // light whose cone just holds the ball): the single scattering, camera, glass, fog,
    // glass, light (4 segments), has a delta end at every segment, so no connection joins
    // it; VCM finds it by merging alone, in the fog's volume. Progressive photon mapping
    // reads it from the caustic pass's volume photons (L S+ M), independently; those also
    // hold the light reflected inside the ball before it scatters, and its camera paths
    // the fog seen by such a reflection, a few per cent more (VCM read 1.5 % and 3.7 %
    // below it at 2000 and 10 000 light paths). BDPT finds none of it (it joins two
    // vertices in the fog: the multiple scattering, of 5 segments and more).
    const auto scene = Scene{Lights{SpotLight<float>{.position = {0.3f, 2, 0.2f}, .direction = {-0.3f, -2, -0.2f}, .intensity = Rgb<float>(10), .inner_angle = 15, .outer_angle = 16}},
                             Object{Sphere<float>({0, 0, 0}, 0.5f), Dielectric<float, ExactFresnel, Fog<float>>{.ior = 1.33f, .interior = {.scattering = Rgb<float>(1.5f), .phase = {.g = 0.2f}}}}};
    using S = std::remove_cvref_t<decltype(scene)>;
    const Camera<float> camera{.position = {0, 0, 3}, .look_at = {0, 0, 0}, .fov = 12};
    const RenderConfig config{.width = 12, .height = 12, .spp = 32, .seed = 7, .progress = false};
    const std::size_t paths = std::size_t(test::samples(10000));
    const double vcm = mean_red(render(camera, Bidirectional(scene, {.method = BidirectionalMethod::vcm, .max_length = 4, .radius = 0.04, .light_paths = paths}), config));
    const double bdpt = mean_red(render(camera, Bidirectional(scene, {.method = BidirectionalMethod::bdpt, .max_length = 4, .light_paths = paths}), config));
    ProgressiveConfig<S> progressive;
    progressive.pass.tracing = {.global_photons = 0, .caustic_photons = paths, .seed = 3};
    progressive.pass.volume_radius = 0.04f;
    const double ppm = mean_red(render(camera, ProgressivePhotonMapper<S>(scene, progressive), config));
    MESSAGE("VCM ", vcm, ", progressive photon mapping ", ppm, ", BDPT ", bdpt);
    CHECK(vcm == doctest::Approx(ppm).epsilon(test::resolved(0.07)).scale(0));
    CHECK(bdpt == 0.0);
}

namespace {

/// The mean of an image's channel c.
double mean_channel(const Film& film, int c)
{
    double sum = 0;
    for (const Rgb<float>& p : film.pixels()) sum += double(p[c]);
    return sum / double(film.pixels().size());
}

// A slab of F2 glass over a floor, lit by a small lamp above it and seen from above: every
// path the camera sees crosses the slab twice on each side of the floor, so both subpaths
// are split into wavelength bands, and every merge joins two split subpaths.
auto slab_over_floor()
{
    return Scene{Lights{}, Object{Sphere<float>({0, 1.5f, 0}, 0.2f), Emissive<float>{.radiance = Rgb<float>(20)}},
                 Object{Box<float>({-3, 0.05f, -3}, {3, 0.25f, 3}), DispersiveDielectric<float>{.glass = glass::f2<double>}},
                 Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}, .kd = 1, .ka = 0}}};
}

const Camera<float> slab_camera{.position = {0, 1.2f, 1.2f}, .look_at = {0, 0, 0}, .fov = 40};

} // namespace

TEST_CASE("a dispersive glass ball under a uniform sky reads the sky in every channel, by BDPT and by VCM")
{
    // White light split into bands and summed again is white: each band's share of white
    // over its probability, a pixel's passes stepping through the bands.
    const Camera<float> camera{.position = {0, 0, 6}, .look_at = {0, 0, 0}, .fov = 2};
    const auto scene = Scene{Lights{EnvironmentLight<float>{.radiance = Rgb<float>(1)}}, Object{Sphere<float>({0, 0, 0}, 1), DispersiveDielectric<float>{.glass = glass::f2<double>}}};
    const RenderConfig config{.width = 8, .height = 8, .spp = int(test::samples(256)), .progress = false};
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::vcm})
        for (const int bands : {8, 81}) {
            CAPTURE(method_name(method));
            CAPTURE(bands);
            const Film film = render(camera, Bidirectional(scene, {.method = method, .dispersion_bands = bands}), config);
            for (int c = 0; c < 3; ++c) CHECK(mean_channel(film, c) == doctest::Approx(1.0).epsilon(test::resolved(0.01)));
        }
}

TEST_CASE("light split by a dispersive slab on both sides of a floor: BDPT and VCM's merging alone read the path tracer's")
{
    // The camera and the lamp each see the floor only through the slab. A pair of subpaths
    // takes one band; a merge with another pair's split vertex counts only in the camera
    // path's band, count times (without that factor merging reads a quarter of the light
    // here, four bands; without the band's test, four times it).
    const auto scene = slab_over_floor();
    const RenderConfig config{.width = 24, .height = 16, .spp = int(test::samples(512)), .seed = 2, .progress = false};
    RenderConfig traced = config;
    traced.spp = int(test::samples(2048));
    const Film reference = render(slab_camera, PathTracer(scene, {.dispersion_bands = 4}), traced);
    const auto grey = [](const Film& f) { return (mean_channel(f, 0) + mean_channel(f, 1) + mean_channel(f, 2)) / 3; };
    // Over 6 seeds the grey means spread by 3 % (BDPT) and 2.5 % (merging) at 256
    // passes, the path tracer's by 0.7 % at 1024 samples; each channel by about twice.
    // (VCM is BDPT's connections and merging's merges weighed together: the two alone.)
    for (const BidirectionalMethod method : {BidirectionalMethod::bdpt, BidirectionalMethod::merging}) {
        CAPTURE(method_name(method));
        const Film film = render(slab_camera, Bidirectional(scene, {.method = method, .radius = 0.05, .dispersion_bands = 4}), config);
        CHECK(grey(film) == doctest::Approx(grey(reference)).epsilon(test::resolved(0.08)));
        for (int c = 0; c < 3; ++c) CHECK(mean_channel(film, c) == doctest::Approx(mean_channel(reference, c)).epsilon(test::resolved(0.15)));
    }
}

TEST_CASE("with dispersion, the bidirectional estimators' images are the same bits for any thread count, crop and range of passes")
{
    check_same_bits(slab_over_floor(), slab_camera, false); // (a pixel's few bands may hold no red)
}
