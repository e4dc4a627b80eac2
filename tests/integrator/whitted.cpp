// SPDX-License-Identifier: MIT
#include <prism/integrator/whitted.hpp>
#include <prism/prism.hpp>

#include "../airlight.hpp"
#include "../furnace.hpp"
#include "../glossy_scenes.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

using namespace prism;
using doctest::Approx;

TEST_CASE_TEMPLATE("a diffuse plane under a point light: L = albedo kd I cos / (pi r^2)", T, float, double)
{
    const Vec3<T> light_at{T(0.5), T(4), T(-1)};
    const T intensity = T(10), albedo = T(0.5), kd = T(0.8);
    const Scene scene{Lights{PointLight<T>{.position = light_at, .intensity = Rgb<T>(intensity)}},
                      Object{Plane<T>({T(0), T(1), T(0)}, T(0)), Diffuse<T>{.albedo = {.color = Rgb<T>(albedo)}, .kd = kd, .ka = T(1)}}};
    const Whitted integrator(scene);
    const Camera<T> camera{.position = {T(0), T(2), T(5)}, .look_at = {T(0), T(0), T(0)}, .fov = T(50)};
    const int width = 64, height = 48;
    const Film film = render(camera, integrator, {.width = width, .height = height, .spp = 1, .threads = 2, .progress = false});
    const auto rays = camera.rays(width, height);
    int checked = 0;
    for (int y = 20; y < height; y += 7)
        for (int x = 1; x < width; x += 9) {
            // Solve the camera ray against y = 0 independently, in double.
            const Ray<T> ray = rays.ray(T(x) + T(0.5), T(y) + T(0.5));
            if (ray.direction.y >= 0) continue;
            const double t = -double(ray.origin.y) / ray.direction.y;
            const double px = ray.origin.x + t * ray.direction.x, pz = ray.origin.z + t * ray.direction.z;
            const double dx = light_at.x - px, dy = light_at.y, dz = light_at.z - pz;
            const double r2 = dx * dx + dy * dy + dz * dz;
            const double expected = albedo * kd / std::acos(-1.0) * intensity * (dy / std::sqrt(r2)) / r2;
            CHECK(film.at(x, y).x == Approx(expected).epsilon(1e-4));
            CHECK(film.at(x, y).z == Approx(expected).epsilon(1e-4));
            ++checked;
        }
    CHECK(checked > 10);
}

TEST_CASE("ambient appears only where every light is occluded")
{
    // Two lights; a ball hides the first from the origin, a wall hides the second from x = 3.
    const Rgb<double> ambient{0.2, 0.2, 0.2};
    Scene scene{Lights{PointLight<double>{.position = {0, 5, 0}, .intensity = Rgb<double>(25)},
                       PointLight<double>{.position = {3, 5, 0}, .intensity = Rgb<double>(25)}},
                Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .kd = 1, .ka = 1}},
                Object{Sphere<double>({0, 2.5, 0}, 0.5), Diffuse<double>{.albedo = {.color = Rgb<double>(0)}, .kd = 0, .ka = 0}}};
    scene.ambient = ambient;
    const Whitted integrator(scene);
    const auto look_down_at = [&](double x) { return integrator.radiance({{x, 0.5, 0.001}, normalize(Vec3<double>{0, -0.5, -0.001})}); };
    // At the origin: the first light is blocked, the second is not: no ambient, one light's share.
    const double r2 = 9 + 25, cos = 5 / std::sqrt(r2);
    CHECK(look_down_at(0).x == Approx(0.5 / std::acos(-1.0) * 25 * cos / r2).epsilon(1e-3));
    // Directly below the ball at x = 0 but with the second light blocked too: ambient only.
    Scene one_light{Lights{PointLight<double>{.position = {0, 5, 0}, .intensity = Rgb<double>(25)}},
                    Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .kd = 1, .ka = 1}},
                    Object{Sphere<double>({0, 2.5, 0}, 0.5), Diffuse<double>{.albedo = {.color = Rgb<double>(0)}, .kd = 0, .ka = 0}}};
    one_light.ambient = ambient;
    const Whitted shadowed(one_light);
    CHECK(shadowed.radiance({{0, 0.5, 0.001}, normalize(Vec3<double>{0, -0.5, -0.001})}).x == Approx(0.5 * 0.2));
}

TEST_CASE("Beer-Lambert on shadow rays: light through an absorbing slab is attenuated by exp(-sigma x)")
{
    const Rgb<double> sigma{1.0, 2.0, 0.5};
    const double thickness = 0.5;
    const Scene scene{Lights{PointLight<double>{.position = {0, 4, 0}, .intensity = Rgb<double>(16)}},
                      Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(1)}, .kd = 1, .ka = 0}},
                      Object{Box<double>({-5, 1, -5}, {5, 1 + thickness, 5}), Dielectric<double>{.ior = 1.5, .interior = {.absorption = sigma}}}};
    const Whitted integrator(scene);
    const auto l = integrator.radiance({{0.3, 0.5, 0}, normalize(Vec3<double>{-0.3, -0.5, 0})});
    const double unshadowed = 1 / std::acos(-1.0) * 16 / 16; // E = I / r^2 = 1 at normal incidence
    CHECK(l.x == Approx(unshadowed * std::exp(-1.0 * thickness)));
    CHECK(l.y == Approx(unshadowed * std::exp(-2.0 * thickness)));
    CHECK(l.z == Approx(unshadowed * std::exp(-0.5 * thickness)));
}

