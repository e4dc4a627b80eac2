// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using doctest::Approx;
using namespace prism;

TEST_CASE("MediumStack: the medium is the highest priority, the latest entered among equals")
{
    MediumStack media;
    CHECK(media.top() == nullptr);
    const Inside glass{1, 0, 2}, water{2, 0, 1}, bubble{3, 0, 1};
    media = media.entered(glass).entered(water);
    CHECK(media.top()->same_object(glass)); // water overlapping the glass's wall: the glass wins
    media = media.entered(bubble);
    CHECK(media.top()->same_object(glass));
    CHECK(media.left(glass).top()->same_object(bubble)); // equal priorities: the latest
    CHECK(media.left(glass).left(bubble).top()->same_object(water));
    CHECK(media.left(Inside{9, 9, 0}).size() == 3); // leaving what it is not in changes nothing
    // Past capacity the oldest is forgotten.
    MediumStack deep;
    for (std::uint32_t i = 0; i < MediumStack::capacity + 2; ++i) deep = deep.entered({0, i, 0});
    CHECK(deep.size() == MediumStack::capacity);
    CHECK(!deep.contains({0, 0, 0}));
    CHECK(deep.top()->index == MediumStack::capacity + 1);
}

TEST_CASE("Nested interfaces: false where a higher-priority medium overlaps, real otherwise")
{
    const Inside glass{0, 0, 2}, water{1, 0, 1};
    const MediumStack in_glass = MediumStack{}.entered(glass);
    // Entering water inside the glass wall (the overlap): false, but now also in water.
    const Interface into_water = nested_interface(in_glass, water, true);
    CHECK(!into_water.real);
    CHECK(into_water.beyond.contains(water));
    // Leaving the glass into the water: real; the far side is water.
    const Interface out_of_glass = nested_interface(into_water.beyond, glass, false);
    CHECK(out_of_glass.real);
    CHECK(outside_of(into_water.beyond, out_of_glass, false)->same_object(water));
    // Leaving the water while still in the glass: false.
    CHECK(!nested_interface(into_water.beyond, water, false).real);
    // Leaving an object never entered (the camera started inside it): real, air beyond.
    const Interface unknown = nested_interface(MediumStack{}, glass, false);
    CHECK(unknown.real);
    CHECK(outside_of(MediumStack{}, unknown, false) == nullptr);
}

namespace {

/// Three slabs n = 1.3 | 1.5 | 1.7 stacked from the top, each overlapping the one below
/// by 0.01 (no coincident faces) and the lower one of higher priority, over nothing.
auto slabs()
{
    return Scene{Lights{DirectionalLight<double>{}},
                 Object{Box<double>({-50, 2, -50}, {50, 3, 50}), Dielectric<double>{.ior = 1.3, .priority = 1}},
                 Object{Box<double>({-50, 1, -50}, {50, 2.01, 50}), Dielectric<double>{.ior = 1.5, .priority = 2}},
                 Object{Box<double>({-50, 0, -50}, {50, 1.01, 50}), Dielectric<double>{.ior = 1.7, .priority = 3}}};
}

/// Follow the refracted ray through a scene as the integrators do (nested_interface,
/// index_of, delta_split), recording the index of the medium and sin(theta) from the
/// vertical along each segment, until it leaves everything.
template <class SceneT>
std::vector<std::pair<double, double>> refract_through(const SceneT& scene, Ray<double> ray, MediumStack media = {})
{
    std::vector<std::pair<double, double>> segments;
    for (int i = 0; i < 20; ++i) {
        const auto hit = scene.closest_hit(ray, {0, infinity<double>});
        const double n_here = index_of(scene, media.top(), 0.0);
        segments.emplace_back(n_here, std::sqrt(1 - ray.direction.y * ray.direction.y));
        if (!hit) break;
        const Crossing<double>& c = hit->crossing;
        scene.visit_material(*hit, [&]<class M>(const M& material) {
            if constexpr (M::transmits) {
                const Interface face = nested_interface(media, {hit->slot, hit->index, nesting_priority(material)}, c.entering);
                if (!face.real) {
                    ray = spawn_ray(c.point, c.error, c.normal, ray.direction);
                } else {
                    const double n_out = index_of(scene, outside_of(media, face, c.entering), 0.0);
                    const auto split = delta_split(material, ray.direction, c.facing_normal(), c.entering, c.point, 0.0, n_out);
                    REQUIRE(split.refracted);
                    ray = spawn_ray(c.point, c.error, c.normal, *split.refracted);
                }
                media = face.beyond;
            }
        });
    }
    return segments;
}

} // namespace

