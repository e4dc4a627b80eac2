// SPDX-License-Identifier: MIT
// PointGridLight: POV-Ray's area_light, a rectangle of point lights that cast one soft
// shadow.
//
// POV-Ray shades a surface by an area_light as by one point light at the rectangle's
// centre, and scales that light by how much of the rectangle the point sees: the
// rectangle's size1 x size2 grid of points (its corners included) is tested by shadow
// rays, and the result is the mean of the four corners of the grid, where each corner of a
// region whose corners differ (or every region, down to adaptive levels) is replaced by
// the mean of its four sub-regions, recursively, until a region is one cell. Each grid
// point is traced at most once per shading point. This is POV-Ray 3.7's
// Trace::TraceAreaLightSubsetShadowRay, written again here: the same grid, the same
// splitting rule (a corner differing from its neighbour by more than 0.1 in the sum of
// its channels' absolute differences, the light's colour times what the shadow ray let
// through), the same means. It is not physical (the shading ignores the light's extent,
// and the mean weighs the grid's points unequally); it is there so that a POV-Ray scene
// with area_light renders as POV-Ray renders it. A physical area light is an emitting
// object (material/emissive.hpp).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/random.hpp>
#include <prism/light/light.hpp>
#include <prism/light/point_light.hpp>

#include <array>
#include <bitset>
#include <cmath>

namespace prism {

/// POV-Ray's `area_light <axis1>, <axis2>, size1, size2 adaptive A [jitter]` on a point
/// light: shaded from `light`'s position, shadowed by the share of the size1 x size2 grid
/// of points spanning axis1 x axis2 around it that a point sees (POV-Ray's adaptive mean).
/// Its photons leave from the centre, as the point light's.
template <Scalar T = float>
struct PointGridLight {
    /// The precision of the light.
    using scalar_type = T;
    /// A delta light: one direction shades, and one sample tells all (its shadow is soft).
    static constexpr bool delta = true;
    /// At most this many grid points (32 x 32; POV-Ray allows more, its sample scenes use up
    /// to 17 x 17): a shading point keeps what each point let through on the stack.
    static constexpr int max_points = 1024;

    PointLight<T> light{};              ///< the light at the rectangle's centre (POV-Ray's colour c: pi c, no falloff)
    Vec3<T> axis1{T(1), T(0), T(0)};    ///< the rectangle's first side, centred on the light
    Vec3<T> axis2{T(0), T(0), T(1)};    ///< its second side
    int size1 = 2;                      ///< grid points along axis1 (1: none off the centre line)
    int size2 = 2;                      ///< grid points along axis2
    int adaptive = 100;                 ///< POV-Ray's adaptive level: regions split unconditionally this many levels deep (its default, 100: every point)
    bool jitter = false;                ///< each point moved by up to half a cell in each axis, at random (POV-Ray's jitter)

    /// The light arriving at p from the centre, as the point light's.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p) const noexcept { return light.sample(p); }
    /// The same: the light's extent changes its shadow only.
    [[nodiscard]] LightSample<T> sample(const Vec3<T>& p, const Vec2<T>&) const noexcept { return light.sample(p); }
    /// The point light's.
    [[nodiscard]] Rgb<T> photon_power(const PhotonAim<T>& aim) const noexcept { return light.photon_power(aim); }
    /// The point light's, from the centre.
    [[nodiscard]] EmittedPhoton<T> emit_photon(const PhotonAim<T>& aim, T u, T v) const noexcept { return light.emit_photon(aim, u, v); }

    /// What reaches p through the shadow of the grid, per channel in [0, 1]:
    /// `through(point)` is what a shadow ray from p to a point of the grid lets through;
    /// `colour` is the light's colour at p (the irradiance over pi), against which POV-Ray's
    /// 0.1 is measured; `rng` jitters the points (jitter only; may be null otherwise).
    template <class Through>
    [[nodiscard]] Rgb<T> shadow(Through&& through, const Rgb<T>& colour, Random* rng) const noexcept
    {
        Grid grid; // each value is written before it is read (traced says which)
        return region(grid, std::forward<Through>(through), colour, rng, 0, 0, size1 - 1, size2 - 1, 0);
    }

