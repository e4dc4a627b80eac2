// SPDX-License-Identifier: MIT
// prism's Bvh against Embree 3 (libembree-dev, used here only), on the same geometry and
// the same rays in one run.
//
// Geometry: N random spheres in [-1, 1]^3 filling 5 % of it (N = 1e2 ... 1e6; Embree's
// point-sphere primitive), and triangle meshes (the Stanford bunny if its OBJ is given,
// a geodesic sphere and a 10^6-triangle terrain). Rays: 1000^2 primary rays from a
// camera, then from every primary hit one cosine-distributed bounce ray and one shadow
// ray to a point light (the same rays for both; prism's hit gives them). Closest hit,
// Embree's rtcIntersect1 (its single-ray API) against Scene::closest_hit (which also
// works out the winner's surface); for shadow rays rtcOccluded1 against
// Scene::transmittance (any hit); on 1 and 2 threads. Times: the minimum and median of `repeats` interleaved
// rounds. Build: prism's on one thread; Embree's on its own (TBB) threads, at its default
// (medium) quality, and for meshes also at high quality (spatial splits; build time only).
// Agreement: the share of rays where both hit, or both miss, with t within 1e-3.
// Embree picks its kernels by the CPU at run time (AVX2 or AVX-512 where there are);
// prism is compiled for the baseline x86-64 (SSE2, 4-wide nodes), or for AVX2 as
// bench_bvh_vs_embree_avx2 (8-wide nodes), whose files are named ..._prism-avx2, or for the
// machine it is built on (-march=native: AVX-512 where there is, as Embree picks) as
// bench_bvh_vs_embree_native, whose files are named ..._prism-native.
// `embree-isa` (sse4.2, avx2, ...) holds Embree to one instruction set, to tell the
// algorithms apart from the ISA; that run writes bvh_vs_embree[_prism-avx2]_<isa>.csv.
//   bench_bvh_vs_embree [results-folder] [repeats] [bunny.obj] [embree-isa]
#include "common.hpp"
#include "embree_rays.hpp"
#include "meshes.hpp"

#include <prism/io/mesh.hpp>

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace prism;
using T = float;

/// A point uniform in [-1, 1]^3.
Vec3<T> test_point(Random& rng)
{
    return {T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1), T(2) * rng.uniform<T>() - T(1)};
}

struct Rays {
    std::vector<Ray<T>> primary, bounce;
    std::vector<Ray<T>> shadow; ///< from each primary hit toward the light, unit direction
    std::vector<T> shadow_end;  ///< where each shadow ray stops: just short of the light
};

/// The light the shadow rays go to, above and in front of the geometry.
const Vec3<T> light_position{T(2), T(3), T(-4)};

/// Seconds to trace `rays` on `threads` threads, each taking a contiguous half.
template <class Trace>
double trace_seconds(const std::vector<Ray<T>>& rays, int threads, Trace&& trace)
{
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    const std::size_t n = rays.size();
    for (int k = 0; k < threads; ++k) pool.emplace_back([&, k] { trace(n * std::size_t(k) / std::size_t(threads), n * std::size_t(k + 1) / std::size_t(threads)); });
    for (auto& t : pool) t.join();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// Primary rays from a camera 4 units from the origin, seeing [-1.3, 1.3]^2 at it.
std::vector<Ray<T>> camera_rays(int size, const Vec3<T>& eye, const Vec3<T>& at, T half_width)
{
    std::vector<Ray<T>> rays;
    const Vec3<T> forward = normalize(at - eye);
    const Vec3<T> right = normalize(cross(forward, Vec3<T>(0, 1, 0))), up = cross(right, forward);
    const T scale = half_width / length(at - eye);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const T u = (T(2) * (T(x) + T(0.5)) / T(size) - T(1)) * scale, v = (T(1) - T(2) * (T(y) + T(0.5)) / T(size)) * scale;
            rays.push_back({eye, normalize(forward + u * right + v * up)});
        }
    return rays;
}

