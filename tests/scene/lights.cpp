// SPDX-License-Identifier: MIT
#include <prism/light/directional_light.hpp>
#include <prism/light/point_light.hpp>
#include <prism/scene/lights.hpp>

#include <doctest/doctest.h>

#include <stdexcept>
#include <type_traits>

TEST_CASE("Lights{...}: lights of their own types, each validated when the list is made")
{
    const prism::Lights lights{prism::PointLight<float>{.position = {0, 1, 0}, .intensity = prism::Rgb<float>(2)},
                               prism::DirectionalLight<float>{.direction = {0, -1, 0}, .irradiance = prism::Rgb<float>(1)}};
    using List = std::remove_cvref_t<decltype(lights)>;
    static_assert(prism::LightList<List>);
    static_assert(!prism::LightList<prism::PointLight<float>>);
    static_assert(prism::detail::lights_of_scalar<List, float>);
    static_assert(!prism::detail::lights_of_scalar<List, double>);
    CHECK(std::get<0>(lights.items).intensity.x == 2);
    const auto negative = [] {
        return prism::Lights{prism::PointLight<float>{.position = prism::Vec3<float>{0, 1, 0}, .intensity = prism::Rgb<float>(-1)}};
    };
    CHECK_THROWS_AS((void)negative(), std::invalid_argument);
}
