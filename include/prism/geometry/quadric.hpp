// SPDX-License-Identifier: MIT
// Quadric: the solid F(p) < 0 of a general second-degree surface.
//
//   F(p) = a x^2 + 2b xy + 2c xz + 2d x + e y^2 + 2f yz + 2g y + h z^2 + 2i z + j
//
// (the factors of 2 keep Q below symmetric; the form of Hanrahan 1983, "Ray tracing
// algebraic surfaces", SIGGRAPH), or
// F(p) = [p 1] Q [p 1]^T with the symmetric matrix Q = [[a b c d] [b e f g] [c f h i] [d g i j]].
// Cones, cylinders and hyperboloids are not convex and most quadrics are unbounded:
// the crossings are classified by the sign of the gradient along the ray, never by the
// order of the roots; a ray along an asymptotic direction (a cylinder's axis, a cone's
// generator) meets the surface once or not at all.
//
// A quadric keeps a local origin o and its coefficients relative to it: F(p) = G(p - o).
// An ellipsoid 10^5 from the world origin written in world coefficients has j ~ 10^10,
// and float then loses its surface entirely; centred on its own origin it is as exact
// as one at the world origin. The factories that take a centre use it as the origin.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/transform.hpp>
#include <prism/geometry/shape.hpp>

#include <algorithm>
#include <array>
#include <limits>

namespace prism {

/// The solid F(p) < 0 of a general second-degree surface, with stable roots and named factories.
template <Scalar T = float>
class Quadric {
public:
    /// The precision of the coefficients and the crossings.
    using scalar_type = T;
    /// At most two crossings: the equation along a ray is of degree 2.
    static constexpr std::size_t max_crossings = 2;

    /// The ten coefficients of the form above (note the factors of 2 on mixed and linear terms).
    struct Coefficients {
        T a = 0; ///< the a of a x^2
        T b = 0; ///< the b of 2b xy
        T c = 0; ///< the c of 2c xz
        T d = 0; ///< the d of 2d x
        T e = 0; ///< the e of e y^2
        T f = 0; ///< the f of 2f yz
        T g = 0; ///< the g of 2g y
        T h = 0; ///< the h of h z^2
        T i = 0; ///< the i of 2i z
        T j = 0; ///< the constant term
    };

    // Quadric Public Methods

    /// Throws std::invalid_argument for a non-finite coefficient, an all-zero quadric,
    /// or one with no x, y or z term (a constant is not a surface).
    constexpr explicit Quadric(const Coefficients& k, const Vec3<T>& origin = Vec3<T>(T(0))) : k_(k), given_(k), origin_(origin)
    {
        detail::require_finite("Quadric origin", origin);
        const std::array<T, 10> all{k.a, k.b, k.c, k.d, k.e, k.f, k.g, k.h, k.i, k.j};
        constexpr const char* names[10] = {"a", "b", "c", "d", "e", "f", "g", "h", "i", "j"};
        for (int n = 0; n < 10; ++n)
            if (!is_finite(all[n])) detail::throw_invalid("Quadric coefficient ", names[n], " must be finite, got ", all[n]);
        const bool variable = k.a != 0 || k.b != 0 || k.c != 0 || k.d != 0 || k.e != 0 || k.f != 0 || k.g != 0 || k.h != 0 || k.i != 0;
        if (!variable && k.j == 0) detail::throw_invalid("Quadric coefficients are all zero");
        if (!variable) detail::throw_invalid("Quadric has no x, y or z term (only the constant ", k.j, ")");
        normalise();
        // The quadric's own size, squared: |j| over its largest quadratic coefficient
        // (0 for a cone, whose apex has no size).
        const T quadratic = std::max({k_.a < T(0) ? -k_.a : k_.a, k_.e < T(0) ? -k_.e : k_.e, k_.h < T(0) ? -k_.h : k_.h});
        near2_ = quadratic > T(0) ? T(64) * (k_.j < T(0) ? -k_.j : k_.j) / quadratic : T(0);
        bounds_ = ellipsoid_bounds();
        bounded_ = bounds_.bounded();
    }