TEST_CASE("mirror and Fresnel weights against the closed forms")
{
    // A constant-kr mirror ball reflects the background: L = kr B.
    Scene mirror{Lights{PointLight<double>{}}, Object{Sphere<double>({0, 0, -5}, 1), Mirror<double>{{.kr = {0.9, 0.5, 0.1}}}}};
    mirror.background = {2, 2, 2};
    const auto m = Whitted(mirror).radiance({{0.3, 0.2, 0}, normalize(Vec3<double>{-0.3, -0.2, -5})});
    CHECK(m.x == Approx(1.8));
    CHECK(m.z == Approx(0.2));

    // Glass with kt = 0 seen at 45 degrees reflects F(45 deg) = 0.0502399 of the sky.
    Scene glass{Lights{PointLight<double>{.position = {0, -10, 0}}}, Object{Plane<double>({0, 1, 0}, 0), Dielectric<double>{.ior = 1.5, .kt = 0}}};
    glass.background = {1, 1, 1};
    const auto g = Whitted(glass).radiance({{-1, 1, 0}, normalize(Vec3<double>{1, -1, 0})});
    CHECK(g.x == Approx(0.05023991).epsilon(1e-6));
}

TEST_CASE("an absorbing glass slab at normal incidence: B (R + (1-R)^2 e^-sd / (1 - R e^-sd)), all orders")
{
    // Every inter-reflection inside the slab is followed (Stokes' series of the slab).
    const double sigma = 1.0, d = 1.0, r = 0.04;
    Scene slab{Lights{PointLight<double>{.position = {0, 50, 50}, .intensity = Rgb<double>(0)}},
               Object{Box<double>({-100, -100, -d}, {100, 100, 0}), Dielectric<double>{.ior = 1.5, .interior = {.absorption = Rgb<double>(sigma)}}}};
    slab.background = {1, 1, 1};
    const Whitted integrator(slab, {.max_depth = 60, .min_weight = 0});
    const double e = std::exp(-sigma * d);
    const double expected = r + (1 - r) * (1 - r) * e / (1 - r * e);
    CHECK(integrator.radiance({{0, 0, 5}, {0, 0, -1}}).x == Approx(expected).epsilon(1e-9));
    // Without absorption all light comes back out, whichever way: L = B.
    Scene clear{Lights{PointLight<double>{.intensity = Rgb<double>(0)}},
                Object{Box<double>({-100, -100, -d}, {100, 100, 0}), Dielectric<double>{.ior = 1.5}}};
    clear.background = {1, 1, 1};
    CHECK(Whitted(clear, {.max_depth = 60, .min_weight = 0}).radiance({{0, 0, 5}, {0, 0, -1}}).x == Approx(1).epsilon(1e-9));
}

TEST_CASE("depth limit and adaptive cut-off end the recursion")
{
    // Two facing mirrors with kr = 0.5 in front of a lit background: each bounce halves.
    Scene corridor{Lights{PointLight<double>{.intensity = Rgb<double>(0)}},
                   Object{Box<double>({-10, -10, -11}, {10, 10, -10}), Mirror<double>{{.kr = Rgb<double>(0.5)}}}};
    corridor.background = {1, 1, 1};
    // One bounce then background: 0.5.
    CHECK(Whitted(corridor, {.max_depth = 1}).radiance({{0, 0, 0}, {0, 0, -1}}).x == Approx(0.5));
    CHECK(Whitted(corridor, {.max_depth = 0}).radiance({{0, 0, 0}, {0, 0, -1}}).x == 0);
    // A weight of 0.5 is below a cut-off of 0.6: the branch is dropped.
    CHECK(Whitted(corridor, {.max_depth = 5, .min_weight = 0.6}).radiance({{0, 0, 0}, {0, 0, -1}}).x == 0);
    CHECK_THROWS_AS(Whitted(corridor, {.max_depth = -1}), std::invalid_argument);
}

// The integrator refers to its scene, so it must not be built from a temporary one.
using SmallScene = Scene<Lights<PointLight<float>>, Object<Sphere<float>, Diffuse<float>>>;
static_assert(std::is_constructible_v<Whitted<SmallScene>, const SmallScene&>);
static_assert(!std::is_constructible_v<Whitted<SmallScene>, SmallScene&&>);

