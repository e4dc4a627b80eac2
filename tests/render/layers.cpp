// SPDX-License-Identifier: MIT
#include <prism/render/layers.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace prism;

namespace {

constexpr int film_width = 40, film_height = 30;

/// A floor of albedo (0.6, 0.5, 0.4) under a point light, a glass ball on it, seen from
/// 2 above looking down and ahead, so the top rows see the sky.
auto floor_scene()
{
    Scene scene{Lights{PointLight<float>{.position = {1, 4, 1}, .intensity = Rgb<float>(30)}},
                Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = {0.6f, 0.5f, 0.4f}}, .kd = 1, .ka = 0}},
                Object{Sphere<float>({0, 0.5f, -2}, 0.5f), Dielectric<float>{.ior = 1.5f}}};
    scene.background = {0.2f, 0.3f, 0.5f};
    return scene;
}

const Camera<float> layers_camera{.position = {0, 2, 2}, .look_at = {0, 1.2f, -2}, .fov = 60};

double channel(const Accumulation& sums, int x, int y, std::size_t c) { return sums.sum(x, y, c).value() / double(sums.weight(x, y)); }

std::size_t index_of(const Accumulation& sums, const char* name)
{
    const auto& names = sums.channels();
    return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
}

} // namespace

TEST_CASE("the surface layers: coverage, albedo, normal and distance of the first surface, against the floor's closed form")
{
    const auto scene = floor_scene();
    const Whitted integrator(scene);
    const RenderConfig config{.width = film_width, .height = film_height, .spp = 1, .threads = 2, .progress = false};
    const Accumulation layers = render_layers(layers_camera, integrator, config);
    CHECK(layers.channels() == layer_channels<Whitted<std::remove_cvref_t<decltype(scene)>>>());
    REQUIRE(layers.channels().size() == 11);
    const CameraRays<float> rays = layers_camera.rays(film_width, film_height);
    int floor = 0, sky = 0;
    for (int y = 0; y < film_height; ++y)
        for (int x = 0; x < film_width; ++x) {
            const Ray<float> ray = rays.ray(float(x) + 0.5f, float(y) + 0.5f);
            const double a = channel(layers, x, y, index_of(layers, "A"));
            if (!(ray.direction.y < 0)) { // the sky: no surface
                ++sky;
                CHECK(a == 0);
                CHECK(channel(layers, x, y, index_of(layers, "Z")) == 0);
                continue;
            }
            // Where the ray meets the floor before the ball (the ball's silhouette aside).
            const double t = -double(ray.origin.y) / double(ray.direction.y);
            const Vec3<double> p = Vec3<double>(ray.origin) + t * Vec3<double>(ray.direction);
            const Vec3<double> o = Vec3<double>(ray.origin) - Vec3<double>(0, 0.5, -2), d = normalize(Vec3<double>(ray.direction));
            const double b = dot(o, d), near_ball = b * b - (dot(o, o) - 0.25 * 1.02); // the ball, a little grown, in the way
            if (near_ball >= 0 || length(p - Vec3<double>(ray.origin)) > 40) continue;
            ++floor;
            CHECK(a == 1);
            CHECK(channel(layers, x, y, index_of(layers, "albedo.R")) == doctest::Approx(0.6).epsilon(1e-6));
            CHECK(channel(layers, x, y, index_of(layers, "albedo.B")) == doctest::Approx(0.4).epsilon(1e-6));
            CHECK(channel(layers, x, y, index_of(layers, "normal.X")) == 0);
            CHECK(channel(layers, x, y, index_of(layers, "normal.Y")) == 1);
            CHECK(channel(layers, x, y, index_of(layers, "Z")) == doctest::Approx(t * length(Vec3<double>(ray.direction))).epsilon(1e-5));
        }
    CHECK(floor > 300);
    CHECK(sky > 100);
    // The glass ball reads albedo 1 (a surface of delta lobes only) and faces the camera.
    const auto [bx, by] = [&] {
        const auto seen = rays.project(Vec3<float>(0, 0.5f, -2));
        return std::pair{int(seen->x), int(seen->y)};
    }();
    CHECK(channel(layers, bx, by, index_of(layers, "albedo.G")) == 1);
    CHECK(channel(layers, bx, by, index_of(layers, "normal.Z")) > 0.5);
}

TEST_CASE("render_layers' image is render_sums' bits, and its crops and sample ranges add up")
{
    const auto scene = floor_scene();
    const Whitted integrator(scene);
    RenderConfig config{.width = film_width, .height = film_height, .spp = 4, .threads = 2, .seed = 3, .progress = false};
    const Accumulation layers = render_layers(layers_camera, integrator, config);
    const Accumulation image = render_sums(layers_camera, integrator, config);
    for (int y = 0; y < film_height; ++y)
        for (int x = 0; x < film_width; ++x)
            for (std::size_t c = 0; c < 3; ++c) REQUIRE(image.sum(x, y, c) == layers.sum(x, y, c)); // R, G, B
    // Anti-aliased edges: coverage between 0 and 1 on the horizon.
    int partial = 0;
    for (int y = 0; y < film_height; ++y)
        for (int x = 0; x < film_width; ++x) {
            const double a = channel(layers, x, y, 3);
            partial += a > 0 && a < 1;
        }
    CHECK(partial > 0);
    Accumulation parts(film_width, film_height, PixelWindow::whole(film_width, film_height), layers.channels());
    config.passes = {0, 1};
    config.crop = {0, 0, film_width, 13};
    parts += render_layers(layers_camera, integrator, config);
    config.crop = {0, 13, film_width, film_height};
    parts += render_layers(layers_camera, integrator, config);
    config.crop = {};
    config.passes = {1, 4};
    config.threads = 1;
    parts += render_layers(layers_camera, integrator, config);
    for (int y = 0; y < film_height; ++y)
        for (int x = 0; x < film_width; ++x) REQUIRE(parts.sums(x, y) == layers.sums(x, y));
}

TEST_CASE("the photon mapper's light parts add up to its image: direct, caustic (the glass ball's) and indirect")
{
    const auto scene = floor_scene();
    using S = std::remove_cvref_t<decltype(scene)>;
    const PhotonMapper<S> mapper(scene, {.tracing = {.global_photons = 20000, .caustic_photons = 20000, .seed = 2}, .gather_rays = 0});
    const RenderConfig config{.width = film_width, .height = film_height, .spp = 2, .threads = 2, .progress = false};
    const Accumulation layers = render_layers(layers_camera, mapper, config);
    REQUIRE(layers.channels().size() == 20);
    const Accumulation image = render_sums(layers_camera, mapper, config);
    double direct = 0, caustic = 0, indirect = 0;
    for (int y = 0; y < film_height; ++y)
        for (int x = 0; x < film_width; ++x) {
            for (std::size_t c = 0; c < 3; ++c) REQUIRE(image.sum(x, y, c) == layers.sum(x, y, c));
            for (std::size_t c = 0; c < 3; ++c) {
                const double d = channel(layers, x, y, 11 + c), k = channel(layers, x, y, 14 + c), i = channel(layers, x, y, 17 + c);
                // Each sample's parts add up to its radiance; the sums round each once.
                CHECK(d + k + i == doctest::Approx(channel(layers, x, y, c)).epsilon(1e-5));
                direct += d, caustic += k, indirect += i;
            }
        }
    CHECK(direct > 0);
    CHECK(caustic > 0);  // under the ball
    CHECK(indirect > 0); // the floor lit by light off the floor seen through the ball, and the sky
    CHECK(layer_channels<PhotonMapper<S>>()[11] == "direct.R");
}