    /// From a 4x4 matrix Q with F(p) = [p 1] Q [p 1]^T; only its symmetric part matters.
    [[nodiscard]] static Quadric from_matrix(const Mat4<T>& q)
    {
        const auto s = [&q](int r, int c) { return T(0.5) * (q[c][r] + q[r][c]); };
        return Quadric({s(0, 0), s(0, 1), s(0, 2), s(0, 3), s(1, 1), s(1, 2), s(1, 3), s(2, 2), s(2, 3), s(3, 3)});
    }

    /// From POV-Ray's quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }:
    /// A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J (same coordinates).
    [[nodiscard]] static constexpr Quadric from_povray(T A, T B, T C, T D, T E, T F, T G, T H, T I, T J)
    {
        return Quadric({A, D / 2, E / 2, G / 2, B, F / 2, H / 2, C, I / 2, J});
    }

    // Named quadrics (inside is F < 0)

    /// The ellipsoid with the given centre and semi-axes, rotated by `rotation` (its
    /// columns are the directions of the x, y and z semi-axes).
    [[nodiscard]] static Quadric ellipsoid(const Vec3<T>& centre, const Vec3<T>& semi_axes, const Mat3<T>& rotation = Mat3<T>(T(1)))
    {
        detail::require_finite("Quadric::ellipsoid centre", centre);
        detail::require_length("Quadric::ellipsoid semi_axes.x", semi_axes.x);
        detail::require_length("Quadric::ellipsoid semi_axes.y", semi_axes.y);
        detail::require_length("Quadric::ellipsoid semi_axes.z", semi_axes.z);
        const Vec3<T> inv2 = T(1) / (semi_axes * semi_axes);
        const Mat3<T> m = rotation * Mat3<T>(inv2.x, 0, 0, 0, inv2.y, 0, 0, 0, inv2.z) * glm::transpose(rotation);
        return centred(m, centre, T(-1));
    }

    /// The infinite circular cylinder of `radius` around the line through `point` along `axis`.
    [[nodiscard]] static Quadric cylinder(const Vec3<T>& point, const Vec3<T>& axis, T radius)
    {
        detail::require_finite("Quadric::cylinder point", point);
        detail::require_nonzero("Quadric::cylinder axis", axis);
        detail::require_length("Quadric::cylinder radius", radius);
        const Vec3<T> u = normalize(axis);
        return centred(Mat3<T>(T(1)) - glm::outerProduct(u, u), point, -radius * radius);
    }

    /// The double cone with its apex at `apex`, opening along +-axis with the given half angle.
    [[nodiscard]] static Quadric cone(const Vec3<T>& apex, const Vec3<T>& axis, T half_angle_degrees)
    {
        detail::require_finite("Quadric::cone apex", apex);
        detail::require_nonzero("Quadric::cone axis", axis);
        if (!(half_angle_degrees > T(0) && half_angle_degrees < T(90)))
            detail::throw_invalid("Quadric::cone half_angle_degrees must be in (0, 90), got ", half_angle_degrees);
        const Vec3<T> u = normalize(axis);
        const T cos = std::cos(half_angle_degrees * pi<T> / T(180));
        return centred(cos * cos * Mat3<T>(T(1)) - glm::outerProduct(u, u), apex, T(0));
    }

    /// z = x^2/a^2 + y^2/b^2: a bowl opening along +z; inside is above it.
    [[nodiscard]] static Quadric elliptic_paraboloid(T a, T b)
    {
        detail::require_positive("Quadric::elliptic_paraboloid a", a);
        detail::require_positive("Quadric::elliptic_paraboloid b", b);
        return Quadric({.a = 1 / (a * a), .e = 1 / (b * b), .i = T(-0.5)});
    }

    /// z = x^2/a^2 - y^2/b^2: a saddle; inside is above it.
    [[nodiscard]] static Quadric hyperbolic_paraboloid(T a, T b)
    {
        detail::require_positive("Quadric::hyperbolic_paraboloid a", a);
        detail::require_positive("Quadric::hyperbolic_paraboloid b", b);
        return Quadric({.a = 1 / (a * a), .e = -1 / (b * b), .i = T(-0.5)});
    }

