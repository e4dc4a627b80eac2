// SPDX-License-Identifier: MIT
// VaryingFog: a medium that absorbs and scatters with a density that varies from point
// to point (smoke, clouds, ground fog, a simulation's grid): its coefficients per channel
// at density 1, times a density field's value (medium/density.hpp).
//
// Nothing about it has a closed form, so it is sampled against a majorant (Woodcock,
// Novak et al. 2014): tentative collisions at the rate of a bound mu of the extinction
// (one per cell of its majorant grid), each one real with the chance of the extinction
// there over mu and null otherwise.
//  - A walker's flight (sample_flight) is spectral tracking (Kutz et al. 2017): at each
//    tentative collision it scatters with a chance P_s, the mean over the channels of
//    sigma_s against sigma_s + sigma_n (sigma_n = mu - sigma_t, the null part), weighed
//    by what the walker carries in each; its weight takes sigma_s / (mu P_s) if it
//    scatters and sigma_n / (mu (1 - P_s)) if not, so every channel's expectation is the
//    collision integral's, absorption carried in the weight. In a grey fog that does not
//    absorb the weights stay 1 (delta tracking).
//  - Transmittance is residual ratio tracking (Novak et al. 2014): in each cell, the
//    exact transmittance of the cell's floor of the density (the control), times the
//    product of 1 - (sigma_t - control) / mu' over tentative collisions at the rate mu'
//    of the residual's bound, with Russian roulette once it falls below 0.1 in every
//    channel. Each estimate is unbiased, not exact; where the density is constant over a
//    cell it is exact (plain ratio tracking there is the indicator of no collision, as
//    noisy as a coin). Where no stream is given (shadow rays, the beam
//    estimate, Whitted's marching), the stream is seeded by a hash of the segment, so a
//    render stays the same bits for any thread count, crop or split.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/core/random.hpp>
#include <prism/medium/density.hpp>
#include <prism/medium/majorant.hpp>
#include <prism/medium/medium.hpp>
#include <prism/medium/phase.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace prism {

/// A scattering medium whose coefficients are `absorption` and `scattering` (sigma_a,
/// sigma_s per unit length at density 1, per channel) times the density of `field` at
/// each point; `phase` the phase function; tracked against a majorant grid of `cells`
/// cells along each axis over the field's box (more cells: tighter bounds, more steps).
template <DensityField Field, PhaseFunction Phase = HenyeyGreenstein<typename Field::scalar_type>>
class VaryingFog {
public:
    /// The precision of positions and coefficients.
    using scalar_type = typename Field::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;
    /// Its phase function's type.
    using phase_type = Phase;
    /// Light scatters in it.
    static constexpr bool scatters = true;

    /// Throws std::invalid_argument, naming the parameter, for a bad field, a negative or
    /// non-finite coefficient, a bad phase function, or cells outside [1, 256].
    VaryingFog(Field field, const Rgb<T>& sigma_a, const Rgb<T>& sigma_s, Phase scatters_by = {}, int cells = 16)
        : phase(scatters_by), field_(std::move(field)), absorption_(sigma_a), scattering_(sigma_s)
    {
        validate();
        majorants_ = MajorantGrid<T>(field_, cells);
        most_ = max_component(absorption_ + scattering_);
        // The trackers step from each cell's entry by draws of mean 1 / mu: that must
        // stay well above the precision of a distance across the box, or they would stall.
        T densest = T(0);
        for (int z = 0; z < cells; ++z)
            for (int y = 0; y < cells; ++y)
                for (int x = 0; x < cells; ++x) densest = std::max(densest, majorants_.bound(x, y, z));
        const Aabb<T> box = field_.bounds();
        const T across = max_component(box.hi - box.lo), mu = densest * most_;
        if (!(mu * across * std::numeric_limits<T>::epsilon() <= T(1) / T(16)))
            detail::throw_invalid("VaryingFog is too dense for its precision: its greatest extinction ", mu, " per unit length over a box ", across,
                                  " across leaves a mean free path below 16 steps of its precision there");
    }

    Phase phase; ///< where scattered light goes

    /// The density field.
    [[nodiscard]] const Field& field() const noexcept { return field_; }
    /// sigma_a at density 1.
    [[nodiscard]] const Rgb<T>& absorption() const noexcept { return absorption_; }
    /// sigma_s at density 1.
    [[nodiscard]] const Rgb<T>& scattering() const noexcept { return scattering_; }
    /// The majorant grid the trackers step through.
    [[nodiscard]] const MajorantGrid<T>& majorants() const noexcept { return majorants_; }
    /// Where the medium is: outside this box it is clear.
    [[nodiscard]] Aabb<T> bounds() const noexcept { return field_.bounds(); }

    /// sigma_s at a point.
    [[nodiscard]] Rgb<T> scattering_at(const Vec3<T>& p) const noexcept { return scattering_ * field_.density(p); }

    /// sigma_t at a point: (sigma_a + sigma_s) times the density there.
    [[nodiscard]] Rgb<T> extinction_at(const Vec3<T>& p) const noexcept { return (absorption_ + scattering_) * field_.density(p); }

