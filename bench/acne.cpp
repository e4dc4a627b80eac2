// SPDX-License-Identifier: MIT
// Stability where ray offsets fail: self-hits ("acne") of rays leaving a surface.
//
// For spheres, boxes and tilted planes placed 1, 10^3, 10^4 and 10^5 from the origin,
// in float and double, camera-like rays hit the shape and a secondary ray leaves the
// hit point: a mirror reflection, a shadow ray to a light outside, or a grazing ray
// within 10^-5..10^-1 radians of the tangent plane. Every such ray leaves a convex
// solid outward, so any crossing with the same shape is a self-hit. Three ways to start
// the new ray: prism's robust offset (error bound of the hit point), the lecture notes'
// fixed epsilon (1e-4 along the normal) and no offset at all.
// Output: results/acne.csv.
//   bench_acne [results-folder]
#include "common.hpp"

#include <array>
#include <cstdio>

namespace {

using prism::Vec3;

enum class Method { robust, epsilon, none };
constexpr std::array methods{Method::robust, Method::epsilon, Method::none};
constexpr const char* method_name(Method m) { return m == Method::robust ? "robust" : m == Method::epsilon ? "epsilon_1e-4" : "none"; }
constexpr std::array kinds{"reflect", "shadow", "grazing"};

template <prism::Scalar T>
Vec3<T> random_direction(prism::Random& rng)
{
    const T z = T(1) - T(2) * rng.uniform<T>();
    const T r = std::sqrt(std::max(T(0), T(1) - z * z));
    const T phi = T(2) * prism::pi<T> * rng.uniform<T>();
    return {r * std::cos(phi), r * std::sin(phi), z};
}

template <prism::Scalar T>
prism::Ray<T> leave(Method method, const prism::Crossing<T>& hit, const Vec3<T>& w)
{
    const Vec3<T> side = prism::dot(w, hit.normal) > T(0) ? hit.normal : -hit.normal;
    switch (method) {
    case Method::robust: return prism::spawn_ray(hit.point, hit.error, hit.normal, w);
    case Method::epsilon: return {hit.point + T(1e-4) * side, w};
    default: return {hit.point, w};
    }
}

template <prism::Scalar T, class Shape>
void sweep(bench::Csv& csv, const char* shape_name, const char* scalar, auto&& make_shape)
{
    for (double distance : {1.0, 1e3, 1e4, 1e5}) {
        std::array<std::array<long, 3>, 3> self_hits{}; // [kind][method]
        std::array<long, 3> rays{};
        prism::Random rng(17u, static_cast<std::uint64_t>(distance));
        for (int i = 0; i < 100000; ++i) {
            const Vec3<T> centre = random_direction<T>(rng) * T(distance);
            const Shape shape = make_shape(centre, rng);
            const Vec3<T> eye = centre + random_direction<T>(rng) * T(4);
            const Vec3<T> aim = centre + random_direction<T>(rng) * (T(0.4) * rng.uniform<T>());
            const Vec3<T> d = prism::normalize(aim - eye);
            const auto crossings = shape.crossings({eye, d}, {T(0), prism::infinity<T>});
            if (crossings.empty()) continue;
            const prism::Crossing<T>& hit = crossings.front();
            const Vec3<T> n = hit.facing_normal(); // facing the eye
            // The three secondary directions, all leaving on the eye's side.
            Vec3<T> tangent = prism::cross(n, random_direction<T>(rng));
            tangent = prism::normalize(tangent);
            const T lift = T(std::pow(10.0, -1.0 - 4.0 * rng.uniform<double>()));
            Vec3<T> light = hit.point + (n + random_direction<T>(rng) * T(0.9)) * T(5);
            const std::array<Vec3<T>, 3> w{prism::reflect(d, n), prism::normalize(light - hit.point),
                                           prism::normalize(tangent + lift * n)};
            const std::array<T, 3> t_max{prism::infinity<T>, prism::length(light - hit.point), prism::infinity<T>};
            for (int k = 0; k < 3; ++k) {
                if (!(prism::dot(w[k], n) > T(0))) continue;
                ++rays[k];
                for (int m = 0; m < 3; ++m) {
                    const auto again = shape.crossings(leave<T>(methods[m], hit, w[k]), {T(0), t_max[k]});
                    self_hits[k][m] += !again.empty();
                }
            }
        }
        for (int k = 0; k < 3; ++k)
            for (int m = 0; m < 3; ++m) {
                csv.row("%s,%s,%g,%s,%s,%ld,%ld", shape_name, scalar, distance, kinds[k], method_name(methods[m]), rays[k], self_hits[k][m]);
                if (methods[m] != Method::none)
                    std::printf("%-6s %-6s %7g %-8s %-13s %6ld rays  %6ld self-hits\n", shape_name, scalar, distance, kinds[k],
                                method_name(methods[m]), rays[k], self_hits[k][m]);
            }
    }
}

template <prism::Scalar T>
void all_shapes(bench::Csv& csv, const char* scalar)
{
    sweep<T, prism::Sphere<T>>(csv, "sphere", scalar, [](const Vec3<T>& c, prism::Random& rng) {
        return prism::Sphere<T>(c, T(0.5) + rng.uniform<T>());
    });
    sweep<T, prism::Box<T>>(csv, "box", scalar, [](const Vec3<T>& c, prism::Random& rng) {
        const Vec3<T> half{T(0.5) + rng.uniform<T>(), T(0.5) + rng.uniform<T>(), T(0.5) + rng.uniform<T>()};
        return prism::Box<T>(c - half, c + half);
    });
    sweep<T, prism::Plane<T>>(csv, "plane", scalar, [](const Vec3<T>& c, prism::Random& rng) {
        return prism::Plane<T>::through(c, random_direction<T>(rng));
    });
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    bench::Csv csv(out / "acne.csv", "shape,scalar,distance,kind,method,rays,self_hits");
    all_shapes<float>(csv, "float");
    all_shapes<double>(csv, "double");
    return 0;
}