TEST_CASE("CSG objects in a scene: they cast shadows, let light through their bores, and refract")
{
    // A bead (a sphere bored along y) over a floor, the light straight above it.
    const auto bead = difference_of(Sphere<double>({0, 2, 0}, 1), Quadric<double>::cylinder({0, 0, 0}, {0, 1, 0}, 0.3));
    const Scene scene{Lights{PointLight<double>{.position = {0, 6, 0}, .intensity = Rgb<double>(36)}},
                      Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{.albedo = {.color = Rgb<double>(1)}, .kd = 1, .ka = 0}},
                      Object{bead, Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .kd = 1, .ka = 0}}};
    const Whitted integrator(scene);
    const auto floor_at = [&](double x) { return integrator.radiance({{x, 0.5, 0.01}, normalize(Vec3<double>{0, -0.5, -0.01})}).x; };
    // Under the bore the light comes through: E = I / r^2 = 36 / 36, L = 1/pi.
    CHECK(floor_at(0) == Approx(1 / std::acos(-1.0)).epsilon(1e-3));
    // Under the ring of the bead: in shadow.
    CHECK(floor_at(0.6) == 0);
    // The bead's top face around the bore is lit from above.
    CHECK(integrator.radiance({{0.6, 5, 0.3}, normalize(Vec3<double>{0, -1, -0.05})}).x > 0.01);

    // A glass lens from two spheres, absorbing, in front of a uniform sky: along its axis
    // every inter-reflection stays on the axis, so the slab's closed form holds with
    // d = 1, the lens's thickness there.
    const double sigma = 0.7, d = 1, r = 0.04;
    Scene lens{Lights{PointLight<double>{.intensity = Rgb<double>(0)}},
               Object{intersection_of(Sphere<double>({-0.6, 0, 0}, 1.1), Sphere<double>({0.6, 0, 0}, 1.1)),
                      Dielectric<double>{.ior = 1.5, .interior = {.absorption = Rgb<double>(sigma)}}}};
    lens.background = {1, 1, 1};
    const double e = std::exp(-sigma * d);
    CHECK(Whitted(lens, {.max_depth = 60, .min_weight = 0}).radiance({{-5, 0, 0}, {1, 0, 0}}).x ==
          Approx(r + (1 - r) * (1 - r) * e / (1 - r * e)).epsilon(1e-9));
}

TEST_CASE("POV-Ray's Phong highlight: phong (R . L)^size E / pi, on top of the diffuse term")
{
    // Light straight above a white floor, seen from the mirror direction of the light's
    // reflection at the point: R . L = 1, so the highlight adds phong E / pi.
    const double phong = 0.5;
    const Scene scene{Lights{PointLight<double>{.position = {0, 2, 0}, .intensity = Rgb<double>(4)}},
                      Object{Plane<double>({0, 1, 0}, 0),
                             Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .kd = 1, .ka = 0, .phong = phong, .phong_size = 40}}};
    const Whitted integrator(scene);
    const double e = 1, inv_pi = 1 / std::acos(-1.0); // E = 4 / 2^2 at normal incidence
    CHECK(integrator.radiance({{0, 1, 0}, {0, -1, 0}}).x == Approx(0.5 * inv_pi * e + phong * inv_pi * e));
    // Seen at 60 degrees off the mirror direction, (cos 60)^40 is negligible.
    const Vec3<double> oblique = normalize(Vec3<double>{std::sqrt(3.0), -1, 0});
    CHECK(integrator.radiance({-oblique, oblique}).x == Approx(0.5 * inv_pi * e).epsilon(1e-6));
}

TEST_CASE("Whitted's furnace: inside a diffuse sphere of albedo 0.5 the walls read their direct light, 0.5, with one light or four")
{
    for (const bool four : {false, true}) {
        CAPTURE(four);
        const auto scene = test::furnace_scene(four);
        const Whitted whitted(scene);
        CHECK(test::furnace_mean(four, [&](const Ray<float>& ray, Random&) { return whitted.radiance(ray); }, 20000, false) ==
              doctest::Approx(1.0).epsilon(1e-4));
    }
    // One light at the centre: 0.5 everywhere, exactly.
    const auto scene = test::furnace_scene(false);
    CHECK(Whitted(scene).radiance({{0, 0, 0}, {0, 0, 1}}).x == doctest::Approx(0.5f).epsilon(1e-5));
}

