// SPDX-License-Identifier: MIT
// Embree 3's side of the mesh benchmarks (bench_bvh_vs_embree, bench_mesh_rays): a prism
// mesh put into an Embree scene, and Embree's single-ray queries on a prism ray. Only for
// programs built where Embree (libembree-dev) is installed.
#pragma once

#include <prism/geometry/triangle_mesh.hpp>

#include <embree3/rtcore.h>

namespace bench {

/// `mesh` as one triangle geometry of `scene`, built at `quality` when the scene is committed.
inline void embree_add_triangles(RTCDevice device, RTCScene scene, const prism::MeshBuffers<float>& mesh, RTCBuildQuality quality)
{
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(g, quality);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) v[3 * i] = mesh.positions[i].x, v[3 * i + 1] = mesh.positions[i].y, v[3 * i + 2] = mesh.positions[i].z;
    auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.triangles.size()));
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) f[3 * i] = mesh.triangles[i][0], f[3 * i + 1] = mesh.triangles[i][1], f[3 * i + 2] = mesh.triangles[i][2];
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
}

/// The t of the closest hit in `scene` (rtcIntersect1), or infinity.
[[nodiscard]] inline float embree_closest(RTCScene scene, const prism::Ray<float>& ray)
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
    rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
    rh.ray.tnear = 0, rh.ray.tfar = prism::infinity<float>, rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? prism::infinity<float> : rh.ray.tfar;
}

/// Whether anything in `scene` lies on the ray between 0 and t_max (rtcOccluded1).
[[nodiscard]] inline bool embree_occluded(RTCScene scene, const prism::Ray<float>& ray, float t_max)
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r{};
    r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
    r.tnear = 0, r.tfar = t_max, r.mask = ~0u;
    rtcOccluded1(scene, &context, &r);
    return r.tfar < 0; // Embree marks an occluded ray with tfar = -inf
}

} // namespace bench
