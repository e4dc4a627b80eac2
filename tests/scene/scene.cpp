// SPDX-License-Identifier: MIT
#include <prism/scene/scene.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include "../ray_property.hpp"

#include <cmath>
#include <string>

using namespace prism;

namespace {

auto test_scene()
{
    using Ball = Object<Sphere<double>, Diffuse<double>>;
    ObjectArray<Sphere<double>, Diffuse<double>> balls{{
        Ball{Sphere<double>({0, 0, -10}, 1), Diffuse<double>{.albedo = {.color = {1, 0, 0}}}},
        Ball{Sphere<double>({0, 0, -5}, 1), Diffuse<double>{.albedo = {.color = {0, 1, 0}}}},
    }};
    return Scene{Lights{PointLight<double>{.position = {0, 10, 0}}}, std::move(balls),
                 Object{Sphere<double>({0, 0, -7}, 1), Mirror<double>{}},
                 Object{Sphere<double>({5, 0, 0}, 1), Dielectric<double>{.ior = 1.5, .interior = {.absorption = {0.5, 1.0, 0.0}}}}};
}

} // namespace

TEST_CASE("closest_hit finds the nearest object over every slot and array element")
{
    const auto scene = test_scene();
    const auto hit = scene.closest_hit({{0, 0, 0}, {0, 0, -1}}, {0, infinity<double>});
    REQUIRE(hit);
    CHECK(hit->crossing.t == doctest::Approx(4));
    CHECK(hit->slot == 0);
    CHECK(hit->index == 1);
    const std::string kind = scene.visit_material(*hit, []<class M>(const M& m) -> std::string {
        if constexpr (has_diffuse<M>) return m.albedo.color.y == 1 ? "green diffuse" : "other diffuse";
        else return "specular";
    });
    CHECK(kind == "green diffuse");
    // Beyond the green ball the mirror ball is next.
    const auto second = scene.closest_hit({{0, 0, 0}, {0, 0, -1}}, {4.5, infinity<double>});
    REQUIRE(second);
    CHECK(second->crossing.t == doctest::Approx(6)); // leaving the green ball at z = -6
}

TEST_CASE("transmittance: opaque blocks, a dielectric absorbs by Beer-Lambert along the chord")
{
    const auto scene = test_scene();
    CHECK(scene.transmittance({{0, 0, 0}, {0, 0, -1}}, 100).x == 0);
    CHECK(scene.transmittance({{0, 0, 0}, {0, 0, -1}}, 3.9).x == 1); // stops before the first ball
    // Through the glass ball at x = 5 along its diameter: chord 2.
    const auto tr = scene.transmittance({{0, 0, 0}, {1, 0, 0}}, 100);
    CHECK(tr.x == doctest::Approx(std::exp(-1.0)));
    CHECK(tr.y == doctest::Approx(std::exp(-2.0)));
    CHECK(tr.z == doctest::Approx(1));
    // Ending inside the glass: half the chord.
    CHECK(scene.transmittance({{0, 0, 0}, {1, 0, 0}}, 5).y == doctest::Approx(std::exp(-1.0)));
    // For a photon mapper glass is opaque: its caustic map brings the light through.
    CHECK(scene.transmittance<prism::ShadowsThroughGlass::blocked>({{0, 0, 0}, {1, 0, 0}}, 100) == Rgb<double>(0));
    CHECK(scene.transmittance<prism::ShadowsThroughGlass::blocked>({{0, 0, 0}, {1, 0, 0}}, 3.9) == Rgb<double>(1));
}

TEST_CASE("bounds() holds every bounded object; lights are visited by number with their own types")
{
    const auto scene = test_scene();
    CHECK(scene.bounds().lo.x <= -1);
    CHECK(scene.bounds().hi.x >= 6);
    CHECK(scene.bounds().lo.z <= -11);
    CHECK(scene.bounds().hi.z >= 1);
    CHECK(scene.bounds().bounded());
    const Scene two{Lights{PointLight<double>{.position = {0, 10, 0}}, DirectionalLight<double>{.irradiance = Rgb<double>(3)}},
                    Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{}}};
    static_assert(decltype(two)::light_count == 2);
    CHECK(two.bounds().empty()); // a half-space only: nothing bounded
    const double kind = two.visit_light(1, []<class L>(const L& light) {
        if constexpr (std::same_as<L, DirectionalLight<double>>) return light.irradiance.x;
        else return -1.0;
    });
    CHECK(kind == 3);
    CHECK(two.visit_light(0, [](const auto& light) { return light.sample({0, 0, 0}).distance; }) == 10);
}