    /// x^2/a^2 + y^2/b^2 - z^2/c^2 = 1: one sheet around the z axis; inside is the waisted tube.
    [[nodiscard]] static Quadric hyperboloid_one_sheet(T a, T b, T c)
    {
        detail::require_positive("Quadric::hyperboloid_one_sheet a", a);
        detail::require_positive("Quadric::hyperboloid_one_sheet b", b);
        detail::require_positive("Quadric::hyperboloid_one_sheet c", c);
        return Quadric({.a = 1 / (a * a), .e = 1 / (b * b), .h = -1 / (c * c), .j = T(-1)});
    }

    /// z^2/c^2 - x^2/a^2 - y^2/b^2 = 1: two sheets opening along +-z; inside is the two cups.
    [[nodiscard]] static Quadric hyperboloid_two_sheets(T a, T b, T c)
    {
        detail::require_positive("Quadric::hyperboloid_two_sheets a", a);
        detail::require_positive("Quadric::hyperboloid_two_sheets b", b);
        detail::require_positive("Quadric::hyperboloid_two_sheets c", c);
        return Quadric({.a = 1 / (a * a), .e = 1 / (b * b), .h = -1 / (c * c), .j = T(1)});
    }

    /// Two planes, (n1.p - d1)(n2.p - d2) = 0: inside where p is on the inner side of
    /// exactly one of them (between two parallel planes, or in two opposite wedges).
    [[nodiscard]] static Quadric plane_pair(const Vec3<T>& n1, T d1, const Vec3<T>& n2, T d2)
    {
        detail::require_nonzero("Quadric::plane_pair n1", n1);
        detail::require_nonzero("Quadric::plane_pair n2", n2);
        detail::require_finite("Quadric::plane_pair d1", d1);
        detail::require_finite("Quadric::plane_pair d2", d2);
        const Mat3<T> m = T(0.5) * (glm::outerProduct(n1, n2) + glm::outerProduct(n2, n1));
        const Vec3<T> q = T(-0.5) * (d2 * n1 + d1 * n2);
        return from_parts(m, q, d1 * d2);
    }

    /// The same surface moved by `transform`: F'(p) = F(transform^-1 p). The origin
    /// moves with the transform and the coefficients take only its linear part L:
    /// Q3' = L^-T Q3 L^-1, q' = L^-T q.
    [[nodiscard]] Quadric transformed(const Transform<T>& transform) const
    {
        Mat4<T> inv = transform.inverse_matrix();
        inv[3] = glm::vec<4, T>(T(0), T(0), T(0), T(1));
        const Mat4<T> local = glm::transpose(inv) * local_matrix() * inv;
        return Quadric(from_matrix(local).k_, transform.point(origin_));
    }

    /// The coefficients as given, relative to origin(). (Crossings are computed from a
    /// copy scaled by a power of two so that the largest is in [1, 2): the same surface.)
    [[nodiscard]] constexpr const Coefficients& coefficients() const noexcept { return given_; }
    /// The point the coefficients are relative to (their own origin, for precision far from the world's).
    [[nodiscard]] constexpr const Vec3<T>& origin() const noexcept { return origin_; }

    /// Q in world coordinates (computed in T, so rounded for a far-away origin).
    [[nodiscard]] Mat4<T> matrix() const noexcept
    {
        const Mat4<T> to_local = glm::translate(Mat4<T>(T(1)), -origin_);
        return glm::transpose(to_local) * local_matrix() * to_local;
    }

    /// F(p), with the coefficients as given.
    [[nodiscard]] constexpr T evaluate(const Vec3<T>& p) const noexcept
    {
        const Vec3<T> v = p - origin_;
        return dot(v, times_q3(given_, v) + T(2) * Vec3<T>(given_.d, given_.g, given_.i)) + given_.j;
    }