class Embree {
public:
    Embree(int threads, const std::string& isa)
    {
        const std::string config = "threads=" + std::to_string(threads) + (isa.empty() ? "" : ",isa=" + isa);
        device_ = rtcNewDevice(config.c_str());
        if (device_ == nullptr) throw std::runtime_error("rtcNewDevice failed");
    }
    Embree(const Embree&) = delete;
    Embree& operator=(const Embree&) = delete;
    ~Embree()
    {
        if (scene_ != nullptr) rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }

    /// Point spheres (x, y, z, r); returns the build time.
    double spheres(const std::vector<Sphere<T>>& balls)
    {
        const auto start = std::chrono::steady_clock::now();
        begin();
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), balls.size()));
        for (std::size_t i = 0; i < balls.size(); ++i) {
            v[4 * i] = balls[i].center().x, v[4 * i + 1] = balls[i].center().y, v[4 * i + 2] = balls[i].center().z;
            v[4 * i + 3] = balls[i].radius();
        }
        return end(g, start);
    }

    /// A triangle mesh, built at `quality` (Embree's default is medium; high adds spatial
    /// splits); returns the build time.
    double triangles(const MeshBuffers<T>& mesh, RTCBuildQuality quality = RTC_BUILD_QUALITY_MEDIUM)
    {
        const auto start = std::chrono::steady_clock::now();
        begin();
        rtcSetSceneBuildQuality(scene_, quality);
        bench::embree_add_triangles(device_, scene_, mesh, quality);
        return finish(start);
    }

    /// Whether anything lies on the ray between 0 and t_max.
    [[nodiscard]] bool occluded(const Ray<T>& ray, float t_max) const { return bench::embree_occluded(scene_, ray, t_max); }

    /// The t of the closest hit, or infinity.
    [[nodiscard]] float closest(const Ray<T>& ray) const { return bench::embree_closest(scene_, ray); }

private:
    void begin()
    {
        if (scene_ != nullptr) rtcReleaseScene(scene_);
        scene_ = rtcNewScene(device_);
    }
    double end(RTCGeometry g, std::chrono::steady_clock::time_point start)
    {
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);
        return finish(start);
    }
    /// The scene committed (built); the seconds since `start`.
    double finish(std::chrono::steady_clock::time_point start)
    {
        rtcCommitScene(scene_);
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
};

/// Primary rays and, from each primary hit, a cosine bounce ray (prism's hit point and
/// normal, offset as prism spawns rays).
template <class SceneT>
Rays make_rays(const SceneT& scene, std::vector<Ray<T>> primary)
{
    Rays rays{std::move(primary), {}, {}, {}};
    Random rng(7u, 7u);
    for (const Ray<T>& r : rays.primary)
        if (const auto hit = scene.closest_hit(r, {T(0), infinity<T>})) {
            const Crossing<T>& c = hit->crossing;
            rays.bounce.push_back(spawn_ray(c.point, c.error, c.normal, cosine_hemisphere(c.facing_normal(), rng)));
            const Ray<T> to_light = spawn_ray(c.point, c.error, c.normal, light_position - c.point);
            const T distance = length(light_position - to_light.origin);
            rays.shadow.push_back({to_light.origin, (light_position - to_light.origin) / distance});
            rays.shadow_end.push_back(distance * T(0.9999));
        }
    return rays;
}

struct Row {
    std::string geometry;
    std::size_t count;
    double prism_build, embree_build;
    double embree_hq_build = -1; ///< Embree's high-quality build (spatial splits), meshes only
};

