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
// Embree also as embree-hq (its high-quality build, spatial splits), embree-robust (its
// watertight, conservative mode), embree-compact (its smaller structures) and embree8 (eight consecutive rays a packet: eight
// neighbouring pixels of a row for primary rays): what a better tree, prism's exactness and
// packets are worth to the peer itself. The `leak` rays (sphere only) start inside the
// closed geodesic sphere and pass through each of its vertices and edge midpoints: every
// one must hit, and the misses printed are rays a test let through.
//   bench_mesh_rays bunny.obj bunny|sphere|terrain primary|bounce|shadow|leak scene|mesh|embree[-hq|-robust|-compact|8] [passes] [embree-isa]
#include "meshes.hpp"

#if PRISM_BENCH_EMBREE
#include "embree_rays.hpp"
#endif

#include <atomic>
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
    /// `isa`: empty for the instruction set Embree picks, or one to hold it to (avx2, ...);
    /// `variant`: "embree" (its defaults), "embree-hq" (the high-quality build, with spatial
    /// splits), "embree-robust" (RTC_SCENE_FLAG_ROBUST: a watertight triangle test and a
    /// conservative node test, as prism's), "embree-compact" (RTC_SCENE_FLAG_COMPACT: its
    /// structures that take less memory) or "embree8" (the defaults, rays traced eight at a
    /// time with rtcIntersect8 / rtcOccluded8).
    EmbreeMesh(const MeshBuffers<T>& mesh, const std::string& isa, const std::string& variant)
        : device_(rtcNewDevice(("threads=1" + (isa.empty() ? "" : ",isa=" + isa)).c_str()))
    {
        if (device_ == nullptr) throw std::runtime_error("rtcNewDevice failed");
        rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeMesh::count_bytes, &bytes_);
        scene_ = rtcNewScene(device_);
        if (variant == "embree-robust") rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
        if (variant == "embree-compact") rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_COMPACT);
        // (The scene's quality chooses the builder; a geometry's is a hint Embree 3 reads
        // only for a scene of low quality.)
        if (variant == "embree-hq") rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
        bench::embree_add_triangles(device_, scene_, mesh, variant == "embree-hq" ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);
        rtcCommitScene(scene_);
    }
    EmbreeMesh(const EmbreeMesh&) = delete;
    EmbreeMesh& operator=(const EmbreeMesh&) = delete;
    /// Bytes Embree holds for the scene once built (its memory monitor's sum: the vertex and
    /// index buffers, the tree and its leaves).
    [[nodiscard]] long long bytes() const { return bytes_.load(); }
    ~EmbreeMesh()
    {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    [[nodiscard]] bool hit(const Ray<T>& ray) const { return bench::embree_closest(scene_, ray) < infinity<T>; }
    [[nodiscard]] bool occluded(const Ray<T>& ray, T end) const { return bench::embree_occluded(scene_, ray, end); }
    /// Rays [first, first + 8) of `rays` (fewer at the end) as one packet: the hits among them.
    [[nodiscard]] long hit8(const std::vector<Ray<T>>& rays, const std::vector<T>* ends, std::size_t first) const
    {
        alignas(32) int valid[8];
        alignas(32) RTCRayHit8 rh{};
        for (std::size_t j = 0; j < 8; ++j) {
            const std::size_t i = first + j;
            valid[j] = i < rays.size() ? -1 : 0;
            const Ray<T>& r = rays[i < rays.size() ? i : first];
            rh.ray.org_x[j] = r.origin.x, rh.ray.org_y[j] = r.origin.y, rh.ray.org_z[j] = r.origin.z;
            rh.ray.dir_x[j] = r.direction.x, rh.ray.dir_y[j] = r.direction.y, rh.ray.dir_z[j] = r.direction.z;
            rh.ray.tnear[j] = 0, rh.ray.tfar[j] = ends ? (*ends)[i < rays.size() ? i : first] : infinity<T>, rh.ray.mask[j] = ~0u;
            rh.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID;
        }
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        long hits = 0;
        if (ends) {
            rtcOccluded8(valid, scene_, &context, &rh.ray);
            for (int j = 0; j < 8; ++j) hits += valid[j] != 0 && rh.ray.tfar[j] < 0;
        } else {
            rtcIntersect8(valid, scene_, &context, &rh);
            for (int j = 0; j < 8; ++j) hits += valid[j] != 0 && rh.hit.geomID[j] != RTC_INVALID_GEOMETRY_ID;
        }
        return hits;
    }

private:
    static bool count_bytes(void* sum, ssize_t bytes, bool) noexcept
    {
        static_cast<std::atomic<long long>*>(sum)->fetch_add(bytes);
        return true;
    }

    std::atomic<long long> bytes_{0};
    RTCDevice device_;
    RTCScene scene_ = nullptr;
};
#endif

} // namespace