TEST_CASE("a mesh floor with tilted vertex normals shades by the shading normal's cosine: L = albedo I cos(ns, wi) / (pi r^2)")
{
    // Two triangles at y = 0 whose four vertex normals all lean 0.4 rad toward +x: the
    // interpolated normal is that one everywhere. The light is placed so that some
    // points see it above the true surface but behind the shading normal (black).
    const double lean = 0.4;
    const Vec3<double> ns{std::sin(lean), std::cos(lean), 0};
    MeshBuffers<double> floor;
    floor.positions = {{-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4}};
    floor.triangles = {{0, 2, 1}, {0, 3, 2}};
    floor.normals.assign(4, ns);
    const Vec3<double> light_at{-2, 0.6, 0};
    const Scene scene{Lights{PointLight<double>{.position = light_at, .intensity = Rgb<double>(10)}},
                      Object{TriangleMesh<double>(floor), Diffuse<double>{.albedo = {.color = Rgb<double>(0.5)}, .ka = 0}}};
    const Whitted integrator(scene);
    int lit = 0, dark = 0;
    for (double x = -3.5; x <= 3.5; x += 0.25)
        for (double z = -3; z <= 3; z += 1.5) {
            const Vec3<double> p{x, 0, z};
            const Rgb<double> radiance = integrator.radiance(Ray<double>{p + Vec3<double>{0, 1, 0.5}, Vec3<double>{0, -1, -0.5}});
            const Vec3<double> to_light = light_at - p;
            const double r2 = dot(to_light, to_light), cos_s = dot(ns, to_light) / std::sqrt(r2);
            const double expected = cos_s > 0 ? 0.5 / std::acos(-1.0) * 10 * cos_s / r2 : 0.0;
            CHECK(radiance.x == Approx(expected).epsilon(1e-9));
            (expected > 0 ? lit : dark) += 1;
        }
    CHECK(lit > 20);
    CHECK(dark > 20);
}

TEST_CASE("Whitted in the two-lobe furnace: direct light on the base and the coat's mirror images, rho_d / (1 - rho_s), within 1 %")
{
    // The coat's mirror images recurse (0.2^k falls under min_weight 1e-4 after 6), the
    // base reads its direct light: 0.5 / 0.8 = 0.625.
    const auto scene = test::coated_furnace_scene();
    const Whitted whitted(scene, {.max_depth = 16, .min_weight = 1e-6f});
    const test::SampleStats stats = test::coated_furnace_samples([&](const Ray<float>& ray, Random&) { return whitted.radiance(ray); }, 2000);
    CHECK(stats.mean == doctest::Approx(test::CoatedFurnace::whitted).epsilon(0.01));
    CHECK(stats.largest <= 1.001 * test::CoatedFurnace::whitted); // no sample is random: every one reads the same
}

TEST_CASE("Whitted lights a glossy floor by its BSDF toward the light: L = f(wo, wi) I cos / r^2, for each glossy material")
{
    const auto check = [](const auto& floor) {
        const auto scene = test::floor_by_image(floor);
        const Whitted whitted(scene);
        const auto lobe = floor.glossy({});
        const LocalFrame<float> frame = LocalFrame<float>::about({0, 1, 0});
        for (const float x : {-0.9f, -0.3f, 0.2f, 0.5f}) {
            const Vec3<float> eye{-0.2f, 2.5f, 0.3f}, p{x, 0, 0.1f};
            const Ray<float> ray{eye, normalize(p - eye)};
            const Vec3<float> to_light = test::mirror_image - p;
            const float r2 = dot(to_light, to_light), cos = to_light.y / std::sqrt(r2);
            const Rgb<float> expected =
                lobe.f(frame.to_local(-ray.direction), frame.to_local(to_light / std::sqrt(r2)), Transport::radiance) * (4.0f * cos / r2);
            const Rgb<float> got = whitted.radiance(ray);
            CAPTURE(x);
            for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(expected[c]).epsilon(1e-4));
        }
    };
    check(RoughConductor<float, ComplexIor<float>>{.fresnel = {.eta = {0.2f, 0.9f, 1.1f}, .k = {3.9f, 2.4f, 2.2f}}, .roughness = {0.3f, 0.6f}});
    check(Phong<float>{.diffuse = {.color = {0.3f, 0.2f, 0.1f}}, .specular = Rgb<float>(0.5f), .exponent = 20});
    check(CoatedDiffuse<float>({.color = {0.6f, 0.3f, 0.2f}}, {.ior = 1.5f, .roughness = 0.3f}));
}

TEST_CASE("Whitted follows a glossy lobe's mirror direction with the lobe's albedo there")
{
    // A rough metal floor under a uniform white background of 1, its light dark: what the
    // floor reflects is its mirror ray's background times the lobe's albedo toward the
    // viewer (the same albedo the path tracer's glossy furnace reads).
    const RoughConductor<double> metal{.fresnel = {.kr = Rgb<double>(0.9)}, .roughness = 0.3};
    Scene scene{Lights{PointLight<double>{.position = {0, 1, 0}, .intensity = Rgb<double>(0)}}, Object{Plane<double>({0, 1, 0}, 0), metal}};
    scene.background = Rgb<double>(1);
    const Whitted whitted(scene);
    for (const double theta : {10.0, 50.0, 80.0}) {
        const Vec3<double> w = test::polar(theta, 0);
        const Ray<double> ray{{w.x, w.z, w.y}, {-w.x, -w.z, -w.y}};
        CAPTURE(theta);
        CHECK(whitted.radiance(ray).x == doctest::Approx(test::albedo_by_quadrature(metal.glossy({}), w)).epsilon(0.01));
    }
}