TEST_CASE("background and ambient are validated")
{
    auto scene = test_scene();
    scene.ambient = {0, -1, 0};
    CHECK_THROWS_WITH_AS(scene.validate(), doctest::Contains("Scene ambient"), std::invalid_argument);
}

// The ray property test (tests/ray_property.hpp), a slice of bench/ray_property: every
// shape, Transformed shapes and CSG trees, 1 to 10^4 from the world origin and from their
// rays, sizes 1 and 10^-3, float and double, 16k rays each. Before the fixes of issue 10 a
// float unit ellipsoid lost 0.1 % of its hits from 100 units and most from 10^4.
TEST_CASE_TEMPLATE("closest_hit loses no hit and spawns on the right side, near and far", T, float, double)
{
    using namespace test::property;
    Counts total;
    std::uint64_t seed = 11;
    for_each_case([&]<class Case>() {
        for (const double distance : {1.0, 1e2, 1e3, 1e4})
            for (const double size : {1.0, 1e-3}) {
                Pcg32 rng(seed++, 3u);
                Counts cell;
                for (int k = 0; k < 4; ++k) {
                    try {
                        cell += fire<Case, T>(place(rng, distance, size), distance, seed * 100 + k, 4096);
                    } catch (const std::invalid_argument&) {
                        // a box of 10^-3 at 10^4 has no extent in float: skipped
                    }
                }
                INFO(Case::name, " distance ", distance, " size ", size);
                CHECK(cell.lost == 0);
                CHECK(cell.disagree == 0);
                CHECK(cell.non_finite == 0);
                CHECK(cell.false_occlusion == 0);
                total += cell;
            }
    });
    // Spawned rays: a few in 10^5 still start on the wrong side at the edges of CSG trees
    // (the full bench reports them); everywhere else none.
    CHECK(total.rays > 1400000);
    CHECK(double(total.wrong_side) <= 1e-4 * double(total.spawn_checks));
    MESSAGE(total.rays, " rays: wrong-side spawns ", total.wrong_side, " of ", total.spawn_checks);
}

namespace {

/// The linear scan the scene did before its arrays had a Bvh: every object asked in
/// slot and index order; crossings lie strictly inside the range, so the first object at
/// a t wins a tie.
template <class SceneT, class R>
auto scanned_hit(const SceneT& scene, const R& ray, Interval<float> range)
{
    struct Best {
        float t = infinity<float>;
        std::uint32_t slot = 9, index = 0;
    } best;
    std::uint32_t slot = 0;
    std::apply([&](const auto&... arrays) {
        ([&](const auto& array) {
            for (std::uint32_t k = 0; k < array.items.size(); ++k) {
                const auto c = array.items[k].shape.crossings(ray, range);
                if (!c.empty()) best = {c.front().t, slot, k}, range.max = c.front().t;
            }
            ++slot;
        }(arrays), ...);
    }, scene.slots);
    return best;
}

} // namespace

TEST_CASE("an array's Bvh finds what a scan of every object finds: the same object at the same t, and the same shadows")
{
    Pcg32 rng(21u, 4u);
    ObjectArray<Sphere<float>, Diffuse<float>> balls;
    for (int i = 0; i < 1000; ++i) {
        const Vec3<float> c = (Vec3<float>{rng.uniform<float>(), rng.uniform<float>(), rng.uniform<float>()} - Vec3<float>(0.5f)) * 20.0f;
        balls.items.push_back({Sphere<float>(c, 0.1f + 0.5f * rng.uniform<float>()), Diffuse<float>{}});
    }
    // Coincident twins: a tie at the same t, which the first one wins.
    balls.items.push_back(balls.items[17]);
    ObjectArray<Plane<float>, Diffuse<float>> planes{{{Plane<float>({0, 1, 0}, -12), Diffuse<float>{}}, {Plane<float>({1, 0, 0}, 12), Diffuse<float>{}}}};
    const Scene scene{Lights{PointLight<float>{.position = {0, 30, 0}}}, std::move(balls), std::move(planes)};
    int mismatches = 0, shadow_mismatches = 0, hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3<float> target = (Vec3<float>{rng.uniform<float>(), rng.uniform<float>(), rng.uniform<float>()} - Vec3<float>(0.5f)) * 20.0f;
        Vec3<float> d = uniform_sphere<float>(rng);
        if (i % 5 == 1) d = {0, 0, i % 2 ? 1.0f : -1.0f}; // axis-aligned
        const float distance = i % 5 == 2 ? 1e4f : (i % 5 == 3 ? 30.0f : 0.0f); // far away, outside, inside the cloud
        const Ray<float> ray{target - d * distance, d};
        const Interval<float> range{0, infinity<float>};
        const auto hit = scene.closest_hit(ray, range);
        const auto scan = scanned_hit(scene, ray, range);
        if (hit) ++hits;
        mismatches += hit ? !(hit->crossing.t == scan.t && hit->slot == scan.slot && hit->index == scan.index) : scan.t < infinity<float>;
        // A shadow ray to a point on the way: blocked exactly where the scan finds a crossing.
        const float t_max = distance + 10.0f * rng.uniform<float>();
        const bool open = max_component(scene.transmittance(ray, t_max)) > 0.0f;
        shadow_mismatches += open != !(scanned_hit(scene, ray, {0, t_max}).t < infinity<float>);
    }
    CHECK(mismatches == 0);
    CHECK(shadow_mismatches == 0);
    CHECK(hits > 10000);
    // The twins: a ray through both reports the first copy.
    const auto& twins = std::get<0>(scene.slots).items;
    const Vec3<float> c = twins.back().shape.center();
    const Ray<float> ray{c, {0, 0, -1}}; // from the centre: both exit at the same t
    const auto hit = scene.closest_hit(ray, {0, infinity<float>});
    REQUIRE(hit);
    CHECK(hit->index == 17);
    CHECK(scanned_hit(scene, ray, {0, infinity<float>}).index == 17);
}

