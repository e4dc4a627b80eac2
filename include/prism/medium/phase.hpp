// SPDX-License-Identifier: MIT
// Phase functions: where light scattered in a medium goes, a density over the sphere of
// directions. Written, as every walker uses them, for the directions of travel before
// and after the scattering (a camera path's as well as a photon's: the function depends
// on their angle only, so it reads the same both ways).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/core/sampling.hpp>

#include <cmath>
#include <concepts>

namespace prism {

/// A direction of travel drawn from a phase function, with its density (solid angle).
template <Scalar T>
struct PhaseSample {
    Vec3<T> direction; ///< unit, the direction of travel after scattering
    T pdf;             ///< its density, the phase function's value there
};

/// A phase function: `value(cos)` for the cosine between the directions of travel before
/// and after scattering (a density over the sphere, integrating to 1), and
/// `sample(direction, u1, u2)` drawing the direction after from exactly that density.
template <class P>
concept PhaseFunction = requires(const P& phase, typename P::scalar_type x, const Vec3<typename P::scalar_type>& d) {
    { phase.value(x) } -> std::same_as<typename P::scalar_type>;
    { phase.sample(d, x, x) } -> std::same_as<PhaseSample<typename P::scalar_type>>;
    phase.validate();
};

/// Henyey and Greenstein's (1941) phase function of mean cosine `g`: 0 scatters evenly
/// (isotropic), toward 1 forward (haze, cloud droplets: 0.7 to 0.9), toward -1 back.
/// p(cos) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2)), drawn by inverting its
/// distribution in cos.
template <Scalar T = float>
struct HenyeyGreenstein {
    /// The precision of the parameter.
    using scalar_type = T;

    T g = T(0); ///< the mean cosine of the scattering angle, in (-1, 1)

    /// The density for the cosine between the directions of travel before and after.
    [[nodiscard]] T value(T cos_theta) const noexcept
    {
        const T denominator = T(1) + g * g - T(2) * g * cos_theta;
        return (T(1) - g * g) / (T(4) * pi<T> * denominator * prism::sqrt(denominator));
    }

    /// A direction of travel after scattering, for `direction` (unit) before, from two
    /// uniform numbers.
    [[nodiscard]] PhaseSample<T> sample(const Vec3<T>& direction, T u1, T u2) const noexcept
    {
        T cos_theta;
        if (std::abs(g) < T(1e-3)) {
            cos_theta = T(1) - T(2) * u1;
        } else {
            const T s = (T(1) - g * g) / (T(1) + g - T(2) * g * u1);
            cos_theta = std::clamp((T(1) + g * g - s * s) / (T(2) * g), T(-1), T(1));
        }
        const T sin_theta = prism::sqrt(std::max(T(0), T(1) - cos_theta * cos_theta));
        const T phi = T(2) * pi<T> * u2;
        const auto [a, b] = orthonormal_frame(direction);
        const Vec3<T> out = sin_theta * (std::cos(phi) * a + std::sin(phi) * b) + cos_theta * direction;
        return {normalize(out), value(cos_theta)};
    }

    /// Throws std::invalid_argument for g outside (-1, 1) or not finite.
    void validate() const
    {
        if (!(g > T(-1) && g < T(1))) detail::throw_invalid("HenyeyGreenstein g must be in (-1, 1), got ", g);
    }
};

static_assert(PhaseFunction<HenyeyGreenstein<float>> && PhaseFunction<HenyeyGreenstein<double>>);

} // namespace prism