    /// Throws std::invalid_argument, naming the parameter, for a bad light, a non-finite
    /// axis, a size below 1 or a grid of more than max_points, or a negative adaptive level.
    constexpr void validate() const
    {
        light.validate();
        detail::require_finite("PointGridLight axis1", axis1);
        detail::require_finite("PointGridLight axis2", axis2);
        if (size1 < 1 || size2 < 1) detail::throw_invalid("PointGridLight size1 and size2 must be >= 1, got ", size1, " x ", size2);
        if (size1 > max_points / size2) detail::throw_invalid("PointGridLight grid of ", size1, " x ", size2, " has more than ", max_points, " points");
        if (adaptive < 0) detail::throw_invalid("PointGridLight adaptive must be >= 0, got ", adaptive);
    }

private:
    /// The grid points traced so far at one shading point.
    struct Grid {
        std::array<Rgb<T>, max_points> value;   ///< what each point let through, where traced
        std::bitset<max_points> traced;         ///< which points were traced
    };

    /// POV-Ray's ColourDistance: the sum of the channels' absolute differences.
    [[nodiscard]] static T distance(const Rgb<T>& a, const Rgb<T>& b) noexcept
    {
        return std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z);
    }

    /// What grid point (u, v) lets through, traced once.
    template <class Through>
    [[nodiscard]] const Rgb<T>& point(Grid& grid, Through& through, Random* rng, int u, int v) const noexcept
    {
        const std::size_t k = std::size_t(u) * std::size_t(size2) + std::size_t(v);
        if (!grid.traced[k]) {
            T ju = T(u), jv = T(v);
            if (jitter && rng) {
                const auto [du, dv] = rng->template uniform2<T>();
                ju += du - T(0.5);
                jv += dv - T(0.5);
            }
            Vec3<T> at = light.position;
            if (size1 > 1) at += axis1 * (ju / T(size1 - 1) - T(0.5));
            if (size2 > 1) at += axis2 * (jv / T(size2 - 1) - T(0.5));
            grid.value[k] = through(at);
            grid.traced.set(k);
        }
        return grid.value[k];
    }

    /// The mean over the region [u1, u2] x [v1, v2], as POV-Ray takes it.
    template <class Through>
    [[nodiscard]] Rgb<T> region(Grid& grid, Through&& through, const Rgb<T>& colour, Random* rng, int u1, int v1, int u2, int v2, int level) const noexcept
    {
        const Rgb<T> corner[4] = {point(grid, through, rng, u1, v1), point(grid, through, rng, u2, v1), point(grid, through, rng, u1, v2),
                                  point(grid, through, rng, u2, v2)};
        if (u2 - u1 <= 1 && v2 - v1 <= 1) return (corner[0] + corner[1] + corner[2] + corner[3]) * T(0.25);
        const T a = distance(colour * corner[0], colour * corner[1]), b = distance(colour * corner[1], colour * corner[3]);
        const T c = distance(colour * corner[3], colour * corner[2]), d = distance(colour * corner[2], colour * corner[0]);
        if (level >= adaptive && a <= T(0.1) && b <= T(0.1) && c <= T(0.1) && d <= T(0.1)) return (corner[0] + corner[1] + corner[2] + corner[3]) * T(0.25);
        // Split at the middle: a middle line shared by both halves when the count between
        // is even (floor and ceil of the midpoint), neighbouring lines when it is odd.
        const int ul = (u1 + u2) / 2, uh = (u1 + u2 + 1) / 2, vl = (v1 + v2) / 2, vh = (v1 + v2 + 1) / 2;
        return (region(grid, through, colour, rng, u1, v1, ul, vl, level + 1) + region(grid, through, colour, rng, uh, v1, u2, vl, level + 1) +
                region(grid, through, colour, rng, u1, vh, ul, v2, level + 1) + region(grid, through, colour, rng, uh, vh, u2, v2, level + 1)) *
               T(0.25);
    }
};

static_assert(Light<PointGridLight<float>>);

} // namespace prism
