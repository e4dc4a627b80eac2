// SPDX-License-Identifier: MIT
// DirectionalLight: parallel light from infinitely far away (the sun).
#pragma once

#include <prism/core/check.hpp>
#include <prism/light/light.hpp>

namespace prism {

/// Parallel light travelling along `direction`, with irradiance E on a surface facing it.
template <Scalar T = float>
struct DirectionalLight {
    using scalar_type = T;

    Vec3<T> direction{T(0), T(-1), T(0)};
    Rgb<T> irradiance{T(1)};

    [[nodiscard]] LightSample<T> sample(const Vec3<T>&) const noexcept
    {
        return {-normalize(direction), infinity<T>, irradiance};
    }

    constexpr void validate() const
    {
        detail::require_nonzero("DirectionalLight direction", direction);
        detail::require_non_negative("DirectionalLight irradiance", irradiance);
    }
};

static_assert(Light<DirectionalLight<float>>);

} // namespace prism