    /// The gradient of F, 2 (Q3 (p - o) + q): the outward normal direction.
    [[nodiscard]] constexpr Vec3<T> gradient(const Vec3<T>& p) const noexcept
    {
        return T(2) * (times_q3(given_, p - origin_) + Vec3<T>(given_.d, given_.g, given_.i));
    }

    /// Whether p is inside: F(p) < 0.
    [[nodiscard]] constexpr bool contains(const Vec3<T>& p) const noexcept { return evaluate_local(p - origin_) < T(0); }

    /// An ellipsoid's box; Aabb::universe() for unbounded quadrics.
    [[nodiscard]] constexpr Aabb<T> bounds() const noexcept { return bounds_; }
    /// Convex where it is bounded: a bounded inside is an ellipsoid's. (A paraboloid's or a
    /// cylinder's inside is convex too, but is not said to be: only what is certain.)
    [[nodiscard]] constexpr bool convex() const noexcept { return bounded_; }

    /// Every crossing of `ray` within `range`, sorted, each entering or leaving by the sign of the gradient along the ray.
    template <bool Surface = true>
    [[nodiscard]] constexpr Crossings<T, 2> crossings(const Ray<T>& ray, Interval<T> range) const noexcept
    {
        // An ellipsoid: a ray that cannot come near its box cannot cross it.
        if (bounded_ && !bounds_.reached_after(ray, range.min)) return {};
        // Compute quadratic coefficients: F(o + t d) = A t^2 + 2 B t + C (h multiplies dz^2),
        // in the quadric's own coordinates.
        const Vec3<T> o = ray.origin - origin_;
        const Vec3<T>& d = ray.direction;
        const Vec3<T> g_o = half_gradient(o);
        const T A = dot(d, quadratic_part(d));
        const T B = dot(d, g_o);
        const T C = dot(o, g_o + linear()) + k_.j;

        // The discriminant is the same for any point of the line taken as its origin, and
        // it is exact only near the quadric: from a far origin, C ~ |o|^2 carries a
        // rounding far larger than B^2 - A C near a hit (a unit ellipsoid seen from 10^4
        // would lose almost every hit). So it is computed from the ray's closest approach
        // to the quadric's origin, m = o + t_m d, where the coefficients are of the
        // quadric's own size, and the surface points are found from there too.
        // (An origin within 8 of the quadric's own sizes of its origin stays: nothing to gain.)
        // A float quadric finds m and decides the discriminant's sign in double, where a
        // float's differences and products are exact: in float, m alone is off the line
        // by an ulp of the distance, and F(m) by float's rounding of the quadric's own
        // scale, so rays within 10^-3 (then 10^-7) of the rim were lost or gained.
        using W = std::conditional_t<(sizeof(T) < sizeof(double)), double, T>;
        T t_m = T(0);
        if (dot(o, o) > near2_) {
            t_m = -dot(o, d) / dot(d, d);
            if (!is_finite(t_m)) t_m = T(0);
        }
        const Vec3<W> d_w(d);
        const Vec3<W> m_w = Vec3<W>(ray.origin) - Vec3<W>(origin_) + W(t_m) * d_w;
        const Coefficients& k = k_;
        const auto q3 = [&k](const Vec3<W>& v) {
            return Vec3<W>(W(k.a) * v.x + W(k.b) * v.y + W(k.c) * v.z, W(k.b) * v.x + W(k.e) * v.y + W(k.f) * v.z,
                           W(k.c) * v.x + W(k.f) * v.y + W(k.h) * v.z);
        };
        const Vec3<W> linear_w(W(k.d), W(k.g), W(k.i));
        const Vec3<W> g_m = q3(m_w) + linear_w;
        const W A_w = dot(d_w, q3(d_w)), B_w = dot(d_w, g_m), C_w = dot(m_w, g_m + linear_w) + W(k.j);
        const W disc_w = difference_of_products(B_w, B_w, A_w, C_w);
        const Vec3<T> m(m_w);
        const T B_m = T(B_w), C_m = T(C_w), disc = T(disc_w);

        Crossings<T, 2> out;
        // No real crossing (disc < 0) or a tangent (disc = 0, a double root): F keeps one
        // sign along the line, that of A (of C when F is constant along it).
        if (!(disc_w > W(0))) {
            out.inside_at_start = A != T(0) ? A < T(0) : C < T(0);
            return out;
        }

        // Stable roots from the ray's own origin (Press et al. 2007, "Numerical Recipes", 3rd edition, section 5.6): q = -(B + sign(B) sqrt(disc));
        // t = C / q and q / A, so a root near t = 0 (a ray leaving the surface) has the
        // sign of C = F(o), the same test that says which side the origin is on.
        // At a root F'(t) = 2(A t + B) = +-2 sqrt(disc): it is -2 sign(B) sqrt(disc) at
        // q / A and +2 sign(B) sqrt(disc) at C / q, so which root enters (F' < 0, the
        // gradient against the ray) follows from sign(B) exactly, for any sign of A.
        // When A = 0 (an asymptotic direction) q / A is infinite and C / q = -C / (2B)
        // is the one root of the linear equation.
        const T root = prism::sqrt(disc);
        const T q = B >= T(0) ? -(B + root) : -(B - root);
        std::array<Crossing<T>, 2> roots; // the first n are written
        if (std::is_constant_evaluated()) roots = {};
        std::size_t n = 0;
        roots[n++] = Crossing<T>::without_surface(C / q, B < T(0));
        const T far = q / A;
        if (is_finite(far)) roots[n++] = Crossing<T>::without_surface(far, B >= T(0));
        if (n == 2 && roots[1].t < roots[0].t) std::swap(roots[0], roots[1]);

        // Inside at range.min: the state after the last root before it, else before the first.
        out.inside_at_start = !roots[0].entering;
        for (std::size_t r = 0; r < n; ++r)
            if (roots[r].t <= range.min) out.inside_at_start = roots[r].entering;
        // A root is a crossing where it lies inside the range and float can hold its point
        // with room to spare (a ray nearly along an open quadric may meet it at t = 1e38,
        // whose point is infinite); the same test for both queries, so that they agree.
        const auto kept = [&](T t) { return range.surrounds(t) && is_finite(T(4) * (ray.origin + t * d)); };
        if constexpr (!Surface) {
            for (std::size_t r = 0; r < n; ++r)
                if (kept(roots[r].t)) out.push_back(roots[r]);
        } else {
            // The same roots measured from m: s = t - t_m, found as stably there, in the
            // same order (t grows with s).
            const T q_m = B_m >= T(0) ? -(B_m + root) : -(B_m - root);
            std::array<T, 2> s{C_m / q_m, q_m / A};
            if (s[1] < s[0]) std::swap(s[0], s[1]);
            for (std::size_t r = 0; r < n; ++r) {
                if (!kept(roots[r].t)) continue;
                // With one root (A = 0) only C_m / q_m is finite.
                T s_r = n == 1 ? C_m / q_m : s[r];
                if (!is_finite(s_r)) s_r = roots[r].t - t_m;
                // (From m, unless that overflows: s of a near-asymptotic direction can be
                // far larger than t, whose point float holds.)
                Vec3<T> local = m + s_r * d;
                if (!is_finite(local)) local = o + roots[r].t * d;
                out.push_back(surface_at(local, d, roots[r].t, roots[r].entering));
            }
        }
        return out;
    }

private:
    // Quadric Private Methods