int main(int argc, char** argv)
{
    if (argc < 5) {
        std::fprintf(stderr, "usage: bench_mesh_rays bunny.obj bunny|sphere|terrain primary|bounce|shadow|leak scene|mesh|embree[-hq|-robust|-compact|8] [passes] [embree-isa]\n");
        return 2;
    }
    const std::string kind = argv[3], query = argv[4];
    const int passes = argc > 5 ? std::atoi(argv[5]) : 5;
    const bool embree_query = query == "embree" || query == "embree-hq" || query == "embree-robust" || query == "embree-compact" || query == "embree8";
    if ((kind != "primary" && kind != "bounce" && kind != "shadow" && kind != "leak") || (query != "scene" && query != "mesh" && !embree_query) || passes < 1) {
        std::fprintf(stderr, "bench_mesh_rays: rays must be primary, bounce, shadow or leak, query scene, mesh or embree[-hq|-robust|-compact|8], passes >= 1; got '%s' '%s' %d\n",
                     kind.c_str(), query.c_str(), passes);
        return 2;
    }
#if !PRISM_BENCH_EMBREE
    if (embree_query) {
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
    if (kind == "leak") {
        // Rays that must hit a closed mesh: from points inside it through each of its
        // vertices and each edge's midpoint (where a test that is not watertight lets
        // rays through), counted as misses.
        if (std::string(argv[2]) != "sphere") {
            std::fprintf(stderr, "bench_mesh_rays: leak rays are for the closed sphere, got '%s'\n", argv[2]);
            return 2;
        }
        rays.clear();
        const Vec3<T> inside[] = {{0, 0, 0}, {T(0.1), T(-0.2), T(0.3)}, {T(-0.45), T(0.05), T(0.2)}};
        for (const Vec3<T>& o : inside) {
            for (const Vec3<T>& p : buffers.positions) rays.push_back({o, normalize(p - o)});
            for (const TriangleIndices& f : buffers.triangles)
                for (int i = 0; i < 3; ++i) {
                    const Vec3<T> mid = (buffers.positions[f[std::size_t(i)]] + buffers.positions[f[std::size_t((i + 1) % 3)]]) * T(0.5);
                    rays.push_back({o, normalize(mid - o)});
                }
        }
    } else if (kind != "primary") {
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
    if (embree_query) embree.emplace(buffers, argc > 6 ? argv[6] : "", query);
    if (embree_query) std::printf("memory: Embree %.2f MB (its buffers, tree and leaves)\n", double(embree->bytes()) / 1e6);
    else std::printf("memory: prism %.2f MB (its corner blocks, tree and leaf order), %.2f MB of positions and indices given\n", double(mesh.memory_bytes()) / 1e6,
                     double(buffers.positions.size() * sizeof(buffers.positions[0]) + buffers.triangles.size() * sizeof(buffers.triangles[0])) / 1e6);
#endif
    long hits = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int pass = 0; pass < passes; ++pass) {
#if PRISM_BENCH_EMBREE
        if (embree && query == "embree8") {
            for (std::size_t i = 0; i < rays.size(); i += 8) hits += embree->hit8(rays, kind == "shadow" ? &ends : nullptr, i);
            continue;
        }
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
    if (kind == "leak") std::printf("leaks: %ld of %zu rays from inside the closed mesh missed it\n", long(rays.size()) * passes - hits, rays.size() * std::size_t(passes));
    return 0;
}
