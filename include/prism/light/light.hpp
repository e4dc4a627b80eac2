// SPDX-License-Identifier: MIT
// What a light tells a shading point, and the Light concept.
#pragma once

#include <prism/core/math.hpp>

#include <concepts>

namespace prism {

/// Light arriving at a point from one light.
template <Scalar T>
struct LightSample {
    Vec3<T> wi{};        ///< unit direction from the point toward the light
    T distance = T(0);   ///< distance to the light (infinity for a directional light)
    Rgb<T> irradiance{}; ///< irradiance on a surface facing the light (W/m^2)
};

template <class L>
concept Light = requires(const L& light, const Vec3<typename L::scalar_type>& p) {
    requires Scalar<typename L::scalar_type>;
    { light.sample(p) } -> std::same_as<LightSample<typename L::scalar_type>>;
    light.validate();
};

} // namespace prism