TEST_CASE("Whitted's glossy furnace: a rough metal of reflectance 1 under a uniform sky reads its lobe's albedo, the sky counted once")
{
    // The sky is counted once, by the lobe's mirror ray (which meets it everywhere) with
    // the lobe's albedo, not by light samples as well. Regression: light samples counted it
    // too, and the floor read 1.8 to 4.5 (56 where a sample met the narrow lobe at
    // roughness 0.1), far above the furnace's 1.
    for (const double roughness : {0.1, 0.3, 0.6}) {
        const RoughConductor<double> metal{.fresnel = {.kr = Rgb<double>(1)}, .roughness = roughness};
        const Scene scene{Lights{EnvironmentLight<double>{}}, Object{Plane<double>({0, 1, 0}, 0), metal}};
        const Whitted whitted(scene);
        for (const double theta : {10.0, 50.0, 80.0}) {
            const Vec3<double> w = test::polar(theta, 0);
            const Ray<double> ray{{w.x, w.z, w.y}, {-w.x, -w.z, -w.y}};
            const double albedo = test::albedo_by_quadrature(metal.glossy({}), w);
            Random rng(3, 1);
            double mean = 0;
            for (int i = 0; i < 4; ++i) mean += whitted.radiance(ray, rng).x / 4;
            CAPTURE(roughness);
            CAPTURE(theta);
            CHECK(mean == doctest::Approx(albedo).epsilon(0.03));
            CHECK(mean <= 1.0);
        }
    }
}

TEST_CASE("Whitted renders frosted glass at roughness 0 as the clean glass it is, bit for bit")
{
    const auto scene_of = [](const auto& glass) {
        return Scene{Lights{PointLight<float>{.position = {1, 4, 3}, .intensity = Rgb<float>(20)}},
                     Object{Plane<float>({0, 1, 0}, 0), Diffuse<float, Checker<float>>{.albedo = {.even = Rgb<float>(0.8f), .odd = Rgb<float>(0.2f), .size = 0.5f}}},
                     Object{Sphere<float>({0, 1, 0}, 1), glass}};
    };
    const auto clean = scene_of(Dielectric<float>{.ior = 1.5f, .interior = {.absorption = {0.1f, 0.2f, 0.3f}}});
    const auto frosted = scene_of(RoughDielectric<float>{.ior = 1.5f, .roughness = 0.0f, .interior = {.absorption = {0.1f, 0.2f, 0.3f}}});
    const Camera<float> camera{.position = {0, 1.5f, 4}, .look_at = {0, 0.8f, 0}, .fov = 40};
    const RenderConfig config{.width = 24, .height = 24, .spp = 1, .threads = 2, .progress = false};
    const Film a = render(camera, Whitted(clean), config), b = render(camera, Whitted(frosted), config);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) REQUIRE(a.at(x, y) == b.at(x, y));
}

TEST_CASE("regression: a texture seen in a mirror is filtered over the camera's cone carried through the mirror")
{
    // A wall 60 m away holds a checker of single texels (0 and 1), seen in a mirror floor:
    // a pixel covers about 3 texels there, where the pyramid's levels above the first are all
    // 0.5. The mirror's ray used to start as a point sample and read the picture's texels
    // one by one: 0 or 1 (or between) from pixel to pixel.
    std::vector<float> texels(256 * 256);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = float((i % 256 + i / 256) % 2);
    const ImageTexture<float> checker(256, 256, 1, texels, {.wrap = Wrap::repeat, .filter = TextureFilter::trilinear});
    // A light along -z lights the wall face-on with irradiance pi: its radiance is its albedo.
    const Scene scene{Lights{DirectionalLight<float>{.direction = {0, 0, -1}, .irradiance = Rgb<float>(pi<float>)}},
                      Object{Plane<float>({0, 1, 0}, 0), Mirror<float>{{.kr = Rgb<float>(1)}}},
                      Object{Quad<float>({-30, 0, -60}, {60, 0, 0}, {0, 60, 0}), Diffuse<float, ImageTexture<float>>{.albedo = checker, .kd = 1, .ka = 0}}};
    const Camera<float> camera{.position = {0, 1, 0}, .look_at = {0, 0, -5}, .fov = 10};
    const Film film = render(camera, Whitted(scene), {.width = 16, .height = 16, .spp = 1, .threads = 1, .progress = false});
    int seen = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            CAPTURE(x);
            CAPTURE(y);
            if (film.at(x, y).x == 0) continue; // above the wall
            ++seen;
            CHECK(film.at(x, y).x == Approx(0.5).epsilon(1e-3));
        }
    CHECK(seen > 128);
}

