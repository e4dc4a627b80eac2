// SPDX-License-Identifier: MIT
// Generated triangle meshes: a geodesic sphere, a box, a height field.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/geometry/triangle_mesh.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace prism {

/// Smooth normals for `mesh`, one per position: the normals of the triangles around
/// each vertex weighted by their angles there (Thuermer & Wuethrich 1998, so a vertex's
/// normal does not depend on how its neighbourhood is split into triangles). A position
/// that no non-degenerate triangle uses gets (0, 1, 0): it is never shaded.
template <Scalar T>
[[nodiscard]] std::vector<Vec3<T>> vertex_normals(const MeshBuffers<T>& mesh)
{
    std::vector<Vec3<double>> sum(mesh.positions.size(), Vec3<double>(0));
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const TriangleIndices& v = mesh.triangles[f];
        for (const std::uint32_t i : v)
            if (i >= mesh.positions.size()) detail::throw_invalid("vertex_normals triangle ", f, " has vertex index ", i, ", past the ", mesh.positions.size(), " positions");
        const std::array<Vec3<double>, 3> p = {Vec3<double>(mesh.positions[v[0]]), Vec3<double>(mesh.positions[v[1]]), Vec3<double>(mesh.positions[v[2]])};
        const Vec3<double> face = cross(p[1] - p[0], p[2] - p[0]);
        const double area2 = length(face);
        if (!(area2 > 0)) continue;
        for (std::size_t k = 0; k < 3; ++k) {
            const Vec3<double> e1 = p[(k + 1) % 3] - p[k], e2 = p[(k + 2) % 3] - p[k];
            // The corner's angle, from atan2 (accurate at small and large angles alike).
            const double angle = std::atan2(length(cross(e1, e2)), dot(e1, e2));
            sum[v[k]] += face * (angle / area2);
        }
    }
    std::vector<Vec3<T>> out(sum.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        const double len = length(sum[i]);
        out[i] = len > 0 ? Vec3<T>(sum[i] / len) : Vec3<T>(T(0), T(1), T(0));
    }
    return out;
}

/// A geodesic sphere: an icosahedron with each triangle split in four `subdivisions`
/// times, every vertex on the sphere (20 * 4^subdivisions triangles). Closed.
template <Scalar T = float>
[[nodiscard]] MeshBuffers<T> icosphere(const Vec3<T>& center, T radius, int subdivisions)
{
    detail::require_finite("icosphere center", center);
    detail::require_positive("icosphere radius", radius);
    if (subdivisions < 0 || subdivisions > 10) detail::throw_invalid("icosphere subdivisions must be in [0, 10], got ", subdivisions);
    const double g = (1 + std::sqrt(5.0)) / 2;
    std::vector<Vec3<double>> unit = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                      {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (auto& v : unit) v = normalize(v);
    std::vector<TriangleIndices> faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                          {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                                          {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
        const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto [at, fresh] = middle.try_emplace(key, std::uint32_t(unit.size()));
            if (fresh) unit.push_back(normalize(unit[a] + unit[b]));
            return at->second;
        };
        std::vector<TriangleIndices> finer;
        finer.reserve(4 * faces.size());
        for (const auto& [a, b, c] : faces) {
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({b, bc, ab});
            finer.push_back({c, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    MeshBuffers<T> out;
    out.positions.reserve(unit.size());
    for (const auto& v : unit) out.positions.push_back(center + radius * Vec3<T>(v));
    out.triangles = std::move(faces);
    return out;
}

/// The box [lo, hi] as 12 triangles. Closed.
template <Scalar T = float>
[[nodiscard]] MeshBuffers<T> box_mesh(const Vec3<T>& lo, const Vec3<T>& hi)
{
    detail::require_finite("box_mesh lo", lo);
    detail::require_finite("box_mesh hi", hi);
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) detail::throw_invalid("box_mesh lo must be below hi on every axis, got ", detail::describe(lo), " and ", detail::describe(hi));
    MeshBuffers<T> out;
    for (int k = 0; k < 8; ++k) out.positions.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
    // Two triangles a face, wound outward.
    out.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                     {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return out;
}

/// The surface y = height(x, z) over [x0, x1] x [z0, z1], sampled at (cells + 1)^2
/// points: 2 cells^2 triangles, facing +y. Open.
template <Scalar T = float, class Height>
[[nodiscard]] MeshBuffers<T> height_field(T x0, T x1, T z0, T z1, int cells, Height&& height)
{
    if (cells < 1 || cells > 16384) detail::throw_invalid("height_field cells must be in [1, 16384], got ", cells);
    if (!(x0 < x1)) detail::throw_invalid("height_field x0 must be below x1, got ", x0, " and ", x1);
    if (!(z0 < z1)) detail::throw_invalid("height_field z0 must be below z1, got ", z0, " and ", z1);
    MeshBuffers<T> out;
    const auto n = std::uint32_t(cells);
    for (std::uint32_t j = 0; j <= n; ++j)
        for (std::uint32_t i = 0; i <= n; ++i) {
            const T x = x0 + (x1 - x0) * T(i) / T(n), z = z0 + (z1 - z0) * T(j) / T(n);
            const T y = T(height(x, z));
            if (!is_finite(y)) detail::throw_invalid("height_field height(", x, ", ", z, ") must be finite, got ", y);
            out.positions.push_back({x, y, z});
        }
    for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            out.triangles.push_back({a, c, b});
            out.triangles.push_back({b, c, d});
        }
    return out;
}

/// The solid between the surface y = height(x, z) over [x0, x1] x [z0, z1] (sampled at
/// (cells + 1)^2 points, as height_field) and the floor y = bottom: the height field on
/// top, the floor as a grid of the same cells facing -y, and four walls, each triangle
/// facing out. Closed: a body of water under waves, a block of terrain. Throws
/// std::invalid_argument, naming the point, where the surface is not above the floor.
template <Scalar T = float, class Height>
[[nodiscard]] MeshBuffers<T> height_field_solid(T x0, T x1, T z0, T z1, int cells, T bottom, Height&& height)
{
    MeshBuffers<T> out = height_field<T>(x0, x1, z0, z1, cells, height);
    const auto n = std::uint32_t(cells), row = n + 1, floor = row * row;
    for (std::uint32_t k = 0; k < floor; ++k) {
        const Vec3<T> top = out.positions[k];
        if (!(top.y > bottom)) detail::throw_invalid("height_field_solid height(", top.x, ", ", top.z, ") = ", top.y, " must be above the bottom ", bottom);
        out.positions.push_back({top.x, bottom, top.z});
    }
    for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t a = floor + j * row + i, b = a + 1, c = a + row, d = c + 1;
            out.triangles.push_back({a, b, c});
            out.triangles.push_back({b, d, c});
        }
    // The walls: t the top's vertices along each edge, f the floor's below them.
    for (std::uint32_t k = 0; k < n; ++k) {
        const auto wall = [&](std::uint32_t t0, std::uint32_t t1, bool flip) {
            const std::uint32_t f0 = t0 + floor, f1 = t1 + floor;
            if (!flip) {
                out.triangles.push_back({t0, t1, f0});
                out.triangles.push_back({t1, f1, f0});
            } else {
                out.triangles.push_back({t1, t0, f0});
                out.triangles.push_back({t1, f0, f1});
            }
        };
        wall(k, k + 1, false);                       // z = z0, facing -z
        wall(n * row + k, n * row + k + 1, true);    // z = z1, facing +z
        wall((k + 1) * row, k * row, false);         // x = x0, facing -x
        wall((k + 1) * row + n, k * row + n, true);  // x = x1, facing +x
    }
    return out;
}

} // namespace prism
