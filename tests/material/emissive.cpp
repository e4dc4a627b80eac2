// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace prism;

namespace {

/// A 2 x 1 picture, nearest texel: (1, 0.2, 0) on the left half (u < 1/2), (0, 0.2, 1) on the right.
ImageTexture<double> two_halves()
{
    const std::vector<float> texels{1, 0.2f, 0, 0, 0.2f, 1};
    return {2, 1, 3, texels, {Wrap::clamp, TextureFilter::nearest}};
}

/// A 1 x 2 picture, nearest texel: 1 on the top row (v > 1/2), 0 below.
ImageTexture<double> top_half()
{
    const std::vector<float> texels{1, 0};
    return {1, 2, 1, texels, {Wrap::clamp, TextureFilter::nearest}};
}

/// The lit sign: a 2 x 1 quad at height 1 facing down (its u along x, from -1 to 1; v along
/// z, from -0.5 to 0.5), radiance 5 times two_halves(), over a floor it lights.
auto sign_scene()
{
    using Sign = Emissive<double, ImageTexture<double>>;
    return Scene{Lights{}, Object{Quad<double>({-1, 1, -0.5}, {2, 0, 0}, {0, 0, 1}), Sign{.radiance = Rgb<double>(5), .pattern = two_halves()}},
                 Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .kd = 1, .ka = 0}}};
}

/// The irradiance the sign gives the floor's point p (upward normal), by the midpoint rule
/// over a grid of n x n cells of the quad (the picture's two halves as they map onto it).
Rgb<double> sign_irradiance_by_quadrature(const Vec3<double>& p, int n)
{
    Rgb<double> sum(0.0);
    const double cell = 2.0 * 1.0 / (double(n) * double(n));
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double u = (i + 0.5) / n, v = (j + 0.5) / n;
            const Vec3<double> x{-1 + 2 * u, 1, -0.5 + v};
            const Vec3<double> d = x - p;
            const double d2 = length_squared(d), cos_floor = d.y / std::sqrt(d2), cos_sign = d.y / std::sqrt(d2);
            const Rgb<double> texel = u < 0.5 ? Rgb<double>{1, 0.2, 0} : Rgb<double>{0, 0.2, 1};
            sum += 5.0 * texel * (cos_floor * cos_sign / d2 * cell);
        }
    return sum;
}

/// Whether a and b agree to 10^-6 in every channel (the picture's texels are floats).
bool near(const Rgb<double>& a, const Rgb<double>& b) { return max_component(abs(a - b)) < 1e-6; }

} // namespace

TEST_CASE("a patterned Emissive: its radiance times the pattern, read by surface coordinates; an unpatterned one reads nothing")
{
    using Sign = Emissive<double, ImageTexture<double>>;
    static_assert(Material<Sign> && emission_varies<Sign>() && reads_coordinates<Sign>());
    static_assert(!emission_varies<Emissive<double>>() && !reads_coordinates<Emissive<double>>());
    static_assert(sizeof(Emissive<float>) == sizeof(Rgb<float>) + 4); // no room for the absent pattern
    const Sign sign{.radiance = Rgb<double>(5), .pattern = two_halves()};
    CHECK(near(sign.emitted_radiance({{}, {0.25, 0.5}, 0}), {5, 1, 0}));
    CHECK(near(sign.emitted_radiance({{}, {0.75, 0.5}, 0}), {0, 1, 5}));
    CHECK(Emissive<double>{.radiance = {1, 2, 3}}.emitted_radiance({{7, 7, 7}, {0.3, 0.1}, 0}) == Rgb<double>{1, 2, 3});
    CHECK_THROWS_WITH_AS((Sign{.radiance = Rgb<double>(-1), .pattern = two_halves()}.validate()), doctest::Contains("Emissive radiance"),
                         std::invalid_argument);
    CHECK_THROWS_AS((Sign{.radiance = Rgb<double>(1)}.validate()), std::invalid_argument); // an empty picture
    // A ray that meets the sign sees the texel there (the quad's coordinates: u along its first edge).
    const auto scene = sign_scene();
    const PathTracer tracer(scene);
    Random rng(1, 1);
    CHECK(near(tracer.radiance(Ray<double>{{-0.7, 0.5, 0.3}, {0, 1, 0}}, rng), {5, 1, 0}));
    CHECK(near(tracer.radiance(Ray<double>{{0.3, 0.5, -0.3}, {0, 1, 0}}, rng), {0, 1, 5}));
}