TEST_CASE("Whitted's single scattering in fog, marched with jittered steps, is the airlight integral to 0.5 %; what lies beyond is seen through the fog")
{
    // tests/airlight.hpp's scene, as the path tracer's test.
    const auto scene = test::airlight_scene();
    const Whitted whitted(scene, {.march_steps = 64}, test::airlight_fog());
    Random rng(4, 2);
    Rgb<double> sum{0};
    const int n = 20000;
    for (int i = 0; i < n; ++i) sum += Rgb<double>(whitted.radiance(test::airlight_ray(), rng));
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        CHECK(sum[c] / n == doctest::Approx(test::airlight(c)).epsilon(0.005).scale(0));
    }
    // A lit white wall 3 away, seen through a box of grey fog 2 thick that absorbs only:
    // exp(-0.5 x 2) of it, and nothing scattered.
    const auto wall = Scene{Lights{PointLight<float>{.position = {0, 0, 0.5f}, .intensity = Rgb<float>(1)}},
                            Object{Plane<float>({0, 0, 1}, -3), Diffuse<float>{.albedo = {.color = Rgb<float>(1)}, .kd = 1, .ka = 0}}};
    const FilledAir<Fog<float>> dark{.medium = {.absorption = Rgb<float>(0.5f)}, .region = {{-1, -1, -2.5f}, {1, 1, -0.5f}}};
    const Whitted clear_air(wall);
    const Whitted in_fog(wall, {}, dark);
    const Ray<float> look{{0, 0, 0}, {0, 0, -1}};
    // The wall's light passes the fog twice: from the light to the wall and back.
    CHECK(in_fog.radiance(look).x == doctest::Approx(clear_air.radiance(look).x * std::exp(-2.0)).epsilon(1e-5).scale(0));
}

TEST_CASE("Whitted's single scattering in fog of varying density (constant in a box, tracked as varying) is the airlight integral over the box, to 0.5 %")
{
    // tests/airlight.hpp's fog as a VaryingFog of density 1 in a box 120 wide: its
    // transmittance by ratio tracking, both along the ray and toward the light. The ray
    // leaves the box at x = 60, 62 from its origin; the light lies inside.
    const auto scene = test::airlight_scene();
    const VaryingFog fog(DensityGrid<float>(2, 2, 2, {Vec3<float>(-60), Vec3<float>(60)}, std::vector<float>(8, 1.0f)),
                         Rgb<float>(test::airlight_absorption), Rgb<float>(test::airlight_scattering), {.g = float(test::airlight_g)});
    const Whitted whitted(scene, {.march_steps = 64}, FilledAir<decltype(fog)>{.medium = fog});
    Random rng(4, 3);
    Rgb<double> sum{0};
    const int n = 20000;
    for (int i = 0; i < n; ++i) sum += Rgb<double>(whitted.radiance(test::airlight_ray(), rng));
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        CHECK(sum[c] / n == doctest::Approx(test::airlight_along(c, {-2, 0, 0}, {1, 0, 0}, {0, 1, 0}, 62.0)).epsilon(0.005).scale(0));
    }
}

TEST_CASE("Whitted marches ground fog along a rising ray: single scattering against a quadrature of the exponential density, to 0.2 %")
{
    // The airlight fog's coefficients times HeightFog's density 2 exp(-(y + 1) / 0.8), a ray
    // rising at 0.1 from (-2, 0, 0) under the airlight's point light: the density varies
    // along the ray and along every shadow ray. The optical depth of a straight segment in
    // it is closed-form (the density is exponential in the height, which is linear along
    // the segment), and the single-scattering integral is Simpson's in double: numbers
    // outside the code under test. Whitted marches the camera side (the midpoint rule, a
    // step of 0.25) and tracks the shadow rays. Measured within 0.02 % in each channel.
    const double base = 2, floor_y = -1, height = 0.8;
    const HeightFog<float> ground{.box = {{-40, -1, -40}, {40, 40, 40}}, .floor = float(floor_y), .base = float(base), .scale_height = float(height)};
    const VaryingFog fog(ground, Rgb<float>(test::airlight_absorption), Rgb<float>(test::airlight_scattering), {.g = float(test::airlight_g)});
    const auto scene = test::airlight_scene();
    const Vec3<double> origin{-2, 0, 0}, w = normalize(Vec3<double>(1, 0.1, 0)), light{0, 1, 0};
    const double reach = (40 - origin.x) / w.x; // the box's far side
    // The integral of the density along a -> b.
    const auto column = [&](const Vec3<double>& a, const Vec3<double>& b) {
        const double l = length(b - a), dy = b.y - a.y;
        const double ea = std::exp(-(a.y - floor_y) / height), eb = std::exp(-(b.y - floor_y) / height);
        return std::abs(dy) < 1e-12 ? base * l * ea : base * l * height / dy * (ea - eb);
    };
    const Whitted whitted(scene, {.march_steps = 256}, FilledAir<decltype(fog)>{.medium = fog});
    Random rng(4, 5);
    Rgb<double> sum{0};
    const int n = 4000;
    const Ray<float> ray{Vec3<float>(origin), Vec3<float>(w)};
    for (int i = 0; i < n; ++i) sum += Rgb<double>(whitted.radiance(ray, rng));
    const HenyeyGreenstein<double> hg{test::airlight_g};
    for (int c = 0; c < 3; ++c) {
        const double st = test::airlight_absorption[c] + test::airlight_scattering[c];
        const auto f = [&](double s) {
            const Vec3<double> p = origin + s * w;
            const Vec3<double> to_point = p - light;
            const double d = length(to_point);
            const double density = base * std::exp(-(p.y - floor_y) / height);
            return test::airlight_scattering[c] * density * std::exp(-st * column(origin, p)) * hg.value(-dot(to_point, w) / d) / (d * d) *
                   std::exp(-st * column(p, light));
        };
        const int m = 200000;
        const double h = reach / m;
        double integral = f(0) + f(reach);
        for (int k = 1; k < m; ++k) integral += f(k * h) * (k % 2 ? 4 : 2);
        integral *= h / 3;
        CAPTURE(c);
        MESSAGE("channel ", c, ": Whitted ", sum[c] / n, ", quadrature ", integral);
        CHECK(sum[c] / n == doctest::Approx(integral).epsilon(0.002).scale(0));
    }
}

