// SPDX-License-Identifier: MIT
#include <prism/light/environment_map.hpp>
#include <prism/prism.hpp>

#include "../support.hpp"
#include "../emission_checks.hpp"

#include <doctest/doctest.h>

#include "../chi2.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace prism;

namespace {

/// The direction at (u, v) of a latitude-longitude image as the header documents it,
/// written out again here: v = 0 the zenith (+y), u = 1/2 toward -z, u = 3/4 toward +x.
Vec3<double> map_direction(double u, double v)
{
    const double theta = pi<double> * v, phi = 2 * pi<double> * (u - 0.5);
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

/// A sky of width x height: a blue-grey gradient, a warm band at the horizon, a few black
/// pixels and a small bright sun at (sun_x, sun_y), as a photographed sky has.
std::vector<Rgb<float>> test_sky(int width, int height, int sun_x, int sun_y, float sun = 2000.0f)
{
    std::vector<Rgb<float>> pixels;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float v = (float(y) + 0.5f) / float(height);
            Rgb<float> p{0.4f + 0.6f * v, 0.6f + 0.3f * v, 1.0f - 0.2f * v};
            if (std::abs(v - 0.5f) < 0.1f) p *= Rgb<float>(2.0f, 1.5f, 1.0f);
            if ((x * 7 + y * 3) % 11 == 0) p = Rgb<float>(0.0f);
            if (x == sun_x && y == sun_y) p = Rgb<float>(sun, 0.9f * sun, 0.7f * sun);
            pixels.push_back(p);
        }
    return pixels;
}

/// The irradiance on a surface facing +y under `map`, by the midpoint rule over the upper
/// hemisphere on n x 2n cells of equal (cos theta, phi) (so of equal solid angle).
Rgb<double> irradiance_facing_up(const EnvironmentMap<double>& map, int n)
{
    Rgb<double> sum{0.0};
    for (int i = 0; i < n; ++i) {
        const double cos_theta = (i + 0.5) / n, sin_theta = std::sqrt(1 - cos_theta * cos_theta);
        for (int j = 0; j < 2 * n; ++j) {
            const double phi = 2 * pi<double> * (j + 0.5) / (2 * n);
            sum += map.arriving_from({sin_theta * std::cos(phi), cos_theta, sin_theta * std::sin(phi)}) * cos_theta;
        }
    }
    return sum * (2 * pi<double> / (2.0 * n * n));
}

/// A floor of albedo a under `map`, seen straight down, reads a E / pi in every integrator
/// that sees direct light (the mean of n estimates against the quadrature's E).
template <class SceneT>
void check_floor_under_map(const SceneT& scene, double expected, const std::string& what)
{
    const Ray<double> down{{0.1, 1, 0.2}, {0, -1, 0}};
    // (Under a sanitizer an eighth of the estimates, and 1.4 %: tests/effort.hpp.)
    const auto mean_of = [&](const auto& integrator, long n) { return test::mean_radiance(integrator, down, n, Random(29, 3)); };
    CHECK_MESSAGE(mean_of(Whitted(scene, {.area_light_grid = 8}), 20000) == doctest::Approx(expected).epsilon(test::resolved(0.005)), what, ": Whitted");
    for (const AreaLightStrategy strategy : {AreaLightStrategy::mis, AreaLightStrategy::light_samples, AreaLightStrategy::bounces}) {
        // Sampling the hemisphere alone meets a small sun by chance: more paths for it.
        const int paths = strategy == AreaLightStrategy::bounces ? 2000000 : 200000;
        CHECK_MESSAGE(mean_of(PathTracer(scene, {.area_lights = strategy}), paths) == doctest::Approx(expected).epsilon(test::resolved(0.005)), what,
                      ": path tracer, strategy ", int(strategy));
    }
    const PhotonMapper mapper(scene, {.tracing = {.global_photons = 20000, .caustic_photons = 0}});
    CHECK_MESSAGE(mean_of(mapper, 20000) == doctest::Approx(expected).epsilon(test::resolved(0.005)), what, ": photon mapper");
}

} // namespace

