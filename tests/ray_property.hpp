// SPDX-License-Identifier: MIT
// The ray property test: random rays, many of them hostile, fired at every kind of shape
// placed near and far, checking that a scene's two-query closest hit agrees with the
// shape's own crossings, that nothing is NaN or Inf, that a ray spawned from the hit
// starts on the side it leaves by, and that a convex shape never shadows a ray leaving
// its outside. Shared by the test suite (a fast slice) and bench/ray_property.cpp (the
// full run, >= 10^7 rays).
#pragma once

#include <prism/prism.hpp>

#include "through_memory.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace test::property {

using prism::Random;
using prism::Vec3;

/// What went wrong, counted over a batch of rays.
struct Counts {
    std::uint64_t rays = 0;
    std::uint64_t hits = 0;            ///< rays the shape's own query says cross it
    std::uint64_t lost = 0;            ///< ... and the scene's closest hit misses
    std::uint64_t disagree = 0;        ///< the scene's hit is not the shape's first crossing (t or point differ), or a hit the shape lacks
    std::uint64_t non_finite = 0;      ///< a crossing with a NaN or infinite field
    std::uint64_t wrong_side = 0;      ///< a ray spawned from the hit starts on the wrong side (its own query says so)
    std::uint64_t spawn_checks = 0;
    std::uint64_t ambiguous = 0;       ///< spawns not checked: at an edge, across a part thinner than 64 error bounds, or tangent
    std::uint64_t false_occlusion = 0; ///< a convex shape blocks a shadow ray leaving its outside
    std::uint64_t occlusion_checks = 0;
    std::uint64_t clear_hits = 0;      ///< float only: the double twin crosses at |cos| > 0.2
    std::uint64_t missed = 0;          ///< ... and the float scene misses

    Counts& operator+=(const Counts& o)
    {
        rays += o.rays, hits += o.hits, lost += o.lost, disagree += o.disagree, non_finite += o.non_finite;
        wrong_side += o.wrong_side, spawn_checks += o.spawn_checks, ambiguous += o.ambiguous, false_occlusion += o.false_occlusion;
        occlusion_checks += o.occlusion_checks, clear_hits += o.clear_hits, missed += o.missed;
        return *this;
    }
    [[nodiscard]] std::uint64_t failures() const { return lost + disagree + non_finite + wrong_side + false_occlusion; }
};

/// Where and how large a shape is, and the random numbers that shape it (drawn once in
/// double, so float and double twins are the same shape up to rounding).
struct Placement {
    Vec3<double> centre{};
    double size = 1;
    std::array<double, 8> u{};
    Vec3<double> axis{0, 0, 1};
};

template <prism::Scalar T>
Vec3<T> cast(const Vec3<double>& v)
{
    return Vec3<T>(T(v.x), T(v.y), T(v.z));
}

inline Vec3<double> unit_direction(Random& rng)
{
    const double z = 1 - 2 * rng.uniform<double>();
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = 2 * prism::pi<double> * rng.uniform<double>();
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// The shapes. Each case makes its shape in either precision from a Placement; `convex`
// says whether a ray leaving its outside can never meet it again.

struct SphereCase {
    static constexpr const char* name = "Sphere";
    static constexpr bool convex = true;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        return prism::Sphere<T>(cast<T>(p.centre), T(p.size));
    }
};

struct BoxCase {
    static constexpr const char* name = "Box";
    static constexpr bool convex = true;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        const Vec3<double> half = p.size * Vec3<double>(0.4 + 0.6 * p.u[0], 0.4 + 0.6 * p.u[1], 0.4 + 0.6 * p.u[2]);
        return prism::Box<T>(cast<T>(p.centre - half), cast<T>(p.centre + half));
    }
};

struct PlaneCase {
    static constexpr const char* name = "Plane";
    static constexpr bool convex = true;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        return prism::Plane<T>::through(cast<T>(p.centre), cast<T>(p.axis));
    }
};

struct EllipsoidCase {
    static constexpr const char* name = "Quadric ellipsoid";
    static constexpr bool convex = true;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        const Vec3<double> semi = p.size * Vec3<double>(0.4 + 0.6 * p.u[0], 0.4 + 0.6 * p.u[1], 0.4 + 0.6 * p.u[2]);
        const auto rotation = prism::Transform<double>::rotate(360 * p.u[3], p.axis).matrix();
        return prism::Quadric<T>::ellipsoid(cast<T>(p.centre), cast<T>(semi), prism::Mat3<T>(rotation));
    }
};

