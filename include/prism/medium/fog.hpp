// SPDX-License-Identifier: MIT
// Fog: a homogeneous medium that absorbs and scatters (haze, smoke of even density, murky
// water), its coefficients per channel, its phase function Henyey-Greenstein's by default.
//
// A walker crossing it draws where it next scatters (free-flight sampling): a channel
// with the chance of its share of what the walker carries, a distance with that
// channel's density sigma_t exp(-sigma_t s), and the weight that makes the draw unbiased
// in every channel, the density being the channels' mixture (the balance heuristic over
// channels, as Cycles does; pbrt-v4 the same over its wavelengths). In a grey fog the
// weights are exact: the albedo sigma_s / sigma_t where it scatters, 1 where it passes.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/core/random.hpp>
#include <prism/medium/medium.hpp>
#include <prism/medium/phase.hpp>

#include <algorithm>
#include <cmath>

namespace prism {

/// A homogeneous scattering medium: `absorption` and `scattering` coefficients per unit
/// length and per channel (sigma_a, sigma_s; their sum the extinction sigma_t), and the
/// `phase` function by which it scatters.
template <Scalar T = float, PhaseFunction Phase = HenyeyGreenstein<T>>
struct Fog {
    /// The precision of the coefficients.
    using scalar_type = T;
    /// Its phase function's type.
    using phase_type = Phase;
    /// Light scatters in it.
    static constexpr bool scatters = true;

    Rgb<T> absorption{T(0)}; ///< sigma_a per channel, per unit length
    Rgb<T> scattering{T(0)}; ///< sigma_s per channel, per unit length
    Phase phase{};           ///< where scattered light goes

    /// sigma_s at a point (the same everywhere).
    [[nodiscard]] constexpr Rgb<T> scattering_at(const Vec3<T>&) const noexcept { return scattering; }

    /// sigma_t = sigma_a + sigma_s.
    [[nodiscard]] constexpr Rgb<T> extinction() const noexcept { return absorption + scattering; }

    /// exp(-sigma_t distance) per channel (1 in a clear channel, even at infinity).
    [[nodiscard]] Rgb<T> transmittance(T distance) const noexcept
    {
        const Rgb<T> sigma = extinction();
        return {channel_transmittance(sigma.x, distance), channel_transmittance(sigma.y, distance), channel_transmittance(sigma.z, distance)};
    }

    /// Where a walker along `ray` (unit direction, in the fog from its origin) carrying
    /// `power` next scatters before `t_max` (which may be infinite), or that it reaches
    /// t_max, and the weight its power takes either way.
    [[nodiscard]] FreeFlight<T> sample_flight(const Ray<T>& ray, T t_max, const Rgb<T>& power, Random& rng) const noexcept
    {
        (void)ray;
        const Rgb<T> sigma = extinction();
        const Rgb<T> chance = channel_chances(power);
        const T pick = rng.uniform<T>();
        int channel = pick < chance.x ? 0 : pick < chance.x + chance.y ? 1 : 2;
        if (!(chance[channel] > T(0))) channel = chance.z > T(0) ? 2 : chance.y > T(0) ? 1 : 0; // past the sum by rounding
        const T u = rng.uniform<T>();
        const T s = sigma[channel] > T(0) ? -std::log1p(-u) / sigma[channel] : infinity<T>;
        if (s < t_max) {
            const T pdf = flight_pdf(power, s);
            if (!(pdf > T(0))) return {t_max, Rgb<T>(T(0)), false};
            return {s, scattering * transmittance(s) / pdf, true};
        }
        const Rgb<T> tr = transmittance(t_max);
        const T passing = dot(chance, tr);
        return {t_max, passing > T(0) ? tr / passing : Rgb<T>(T(0)), false};
    }

    /// The density with which sample_flight, for a walker carrying `power`, scatters at
    /// distance t: the channels' mixture, sum over c of P(c) sigma_t,c exp(-sigma_t,c t).
    /// (The path tracer weighs its equiangular samples against it.)
    [[nodiscard]] T flight_pdf(const Rgb<T>& power, T t) const noexcept { return dot(channel_chances(power), extinction() * transmittance(t)); }

    /// Throws std::invalid_argument, naming the parameter, for a negative or non-finite
    /// coefficient or a bad phase function.
    void validate() const
    {
        detail::require_non_negative("Fog absorption", absorption);
        detail::require_non_negative("Fog scattering", scattering);
        phase.validate();
    }

private:
    /// The chance of drawing each channel's distance: its share of what the walker carries.
    [[nodiscard]] static Rgb<T> channel_chances(const Rgb<T>& power) noexcept
    {
        const T total = power.x + power.y + power.z;
        return total > T(0) ? power / total : Rgb<T>(T(1) / T(3));
    }

    [[nodiscard]] static T channel_transmittance(T sigma, T distance) noexcept { return sigma > T(0) ? std::exp(-sigma * distance) : T(1); }
};

static_assert(ScatteringMedium<Fog<float>> && ScatteringMedium<Fog<double>>);

} // namespace prism