TEST_CASE("an environment map lays its image on the sphere as documented: the zenith on top, -z in the middle, +x to the right")
{
    const int w = 8, h = 4;
    std::vector<Rgb<float>> pixels;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) pixels.push_back(Rgb<float>(float(1 + x + 10 * y), float(y), 1.0f));
    const EnvironmentMap<double> map(w, h, pixels);
    // At every pixel's centre the bilinear radiance is the pixel itself.
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Vec3<double> d = map_direction((x + 0.5) / w, (y + 0.5) / h);
            CHECK_MESSAGE(map.arriving_from(d).x == doctest::Approx(1 + x + 10 * y).epsilon(1e-9), "pixel (", x, ", ", y, ")");
        }
    // Halfway between two columns' centres, and across the seam at u = 0 (= 1).
    CHECK(map.arriving_from(map_direction(2.0 / w, 0.5 / h)).x == doctest::Approx(2.5).epsilon(1e-9));
    CHECK(map.arriving_from(map_direction(0.0, 1.5 / h)).x == doctest::Approx((1 + 10 + 8 + 10) / 2.0).epsilon(1e-9));
    // Straight up is the top row (held at the pole), straight down the bottom.
    CHECK(map.arriving_from({0, 1, 0}).y == doctest::Approx(0).scale(1));
    CHECK(map.arriving_from({0, -1, 0}).y == doctest::Approx(3).epsilon(1e-12));
    // -z is the middle, between columns 3 and 4 of rows 1 and 2; +x is column 6's left edge.
    CHECK(map.arriving_from({0, 0, -1}).x == doctest::Approx((14 + 15 + 24 + 25) / 4.0).epsilon(1e-9));
    CHECK(map.arriving_from({1, 0, 0}).x == doctest::Approx((16 + 17 + 26 + 27) / 4.0).epsilon(1e-9));
    // Turned by 90 degrees about +y (counterclockwise from above): what was at -z is at -x.
    const EnvironmentMap<double> turned(w, h, pixels, {.rotation_degrees = 90});
    Random rng(3, 3);
    for (int i = 0; i < 1000; ++i) {
        const Vec3<double> d = uniform_sphere<double>(rng);
        const Vec3<double> d_turned{d.z, d.y, -d.x}; // +90 degrees about y: -z goes to -x
        CHECK(turned.arriving_from(d_turned).x == doctest::Approx(map.arriving_from(d).x).epsilon(1e-9));
    }
    CHECK(turned.arriving_from({-1, 0, 0}).x == doctest::Approx(map.arriving_from({0, 0, -1}).x).epsilon(1e-9));
}

TEST_CASE("an environment map is sampled as densely as its pdf says (chi-square), and its pdf integrates to 1")
{
    for (const double rotation : {0.0, 37.0}) {
        const EnvironmentMap<double> map(16, 8, test_sky(16, 8, 5, 2, 50.0f), {.rotation_degrees = rotation});
        const test::Chi2 c = test::chi2_directions([&](double u, double v) { return map.sample({}, {u, v}).wi; },
                                                   [&](const Vec3<double>& w) { return map.pdf(w); }, {0, 1, 0}, 2000000, 40, 80, 40);
        MESSAGE("rotation ", rotation, ": chi2 ", c.statistic, " with ", c.degrees, " degrees, p = ", c.p_value, "; missing ", c.missing, ", stray ", c.stray);
        CHECK(c.p_value > 1e-3);
        // Under the renders' Sobol points (the statistic far below its degrees of freedom,
        // as the counts scatter less than a multinomial's; a wrong density still adds much).
        const test::Chi2 sobol = test::chi2_directions([&](double u, double v) { return map.sample({}, {u, v}).wi; },
                                                       [&](const Vec3<double>& w) { return map.pdf(w); }, {0, 1, 0}, 2000000, 40, 80, 40, -1, 7, SamplerKind::sobol);
        MESSAGE("under Sobol points: chi2 ", sobol.statistic, " with ", sobol.degrees, " degrees, p = ", sobol.p_value);
        CHECK(sobol.p_value > 1e-3);
        CHECK(std::abs(c.missing) < 1e-3 * 2e6);
        CHECK(c.stray == 0);
        // Each sample's density is pdf() of its direction, but where rounding moves a sample
        // across a pixel's edge.
        Random rng(4, 4);
        int off = 0;
        for (int i = 0; i < 100000; ++i) {
            const LightSample<double> s = map.sample({}, {rng.uniform<double>(), rng.uniform<double>()});
            CHECK(s.distance == infinity<double>);
            CHECK(std::abs(length(s.wi) - 1) < 1e-12);
            if (std::abs(s.pdf - map.pdf(s.wi)) > 1e-9 * s.pdf) ++off;
            const Rgb<double> want = map.arriving_from(s.wi) / s.pdf;
            for (int ch = 0; ch < 3; ++ch) CHECK(s.irradiance[ch] == doctest::Approx(want[ch]).epsilon(1e-12));
        }
        CHECK(off < 10);
        // The density over the sphere, by the midpoint rule on cells of equal solid angle.
        double total = 0;
        const int n = 400;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < 2 * n; ++j) {
                const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), phi = 2 * pi<double> * (j + 0.5) / (2 * n);
                total += map.pdf({r * std::cos(phi), z, r * std::sin(phi)});
            }
        CHECK(total * 4 * pi<double> / (2.0 * n * n) == doctest::Approx(1).epsilon(2e-3));
    }
}