TEST_CASE("Through stacked slabs 1.3 | 1.5 | 1.7 the invariant n sin(theta) holds across every interface")
{
    const auto scene = slabs();
    for (double theta0 : {0.1, 0.5, 0.9, 1.3}) {
        const Ray<double> ray{{-3, 4, 0.3}, {std::sin(theta0), -std::cos(theta0), 0}};
        const auto segments = refract_through(scene, ray);
        // air, 1.3, 1.5, 1.7, air; each overlap's false interface starts a segment in the same medium.
        REQUIRE(segments.size() == 7);
        const double expected[] = {1.0, 1.3, 1.5, 1.5, 1.7, 1.7, 1.0};
        for (std::size_t i = 0; i < segments.size(); ++i) {
            CHECK(segments[i].first == expected[i]);
            CHECK(segments[i].first * segments[i].second == Approx(std::sin(theta0)).epsilon(1e-12));
        }
    }
}

TEST_CASE("Total internal reflection at a glass-water interface starts at asin(1.33 / 1.5)")
{
    // Glass (priority 2) over water (priority 1) overlapping it by 0.01; rays start in
    // the glass, going down at theta from the vertical.
    const Scene scene{Lights{DirectionalLight<double>{}},
                      Object{Box<double>({-50, 0, -50}, {50, 1, 50}), Dielectric<double>{.ior = 1.5, .priority = 2}},
                      Object{Box<double>({-50, -1, -50}, {50, 0.01, 50}), Dielectric<double>{.ior = 1.33, .priority = 1}}};
    const Dielectric<double>& glass = get<0>(scene.slots).material;
    const double critical = std::asin(1.33 / 1.5);
    CHECK(critical * 180 / std::numbers::pi == Approx(62.457).epsilon(1e-4));
    const MediumStack in_glass = MediumStack{}.entered({0, 0, 2});
    for (double theta : {critical - 1e-3, critical - 1e-6, critical + 1e-6, critical + 1e-3}) {
        const Vec3<double> d{std::sin(theta), -std::cos(theta), 0};
        const Ray<double> ray{{0, 0.5, 0}, d};
        // The first surface is the water's top, inside the glass: false; the next is the glass's bottom.
        auto hit = scene.closest_hit(ray, {0, infinity<double>});
        REQUIRE(hit);
        CHECK(hit->slot == 1);
        const Interface water_top = nested_interface(in_glass, {hit->slot, hit->index, 1}, true);
        CHECK(!water_top.real);
        hit = scene.closest_hit(spawn_ray(hit->crossing.point, hit->crossing.error, hit->crossing.normal, d), {0, infinity<double>});
        REQUIRE(hit);
        CHECK(hit->slot == 0);
        const Interface glass_bottom = nested_interface(water_top.beyond, {0, 0, 2}, false);
        CHECK(glass_bottom.real);
        const double n_out = index_of(scene, outside_of(water_top.beyond, glass_bottom, false), 0.0);
        CHECK(n_out == 1.33);
        const auto split = delta_split(glass, d, hit->crossing.facing_normal(), false, hit->crossing.point, 0.0, n_out);
        CHECK(bool(split.refracted) == (theta < critical));
    }
}