    /// Scale every coefficient by one power of two (exactly) so that the largest is in
    /// [1, 2): the same surface, but A, B and C of a ray neither overflow nor vanish
    /// when the user's coefficients are as small as 1e-45 or as large as 1e30.
    constexpr void normalise() noexcept
    {
        T largest = T(0);
        for (const T x : {k_.a, k_.b, k_.c, k_.d, k_.e, k_.f, k_.g, k_.h, k_.i, k_.j}) largest = std::max(largest, x < T(0) ? -x : x);
        // By steps of 2, each exact, so that this stays a constant expression.
        const auto times = [this](T factor) {
            for (T* x : {&k_.a, &k_.b, &k_.c, &k_.d, &k_.e, &k_.f, &k_.g, &k_.h, &k_.i, &k_.j}) *x *= factor;
        };
        for (; largest >= T(2); largest *= T(0.5)) times(T(0.5));
        for (; largest < T(1); largest *= T(2)) times(T(2));
    }

    static Quadric from_parts(const Mat3<T>& m, const Vec3<T>& q, T j)
    {
        return Quadric({m[0][0], T(0.5) * (m[1][0] + m[0][1]), T(0.5) * (m[2][0] + m[0][2]), q.x, m[1][1],
                        T(0.5) * (m[2][1] + m[1][2]), q.y, m[2][2], q.z, j});
    }