TEST_CASE("drawn by the image, a sky with a sun is estimated with the same mean as uniform directions give, and far lower variance")
{
    const EnvironmentMap<double> map(64, 32, test_sky(64, 32, 20, 9));
    const Rgb<double> exact = irradiance_facing_up(map, 1500);
    // One-sample estimates of the irradiance on a surface facing up: L cos / pdf.
    const auto estimate = [&](bool by_image, long n) {
        Random rng(11, by_image ? 1 : 2);
        double sum = 0, squares = 0;
        for (long i = 0; i < n; ++i) {
            const Vec2<double> u{rng.uniform<double>(), rng.uniform<double>()};
            double e = 0;
            if (by_image) {
                const LightSample<double> s = map.sample({}, u);
                e = s.irradiance.x * std::max(0.0, s.wi.y);
            } else {
                const Vec3<double> w = uniform_sphere(u.x, u.y);
                e = map.arriving_from(w).x * std::max(0.0, w.y) * 4 * pi<double>;
            }
            sum += e;
            squares += e * e;
        }
        const double mean = sum / double(n);
        return std::pair{mean, squares / double(n) - mean * mean};
    };
    const long n = 400000;
    const auto [image_mean, image_variance] = estimate(true, n);
    const auto [uniform_mean, uniform_variance] = estimate(false, n);
    MESSAGE("irradiance ", exact.x, ": by the image ", image_mean, " (variance ", image_variance, "), uniform ", uniform_mean, " (variance ",
            uniform_variance, "): ", uniform_variance / image_variance, " times the variance");
    CHECK(std::abs(image_mean - exact.x) < 4 * std::sqrt(image_variance / double(n)));
    CHECK(std::abs(uniform_mean - exact.x) < 4 * std::sqrt(uniform_variance / double(n)));
    CHECK(uniform_variance > 20 * image_variance);
}

TEST_CASE("a floor under an environment map reads albedo E / pi in every integrator, E by quadrature over the image")
{
    // A constant image is the uniform sky of radiance 1: E = pi.
    const Scene white{Lights{EnvironmentMap<double>(8, 4, std::vector<Rgb<float>>(32, Rgb<float>(1.0f)))},
                      Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(1)}}}};
    check_floor_under_map(white, 1.0, "constant image");
    const EnvironmentMap<double> sky(32, 16, test_sky(32, 16, 9, 4, 200.0f), {.strength = 0.5, .rotation_degrees = 20});
    const double e = irradiance_facing_up(sky, 1500).x;
    const Scene scene{Lights{sky}, Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}}}};
    check_floor_under_map(scene, 0.5 * e / pi<double>, "sky with a sun");
}

TEST_CASE("an environment map's photons light a floor with the irradiance its image gives")
{
    const EnvironmentMap<double> sky(32, 16, test_sky(32, 16, 9, 4, 200.0f));
    const double e = irradiance_facing_up(sky, 1500).x;
    const Scene scene{Lights{sky}, Object{Quad<double>({-5, 0, 5}, {10, 0, 0}, {0, 0, -10}), Diffuse<double>{.albedo = {.color = Rgb<double>(0)}}}};
    const PhotonMaps maps = trace_photons(scene, {.global_photons = test::samples(1000000), .caustic_photons = 0, .shadow_photons = false, .seed = 6});
    const Rgb<float> photons = maps.global.irradiance_within({0, 0, 0}, {0, 1, 0}, 2.0f);
    MESSAGE("irradiance from the photons: ", photons.x, " (quadrature: ", e, ")");
    CHECK(photons.x == doctest::Approx(e).epsilon(test::resolved(0.02)));
}