TEST_CASE("slots are visited nearest first, and find what a scan of the slots in turn finds, ties across slots included")
{
    // Two clouds in two treed slots, the far one (for rays along +z) first, and twins of
    // some of its balls in the near slot: a ray meets the near slot's box first, finds a
    // twin there, and must still report the far slot's copy, at the same t (the scan
    // asks the far slot first). Before them a scanned slot of three balls (too few for a
    // tree), also twinned in the near slot; after them a scanned slot of planes.
    Pcg32 rng(33u, 5u);
    const auto random_point = [&] { return (Vec3<float>{rng.uniform<float>(), rng.uniform<float>(), rng.uniform<float>()} - Vec3<float>(0.5f)) * 20.0f; };
    ObjectArray<Sphere<float>, Diffuse<float>> few, far, near;
    for (int i = 0; i < 600; ++i) {
        const Vec3<float> c = random_point();
        (c.z > 0 ? far : near).items.push_back({Sphere<float>(c, 0.2f + 0.6f * rng.uniform<float>()), Diffuse<float>{}});
    }
    for (std::size_t k = 0; k < far.items.size(); k += 7) near.items.push_back(far.items[k]);
    for (const float x : {-4.0f, 0.0f, 4.0f}) few.items.push_back({Sphere<float>({x, 1.0f, 6.0f}, 1.5f), Diffuse<float>{}});
    for (const auto& ball : few.items) near.items.push_back(ball);
    ObjectArray<Plane<float>, Diffuse<float>> planes{{{Plane<float>({0, 1, 0}, -12), Diffuse<float>{}}, {Plane<float>({0, 0, 1}, -12), Diffuse<float>{}}}};
    const Scene scene{Lights{PointLight<float>{.position = {0, 30, 0}}}, std::move(few), std::move(far), std::move(near), std::move(planes)};
    int mismatches = 0, hits = 0;
    std::array<int, 4> wins{};
    for (int i = 0; i < 40000; ++i) {
        const Vec3<float> target = i % 4 == 0 ? Vec3<float>{8.0f * (rng.uniform<float>() - 0.5f), 1.0f + 2.0f * (rng.uniform<float>() - 0.5f), 6.0f} : random_point();
        Vec3<float> d = i % 2 ? normalize(Vec3<float>{0.3f * (rng.uniform<float>() - 0.5f), 0.3f * (rng.uniform<float>() - 0.5f), 1.0f}) : uniform_sphere<float>(rng);
        if (i % 7 == 3) d = {0, 0, 1}; // axis-aligned
        const float distance = i % 3 == 0 ? 40.0f : (i % 3 == 1 ? 1e4f : 0.0f);
        const Ray<float> ray{target - d * distance, d};
        const auto hit = scene.closest_hit(ray, {0, infinity<float>});
        const auto scan = scanned_hit(scene, ray, {0, infinity<float>});
        hits += hit.has_value();
        if (hit) ++wins[hit->slot];
        mismatches += hit ? !(hit->crossing.t == scan.t && hit->slot == scan.slot && hit->index == scan.index) : scan.t < infinity<float>;
    }
    CHECK(mismatches == 0);
    CHECK(hits > 20000);
    CHECK(wins[0] > 1000); // the scanned slot's balls beat their twins
    CHECK(wins[1] > 1000);
    CHECK(wins[2] > 1000);
}
