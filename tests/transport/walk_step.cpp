// SPDX-License-Identifier: MIT
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <vector>

using namespace prism;

namespace {

/// What a step showed its hooks.
struct Seen {
    int surfaces = 0, media = 0, escapes = 0, matched = 0;
    double path = 0;          ///< the arrival's path, at a surface or in a medium
    double outside_index = 0; ///< at a surface
    Vec3<double> point{};     ///< where it arrived
    Rgb<double> tint{0};      ///< an index-matched boundary's
};

/// One step from `ray` inside `media`, its hooks recording what they are shown and leaving
/// a surface (or a medium) along `leave` (nothing: ending the walk there).
template <class SceneT, class Air = StraightAir>
Step<double> step_once(const SceneT& scene, Ray<double>& ray, MediumStack& media, Rgb<double>& power, Random& rng, Seen& seen,
                       std::optional<Vec3<double>> leave, const Air& air = {})
{
    return walk_step(scene, air, ray, media, power, rng,
                     StepHooks{.on_surface =
                                   [&]<class M>(const M&, const SurfaceArrival<double>& at) {
                                       ++seen.surfaces;
                                       seen.path = at.path;
                                       seen.outside_index = at.outside_index;
                                       seen.point = at.hit.crossing.point;
                                       return leave;
                                   },
                               .on_medium =
                                   [&]<class Md>(const Md&, const MediumArrival<double>& at) {
                                       ++seen.media;
                                       seen.path = at.path;
                                       seen.point = at.point;
                                       return leave;
                                   },
                               .on_escape = [&](const Ray<double>&) { ++seen.escapes; },
                               .through_matched =
                                   [&](const Rgb<double>& tint) {
                                       ++seen.matched;
                                       seen.tint = tint;
                                       power *= tint;
                                       return true;
                                   },
                               .at_interface = [](const auto&) { return 0.0; }});
}

} // namespace

TEST_CASE("walk_step passes a false interface (inside glass of higher priority) and an index-matched one (its tint taken) straight, with no vertex")
{
    // A ball of glass of priority 1 and radius 2 holds one of priority 0 and radius 1: the
    // inner ball's surfaces are false from inside the outer. From z = -3 along +z, a path
    // that goes straight on at every vertex makes one at z = -2 (entering the outer ball),
    // passes z = -1 and z = 1, and makes one at z = 2, leaving it for the air.
    const auto scene = Scene{Lights{PointLight<double>{.position = {0, 0, 5}, .intensity = Rgb<double>(1)}},
                             Object{Sphere<double>({0, 0, 0}, 2), Dielectric<double>{.ior = 1.5, .priority = 1}},
                             Object{Sphere<double>({0, 0, 0}, 1), Dielectric<double>{.ior = 1.3, .priority = 0}}};
    Random rng(1, 2);
    Ray<double> ray{{0, 0, -3}, {0, 0, 1}};
    MediumStack media;
    Rgb<double> power(1);
    Seen seen;
    const double expected_paths[] = {1.0, 1.0, 2.0, 1.0};
    const StepEnd expected_ends[] = {StepEnd::surface, StepEnd::passed, StepEnd::passed, StepEnd::surface};
    const bool inside[] = {true, true, true, false};
    for (int k = 0; k < 4; ++k) {
        const Step<double> step = step_once(scene, ray, media, power, rng, seen, Vec3<double>(0, 0, 1));
        CHECK(step.end == expected_ends[k]);
        CHECK(step.path == doctest::Approx(expected_paths[k]).epsilon(1e-9));
        CHECK(ray.direction.z == doctest::Approx(1.0)); // straight on
        CHECK((media.top() != nullptr) == inside[k]);
    }
    CHECK(seen.surfaces == 2);
    CHECK(seen.point.z == doctest::Approx(2.0));
    CHECK(seen.outside_index == 1.0);

    // A ball of index 1 in the air (exact Fresnel) reflects nothing: its surface is no
    // vertex, and the path takes its kt.
    const auto matched = Scene{Lights{PointLight<double>{.position = {0, 0, 5}, .intensity = Rgb<double>(1)}},
                               Object{Sphere<double>({0, 0, 0}, 1), Dielectric<double>{.ior = 1.0, .kt = 0.25}},
                               Object{Sphere<double>({0, 0, 4}, 1), Diffuse<double>{}}};
    Ray<double> through{{0, 0, -3}, {0, 0, 1}};
    MediumStack none;
    Rgb<double> carried(1);
    Seen at_ball;
    std::vector<StepEnd> ends;
    for (int k = 0; k < 3; ++k) ends.push_back(step_once(matched, through, none, carried, rng, at_ball, std::nullopt).end);
    CHECK(ends == std::vector<StepEnd>{StepEnd::passed, StepEnd::passed, StepEnd::ended});
    CHECK(at_ball.matched == 2);
    CHECK(at_ball.tint.x == 0.25);
    CHECK(carried.x == doctest::Approx(0.0625));
    CHECK(at_ball.surfaces == 1);
    CHECK(at_ball.point.z == doctest::Approx(3.0));
}

