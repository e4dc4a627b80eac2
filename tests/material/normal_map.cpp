// SPDX-License-Identifier: MIT
#include <prism/material/normal_map.hpp>
#include <prism/material/image_texture.hpp>
#include <prism/integrator/path_tracer.hpp>
#include <prism/integrator/whitted.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace prism;
using doctest::Approx;

namespace {

/// A one-number texture of the function f(u, v).
template <class F>
struct Field {
    using scalar_type = double;
    F f;
    [[nodiscard]] double value(const TexturePoint<double>& at) const noexcept { return f(at.uv.x, at.uv.y); }
    void validate() const {}
};
template <class F>
Field(F) -> Field<F>;

/// One normal everywhere, as a normal map's RGB.
struct ConstantNormal {
    using scalar_type = double;
    Vec3<double> n;
    [[nodiscard]] Rgb<double> albedo(const TexturePoint<double>&) const noexcept { return (n + Vec3<double>(1)) * 0.5; }
    void validate() const {}
};

/// The floor y = 0 (u = x, v = -z: Plane's face axes) seen straight down at (x, z).
Crossing<double> floor_at(double x, double z)
{
    const Plane<double> floor({0, 1, 0}, 0);
    Crossing<double> c = floor.crossings({{x, 1, z}, {0, -1, 0}}, {0, infinity<double>}).front();
    floor.coordinates(c);
    return c;
}

using Matte = Diffuse<double>;

} // namespace

static_assert(Material<NormalMapped<Matte, ImageTexture<double>>> && Material<BumpMapped<RoughConductor<double>, ImageTexture<double>>>);

TEST_CASE("a normal map tilts the shading normal in the tangent frame (t along dp/du, b along dp/dv); a flat map changes nothing")
{
    Crossing<double> c = floor_at(0.3, -0.2);
    NormalMapped<Matte, ConstantNormal>(Matte{}, {{0, 0, 1}}).shade(c);
    CHECK(c.shading == Vec3<double>(0, 1, 0));
    // On the floor t = +x and b = -z.
    const Vec3<double> m = normalize(Vec3<double>{0.3, 0.2, 1});
    c = floor_at(0.3, -0.2);
    NormalMapped<Matte, ConstantNormal>(Matte{}, {m}).shade(c);
    CHECK(c.shading.x == Approx(m.x));
    CHECK(c.shading.z == Approx(-m.y));
    CHECK(c.shading.y == Approx(m.z));
    CHECK(c.normal == Vec3<double>(0, 1, 0)); // the true normal stays
    // Half strength: half the tangent part.
    c = floor_at(0.3, -0.2);
    NormalMapped<Matte, ConstantNormal>(Matte{}, {m}, 0.5).shade(c);
    const Vec3<double> halved = normalize(Vec3<double>{0.5 * m.x, m.z, -0.5 * m.y});
    CHECK(length(c.shading - halved) < 1e-12);
}

TEST_CASE("a map that would turn the normal past the surface is bent back above it: no light leaks through")
{
    for (const Vec3<double> m : {Vec3<double>{1, 0, 0}, normalize(Vec3<double>{1, 0.5, -0.2}), Vec3<double>{0, -1, 0}}) {
        Crossing<double> c = floor_at(0, 0);
        NormalMapped<Matte, ConstantNormal>(Matte{}, {m}).shade(c);
        CHECK(dot(c.shading, c.normal) >= 0.0099);
        CHECK(length(c.shading) == Approx(1));
    }
}