/// Times both on both ray sets and thread counts, interleaved, and writes the rows.
template <class SceneT>
void race(bench::Csv& csv, const Row& row, const SceneT& scene, Embree& embree, const Rays& rays, int repeats)
{
    for (const auto* set : {&rays.primary, &rays.bounce, &rays.shadow}) {
        const bool shadow = set == &rays.shadow;
        const char* kind = set == &rays.primary ? "primary" : (shadow ? "shadow" : "bounce");
        // A shadow ray asks whether anything blocks it (prism: the transmittance of a
        // scene of opaque objects, an any-hit query; Embree: rtcOccluded1); the others ask
        // for the closest hit.
        const auto prism_hit = [&](std::size_t i) {
            return shadow ? scene.transmittance((*set)[i], rays.shadow_end[i]).r == T(0) : scene.closest_hit((*set)[i], {T(0), infinity<T>}).has_value();
        };
        const auto embree_hit = [&](std::size_t i) { return shadow ? embree.occluded((*set)[i], rays.shadow_end[i]) : embree.closest((*set)[i]) < infinity<float>; };
        // The timed loops: one query each, so that the compiler inlines that one alone
        // (a loop over prism_hit, holding both queries, traced the bunny's primary rays
        // at two thirds of the speed).
        const auto prism_hits = [&](std::size_t a, std::size_t b) {
            long h = 0;
            if (shadow)
                for (std::size_t i = a; i < b; ++i) h += scene.transmittance((*set)[i], rays.shadow_end[i]).r == T(0);
            else
                for (std::size_t i = a; i < b; ++i) h += scene.closest_hit((*set)[i], {T(0), infinity<T>}).has_value();
            return h;
        };
        const auto embree_hits = [&](std::size_t a, std::size_t b) {
            long h = 0;
            if (shadow)
                for (std::size_t i = a; i < b; ++i) h += embree.occluded((*set)[i], rays.shadow_end[i]);
            else
                for (std::size_t i = a; i < b; ++i) h += embree.closest((*set)[i]) < infinity<float>;
            return h;
        };
        // Agreement.
        std::size_t agree = 0, hits = 0;
        for (std::size_t i = 0; i < set->size(); ++i) {
            const Ray<T>& r = (*set)[i];
            if (shadow) {
                const bool blocked = prism_hit(i);
                hits += blocked;
                agree += blocked == embree_hit(i);
                continue;
            }
            const auto h = scene.closest_hit(r, {T(0), infinity<T>});
            const float te = embree.closest(r);
            const float tp = h ? h->crossing.t : infinity<float>;
            hits += h.has_value();
            agree += (!h && !(te < infinity<float>)) || (h && std::abs(tp - te) <= 1e-3f * std::max(1.0f, tp));
        }
        for (const int threads : {1, 2}) {
            std::vector<double> tp, te;
            std::vector<long> sink(2, 0);
            for (int round = 0; round < repeats; ++round) {
                tp.push_back(trace_seconds(*set, threads, [&](std::size_t a, std::size_t b) {
                    const long h = prism_hits(a, b);
                    if (a == 0) sink[0] = h;
                }));
                te.push_back(trace_seconds(*set, threads, [&](std::size_t a, std::size_t b) {
                    const long h = embree_hits(a, b);
                    if (a == 0) sink[1] = h;
                }));
            }
            const double n = double(set->size());
            const double p_min = n / *std::min_element(tp.begin(), tp.end()) / 1e6, e_min = n / *std::min_element(te.begin(), te.end()) / 1e6;
            const double p_med = n / median(tp) / 1e6, e_med = n / median(te) / 1e6;
            const std::string hq = row.embree_hq_build < 0 ? "" : std::to_string(row.embree_hq_build);
            csv.row("%s,%zu,%s,%d,%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%s,%.5f,%.5f", row.geometry.c_str(), row.count, kind, threads, set->size(), p_min, p_med, e_min,
                    e_med, row.prism_build, row.embree_build, hq.c_str(), double(agree) / n, double(hits) / n);
            std::printf("%-9s %8zu %-7s %d thr: prism %7.2f Mrays/s, Embree %7.2f (ratio min-time %.2f, median %.2f); build %.3f s vs %.3f s%s%s; agree %.5f, "
                        "hit %.3f\n",
                        row.geometry.c_str(), row.count, kind, threads, p_min, e_min, p_min / e_min, p_med / e_med, row.prism_build, row.embree_build,
                        hq.empty() ? "" : ", high quality ", hq.c_str(), double(agree) / n, double(hits) / n);
            std::fflush(stdout);
        }
    }
}

} // namespace

