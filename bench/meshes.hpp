// SPDX-License-Identifier: MIT
// The meshes the mesh benchmarks share (bench_bvh_vs_embree, bench_mesh_rays): the Stanford
// bunny scaled into [-1, 1]^3, a geodesic sphere of 327 680 triangles and a terrain of
// 999 698.
#pragma once

#include <prism/io/mesh.hpp>
#include <prism/prism.hpp>

#include <cmath>
#include <string>

namespace bench {

/// The bunny from its OBJ file, scaled into [-1, 1]^3 about its box's centre.
inline prism::MeshBuffers<float> scaled_bunny(const std::string& obj)
{
    using T = float;
    prism::MeshBuffers<T> b = prism::load_obj<T>(obj);
    prism::Aabb<T> box;
    for (const auto& p : b.positions) box = box.merged({p, p});
    const prism::Vec3<T> middle = T(0.5) * (box.lo + box.hi);
    const T scale = T(2) / prism::max_component(box.hi - box.lo);
    for (auto& p : b.positions) p = (p - middle) * scale;
    return b;
}

/// A unit geodesic sphere: an icosahedron subdivided 7 times.
inline prism::MeshBuffers<float> geodesic_sphere() { return prism::icosphere<float>({0.0f, 0.0f, 0.0f}, 1.0f, 7); }

/// Rolling hills over [-1.5, 1.5]^2, 707 x 707 samples.
inline prism::MeshBuffers<float> terrain()
{
    using T = float;
    return prism::height_field<T>(T(-1.5), T(1.5), T(-1.5), T(1.5), 707, [](T x, T z) {
        return T(0.15) * std::sin(T(7) * x) * std::cos(T(5) * z) + T(0.05) * std::sin(T(31) * x + T(17) * z) - T(0.3);
    });
}

} // namespace bench