    /// (p - c)^T M (p - c) + k: a quadric with its origin at c.
    static Quadric centred(const Mat3<T>& m, const Vec3<T>& c, T k) { return Quadric(from_parts(m, Vec3<T>(T(0)), k).k_, c); }

    [[nodiscard]] Mat4<T> local_matrix() const noexcept
    {
        const Coefficients& k = given_;
        return Mat4<T>(k.a, k.b, k.c, k.d, k.b, k.e, k.f, k.g, k.c, k.f, k.h, k.i, k.d, k.g, k.i, k.j);
    }

    [[nodiscard]] constexpr T evaluate_local(const Vec3<T>& p) const noexcept { return dot(p, half_gradient(p) + linear()) + k_.j; }

    [[nodiscard]] constexpr Vec3<T> linear() const noexcept { return {k_.d, k_.g, k_.i}; }

    /// Q3 v for the coefficients k: their quadratic part applied to a vector.
    [[nodiscard]] static constexpr Vec3<T> times_q3(const Coefficients& k, const Vec3<T>& v) noexcept
    {
        return {k.a * v.x + k.b * v.y + k.c * v.z, k.b * v.x + k.e * v.y + k.f * v.z, k.c * v.x + k.f * v.y + k.h * v.z};
    }

    /// Q3 v, the (normalised) quadratic part applied to a vector.
    [[nodiscard]] constexpr Vec3<T> quadratic_part(const Vec3<T>& v) const noexcept { return times_q3(k_, v); }

    [[nodiscard]] constexpr Vec3<T> half_gradient(const Vec3<T>& p) const noexcept { return quadratic_part(p) + linear(); }

    /// The sum of the magnitudes of F's terms at p: F(p) is computed to within gamma(n) of it.
    [[nodiscard]] constexpr T magnitude(const Vec3<T>& p) const noexcept
    {
        const Vec3<T> a = abs(p);
        const auto m = [](T x) { return x < T(0) ? -x : x; };
        return m(k_.a) * a.x * a.x + m(k_.e) * a.y * a.y + m(k_.h) * a.z * a.z +
               T(2) * (m(k_.b) * a.x * a.y + m(k_.c) * a.x * a.z + m(k_.f) * a.y * a.z + m(k_.d) * a.x + m(k_.g) * a.y + m(k_.i) * a.z) +
               m(k_.j);
    }