TEST_CASE("walk_step: a path that refracts goes on inside the object, one that reflects stays out; one that misses everything escapes")
{
    const auto scene = Scene{Lights{PointLight<double>{.position = {0, 0, 5}, .intensity = Rgb<double>(1)}},
                             Object{Sphere<double>({0, 0, 0}, 1), Dielectric<double>{.ior = 1.5}}};
    Random rng(1, 2);
    Rgb<double> power(1);
    Seen seen;
    for (const double way : {1.0, -1.0}) {
        Ray<double> ray{{0, 0, -3}, {0, 0, 1}};
        MediumStack media;
        const Step<double> step = step_once(scene, ray, media, power, rng, seen, Vec3<double>(0, 0, way));
        CHECK(step.end == StepEnd::surface);
        CHECK(step.path == doctest::Approx(2.0));
        CHECK((media.top() != nullptr) == (way > 0)); // inside the glass after refracting
        CHECK(ray.direction.z == way);
        CHECK(ray.origin.z == doctest::Approx(-1.0));
    }
    Ray<double> away{{0, 0, -3}, {0, 0, -1}};
    MediumStack media;
    const Step<double> step = step_once(scene, away, media, power, rng, seen, std::nullopt);
    CHECK(step.end == StepEnd::escaped);
    CHECK(seen.escapes == 1);
}

TEST_CASE("walk_step in fog: a path scatters before a wall at distance L with probability 1 - exp(-sigma L), at the truncated exponential's mean distance")
{
    // Fog that only scatters (albedo 1: the flight's weight is 1), a wall at z = L.
    const double sigma = 0.7, L = 2.0;
    const FilledAir<Fog<double>> air{.medium = {.scattering = Rgb<double>(sigma)}};
    const auto scene = Scene{Lights{PointLight<double>{.position = {0, 0, -5}, .intensity = Rgb<double>(1)}},
                             Object{Plane<double>({0, 0, 1}, L), Diffuse<double>{}}};
    Random rng(7, 11);
    const int n = 40000;
    int scattered = 0;
    double paths = 0, largest_miss = 0;
    for (int i = 0; i < n; ++i) {
        rng.bounce(0);
        Ray<double> ray{{0, 0, 0}, {0, 0, 1}};
        MediumStack media;
        Rgb<double> power(1);
        Seen seen;
        const Step<double> step = step_once(scene, ray, media, power, rng, seen, Vec3<double>(1, 0, 0), air);
        if (step.end == StepEnd::medium) {
            ++scattered;
            paths += step.path;
            // The arrival's point lies at its path along the ray, and the next step leaves from there.
            largest_miss = std::max({largest_miss, std::abs(seen.point.z - step.path), std::abs(ray.origin.z - step.path)});
            CHECK(ray.direction.x == 1.0);
        } else {
            CHECK(step.end == StepEnd::surface);
        }
        CHECK(power.x == doctest::Approx(1.0));
    }
    const double p = 1 - std::exp(-sigma * L);
    const double rate = double(scattered) / n;
    CHECK(std::abs(rate - p) < 4 * std::sqrt(p * (1 - p) / n));
    // E[t | t < L] for t ~ sigma exp(-sigma t), and its standard error over the scattered.
    const double mean = 1 / sigma - L * std::exp(-sigma * L) / p;
    const double second = 2 / (sigma * sigma) - (L * L + 2 * L / sigma) * std::exp(-sigma * L) / p;
    CHECK(std::abs(paths / scattered - mean) < 4 * std::sqrt((second - mean * mean) / scattered));
    CHECK(largest_miss < 1e-12);
}