TEST_CASE("a sky whose one lit pixel is 2^100 (1.3e30) renders 2^100 times the image of one whose pixel is 1, bit for bit")
{
    // Regression: samples of 2^40 (1.1e12) or more were left out of the film, and a sky
    // of one very bright pixel (an 8 KB .hdr can hold 10^38) rendered black. A power of
    // two scales every sample exactly, so the images differ by that factor alone.
    const auto image = [](float sun) {
        std::vector<Rgb<float>> pixels(16 * 8, Rgb<float>(0.0f));
        pixels[3 * 16 + 5] = Rgb<float>(sun);
        const Scene scene{Lights{EnvironmentMap<double>(16, 8, pixels)}, Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{}}};
        const Camera<double> camera{.position = {0, 2, 3}, .look_at = {0, 0, 0}, .fov = 40};
        return render(camera, PathTracer(scene), {.width = 8, .height = 8, .spp = 4, .threads = 2, .progress = false});
    };
    const Film one = image(1.0f), bright = image(0x1p100f);
    CHECK(bright.rejected() == 0);
    int lit = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            REQUIRE(bright.at(x, y).r == 0x1p100f * one.at(x, y).r);
            lit += one.at(x, y).r > 0;
        }
    CHECK(lit > 32);
}

TEST_CASE("an environment map refuses an image it cannot light by, naming the pixel or the parameter")
{
    const auto message = [](int w, int h, const std::vector<Rgb<float>>& pixels, EnvironmentMapSettings<float> settings = {}) {
        try {
            (void)EnvironmentMap<float>(w, h, pixels, settings);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    std::vector<Rgb<float>> pixels(6, Rgb<float>(1.0f));
    CHECK(message(3, 2, pixels) == "accepted");
    CHECK(message(3, 3, pixels) == "prism: EnvironmentMap pixels: 6 for an image of 3 x 3");
    CHECK(message(0, 2, {}) == "prism: EnvironmentMap size must be at least 1 x 1, got 0 x 2");
    CHECK(message(3, 2, pixels, {.strength = 0}).find("EnvironmentMap strength must be finite and > 0, got 0") != std::string::npos);
    CHECK(message(3, 2, pixels, {.rotation_degrees = INFINITY}).find("EnvironmentMap rotation_degrees must be finite") != std::string::npos);
    pixels[4].y = -1;
    CHECK(message(3, 2, pixels) == "prism: EnvironmentMap pixel (1, 1) must be finite and >= 0 in every channel, got (1, -1, 1)");
    pixels[4] = Rgb<float>(NAN);
    CHECK(message(3, 2, pixels).find("pixel (1, 1) must be finite") != std::string::npos);
    // Radiance a float holds, but whose estimates L / pdf would not fit.
    pixels[4] = Rgb<float>(3e37f);
    CHECK(message(3, 2, pixels).find("too large for this precision") != std::string::npos);
    // Black everywhere: it lights nothing, drawn uniformly.
    const EnvironmentMap<float> black(3, 2, std::vector<Rgb<float>>(6, Rgb<float>(0.0f)));
    const LightSample<float> s = black.sample({}, {0.3f, 0.6f});
    CHECK(s.irradiance == Rgb<float>(0.0f));
    CHECK(s.pdf == doctest::Approx(1 / (4 * pi<double>)).epsilon(1e-5));
}

TEST_CASE("an environment map's emission carries pi R^2 times its radiance over the sphere, from directions its pdf draws")
{
    const EnvironmentMap<double> sky(32, 16, test_sky(32, 16, 9, 4, 200.0f), {.strength = 0.5, .rotation_degrees = 20});
    const BoundingSphere<double> sphere{{1, 2, 3}, 2};
    const Rgb<double> power = test::emitted_power(sky, sphere, int(test::samples(100000)));
    const Rgb<double> expected = sky.photon_power({nullptr, &sphere});
    // Each ray carries L / pdf over its disk's density: the sky's importance sampling makes it nearly constant.
    for (int k = 0; k < 3; ++k) CHECK(power[k] == doctest::Approx(expected[k]).epsilon(test::resolved(0.01)));
}