TEST_CASE("a patterned area light's power is pi A times its mean radiance, and its light samples give the floor the irradiance quadrature gives")
{
    const auto scene = sign_scene();
    const auto lights = scene.area_lights();
    // pi A L mean(texel): half of each texel's colour, A = 2.
    const Rgb<double> power = lights.photon_power({});
    const Rgb<double> expected = pi<double> * 2.0 * 5.0 * Rgb<double>{0.5, 0.2, 0.5};
    for (int c = 0; c < 3; ++c) CHECK(power[c] == doctest::Approx(expected[c]).epsilon(1e-6));
    // A sphere whose upper half glows: its mean over the area is 1/2 (v = 1 - theta / pi).
    const Scene globe{Lights{}, Object{Sphere<double>({0, 3, 0}, 0.5), Emissive<double, ImageTexture<double>>{.radiance = Rgb<double>(2), .pattern = top_half()}}};
    CHECK(globe.area_lights().photon_power({}).x == doctest::Approx(pi<double> * (pi<double>) * 2.0 * 0.5).epsilon(0.01)); // pi (4 pi r^2) L / 2
    // Light samples at floor points, against the midpoint rule over the sign.
    Random rng(5, 5);
    for (const Vec3<double> p : {Vec3<double>{0, 0, 0}, Vec3<double>{-0.6, 0, 0.3}, Vec3<double>{0.8, 0, -0.4}}) {
        CAPTURE(p);
        const Rgb<double> exact = sign_irradiance_by_quadrature(p, 1000);
        const int n = 200000;
        Rgb<double> sum(0.0), squares(0.0);
        for (int i = 0; i < n; ++i) {
            const LightSample<double> s = lights.sample(p, {rng.uniform<double>(), rng.uniform<double>()});
            const Rgb<double> e = s.irradiance * std::max(s.wi.y, 0.0);
            sum += e;
            squares += e * e;
        }
        for (int c = 0; c < 3; c += 2) {
            const double mean = sum[c] / n, error = std::sqrt((squares[c] / n - mean * mean) / n);
            CHECK(std::abs(mean - exact[c]) < 4 * error + 1e-4 * exact[c]);
        }
    }
}

TEST_CASE("photons leave a patterned area light with the power each part of it sends")
{
    // The sign's left half sends pi (A / 2) L (1, 0.2, 0), its right half pi (A / 2) L (0, 0.2, 1):
    // the photons leaving each half carry that, in every channel.
    const auto scene = sign_scene();
    const auto lights = scene.area_lights();
    const Rgb<double> total = lights.photon_power({});
    Random rng(9, 9);
    const int n = 400000;
    Rgb<double> left(0.0), right(0.0);
    for (int i = 0; i < n; ++i) {
        const EmittedPhoton<double> photon = lights.emit_photon({}, rng.uniform<double>(), rng.uniform<double>(), rng);
        (photon.ray.origin.x < 0 ? left : right) += photon.weight * total / double(n);
    }
    const double each_half = pi<double> * 1.0 * 5.0;
    CHECK(left.x == doctest::Approx(each_half).epsilon(0.01));
    CHECK(left.y == doctest::Approx(0.2 * each_half).epsilon(0.01));
    CHECK(left.z == doctest::Approx(0.0));
    CHECK(right.x == doctest::Approx(0.0));
    CHECK(right.y == doctest::Approx(0.2 * each_half).epsilon(0.01));
    CHECK(right.z == doctest::Approx(each_half).epsilon(0.01));
}