TEST_CASE("A glass sphere nested in a sphere of the same glass is invisible, to Whitted and to photons")
{
    const auto scene_with = [](auto... inner) {
        Scene scene{Lights{PointLight<double>{.position = {2, 6, 3}, .intensity = Rgb<double>(40)}},
                    Object{Plane<double>({0, 1, 0}, 0), Diffuse<double, Checker<double>>{.albedo = {.even = {0.9, 0.2, 0.1}, .odd = {0.1, 0.3, 0.9}, .size = 0.5}}},
                    Object{Sphere<double>({0, 1.2, 0}, 1), Dielectric<double>{.ior = 1.5}}, inner...};
        scene.background = {0.4, 0.6, 0.9};
        return scene;
    };
    const auto single = scene_with();
    const auto nested = scene_with(Object{Sphere<double>({0.2, 1.1, 0.1}, 0.5), Dielectric<double>{.ior = 1.5}});
    const Camera<double> camera{.position = {0, 1.5, 5}, .look_at = {0, 1, 0}, .up = {0, 1, 0}, .fov = 40};
    const auto rays = camera.rays(32, 24);
    // Deep enough that the inner sphere's extra (invisible) interfaces truncate nothing that counts.
    const Whitted a(single, {.max_depth = 40, .min_weight = 1e-9});
    const Whitted b(nested, {.max_depth = 40, .min_weight = 1e-9});
    double worst = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) {
            const Rgb<double> u = a.radiance(rays.ray(x + 0.5, y + 0.5)), v = b.radiance(rays.ray(x + 0.5, y + 0.5));
            worst = std::max({worst, std::abs(u.x - v.x), std::abs(u.y - v.y), std::abs(u.z - v.z)});
        }
    // Rounding only (each extra interface refracts at eta = 1 and offsets its ray). Before
    // nesting, the inner sphere refracted as if in air: pixels off by up to 0.79.
    CHECK(worst < 1e-6);
    // Photons: the same caustic, within noise (the inner surfaces reflect nothing): its
    // total power, and the power in the focus, under the ball away from the light.
    // Before, the caustic power came out 14 % high, and with nesting but the light aimed
    // at both balls counted twice (their cones overlap), 26 % high.
    const PhotonTracerConfig config{.global_photons = 0, .caustic_photons = 200000, .shadow_photons = false};
    const auto caustic_of = [&](const auto& scene) {
        double total = 0, focus = 0;
        const PhotonMaps maps = trace_photons(scene, config);
        for (const Photon& p : maps.caustic.photons()) {
            total += p.power().x;
            if (std::hypot(p.position.x + 0.5f, p.position.z + 0.75f) < 0.6f) focus += p.power().x;
        }
        return std::pair{total, focus};
    };
    const auto [total1, focus1] = caustic_of(single);
    const auto [total2, focus2] = caustic_of(nested);
    CHECK(total2 == Approx(total1).epsilon(0.01));
    CHECK(focus2 == Approx(focus1).epsilon(0.02));
    CHECK(focus1 > 0.3 * total1); // the focus holds much of it: a real test
}

TEST_CASE("Shadow rays through overlapping objects: the higher priority's medium fills the overlap, no tint at a false interface")
{
    // Glass (priority 2, absorbing 0.5 per unit, kt 0.9) over water (priority 1, 0.2, kt 0.8)
    // that reaches 0.2 into the glass. A shadow ray straight up through both: water over
    // [-1, 0], glass over [0, 1] (the overlap is glass), tints at y = -1, 0 and 1 only.
    const Scene scene{Lights{DirectionalLight<double>{}},
                      Object{Box<double>({-5, 0, -5}, {5, 1, 5}), Dielectric<double>{.ior = 1.5, .interior = {.absorption = Rgb<double>(0.5)}, .kt = 0.9, .priority = 2}},
                      Object{Box<double>({-5, -1, -5}, {5, 0.2, 5}), Dielectric<double>{.ior = 1.33, .interior = {.absorption = Rgb<double>(0.2)}, .kt = 0.8, .priority = 1}}};
    const Ray<double> up{{0, -2, 0}, {0, 1, 0}};
    const double expected = 0.8 * std::exp(-0.2 * 1.0) * 0.9 * std::exp(-0.5 * 1.0) * 0.9;
    CHECK(scene.transmittance(up, 5.0).x == Approx(expected).epsilon(1e-12));
    // Each object on its own (before: 0.8^2 e^(-0.2 * 1.2) 0.9^2 e^(-0.5), the overlap counted twice).
    const double per_object = 0.8 * 0.8 * std::exp(-0.2 * 1.2) * 0.9 * 0.9 * std::exp(-0.5);
    CHECK(std::abs(expected - per_object) > 0.05);
    // Starting inside the overlap: glass over [0.1, 1], one tint, at y = 1.
    const Ray<double> from_overlap{{0, 0.1, 0}, {0, 1, 0}};
    CHECK(scene.transmittance(from_overlap, 3.0).x == Approx(std::exp(-0.5 * 0.9) * 0.9).epsilon(1e-12));
    // Objects that do not overlap keep the per-object rule exactly.
    const Scene apart{Lights{DirectionalLight<double>{}},
                      Object{Box<double>({-5, 0, -5}, {5, 1, 5}), Dielectric<double>{.ior = 1.5, .interior = {.absorption = Rgb<double>(0.5)}, .kt = 0.9}},
                      Object{Box<double>({-5, -1, -5}, {5, -0.5, 5}), Dielectric<double>{.ior = 1.33, .interior = {.absorption = Rgb<double>(0.2)}, .kt = 0.8}}};
    CHECK(apart.transmittance(up, 5.0).x == Approx(0.9 * 0.9 * std::exp(-0.5) * 0.8 * 0.8 * std::exp(-0.2 * 0.5)).epsilon(1e-12));
}