TEST_CASE("regression: Whitted's camera inside a ball of fog sees the light the fog scatters: the airlight integral to the ball's surface, to 0.5 %")
{
    // tests/airlight.hpp's fog inside a ball of radius 50 (a surface that does not
    // refract) about the light and the camera; the ray leaves it 50 + 2 = 52 from its
    // origin (the light's path from every point of the ray stays inside). Before
    // Scene::media_at the camera started in no object and saw only the sphere's far side
    // through the fog's transmittance: 0.
    using Foggy = Dielectric<float, ExactFresnel, Fog<float>>;
    const auto scene = Scene{Lights{PointLight<float>{.position = {0, 1, 0}, .intensity = Rgb<float>(1)}},
                             Object{Sphere<float>({0, 0, 0}, 50), Foggy{.ior = 1, .interior = test::airlight_fog().medium}}};
    const Whitted whitted(scene, {.march_steps = 64});
    Random rng(4, 4);
    Rgb<double> sum{0};
    const int n = 20000;
    for (int i = 0; i < n; ++i) sum += Rgb<double>(whitted.radiance(test::airlight_ray(), rng));
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        CHECK(sum[c] / n == doctest::Approx(test::airlight_along(c, {-2, 0, 0}, {1, 0, 0}, {0, 1, 0}, 52.0)).epsilon(0.005).scale(0));
    }
}

TEST_CASE("Whitted's airlight: the airlight integral to 0.01 % with 16 nodes and no random numbers, a spot light's falloff within it; no shadows")
{
    // tests/airlight.hpp's scene and its quadrature, summed by Gauss-Legendre in the angle
    // seen from the light: 16 nodes reach float's precision there, 4 nodes 1 %.
    const auto scene = test::airlight_scene();
    for (const int nodes : {4, 16}) {
        const Whitted whitted(scene, {.in_scattering = InScattering::airlight, .airlight_nodes = nodes}, test::airlight_fog());
        const Rgb<float> found = whitted.radiance(test::airlight_ray());
        for (int c = 0; c < 3; ++c) {
            CAPTURE(nodes);
            CAPTURE(c);
            CHECK(found[c] == doctest::Approx(test::airlight(c)).epsilon(nodes == 16 ? 1e-4 : 1e-2).scale(0));
        }
    }
    // A spot light at the same place pointing down, its cone 30 to 40 degrees: the
    // quadrature of the same integrand with the falloff (each of 200000 Simpson points lit
    // by the light's own sample, a number outside the rule under test).
    const SpotLight<float> spot{.position = {0, 1, 0}, .direction = {0.3f, -1, 0}, .intensity = Rgb<float>(2), .inner_angle = 30, .outer_angle = 40};
    const Scene spotlit{Lights{spot}, Object{Sphere<float>({0, -1000, 0}, 1e-3f), Diffuse<float>{}}};
    // The cone's edge, where the falloff's second derivative jumps, converges slower than
    // the rest: 0.22 % at 32 nodes, 0.13 % at 64 (measured).
    const Rgb<float> found = Whitted(spotlit, {.in_scattering = InScattering::airlight, .airlight_nodes = 32}, test::airlight_fog()).radiance(test::airlight_ray());
    const Rgb<float> finer = Whitted(spotlit, {.in_scattering = InScattering::airlight, .airlight_nodes = 64}, test::airlight_fog()).radiance(test::airlight_ray());
    for (int c = 0; c < 3; ++c) {
        const double st = test::airlight_absorption[c] + test::airlight_scattering[c];
        const HenyeyGreenstein<double> hg{test::airlight_g};
        const auto f = [&](double s) {
            const Vec3<double> p{-2 + s, 0, 0};
            const LightSample<float> sample = spot.sample(Vec3<float>(p));
            const double d = double(sample.distance);
            return test::airlight_scattering[c] * std::exp(-st * s) * hg.value(double(sample.wi.x)) * double(sample.irradiance[c]) * std::exp(-st * d);
        };
        const int n = 200000;
        const double h = 60.0 / n;
        double sum = f(0) + f(60);
        for (int i = 1; i < n; ++i) sum += f(i * h) * (i % 2 ? 4 : 2);
        CAPTURE(c);
        MESSAGE("spot, channel ", c, ": 32 nodes ", found[c], ", 64 nodes ", finer[c], ", Simpson ", sum * h / 3);
        CHECK(found[c] == doctest::Approx(sum * h / 3).epsilon(5e-3).scale(0));
        CHECK(finer[c] == doctest::Approx(sum * h / 3).epsilon(2e-3).scale(0));
        CHECK(std::abs(finer[c] - sum * h / 3) < std::abs(found[c] - sum * h / 3));
    }
    // No shadow rays: a wall between the light and the ray changes nothing, where
    // marching sees its shadow.
    const Scene walled{Lights{PointLight<float>{.position = {0, 1, 0}, .intensity = Rgb<float>(1)}},
                       Object{Box<float>({-50, 0.5f, -50}, {50, 0.6f, 50}), Diffuse<float>{}}};
    const Whitted airlight(walled, {.in_scattering = InScattering::airlight}, test::airlight_fog());
    const Whitted marched(walled, {.march_steps = 64}, test::airlight_fog());
    CHECK(airlight.radiance(test::airlight_ray()).x == doctest::Approx(test::airlight(0)).epsilon(1e-4).scale(0));
    CHECK(marched.radiance(test::airlight_ray()).x == 0.0f);
    CHECK_THROWS_WITH_AS(Whitted(scene, {.airlight_nodes = 0}, test::airlight_fog()), doctest::Contains("Whitted airlight_nodes must be in [1, 64], got 0"),
                         std::invalid_argument);
}

