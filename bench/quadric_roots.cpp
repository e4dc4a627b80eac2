// SPDX-License-Identifier: MIT
// Where quadric root finding fails: the textbook formula against prism's.
//
//   asymptotic  a ray tilted by eps from a paraboloid's axis: A = sin^2(eps) -> 0. The
//               textbook (-B - sqrt(B^2 - 4AC)) / 2A cancels; q = -(B + sign(B) sqrt(disc)),
//               t = C / q does not.
//   grazing     chords of the unit sphere (as a quadric) at 1 - delta from the centre:
//               the discriminant cancels, for any formula; prism's Sphere, which computes
//               it from the ray's closest approach (Ray Tracing Gems ch. 7), does better.
//   distance    one ellipsoid placed 1 ... 1e5 from the origin: written in world
//               coefficients (j ~ D^2) or around its own origin (prism's factories).
// Error: relative error of the first root against a long-double solution of the same
// problem (asymptotic, grazing), or distance of the hit point from the true surface
// (distance). Output: results/quadric_roots.csv.
//   bench_quadric_roots [results-folder]
#include "common.hpp"

#include <cmath>
#include <optional>

namespace {

using prism::Quadric;
using prism::Vec3;
using L = long double;

/// The seed's textbook solution: the smallest positive root of A t^2 + B t + C.
template <prism::Scalar T>
std::optional<T> textbook_root(const typename Quadric<T>::Coefficients& k, const Vec3<T>& o, const Vec3<T>& d)
{
    const T A = k.a * d.x * d.x + 2 * k.b * d.x * d.y + 2 * k.c * d.x * d.z + k.e * d.y * d.y + 2 * k.f * d.y * d.z + k.h * d.z * d.z;
    const T B = 2 * (k.a * o.x * d.x + k.b * (o.x * d.y + d.x * o.y) + k.c * (o.x * d.z + d.x * o.z) + k.d * d.x + k.e * o.y * d.y +
                     k.f * (o.y * d.z + d.y * o.z) + k.g * d.y + k.h * o.z * d.z + k.i * d.z);
    const T C = k.a * o.x * o.x + 2 * k.b * o.x * o.y + 2 * k.c * o.x * o.z + 2 * k.d * o.x + k.e * o.y * o.y + 2 * k.f * o.y * o.z +
                2 * k.g * o.y + k.h * o.z * o.z + 2 * k.i * o.z + k.j;
    if (A == 0) return B != 0 ? std::optional<T>(-C / B) : std::nullopt;
    const T disc = B * B - 4 * A * C;
    if (disc < 0) return std::nullopt;
    const T t0 = (-B - std::sqrt(disc)) / (2 * A), t1 = (-B + std::sqrt(disc)) / (2 * A);
    const T lo = std::min(t0, t1), hi = std::max(t0, t1);
    return lo > 0 ? lo : hi > 0 ? std::optional<T>(hi) : std::nullopt;
}

/// The same problem in long double: coefficients of F(o + t d) from the T inputs, stable roots.
template <prism::Scalar T>
std::optional<L> reference_root(const typename Quadric<T>::Coefficients& k, const Vec3<T>& o_in, const Vec3<T>& d_in)
{
    const L ox = o_in.x, oy = o_in.y, oz = o_in.z, dx = d_in.x, dy = d_in.y, dz = d_in.z;
    const L a = k.a, b = k.b, c = k.c, dd = k.d, e = k.e, f = k.f, g = k.g, h = k.h, i = k.i, j = k.j;
    const L A = a * dx * dx + 2 * b * dx * dy + 2 * c * dx * dz + e * dy * dy + 2 * f * dy * dz + h * dz * dz;
    const L B = a * ox * dx + b * (ox * dy + dx * oy) + c * (ox * dz + dx * oz) + dd * dx + e * oy * dy + f * (oy * dz + dy * oz) + g * dy +
                h * oz * dz + i * dz;
    const L C = a * ox * ox + 2 * b * ox * oy + 2 * c * ox * oz + 2 * dd * ox + e * oy * oy + 2 * f * oy * oz + 2 * g * oy + h * oz * oz +
                2 * i * oz + j;
    const L disc = B * B - A * C;
    if (disc <= 0) return std::nullopt; // no crossing, or a tangent touch: nothing to measure
    const L q = B >= 0 ? -(B + std::sqrt(disc)) : -(B - std::sqrt(disc));
    const L r0 = C / q, r1 = A != 0 ? q / A : INFINITY;
    const L lo = std::min(r0, r1), hi = std::max(r0, r1);
    return lo > 0 ? lo : hi > 0 ? std::optional<L>(hi) : std::nullopt;
}

template <prism::Scalar T, class S>
std::optional<T> prism_root(const S& shape, const Vec3<T>& o, const Vec3<T>& d)
{
    const auto c = shape.crossings({o, d}, {T(0), prism::infinity<T>});
    return c.empty() ? std::nullopt : std::optional<T>(c.front().t);
}

double relative(std::optional<double> t, std::optional<L> reference)
{
    if (!reference) return NAN;
    if (!t) return 1.0; // missed a root that exists: as bad as it gets
    return double(std::abs((L(*t) - *reference) / *reference));
}

template <prism::Scalar T>
void run(bench::Csv& csv, const char* scalar)
{
    // Asymptotic: z = x^2 + y^2 (a paraboloid), from (0.5, 0, -5) almost along +z.
    const auto bowl = Quadric<T>::elliptic_paraboloid(T(1), T(1));
    for (double eps = 1e-1; eps >= 1e-12; eps /= std::sqrt(10.0)) {
        const Vec3<T> o{T(0.5), T(0), T(-5)}, d{T(std::sin(eps)), T(0), T(std::cos(eps))};
        const auto ref = reference_root<T>(bowl.coefficients(), o, d);
        csv.row("asymptotic,%s,textbook,%.6g,%.6g", scalar, eps, relative(textbook_root<T>(bowl.coefficients(), o, d), ref));
        csv.row("asymptotic,%s,prism quadric,%.6g,%.6g", scalar, eps, relative(prism_root<T>(bowl, o, d), ref));
    }
    // Grazing: x^2 + y^2 + z^2 = 1 as a quadric, and as prism's Sphere.
    const Quadric<T> ball({.a = 1, .e = 1, .h = 1, .j = -1});
    const prism::Sphere<T> sphere({T(0), T(0), T(0)}, T(1));
    for (double delta = 1e-1; delta >= 1e-13; delta /= std::sqrt(10.0)) {
        const Vec3<T> o{T(-5), T(1 - delta), T(0)}, d{T(1), T(0), T(0)};
        const auto ref = reference_root<T>(ball.coefficients(), o, d);
        if (!ref) continue; // 1 - delta rounded to 1 in this precision: the input is a tangent
        csv.row("grazing,%s,textbook,%.6g,%.6g", scalar, delta, relative(textbook_root<T>(ball.coefficients(), o, d), ref));
        csv.row("grazing,%s,prism quadric,%.6g,%.6g", scalar, delta, relative(prism_root<T>(ball, o, d), ref));
        csv.row("grazing,%s,prism sphere,%.6g,%.6g", scalar, delta, relative(prism_root<T>(sphere, o, d), ref));
    }
    // Distance: semi-axes (1, 0.7, 0.5) centred D from the origin; error = how far the hit
    // point is from the true ellipsoid, |F(p)| / |grad F(p)| in long double.
    for (double distance = 1; distance <= 1.01e5; distance *= std::sqrt(10.0)) {
        const Vec3<double> centre = distance * Vec3<double>{0.6, 0.8, 0};
        const Vec3<T> c(centre);
        const auto local = Quadric<T>::ellipsoid(c, {T(1), T(0.7), T(0.5)});
        const auto world = Quadric<T>::from_matrix(local.matrix()); // the same surface, world coefficients
        const auto off_surface = [&](const Vec3<T>& p) {
            const L x = (L(p.x) - centre.x) / 1, y = (L(p.y) - centre.y) / 0.7L, z = (L(p.z) - centre.z) / 0.5L;
            const L f = x * x + y * y + z * z - 1;
            const L gx = 2 * x, gy = 2 * y / 0.7L, gz = 2 * z / 0.5L;
            return double(std::abs(f) / std::sqrt(gx * gx + gy * gy + gz * gz));
        };
        double worst[3] = {0, 0, 0};
        prism::Random rng(5u, 5u);
        for (int n = 0; n < 200; ++n) {
            const Vec3<T> o = c + Vec3<T>{T(-4), T(0.6) * rng.uniform<T>() - T(0.3), T(0.4) * rng.uniform<T>() - T(0.2)};
            const Vec3<T> d = prism::normalize(c + Vec3<T>{T(0), T(0.2) * rng.uniform<T>() - T(0.1), T(0)} - o);
            if (const auto t = textbook_root<T>(world.coefficients(), o, d)) worst[0] = std::max(worst[0], off_surface(o + *t * d));
            else worst[0] = 1;
            const auto cw = world.crossings({o, d}, {T(0), prism::infinity<T>});
            worst[1] = std::max(worst[1], cw.empty() ? 1.0 : off_surface(cw.front().point));
            const auto cl = local.crossings({o, d}, {T(0), prism::infinity<T>});
            worst[2] = std::max(worst[2], cl.empty() ? 1.0 : off_surface(cl.front().point));
        }
        csv.row("distance,%s,textbook (world coefficients),%.6g,%.6g", scalar, distance, worst[0]);
        csv.row("distance,%s,prism quadric (world coefficients),%.6g,%.6g", scalar, distance, worst[1]);
        csv.row("distance,%s,prism quadric (own origin),%.6g,%.6g", scalar, distance, worst[2]);
        std::printf("%-6s distance %8.0f  hit point off the surface: textbook %.2e  world coefficients %.2e  own origin %.2e\n", scalar,
                    distance, worst[0], worst[1], worst[2]);
    }
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    bench::Csv csv(out / "quadric_roots.csv", "experiment,scalar,method,x,error");
    run<float>(csv, "float");
    run<double>(csv, "double");
    return 0;
}
