// SPDX-License-Identifier: MIT
// Crossings: every place a ray crosses a solid's boundary, sorted, in fixed capacity.
//
// This is the currency of prism's geometry. A shape reports all its boundary
// crossings inside a parameter range, together with whether the range starts inside
// the solid; CSG combines two such lists into a third (Roth 1982). The capacity N is
// known at compile time (a sphere crosses at most twice), so nothing is allocated.
#pragma once

#include <prism/core/config.hpp>
#include <prism/core/math.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace prism {

/// One boundary crossing of a ray with a solid. Queries without the surface fill in
/// only t and entering. No member has a default value: a Crossings list leaves the slots
/// it does not use unwritten (every query would otherwise clear them all); `Crossing<T>{}`
/// is all zeros.
template <Scalar T>
struct Crossing {
    T t;           ///< ray parameter
    Vec3<T> point; ///< the crossing point, refined onto the surface
    Vec3<T> error; ///< absolute error bound of `point`, per axis
    Vec3<T> normal; ///< unit outward normal (the gradient of the inside function)
    bool entering; ///< the ray goes from outside to inside here (gradient . direction < 0)
    std::uint32_t path; ///< in a CSG tree, which child it came from at each node, innermost highest (CsgNode::coordinates reads it)
    Vec3<T> shading; ///< unit outward shading normal: a mesh's interpolated vertex normal, else `normal`
    // Surface coordinates (docs/guide.md, "Surface coordinates"): a mesh's come with its
    // crossings; every other shape's are added by add_coordinates (geometry/shape.hpp),
    // which the scene calls only for a material that reads them. Zero until then, and on a
    // shape without them.
    Vec2<T> uv;      ///< surface coordinates (u, v)
    Vec3<T> dpdu;    ///< how the point moves with u, dp/du
    Vec3<T> dpdv;    ///< how the point moves with v, dp/dv
    T footprint;     ///< the width of the ray's footprint here, across the surface (scene queries set it: Ray::width); 0 for a point

    /// A crossing of a surface without vertex normals or coordinates: it shades with
    /// its true normal.
    [[nodiscard]] static constexpr Crossing flat(T t, const Vec3<T>& point, const Vec3<T>& error, const Vec3<T>& normal, bool entering) noexcept
    {
        return {t, point, error, normal, entering, 0, normal, Vec2<T>(T(0)), Vec3<T>(T(0)), Vec3<T>(T(0)), T(0)};
    }

    /// This crossing with surface coordinates uv and their derivatives.
    [[nodiscard]] constexpr Crossing with_uv(const Vec2<T>& coordinates, const Vec3<T>& dp_du, const Vec3<T>& dp_dv) const noexcept
    {
        Crossing c = *this;
        c.uv = coordinates;
        c.dpdu = dp_du;
        c.dpdv = dp_dv;
        return c;
    }

    /// Whether the shape gave surface coordinates here (dp/du and dp/dv not both zero).
    [[nodiscard]] constexpr bool has_uv() const noexcept { return dpdu != Vec3<T>(T(0)) || dpdv != Vec3<T>(T(0)); }

    /// The unit normal on the side the ray arrives from (outward when it enters).
    [[nodiscard]] constexpr Vec3<T> facing_normal() const noexcept { return entering ? normal : -normal; }

    /// The unit shading normal, turned to the side the ray arrives from as `normal` is
    /// (it may still lean away from the ray: see material/scattering.hpp).
    [[nodiscard]] constexpr Vec3<T> facing_shading() const noexcept { return entering ? shading : -shading; }

    /// Whether the shading normal is the true one (every shape but a mesh with vertex normals).
    [[nodiscard]] constexpr bool shades_flat() const noexcept { return shading == normal; }

    /// A crossing without its surface: point, error and normal are left unwritten (zeros
    /// in a constant expression), for the queries that never read them.
    [[nodiscard]] static constexpr Crossing without_surface(T t, bool entering) noexcept
    {
        Crossing c;
        if (std::is_constant_evaluated()) c = {};
        c.t = t;
        c.entering = entering;
        return c;
    }
};

namespace detail {

/// The directions of u and v on a flat face with unit normal n (planes, a box's faces):
/// u runs along cross(up, n) and v along cross(n, u), with up +y, or -z for a face that
/// looks up or down. So (u, v, n) is right-handed: a picture reads the right way round
/// seen from the side n points to; on a wall u runs to the viewer's right and v up, and
/// on a floor (n = +y) u runs along +x and v along -z.
template <Scalar T>
[[nodiscard]] constexpr std::pair<Vec3<T>, Vec3<T>> face_axes(const Vec3<T>& n) noexcept
{
    const Vec3<T> up = std::abs(n.y) > T(0.999) ? Vec3<T>(T(0), T(0), T(-1)) : Vec3<T>(T(0), T(1), T(0));
    const Vec3<T> u = normalize(cross(up, n));
    return {u, cross(n, u)};
}

} // namespace detail

/// The sorted boundary crossings of a ray within a range, at most N of them.
template <Scalar T, std::size_t N>
struct Crossings {
    /// The most crossings the list can hold.
    static constexpr std::size_t capacity = N;

    std::array<Crossing<T>, N> items; ///< the first `count` are set; the rest are unwritten (zeros in a constant expression)
    std::size_t count = 0; ///< how many crossings are set
    bool inside_at_start = false; ///< the ray is inside the solid at the start of the range

    constexpr Crossings() noexcept
    {
        // A constant expression may not hold unwritten values; at run time the unused
        // slots are never read, and clearing them cost 3 % of a CSG scene's render.
        if (std::is_constant_evaluated()) items = {};
    }

    /// The number of crossings.
    [[nodiscard]] constexpr std::size_t size() const noexcept { return count; }
    /// Whether the ray crosses no boundary in the range.
    [[nodiscard]] constexpr bool empty() const noexcept { return count == 0; }
    /// The i-th crossing, nearest first.
    [[nodiscard]] constexpr const Crossing<T>& operator[](std::size_t i) const noexcept { return items[i]; }
    /// The nearest crossing; only when not empty().
    [[nodiscard]] constexpr const Crossing<T>& front() const noexcept { return items[0]; }
    /// The nearest crossing.
    [[nodiscard]] constexpr const Crossing<T>* begin() const noexcept { return items.data(); }
    /// One past the farthest crossing.
    [[nodiscard]] constexpr const Crossing<T>* end() const noexcept { return items.data() + count; }

    /// Append a crossing at or after the last one.
    constexpr void push_back(const Crossing<T>& c) noexcept
    {
        PRISM_ASSERT(count < N);
        PRISM_ASSERT(count == 0 || items[count - 1].t <= c.t);
        items[count++] = c;
    }
};

} // namespace prism