struct CylinderCase {
    static constexpr const char* name = "Quadric cylinder";
    static constexpr bool convex = false;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        return prism::Quadric<T>::cylinder(cast<T>(p.centre), cast<T>(p.axis), T(p.size * (0.3 + 0.7 * p.u[0])));
    }
};

struct ConeCase {
    static constexpr const char* name = "Quadric cone";
    static constexpr bool convex = false;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        return prism::Quadric<T>::cone(cast<T>(p.centre), cast<T>(p.axis), T(15 + 60 * p.u[0]));
    }
};

struct TransformedSphereCase {
    static constexpr const char* name = "Transformed<Sphere>";
    static constexpr bool convex = true;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        using X = prism::Transform<T>;
        const Vec3<double> scale = p.size * Vec3<double>(0.4 + 0.6 * p.u[0], 0.4 + 0.6 * p.u[1], 0.4 + 0.6 * p.u[2]);
        return prism::Transformed(prism::Sphere<T>({T(0), T(0), T(0)}, T(1)),
                                  X::scale(cast<T>(scale)).then(X::rotate(T(360 * p.u[3]), cast<T>(p.axis))).then(X::translate(cast<T>(p.centre))));
    }
};

struct TransformedQuadricCase {
    static constexpr const char* name = "Transformed<Quadric>";
    static constexpr bool convex = true;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        using X = prism::Transform<T>;
        const auto ball = prism::Quadric<T>::ellipsoid({T(0), T(0), T(0)}, {T(1), T(0.6), T(0.8)});
        return prism::Transformed(ball, X::scale(Vec3<T>(T(p.size))).then(X::rotate(T(360 * p.u[3]), cast<T>(p.axis))).then(X::translate(cast<T>(p.centre))));
    }
};

/// The bead of csg_quadrics: a ball bored by a quadric cylinder.
struct BeadCase {
    static constexpr const char* name = "Difference<Sphere, cylinder>";
    static constexpr bool convex = false;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        return prism::difference_of(prism::Sphere<T>(cast<T>(p.centre), T(p.size)),
                                    prism::Quadric<T>::cylinder(cast<T>(p.centre), cast<T>(p.axis), T(p.size * (0.2 + 0.5 * p.u[0]))));
    }
};

/// A lens: the intersection of two balls.
struct LensCase {
    static constexpr const char* name = "Intersection<Sphere, Sphere>";
    static constexpr bool convex = true;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        const Vec3<double> shift = p.axis * (p.size * (0.3 + 0.6 * p.u[0]));
        return prism::intersection_of(prism::Sphere<T>(cast<T>(p.centre + shift), T(p.size)), prism::Sphere<T>(cast<T>(p.centre - shift), T(p.size)));
    }
};

/// A thin shell: a ball minus a ball 1 % smaller.
struct ShellCase {
    static constexpr const char* name = "thin shell (Sphere - Sphere)";
    static constexpr bool convex = false;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        return prism::difference_of(prism::Sphere<T>(cast<T>(p.centre), T(p.size)), prism::Sphere<T>(cast<T>(p.centre), T(p.size * 0.99)));
    }
};

/// A tree of depth three: (box - ellipsoid) + (ball & half-space) - cylinder.
struct TreeCase {
    static constexpr const char* name = "CSG tree";
    static constexpr bool convex = false;
    template <prism::Scalar T>
    static auto make(const Placement& p)
    {
        const Vec3<double> half = p.size * Vec3<double>(0.5 + 0.4 * p.u[0], 0.5 + 0.4 * p.u[1], 0.5 + 0.4 * p.u[2]);
        const Vec3<double> off = p.size * Vec3<double>(p.u[4] - 0.5, p.u[5] - 0.5, p.u[6] - 0.5);
        auto bitten = prism::difference_of(prism::Box<T>(cast<T>(p.centre - half), cast<T>(p.centre + half)),
                                           prism::Quadric<T>::ellipsoid(cast<T>(p.centre + half), cast<T>(half)));
        auto cap = prism::intersection_of(prism::Sphere<T>(cast<T>(p.centre + off), T(p.size * 0.8)),
                                          prism::Plane<T>::through(cast<T>(p.centre + off), cast<T>(p.axis)));
        return prism::difference_of(prism::union_of(std::move(bitten), std::move(cap)),
                                    prism::Quadric<T>::cylinder(cast<T>(p.centre), cast<T>(Vec3<double>(p.axis.y, -p.axis.x, p.axis.z)),
                                                                T(p.size * 0.15)));
    }
};