TEST_CASE("a bump map shades as the moved surface: a ramp's normal, and a sine's, as a normal map of its slopes gives")
{
    // Heights a u on the floor: the surface y = a x, normal (-a, 1, 0) / |.|.
    const double a = 0.4;
    Crossing<double> c = floor_at(0.7, 0.3);
    BumpMapped<Matte, Field<double (*)(double, double)>>(Matte{}, {[](double u, double) { return 0.4 * u; }}, 1.0).shade(c);
    const Vec3<double> ramp = normalize(Vec3<double>{-a, 1, 0});
    CHECK(length(c.shading - ramp) < 1e-9);
    // Heights 0.05 sin(2 pi u) cos(2 pi v): the bump map against a normal map of the
    // analytic normal (-h_u, -h_v, 1) in the tangent frame.
    const auto h = [](double u, double v) { return 0.05 * std::sin(2 * pi<double> * u) * std::cos(2 * pi<double> * v); };
    const BumpMapped<Matte, Field<decltype(h)>> bumped(Matte{}, {h}, 1.0);
    double worst = 0;
    for (int i = 0; i < 100; ++i) {
        const double x = 0.013 + i * 0.0371, z = -0.21 * i;
        Crossing<double> b = floor_at(x, z), n = b;
        bumped.shade(b);
        const double u = n.uv.x, v = n.uv.y;
        const double h_u = 0.05 * 2 * pi<double> * std::cos(2 * pi<double> * u) * std::cos(2 * pi<double> * v);
        const double h_v = -0.05 * 2 * pi<double> * std::sin(2 * pi<double> * u) * std::sin(2 * pi<double> * v);
        NormalMapped<Matte, ConstantNormal>(Matte{}, {normalize(Vec3<double>{-h_u, -h_v, 1})}).shade(n);
        worst = std::max(worst, length(b.shading - n.shading));
    }
    CHECK(worst < 1e-5);
}

TEST_CASE("a bump map on a sphere: heights that grow with the radius tilt nothing; a mirrored frame keeps the tilt outward")
{
    const Sphere<double> ball({0, 0, 0}, 2);
    Crossing<double> c0 = ball.crossings({{0.3, 0.4, -5}, {0, 0, 1}}, {0, infinity<double>}).front();
    ball.coordinates(c0);
    Crossing<double> c = c0;
    BumpMapped<Matte, Field<double (*)(double, double)>>(Matte{}, {[](double, double) { return 0.3; }}, 1.0).shade(c);
    CHECK(length(c.shading - c0.normal) < 1e-12);
    // A height rising with v (toward the top) tilts the normal down, toward -y, in both
    // handednesses.
    for (const bool mirrored : {false, true}) {
        Crossing<double> m = c0;
        if (mirrored) m.dpdu = -m.dpdu, m.uv.x = -m.uv.x;
        BumpMapped<Matte, Field<double (*)(double, double)>>(Matte{}, {[](double, double v) { return 0.5 * v; }}, 1.0).shade(m);
        CHECK(m.shading.y < c0.normal.y - 0.01);
        CHECK(dot(m.shading, c0.normal) > 0.9);
    }
}

TEST_CASE("Whitted and the path tracer shade by the map: a tilted floor under a directional light reads albedo E cos(n', l) / pi")
{
    // The scene hands out crossings with the map's normal (Scene::closest_hit); a
    // directional light at 40 degrees, seen through a camera straight above.
    const Vec3<double> tilt = normalize(Vec3<double>{0.35, 0.1, 1});
    const Vec3<double> to_light = normalize(Vec3<double>{std::sin(0.7), std::cos(0.7), 0});
    const Scene scene{Lights{DirectionalLight<double>{.direction = -to_light, .irradiance = Rgb<double>(2)}},
                      Object{Plane<double>({0, 1, 0}, 0), NormalMapped<Diffuse<double>, ConstantNormal>(Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .kd = 1}, {tilt})}};
    const Camera<double> camera{.position = {0, 3, 0}, .look_at = {0, 0, 0}, .up = {0, 0, -1}, .fov = 20};
    const auto hit = scene.closest_hit(camera.rays(8, 8).ray(4, 4), {0, infinity<double>});
    REQUIRE(hit);
    const Vec3<double> n_world{tilt.x, tilt.z, -tilt.y}; // t = +x, b = -z, n = +y
    CHECK(length(hit->crossing.shading - n_world) < 1e-12);
    const double expected = 0.5 / pi<double> * 2 * dot(n_world, to_light);
    const Film whitted = render(camera, Whitted(scene), {.width = 8, .height = 8, .spp = 1, .threads = 1, .progress = false});
    CHECK(whitted.at(4, 4).x == Approx(expected).epsilon(1e-4));
    const PathTracer path(scene, {.max_diffuse_bounces = 0});
    const Film film = render(camera, path, {.width = 8, .height = 8, .spp = 4, .threads = 1, .progress = false});
    CHECK(film.at(4, 4).x == Approx(expected).epsilon(1e-3));
}
