// SPDX-License-Identifier: MIT
// The scene's air: uniform (rays go straight, the default), of a varying index
// (graded-index air: mirages, a flattened setting sun), through which rays curve, or
// filled with a medium that scatters (FilledAir: fog, haze, murky water around everything,
// in straight or graded air).
//
// GradedAir puts an index field (medium/graded_index.hpp) in a box; outside the box the
// field must be uniform, and rays go straight there. LayeredAir is flat layers of
// constant index, refracting at each boundary. How a ray travels through either to the first surface it meets is
// transport/travel.hpp's.
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/core/check.hpp>
#include <prism/medium/graded_index.hpp>
#include <prism/medium/medium.hpp>

namespace prism {

/// Uniform air of index 1: rays are straight.
struct StraightAir {
    /// Rays through it are straight.
    static constexpr bool curved = false;
    /// Nothing to check.
    constexpr void validate() const {}
};

/// Air filled, within `region` (everywhere by default), with a medium that absorbs and
/// scatters: the fog a scene stands in, the water around an underwater scene. Outside the
/// region the air is clear. (An object's inside takes its own medium, its material's
/// interior.) `Base` is the air the medium fills: straight (the default), or GradedAir or
/// LayeredAir, through which rays curve (a mirage seen through haze): a walker in it
/// scatters along the curved path, by the medium's coefficients per unit of the path's
/// length.
template <ScatteringMedium M, class Base = StraightAir>
struct FilledAir {
    /// The medium's precision.
    using scalar_type = typename M::scalar_type;
    /// Rays through it curve where they curve through its base.
    static constexpr bool curved = Base::curved;
    /// Light scatters in it.
    static constexpr bool scatters = true;
    static_assert(!requires { requires Base::scatters; }, "FilledAir's base is the air it fills: StraightAir, GradedAir or LayeredAir");

    M medium{}; ///< what fills the region
    Aabb<scalar_type> region = Aabb<scalar_type>::universe(); ///< where the medium is (a box; everywhere by default)
    Base base{}; ///< the air it fills: straight, or of a varying index

    /// Where the air is not clear: the region, within the medium's own box where it has
    /// one (a medium of varying density).
    [[nodiscard]] Aabb<scalar_type> bounds() const noexcept
    {
        if constexpr (requires { medium.bounds(); }) {
            const Aabb<scalar_type> box = medium.bounds();
            return {component_max(region.lo, box.lo), component_min(region.hi, box.hi)};
        } else {
            return region;
        }
    }

    /// Throws std::invalid_argument, naming the parameter, for a bad medium or base, or an empty region.
    void validate() const
    {
        medium.validate();
        if (region.empty()) detail::throw_invalid("FilledAir region must not be empty");
        base.validate();
    }
};

/// Whether the scene's air `Air` scatters light (FilledAir).
template <class Air>
inline constexpr bool air_scatters = requires { requires Air::scatters; };

/// Air whose index is `field` inside `region` (uniform outside it); rays through it curve.
template <IndexField F>
struct GradedAir {
    /// The field's precision.
    using scalar_type = typename F::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;
    /// Rays through it curve.
    static constexpr bool curved = true;

    F field{}; ///< the refractive index inside the region
    Aabb<T> region{};                                   ///< where the index varies
    typename AdaptiveStepper<F>::Config stepping{};     ///< the stepper's tolerance and step lengths
    /// A chord that meets a surface is halved (Sharma steps of half the dt) until it is
    /// at most this long, so the landing point lies on the curve, not on a chord that
    /// cuts under it (a chord of length L sags by about L^2 / (8 R) from a path of radius R).
    T landing_chord = T(1e-3);
    int max_steps = 1000000;                            ///< a ray still in the air after this many steps is lost (background)

    /// Throws std::invalid_argument, naming the parameter, for a bad field, an unbounded or empty region, max_steps < 1, landing_chord <= 0 or bad stepping.
    void validate() const
    {
        field.validate();
        if (!region.bounded()) detail::throw_invalid("GradedAir region must be a bounded, non-empty box");
        if (max_steps < 1) detail::throw_invalid("GradedAir max_steps must be >= 1, got ", max_steps);
        detail::require_positive("GradedAir landing_chord", landing_chord);
        (void)AdaptiveStepper<F>(field, stepping); // checks the stepping
    }
};

/// Layered air: `layers` flat layers between heights `bottom` and `top`, each
/// of the field's index at its middle height (stratified fields only); a ray goes
/// straight within a layer and refracts by Snell's law (or reflects totally) at each
/// boundary; above and below the layers it goes straight. The second policy beside
/// GradedAir, for comparison: it keeps n cos(theta) exactly but converges only at first
/// order in the layer height (bench/graded_index.cpp).
template <IndexField F>
struct LayeredAir {
    /// The field's precision.
    using scalar_type = typename F::scalar_type;
    /// Shorthand for scalar_type.
    using T = scalar_type;
    /// Rays through it bend at the layers' boundaries.
    static constexpr bool curved = true;

    F field{}; ///< the index field the layers sample at their middle heights
    T bottom = T(0); ///< height of the lowest layer's bottom
    T top = T(1); ///< height of the highest layer's top
    int layers = 100; ///< the number of layers

    /// Throws std::invalid_argument, naming the parameter, for a bad field, top <= bottom or layers < 1.
    void validate() const { (void)LayeredMedium<F>(field, bottom, top, layers); }
};

} // namespace prism