/// The kinds of ray fired, in turn.
enum class RayKind { aimed, grazing, axis_aligned, denormal, signed_zero, long_or_short, count };

inline const char* kind_name(RayKind kind)
{
    constexpr const char* names[] = {"aimed", "grazing", "axis-aligned", "denormal", "signed-zero", "length 2^+-30"};
    return names[static_cast<int>(kind)];
}

/// Fire `rays` rays of every kind at the shape of Case placed by `placement`, from
/// origins `distance` away from it. Float shapes are also compared with their double twin.
template <class Case, prism::Scalar T>
Counts fire(const Placement& placement, double distance, std::uint64_t seed, std::size_t rays)
{
    using namespace prism;
    const auto shape = Case::template make<T>(placement);
    const auto twin = Case::template make<double>(placement);
    const Scene scene{Lights{PointLight<T>{.position = cast<T>(placement.centre + Vec3<double>(0, 3 * placement.size + distance, 0))}},
                      Object{shape, Diffuse<T>{}}};
    Random rng(seed, 0x9e3779b97f4a7c15ULL);
    Counts counts;
    const auto finite = [](const Crossing<T>& c) {
        return is_finite(c.t) && is_finite(c.point) && is_finite(c.error) && is_finite(c.normal);
    };
    for (std::size_t i = 0; i < rays; ++i) {
        const auto kind = static_cast<RayKind>(i % static_cast<std::size_t>(RayKind::count));
        // A target near the shape, and a direction toward it from `distance` away.
        Vec3<double> target = placement.centre + placement.size * 1.2 * unit_direction(rng) * std::cbrt(rng.uniform<double>());
        Vec3<double> dir = unit_direction(rng);
        if (kind == RayKind::grazing) {
            // Along the tangent plane of a point on the surface.
            // Aimed off the centre, which is a cone's apex.
            const Vec3<double> aim = placement.centre + 0.3 * placement.size * unit_direction(rng);
            const auto c = twin.crossings({aim - 3 * placement.size * dir, dir}, Interval<double>::universe());
            if (!c.empty()) {
                const auto& first = c.front();
                target = first.point;
                dir = normalize(cross(first.normal, unit_direction(rng)));
            }
        }
        if (kind == RayKind::axis_aligned) {
            const int axis = static_cast<int>(rng.uniform<double>() * 3) % 3;
            const double sign = dir[axis] < 0 ? -1 : 1;
            dir = Vec3<double>(0);
            dir[axis] = sign;
        }
        Ray<T> ray{cast<T>(target - distance * dir), cast<T>(dir)};
        if (kind == RayKind::denormal || kind == RayKind::signed_zero) {
            // The smallest component (or two) becomes a denormal or a signed zero.
            int a = 0;
            for (int k = 1; k < 3; ++k)
                if (std::abs(dir[k]) < std::abs(dir[a])) a = k;
            const T tiny = kind == RayKind::denormal ? std::numeric_limits<T>::denorm_min() * T(1 + (i % 7)) : T(0);
            ray.direction[a] = dir[a] < 0 ? -tiny : tiny;
            if (i % 3 == 0) ray.direction[(a + 1) % 3] = dir[(a + 1) % 3] < 0 ? -tiny : tiny;
            ray.origin = cast<T>(target) - T(distance) * ray.direction / length(ray.direction);
        }
        if (kind == RayKind::long_or_short) ray.direction *= std::ldexp(T(1), static_cast<int>(rng.uniform<double>() * 61) - 30);
        test::through_memory(ray); // the twin sees the float ray's own bits

        if (length_squared(Vec3<double>(ray.direction)) == 0) continue;
        ++counts.rays;

        const auto own = shape.crossings(ray, {T(0), infinity<T>});
        const auto hit = scene.closest_hit(ray, {T(0), infinity<T>});
        bool bad = false;
        for (const Crossing<T>& c : own) bad |= !finite(c);
        if (hit) bad |= !finite(hit->crossing);
        counts.non_finite += bad;

        if constexpr (std::is_same_v<T, float>) if (kind != RayKind::grazing) {
            // Against the double twin on the same (exactly converted) ray: a clear hit is
            // one the ray meets at more than a grazing angle, away from the surface's edges.
            const Ray<double> wide{Vec3<double>(ray.origin), Vec3<double>(ray.direction)};
            const auto exact = twin.crossings(wide, {0.0, infinity<double>});
            if (!exact.empty()) {
                const auto& e = exact.front();
                const double cos = std::abs(dot(normalize(wide.direction), e.normal));
                const bool alone = exact.size() < 2 || (exact[1].t - e.t) * length(wide.direction) > 0.05 * placement.size;
                if (cos > 0.2 && alone && twin.contains(e.point + 0.01 * placement.size * normalize(wide.direction)) == e.entering) {
                    ++counts.clear_hits;
                    counts.missed += !hit;
                }
            }
        }

        if (own.empty()) {
            counts.disagree += hit.has_value();
            continue;
        }
        ++counts.hits;
        if (!hit) {
            ++counts.lost;
            continue;
        }
        const Crossing<T>& c = hit->crossing;
        if (c.t != own.front().t || c.point != own.front().point) ++counts.disagree;

        // Rays spawned from the hit: on through the surface, and reflected back. Which
        // side is right is decided only where it can be: the double twin must see the
        // solid on one side and not the other, 128 error bounds away along the normal and
        // 64 to every side of that (not at an edge, nor across a part thinner than the
        // point's own uncertainty), and the direction must leave the surface at more
        // than a tangent.
        const Vec3<T> d = normalize(ray.direction);
        if (!is_finite(d) || bad) continue;
        const Vec3<T> facing = c.facing_normal();
        const Vec3<T> reflected = reflect(d, facing);
        const Vec3<double> p{c.point}, n{c.normal};
        const double delta = 64 * max_component(Vec3<double>(c.error)) + 1e-300;
        bool decidable = true;
        for (int e = 0; e < 7; ++e) {
            Vec3<double> aside(0);
            if (e < 6) aside[e % 3] = e < 3 ? delta : -delta;
            decidable &= twin.contains(p - 2 * delta * n + aside) && !twin.contains(p + 2 * delta * n + aside);
        }
        for (const Vec3<T>& w : {d, reflected}) {
            const T cos = dot(w, c.normal);
            // Nor where the line through the point along w meets another surface within
            // 4 of those bounds (the ray lies in a face of the solid).
            const auto near = twin.template crossings<false>({p - 4 * delta * Vec3<double>(w), Vec3<double>(w)}, {0.0, 8 * delta});
            if (!decidable || near.size() != 1 || !(std::abs(cos) > T(1e-3))) {
                ++counts.ambiguous;
                continue;
            }
            ++counts.spawn_checks;
            // The side a spawned ray starts on, as every later query of it sees it.
            const auto again = shape.template crossings<false>(spawn_ray(c.point, c.error, c.normal, w), {T(0), infinity<T>});
            counts.wrong_side += again.inside_at_start != (cos < T(0));
        }
        if constexpr (Case::convex) {
            // Leaving the outside of a convex solid, nothing of it lies ahead.
            const Vec3<T> outward = c.entering ? reflected : d;
            if (!decidable || !(dot(outward, c.normal) > T(1e-3))) continue; // far off, the hit's side may be a guess
            ++counts.occlusion_checks;
            counts.false_occlusion += scene.transmittance(spawn_ray(c.point, c.error, c.normal, outward), infinity<T>) != Rgb<T>(T(1));
        }
    }
    return counts;
}

/// A placement `distance` from the world origin (0: at it), of the given size.
inline Placement place(Random& rng, double distance, double size)
{
    Placement p;
    p.centre = distance * unit_direction(rng);
    p.size = size;
    for (double& x : p.u) x = rng.uniform<double>();
    p.axis = unit_direction(rng);
    return p;
}

/// Every case in one list, for loops over them.
template <class F>
void for_each_case(F&& f)
{
    f.template operator()<SphereCase>();
    f.template operator()<BoxCase>();
    f.template operator()<PlaneCase>();
    f.template operator()<EllipsoidCase>();
    f.template operator()<CylinderCase>();
    f.template operator()<ConeCase>();
    f.template operator()<TransformedSphereCase>();
    f.template operator()<TransformedQuadricCase>();
    f.template operator()<BeadCase>();
    f.template operator()<LensCase>();
    f.template operator()<ShellCase>();
    f.template operator()<TreeCase>();
}

} // namespace test::property
