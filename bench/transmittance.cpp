// SPDX-License-Identifier: MIT
// Transmittance through a medium of varying density, four ways, error against time:
// residual ratio tracking (VaryingFog's, each majorant cell's floor its control), plain
// ratio tracking and the track-length estimator (delta tracking's indicator of no
// collision), both written here against the same majorant grid, and ray marching
// (midpoints, biased). Two media: a smoke of value noise on a 32^3 grid (optical depths
// 0 to about 6 across) and ground fog. 1024 rays cross each box in every direction; the
// reference for each is exp(-int sigma_t) by Simpson's rule in double over 40000
// intervals (ground fog: its closed form). The error is the RMS over rays of the error
// (transmittance is in [0, 1]; what a pixel shows) of one call averaging `setting`
// estimates (or marching `setting` steps).
//
// usage: bench_transmittance [RESULTS_DIR]   writes RESULTS_DIR/transmittance.csv (bench/results by default)
#include "common.hpp"

#include <prism/prism.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace prism;
using T = float;

/// Value noise in [0, 1): a hashed lattice, smoothly interpolated.
float noise(float x, float y, float z)
{
    const auto value = [](int i, int j, int k) {
        std::uint32_t h = std::uint32_t(i) * 73856093u ^ std::uint32_t(j) * 19349663u ^ std::uint32_t(k) * 83492791u;
        h ^= h >> 13, h *= 0x5bd1e995u, h ^= h >> 15;
        return float(h & 0xffffffu) / float(1u << 24);
    };
    const int i = int(std::floor(x)), j = int(std::floor(y)), k = int(std::floor(z));
    const auto s = [](float t) { return t * t * (3 - 2 * t); };
    const float fx = s(x - float(i)), fy = s(y - float(j)), fz = s(z - float(k));
    const auto mix = [](float a, float b, float t) { return a + t * (b - a); };
    const auto row = [&](int jj, int kk) { return mix(value(i, jj, kk), value(i + 1, jj, kk), fx); };
    const auto plane = [&](int kk) { return mix(row(j, kk), row(j + 1, kk), fy); };
    return mix(plane(k), plane(k + 1), fz);
}

/// Plain ratio tracking against the medium's majorant grid (no control).
template <class M>
Rgb<T> ratio_tracking(const M& medium, const Ray<T>& ray, T t_max, Random& rng)
{
    const Rgb<T> sigma_t = medium.absorption() + medium.scattering();
    const T most = max_component(sigma_t);
    Rgb<T> tr{T(1)};
    medium.majorants().traverse(ray, T(0), t_max, [&](T a, T b, const MajorantGrid<T>::Range& range) {
        const T mu = range.bound * most;
        if (!(mu > 0)) return true;
        for (T s = 0;;) {
            s += -std::log1p(-rng.uniform<T>()) / mu;
            if (!(s < b - a)) return true;
            tr *= component_max(Rgb<T>(1) - sigma_t * (medium.field().density(ray.at(a + s)) / mu), Rgb<T>(0));
            if (max_component(tr) < T(0.1)) {
                if (rng.uniform<T>() < T(0.5)) return tr = Rgb<T>(0), false;
                tr *= T(2);
            }
        }
    });
    return tr;
}

/// The track-length estimator: 1 if delta tracking finds no real collision, else 0 (grey: channel 0's extinction).
template <class M>
T track_length(const M& medium, const Ray<T>& ray, T t_max, Random& rng)
{
    const T sigma = medium.absorption().x + medium.scattering().x;
    bool hit = false;
    medium.majorants().traverse(ray, T(0), t_max, [&](T a, T b, const MajorantGrid<T>::Range& range) {
        const T mu = range.bound * sigma;
        if (!(mu > 0)) return true;
        for (T s = 0;;) {
            s += -std::log1p(-rng.uniform<T>()) / mu;
            if (!(s < b - a)) return true;
            if (rng.uniform<T>() * mu < sigma * medium.field().density(ray.at(a + s))) return hit = true, false;
        }
    });
    return hit ? T(0) : T(1);
}

/// Midpoint ray marching over the part of the ray in the medium's box.
template <class M>
T march(const M& medium, const Ray<T>& ray, T t_max, int steps)
{
    const Interval<T> span = medium.bounds().clip(ray, {T(0), t_max});
    if (span.empty()) return T(1);
    const T sigma = medium.absorption().x + medium.scattering().x, h = (span.max - span.min) / T(steps);
    T depth = 0;
    for (int i = 0; i < steps; ++i) depth += medium.field().density(ray.at(span.min + (T(i) + T(0.5)) * h));
    return std::exp(-sigma * depth * h);
}

