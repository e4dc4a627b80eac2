// SPDX-License-Identifier: MIT
#include <prism/transport/media.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

#include <cmath>

using namespace prism;

namespace {

/// Slot 0: a tinted glass ball (n = 1.5, absorbing 0.4 / 0.2 / 0.1 per unit); slot 1: a
/// diffuse floor.
auto tinted_glass_scene()
{
    return Scene{Lights{PointLight<double>{.position = {0, 5, 0}, .intensity = Rgb<double>(1)}},
                 Object{Sphere<double>({0, 1, 0}, 1), Dielectric<double>{.ior = 1.5, .interior = {.absorption = {0.4, 0.2, 0.1}}}},
                 Object{Plane<double>({0, 1, 0}, 0), Diffuse<double>{}}};
}

} // namespace

TEST_CASE("index_of: the air's 1 for no object, the glass's index inside it, 1 for an object that does not transmit")
{
    const auto scene = tinted_glass_scene();
    CHECK(index_of(scene, nullptr, 0.0) == 1.0);
    const Inside glass{0, 0, 0}, floor{1, 0, 0};
    CHECK(index_of(scene, &glass, 0.0) == 1.5);
    CHECK(index_of(scene, &glass, 589.3) == 1.5); // a glass that does not disperse: the same at any wavelength
    CHECK(index_of(scene, &floor, 0.0) == 1.0);
}

TEST_CASE("attenuate_segment: Beer-Lambert over the segment in the medium the path is in, or inside the object it leaves")
{
    const auto scene = tinted_glass_scene();
    const Diffuse<double> floor_material{};
    const Dielectric<double> glass = get<0>(scene.slots).material;
    // A segment of length 2 x 0.75 = 1.5 (t 0.75 along a direction of length 2).
    const Ray<double> ray{{0, 1, 0}, {0, 2, 0}};
    const auto at = Crossing<double>::flat(0.75, {0, 2.5, 0}, {0, 0, 0}, {0, 1, 0}, false);
    // In the glass (its medium on the stack), arriving at the floor's material: the glass's absorption.
    Rgb<double> light(1);
    attenuate_segment(scene, MediumStack{}.entered({0, 0, 0}), floor_material, at, ray, light);
    CHECK(light.x == doctest::Approx(std::exp(-0.4 * 1.5)));
    CHECK(light.z == doctest::Approx(std::exp(-0.1 * 1.5)));
    // In no object, leaving the glass: the path was inside it all the same.
    light = Rgb<double>(1);
    attenuate_segment(scene, MediumStack{}, glass, at, ray, light);
    CHECK(light.y == doctest::Approx(std::exp(-0.2 * 1.5)));
    // In no object, arriving at the floor: nothing taken.
    light = Rgb<double>(1);
    attenuate_segment(scene, MediumStack{}, floor_material, at, ray, light);
    CHECK(light == Rgb<double>(1));
}

TEST_CASE("air_transmittance: exp(-sigma_t d) over the part of a shadow ray inside FilledAir's region, 1 in clear air")
{
    const FilledAir<Fog<double>> air{.medium = {.absorption = {0.1, 0.2, 0.3}, .scattering = {0.3, 0.2, 0.1}}, .region = {{-1, -1, -1}, {1, 1, 1}}};
    const Ray<double> ray{{-3, 0.5, 0}, {1, 0, 0}}; // crosses the box from x = -1 to 1
    CHECK(air_transmittance(air, ray, 10.0).x == doctest::Approx(std::exp(-0.4 * 2)));
    CHECK(air_transmittance(air, ray, 2.5).y == doctest::Approx(std::exp(-0.4 * 0.5))); // stops half a unit into the box
    CHECK(air_transmittance(air, ray, infinity<double>).z == doctest::Approx(std::exp(-0.4 * 2)));
    CHECK(air_transmittance(air, Ray<double>{{-3, 2, 0}, {1, 0, 0}}, 10.0) == Rgb<double>(1)); // passes above the box
    CHECK(air_transmittance(StraightAir{}, ray, 10.0) == Rgb<double>(1));
    const FilledAir<Fog<double>> everywhere{.medium = {.scattering = Rgb<double>(0.5)}};
    CHECK(air_transmittance(everywhere, ray, 3.0).x == doctest::Approx(std::exp(-1.5)));
    CHECK(air_transmittance(everywhere, ray, infinity<double>).x == 0);
    CHECK_THROWS_WITH_AS((FilledAir<Fog<double>>{.region = {}}.validate()), doctest::Contains("FilledAir region"), std::invalid_argument);
}