    /// The crossing at t of a ray with direction d, near the point p given in the
    /// quadric's own coordinates.
    [[nodiscard]] constexpr Crossing<T> surface_at(Vec3<T> point, const Vec3<T>& d, T t, bool entering) const noexcept
    {
        Vec3<T> g = half_gradient(point);
        const T gg = dot(g, g);
        Vec3<T> normal, error;
        bool singular = !(gg > T(0)) || !is_finite(gg);
        if (!singular) {
            // Refine the hit point with one Newton step along the gradient, onto F = 0
            // (kept only where finite: a gradient of 1e-20 may throw it to infinity).
            const Vec3<T> refined = point - (evaluate_local(point) / (T(2) * gg)) * g;
            if (is_finite(refined)) point = refined;
            g = half_gradient(point);
            // |g| as length(g), unless g . g is so small that it has lost digits (or is
            // 0): then from g over its largest component, which cannot underflow (a
            // quadric of denormal coefficients had normals of length 1.2).
            T g_length = length(g);
            if (g_length * g_length >= std::numeric_limits<T>::min() / std::numeric_limits<T>::epsilon() && is_finite(g_length)) {
                normal = g * (T(1) / g_length);
            } else {
                const T largest = max_component(abs(g));
                const Vec3<T> scaled = largest > T(0) && is_finite(largest) ? g / largest : Vec3<T>(T(0));
                const T scaled_length = length(scaled);
                normal = scaled * (T(1) / scaled_length);
                g_length = largest * scaled_length;
            }
            // What is left is F's rounding, gamma(12) of its terms, over |grad F| = 2 |g|,
            // along the normal; along the surface the point carries its own rounding.
            const T along = gamma<T>(12) * magnitude(point) / (T(2) * g_length);
            error = along * abs(normal) + gamma<T>(2) * abs(point);
            // A gradient too small to give a normal or a finite bound: as singular.
            singular = !is_finite(normal) || !is_finite(error);
        }
        if (singular) {
            // A singular point (a cone's apex): no normal; face the ray. (Over its largest
            // component first: a direction of 1e-22 has a denormal length squared, and
            // normalised as it is came out 1 % short.)
            const Vec3<T> facing = normalize(d / max_component(abs(d)));
            normal = entering ? -facing : facing;
            error = gamma<T>(4) * abs(point);
        }
        // Back to world coordinates: one more rounding of the sum.
        const Vec3<T> world = point + origin_;
        return Crossing<T>::flat(t, world, error + gamma<T>(1) * abs(world), normal, entering);
    }

    /// Bounds of an ellipsoid (Q3 positive definite, solid non-empty), else the universe:
    /// F = (p - c)^T Q3 (p - c) - k with c = -Q3^-1 q and k = q^T Q3^-1 q - j; the box
    /// half-extent on axis i is sqrt(k (Q3^-1)_ii).
    [[nodiscard]] constexpr Aabb<T> ellipsoid_bounds() const noexcept
    {
        const Coefficients& k = k_;
        const T m1 = k.a, m2 = difference_of_products(k.a, k.e, k.b, k.b);
        const T det = k.a * (k.e * k.h - k.f * k.f) - k.b * (k.b * k.h - k.f * k.c) + k.c * (k.b * k.f - k.e * k.c);
        if (!(m1 > T(0) && m2 > T(0) && det > T(0))) return Aabb<T>::universe();
        // Inverse of the symmetric 3x3 by cofactors.
        const T i00 = (k.e * k.h - k.f * k.f) / det, i11 = (k.a * k.h - k.c * k.c) / det, i22 = (k.a * k.e - k.b * k.b) / det;
        const T i01 = (k.c * k.f - k.b * k.h) / det, i02 = (k.b * k.f - k.c * k.e) / det, i12 = (k.b * k.c - k.a * k.f) / det;
        const Vec3<T> q = linear();
        const Vec3<T> inv_q{i00 * q.x + i01 * q.y + i02 * q.z, i01 * q.x + i11 * q.y + i12 * q.z, i02 * q.x + i12 * q.y + i22 * q.z};
        const Vec3<T> centre = -inv_q;
        const T level = dot(q, inv_q) - k.j;
        if (!(level > T(0))) return {}; // empty solid
        // Widened by a relative margin for the rounding of the formula above, then by the
        // rounding of the sums, and rounded outward: the box holds the whole surface.
        const Vec3<T> half = Vec3<T>(prism::sqrt(level * i00), prism::sqrt(level * i11), prism::sqrt(level * i22)) * T(1.0001);
        const Vec3<T> mid = origin_ + centre;
        const Vec3<T> pad = gamma<T>(4) * (abs(origin_) + abs(centre) + half);
        return Aabb<T>{mid - half - pad, mid + half + pad}.rounded_out();
    }

    Coefficients k_;     ///< normalised: the largest in [1, 2)
    Coefficients given_; ///< as the user wrote them
    Vec3<T> origin_{};
    Aabb<T> bounds_;
    T near2_ = T(0); ///< origins within this squared distance of origin_ are solved from where they are
    bool bounded_ = false;
};

static_assert(Shape<Quadric<float>>);
static_assert(Shape<Quadric<double>>);

} // namespace prism
