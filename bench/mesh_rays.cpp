// SPDX-License-Identifier: MIT
// One mesh, one kind of ray, traced `passes` times: the rays of bench/bvh_vs_embree.cpp
// (1000^2 primary rays, a cosine bounce and a shadow ray from each primary hit) against
// the bunny, the geodesic sphere or the terrain, through the Scene (closest_hit, or
// transmittance for shadow rays: what a renderer asks) or the TriangleMesh alone
// (first_crossing, any_crossing), or, where it is built with Embree 3, Embree's single-ray
// queries on the same mesh (rtcIntersect1, rtcOccluded1): the peer, counted the same way.
// It prints the rays traced a second.
//
// Timing on a shared machine wanders by 10 % from run to run; the instructions a ray
// takes do not. bench/mesh_instructions.py runs this program under valgrind's cachegrind
// with 1 and 2 passes and takes the difference: the instructions of one pass of the rays,
// build and set-up left out (a deterministic count, for changes to the kernel that move
// it by a few per cent; not a time, since it does not see cache misses).
//   bench_mesh_rays bunny.obj bunny|sphere|terrain primary|bounce|shadow scene|mesh|embree [passes] [embree-isa]
#include "meshes.hpp"

#if PRISM_BENCH_EMBREE
#include "embree_rays.hpp"
#endif

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

using namespace prism;
using T = float;

namespace {

MeshBuffers<T> mesh_named(const std::string& name, const std::string& bunny)
{
    if (name == "bunny") return bench::scaled_bunny(bunny);
    if (name == "sphere") return bench::geodesic_sphere();
    if (name == "terrain") return bench::terrain();
    std::fprintf(stderr, "bench_mesh_rays: mesh must be bunny, sphere or terrain, got '%s'\n", name.c_str());
    std::exit(2);
}

#if PRISM_BENCH_EMBREE
/// Embree's scene of one triangle mesh (its defaults: BVH8 where the CPU has AVX, SAH
/// build of medium quality), and its single-ray queries.
class EmbreeMesh {
public:
    /// `isa`: empty for the instruction set Embree picks, or one to hold it to (avx2, ...).
    EmbreeMesh(const MeshBuffers<T>& mesh, const std::string& isa) : device_(rtcNewDevice(("threads=1" + (isa.empty() ? "" : ",isa=" + isa)).c_str()))
    {
        if (device_ == nullptr) throw std::runtime_error("rtcNewDevice failed");
        scene_ = rtcNewScene(device_);
        bench::embree_add_triangles(device_, scene_, mesh, RTC_BUILD_QUALITY_MEDIUM);
        rtcCommitScene(scene_);
    }
    EmbreeMesh(const EmbreeMesh&) = delete;
    EmbreeMesh& operator=(const EmbreeMesh&) = delete;
    ~EmbreeMesh()
    {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    [[nodiscard]] bool hit(const Ray<T>& ray) const { return bench::embree_closest(scene_, ray) < infinity<T>; }
    [[nodiscard]] bool occluded(const Ray<T>& ray, T end) const { return bench::embree_occluded(scene_, ray, end); }

private:
    RTCDevice device_;
    RTCScene scene_ = nullptr;
};
#endif

} // namespace

int main(int argc, char** argv)
{
    if (argc < 5) {
        std::fprintf(stderr, "usage: bench_mesh_rays bunny.obj bunny|sphere|terrain primary|bounce|shadow scene|mesh [passes]\n");
        return 2;
    }
    const std::string kind = argv[3], query = argv[4];
    const int passes = argc > 5 ? std::atoi(argv[5]) : 5;
    if ((kind != "primary" && kind != "bounce" && kind != "shadow") || (query != "scene" && query != "mesh" && query != "embree") || passes < 1) {
        std::fprintf(stderr, "bench_mesh_rays: rays must be primary, bounce or shadow, query scene, mesh or embree, passes >= 1; got '%s' '%s' %d\n",
                     kind.c_str(), query.c_str(), passes);
        return 2;
    }
#if !PRISM_BENCH_EMBREE
    if (query == "embree") {
        std::fprintf(stderr, "bench_mesh_rays: built without Embree (libembree-dev): no 'embree' query\n");
        return 2;
    }
#endif
    const MeshBuffers<T> buffers = mesh_named(argv[2], argv[1]);
    const TriangleMesh<T> mesh(buffers.positions, buffers.triangles);
    const Scene scene{Lights{PointLight<T>{}}, Object{mesh, Diffuse<T>{}}};

    // bench_bvh_vs_embree's rays: a camera 4 units away seeing [-1.3, 1.3]^2 at the origin.
    const Vec3<T> eye{T(0.3), T(0.4), T(-4)}, light{T(2), T(3), T(-4)};
    const Vec3<T> forward = normalize(-eye);
    const Vec3<T> right = normalize(cross(forward, Vec3<T>(0, 1, 0))), up = cross(right, forward);
    const T scale = T(1.3) / length(eye);
    std::vector<Ray<T>> rays;
    std::vector<T> ends; // a shadow ray's end, short of the light
    for (int y = 0; y < 1000; ++y)
        for (int x = 0; x < 1000; ++x) {
            const T u = (T(2) * (T(x) + T(0.5)) / T(1000) - T(1)) * scale, v = (T(1) - T(2) * (T(y) + T(0.5)) / T(1000)) * scale;
            rays.push_back({eye, normalize(forward + u * right + v * up)});
        }
    if (kind != "primary") {
        std::vector<Ray<T>> next;
        Random rng(7u, 7u);
        for (const Ray<T>& r : rays)
            if (const auto hit = scene.closest_hit(r, {T(0), infinity<T>})) {
                const Crossing<T>& c = hit->crossing;
                const Ray<T> bounce = spawn_ray(c.point, c.error, c.normal, cosine_hemisphere(c.facing_normal(), rng));
                const Ray<T> to_light = spawn_ray(c.point, c.error, c.normal, light - c.point);
                const T distance = length(light - to_light.origin);
                if (kind == "bounce") next.push_back(bounce);
                else next.push_back({to_light.origin, (light - to_light.origin) / distance}), ends.push_back(distance * T(0.9999));
            }
        rays = std::move(next);
    }

#if PRISM_BENCH_EMBREE
    std::optional<EmbreeMesh> embree;
    if (query == "embree") embree.emplace(buffers, argc > 6 ? argv[6] : "");
#endif
    long hits = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int pass = 0; pass < passes; ++pass) {
#if PRISM_BENCH_EMBREE
        if (embree) {
            if (kind == "shadow")
                for (std::size_t i = 0; i < rays.size(); ++i) hits += embree->occluded(rays[i], ends[i]);
            else
                for (const Ray<T>& r : rays) hits += embree->hit(r);
            continue;
        }
#endif
        if (kind == "shadow") {
            for (std::size_t i = 0; i < rays.size(); ++i)
                hits += query == "scene" ? scene.transmittance(rays[i], ends[i]).r == T(0) : mesh.any_crossing(rays[i], {T(0), ends[i]});
        } else if (query == "scene") {
            for (const Ray<T>& r : rays) hits += scene.closest_hit(r, {T(0), infinity<T>}).has_value();
        } else {
            for (const Ray<T>& r : rays) hits += mesh.first_crossing(r, {T(0), infinity<T>}) < infinity<T>;
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s %s %s: %zu rays, %d passes, %.3f Mrays/s, %ld hits\n", argv[2], kind.c_str(), query.c_str(), rays.size(), passes,
                double(rays.size()) * passes / seconds / 1e6, hits);
    return 0;
}