int main(int argc, char** argv)
{
    const std::filesystem::path out = argc > 1 ? argv[1] : "bench/results";
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
    const std::string bunny = argc > 3 ? argv[3] : "";
    const std::string isa = argc > 4 ? argv[4] : "";
    if (isa.find_first_of(",=") != std::string::npos) {
        std::fprintf(stderr, "bench_bvh_vs_embree: embree-isa must be one instruction set name (sse4.2, avx2, ...), got '%s'\n", isa.c_str());
        return 2;
    }
    if (repeats < 1) {
        std::fprintf(stderr, "bench_bvh_vs_embree: repeats must be >= 1, got '%s'\n", argv[2]);
        return 2;
    }
#if defined(PRISM_BENCH_NATIVE)
    const std::string name = "bvh_vs_embree_prism-native";
#elif defined(__AVX2__)
    const std::string name = "bvh_vs_embree_prism-avx2";
#else
    const std::string name = "bvh_vs_embree";
#endif
    std::printf("prism: Bvh<float> nodes %d wide; Embree: %s\n", Bvh<T>::width, isa.empty() ? "as it comes" : ("held to " + isa).c_str());
    bench::Csv csv(out / (name + (isa.empty() ? "" : "_" + isa) + ".csv"),
                   "geometry,count,rays,threads,ray_count,prism_mrays_min,prism_mrays_median,embree_mrays_min,embree_mrays_median,prism_build_s,embree_build_s,"
                   "embree_hq_build_s,agree,hit_share");
    Embree embree(2, isa);
    const Lights lights{PointLight<T>{}};
    const auto primary = camera_rays(1000, {T(0.3), T(0.4), T(-4)}, {T(0), T(0), T(0)}, T(1.3));

    for (const std::size_t n : {std::size_t(100), std::size_t(1000), std::size_t(10000), std::size_t(100000), std::size_t(1000000)}) {
        Random rng(1u, 1u);
        const T radius = T(std::cbrt(0.05 * 8 / (4.0 / 3 * pi<double> * double(n))));
        std::vector<Sphere<T>> balls;
        ObjectArray<Sphere<T>, Diffuse<T>> array;
        for (std::size_t i = 0; i < n; ++i) {
            balls.emplace_back(test_point(rng), radius);
            array.items.emplace_back(balls.back(), Diffuse<T>{});
        }
        auto start = std::chrono::steady_clock::now();
        const Scene scene{lights, std::move(array)};
        const double prism_build = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double embree_build = embree.spheres(balls);
        race(csv, {"spheres", n, prism_build, embree_build}, scene, embree, make_rays(scene, primary), repeats);
    }

    std::vector<std::pair<std::string, MeshBuffers<T>>> meshes;
    if (!bunny.empty()) meshes.emplace_back("bunny", bench::scaled_bunny(bunny));
    meshes.emplace_back("sphere", bench::geodesic_sphere());
    meshes.emplace_back("terrain", bench::terrain());
    for (const auto& [mesh_name, buffers] : meshes) {
        auto start = std::chrono::steady_clock::now();
        const Scene scene{lights, Object{TriangleMesh<T>(buffers.positions, buffers.triangles), Diffuse<T>{}}};
        const double prism_build = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double embree_hq_build = embree.triangles(buffers, RTC_BUILD_QUALITY_HIGH);
        const double embree_build = embree.triangles(buffers);
        race(csv, {mesh_name, buffers.triangles.size(), prism_build, embree_build, embree_hq_build}, scene, embree, make_rays(scene, primary), repeats);
    }
    return 0;
}