TEST_CASE("fog filling graded air: Whitted sums the airlight over each straight piece of the path, the integral to 0.01 % over a hundred pieces")
{
    // The airlight scene in GradedAir of a uniform index, cut into pieces of at most 0.5 by
    // the stepper inside a box 50 about the light (straight beyond it): the pieces, each
    // seen through the fog before it, must add up to the one integral.
    const auto air = test::airlight_fog_in_pieces();
    const auto scene = test::airlight_scene();
    int pieces = 0;
    Ray<float> segment{};
    (void)first_hit_in_air(scene, air, test::airlight_ray(), segment, nullptr, [&](const Ray<float>&, float, float) { return ++pieces > 0; });
    CHECK(pieces > 100);
    const Rgb<float> found = Whitted(scene, {.in_scattering = InScattering::airlight, .airlight_nodes = 16}, air).radiance(test::airlight_ray());
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        CHECK(found[c] == doctest::Approx(test::airlight(c)).epsilon(1e-4).scale(0));
    }
}

namespace {

/// Whitted with the sampler's work done for every pixel: its radiance, without saying
/// that it draws nothing (the slow twin of render()'s skip).
template <class I>
struct DrawsAll {
    using scalar_type = typename I::scalar_type;
    const I* integrator;
    [[nodiscard]] Rgb<scalar_type> radiance(const Ray<scalar_type>& ray, Random& rng) const noexcept { return integrator->radiance(ray, rng); }
};

} // namespace

TEST_CASE("Whitted with delta lights draws nothing, and render() skips the sampler for it: the same bits as with it")
{
    // A point light, a spot light, CSG, glass and a mirror: no random number anywhere.
    Scene scene{Lights{PointLight<float>{.position = {2, 5, 3}, .intensity = Rgb<float>(40)},
                       SpotLight<float>{.position = {-3, 4, 1}, .direction = {0.5f, -1, 0}, .intensity = Rgb<float>(30)}},
                Object{Plane<float>({0, 1, 0}, 0), Diffuse<float, Checker<float>>{}},
                Object{Sphere<float>({0, 1, 0}, 1), Dielectric<float>{.ior = 1.5f}},
                Object{difference_of(Sphere<float>({2, 0.7f, -1}, 0.7f), Sphere<float>({2.3f, 1, -1.2f}, 0.4f)), Mirror<float>{}}};
    const Whitted integrator(scene, {.max_depth = 6});
    static_assert(draws_nothing<decltype(integrator)> && !draws_nothing<DrawsAll<decltype(integrator)>>);
    const Camera<float> camera{.position = {0, 2, 7}, .look_at = {0.5f, 0.8f, 0}, .fov = 45};
    for (const int threads : {1, 2}) {
        const RenderConfig config{.width = 96, .height = 64, .threads = unsigned(threads), .progress = false, .tile_size = 7};
        const Film fast = render(camera, integrator, config), slow = render(camera, DrawsAll<decltype(integrator)>{&integrator}, config);
        CHECK(std::memcmp(fast.pixels().data(), slow.pixels().data(), fast.pixels().size() * sizeof(fast.pixels()[0])) == 0);
        CHECK(fast.at(48, 40) != fast.at(0, 0)); // (not a blank image)
        const Accumulation sums = render_sums(camera, integrator, config), twin = render_sums(camera, DrawsAll<decltype(integrator)>{&integrator}, config);
        const Film a = sums.image(), b = twin.image();
        CHECK(std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(a.pixels()[0])) == 0);
    }
    // An area light draws: not skipped.
    static_assert(!Whitted<Scene<Lights<PointGridLight<float>>, Object<Sphere<float>, Diffuse<float>>>>::draws_nothing);
}