    /// An unbiased estimate of the transmittance along `ray` (unit direction) from its
    /// origin to t_max (may be infinite), by residual ratio tracking with `rng`.
    [[nodiscard]] Rgb<T> transmittance(const Ray<T>& ray, T t_max, Random& rng) const noexcept
    {
        Rgb<T> tr{T(1)};
        const Rgb<T> sigma_t = absorption_ + scattering_;
        majorants_.traverse(ray, T(0), t_max, [&](T a, T b, const typename MajorantGrid<T>::Range& range) {
            if (range.floor > T(0)) {
                const Rgb<T> depth = sigma_t * (range.floor * (b - a));
                tr *= Rgb<T>(std::exp(-depth.x), std::exp(-depth.y), std::exp(-depth.z));
                if (!(max_component(tr) > T(0))) return false;
            }
            const T mu = (range.bound - range.floor) * most_;
            if (!(mu > T(0))) return true;
            for (T s = T(0);;) { // (from the cell's entry: s advances while t = a + s may not, far from the origin)
                s += -std::log1p(-rng.uniform<T>()) / mu;
                if (!(s < b - a)) return true;
                const T residual = checked_density(ray.at(a + s), range.bound) - range.floor;
                tr *= component_max(Rgb<T>(T(1)) - sigma_t * (residual / mu), Rgb<T>(T(0)));
                if (max_component(tr) < T(0.1)) {
                    if (rng.uniform<T>() < T(0.5)) {
                        tr = Rgb<T>(T(0));
                        return false;
                    }
                    tr *= T(2);
                }
            }
        });
        return tr;
    }

    /// The same estimate with a stream seeded by the segment itself (its origin,
    /// direction and t_max): the same segment always gives the same estimate.
    [[nodiscard]] Rgb<T> transmittance(const Ray<T>& ray, T t_max) const noexcept
    {
        Random rng = stream_of(ray, t_max);
        return transmittance(ray, t_max, rng);
    }

    /// Where a walker along `ray` (unit direction, from its origin) carrying `power` next
    /// scatters before t_max (may be infinite), or that it reaches t_max, and the weight
    /// its power takes either way: spectral tracking (see the file's comment).
    [[nodiscard]] FreeFlight<T> sample_flight(const Ray<T>& ray, T t_max, const Rgb<T>& power, Random& rng) const noexcept
    {
        const Rgb<T> sigma_t = absorption_ + scattering_;
        const T carried = power.x + power.y + power.z;
        const Rgb<T> share = carried > T(0) ? power / carried : Rgb<T>(T(1) / T(3));
        Rgb<T> weight{T(1)};
        FreeFlight<T> out{t_max, weight, false};
        bool ended = false;
        majorants_.traverse(ray, T(0), t_max, [&](T a, T b, const typename MajorantGrid<T>::Range& range) {
            const T mu = range.bound * most_;
            if (!(mu > T(0))) return true;
            for (T s = T(0);;) { // (as in transmittance)
                s += -std::log1p(-rng.uniform<T>()) / mu;
                if (!(s < b - a)) return true;
                const T t = a + s;
                const T density = checked_density(ray.at(t), range.bound);
                const Rgb<T> scatter = scattering_ * density;
                const Rgb<T> null = component_max(Rgb<T>(mu) - sigma_t * density, Rgb<T>(T(0)));
                const Rgb<T> history = share * weight;
                const T toward_scatter = dot(history, scatter), toward_null = dot(history, null);
                if (!(toward_scatter + toward_null > T(0))) { // absorbed in every channel it carries
                    out = {t_max, Rgb<T>(T(0)), false};
                    ended = true;
                    return false;
                }
                const T p_scatter = toward_scatter / (toward_scatter + toward_null);
                if (rng.uniform<T>() < p_scatter) {
                    out = {t, weight * scatter / (mu * p_scatter), true};
                    ended = true;
                    return false;
                }
                weight *= null / (mu * (T(1) - p_scatter));
            }
        });
        if (!ended) out.weight = weight;
        return out;
    }

    /// Throws std::invalid_argument, naming the parameter, for a bad field, a negative or
    /// non-finite coefficient or a bad phase function.
    void validate() const
    {
        field_.validate();
        detail::require_non_negative("VaryingFog absorption", absorption_);
        detail::require_non_negative("VaryingFog scattering", scattering_);
        phase.validate();
    }

private:
    /// The density at p, which the cell's bound must not be below (a field whose
    /// max_over lies would bias every estimate: caught where assertions are on).
    [[nodiscard]] T checked_density(const Vec3<T>& p, [[maybe_unused]] T bound) const noexcept
    {
        const T density = field_.density(p);
        PRISM_ASSERT(density <= bound * (T(1) + T(1e-4)) + std::numeric_limits<T>::min());
        return density;
    }

    /// A stream from the bits of a segment (splitmix64 over them).
    [[nodiscard]] static Random stream_of(const Ray<T>& ray, T t_max) noexcept
    {
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        const auto mix = [&](T value) {
            std::uint64_t z = h + std::uint64_t(std::bit_cast<std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>(value)) + 0x9e3779b97f4a7c15ULL;
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
            h = z ^ (z >> 31);
        };
        for (int a = 0; a < 3; ++a) mix(ray.origin[a]), mix(ray.direction[a]);
        mix(t_max);
        return Random(h, h >> 1);
    }

    Field field_;
    Rgb<T> absorption_;
    Rgb<T> scattering_;
    MajorantGrid<T> majorants_{};
    T most_ = T(0);
};

} // namespace prism