template <class M, class Reference>
void measure(bench::Csv& csv, const char* medium_name, const M& medium, Reference reference)
{
    // Rays between two points on a sphere around the box: every direction, every depth.
    const Aabb<T> box = medium.bounds();
    const Vec3<T> centre = T(0.5) * (box.lo + box.hi);
    const T radius = T(0.75) * length(box.hi - box.lo);
    Random place(3, 9);
    std::vector<Ray<T>> rays;
    std::vector<double> expected;
    while (rays.size() < 1024) {
        const Vec3<T> a = centre + radius * uniform_sphere<T>(place), b = centre + T(0.5) * radius * uniform_sphere<T>(place);
        const Ray<T> ray{a, normalize(b - a)};
        if (box.clip(ray, {T(0), infinity<T>}).empty()) continue;
        rays.push_back(ray);
        expected.push_back(reference(ray));
    }
    const auto run = [&](const char* method, int setting, auto estimate) {
        std::vector<double> found(rays.size());
        const int rounds = 4;
        const double seconds = bench::min_seconds(3, [&] {
            for (int round = 0; round < rounds; ++round) {
                Random rng(11, std::uint64_t(round));
                for (std::size_t i = 0; i < rays.size(); ++i) found[i] = estimate(rays[i], rng);
            }
        });
        double squares = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) squares += std::pow(found[i] - expected[i], 2);
        const double error = std::sqrt(squares / double(rays.size()));
        const double ns = 1e9 * seconds / (rounds * double(rays.size()));
        std::printf("%-8s %-13s %6d %12.0f %14.4g\n", medium_name, method, setting, ns, error);
        csv.row("%s,%s,%d,%.1f,%.6g", medium_name, method, setting, ns, error);
    };
    for (const int n : {1, 4, 16, 64, 256}) {
        run("residual", n, [&](const Ray<T>& ray, Random& rng) {
            double sum = 0;
            for (int k = 0; k < n; ++k) sum += medium.transmittance(ray, infinity<T>, rng).x;
            return sum / n;
        });
        run("ratio", n, [&](const Ray<T>& ray, Random& rng) {
            double sum = 0;
            for (int k = 0; k < n; ++k) sum += ratio_tracking(medium, ray, infinity<T>, rng).x;
            return sum / n;
        });
        run("track-length", n, [&](const Ray<T>& ray, Random& rng) {
            double sum = 0;
            for (int k = 0; k < n; ++k) sum += track_length(medium, ray, infinity<T>, rng);
            return sum / n;
        });
    }
    for (const int steps : {4, 16, 64, 256, 1024})
        run("march", steps, [&](const Ray<T>& ray, Random&) { return double(march(medium, ray, infinity<T>, steps)); });
}

} // namespace

int main(int argc, char** argv)
{
    const std::string results = argc > 1 ? argv[1] : "bench/results";
    bench::Csv csv(results + "/transmittance.csv", "medium,method,setting,nanoseconds_per_ray,rms_error");
    std::printf("%-8s %-13s %6s %12s %14s\n", "medium", "method", "n", "ns per ray", "RMS error");
    // Smoke: value noise on a 32^3 grid over the unit cube, sigma_t up to about 6.
    const int n = 32;
    const Aabb<T> box{Vec3<T>(0), Vec3<T>(1)};
    std::vector<float> values;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) values.push_back(std::max(0.0f, 2.2f * noise(0.25f * float(x), 0.25f * float(y), 0.25f * float(z)) - 0.5f));
    const VaryingFog smoke(DensityGrid<T>(n, n, n, box, values), Rgb<T>(0.5f), Rgb<T>(3.5f), {}, 16);
    const DensityGrid<double> exact(n, n, n, {Vec3<double>(0), Vec3<double>(1)}, values);
    measure(csv, "smoke", smoke, [&](const Ray<T>& ray) {
        const Interval<T> span = box.clip(ray, {T(0), infinity<T>});
        const int m = 40000;
        const double a = span.min, h = (double(span.max) - a) / m;
        const Vec3<double> o(ray.origin), d(ray.direction);
        double sum = 0;
        for (int i = 0; i <= m; ++i) sum += (i == 0 || i == m ? 1 : i % 2 ? 4 : 2) * exact.density(o + (a + i * h) * d);
        return std::exp(-4.0 * sum * h / 3);
    });
    // Ground fog over a 2 x 1 x 2 box: density 3 at the floor, thinning by e every 0.25.
    const HeightFog<T> ground{.box = {{-1, 0, -1}, {1, 1, 1}}, .floor = 0, .base = 3, .scale_height = 0.25f};
    const VaryingFog fog(ground, Rgb<T>(0.2f), Rgb<T>(0.8f), {}, 16);
    measure(csv, "ground", fog, [&](const Ray<T>& ray) {
        const Interval<T> span = ground.box.clip(ray, {T(0), infinity<T>});
        const Vec3<double> o(ray.origin), d(ray.direction);
        const double y0 = o.y + span.min * d.y, y1 = o.y + span.max * d.y, length = double(span.max) - span.min;
        const double depth = std::abs(d.y) < 1e-9 ? 3 * std::exp(-y0 / 0.25) * length : 3 * 0.25 / d.y * (std::exp(-y0 / 0.25) - std::exp(-y1 / 0.25));
        return std::exp(-depth);
    });
    return 0;
}
