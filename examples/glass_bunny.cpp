// SPDX-License-Identifier: MIT
// glass_bunny: the Stanford bunny (a closed 3674-triangle mesh, assets/bunny.obj) in
// glass on a checkered floor under a point light, photon-mapped: the bunny focuses the
// light into a caustic inside its shadow. Around it, twelve small clay bunnies: one mesh
// and one Bvh shared by twelve transforms (instances, a two-level hierarchy). The file
// has no normals; smooth vertex normals (vertex_normals) shade it.
#include "cli.hpp"
#include "methods.hpp"

#include <prism/prism.hpp>
#include <prism/io/mesh.hpp>

#ifndef PRISM_ASSET_DIR
#error "PRISM_ASSET_DIR names the folder that holds bunny.obj (examples/CMakeLists.txt sets it)"
#endif

int main(int argc, char** argv)
{
    return examples::run([&] {
        using namespace prism;
        examples::Options options;
        options.images = {"glass_bunny"}; // checked before rendering, written together after
        options.render.width = 640;
        options.render.height = 400;
        options.render.spp = 4;
        options.photons = 100000;
        options.caustic_photons = 1000000;
        options.method = "direct"; // one light over an open floor: little indirect light to gather
        if (!examples::parse(argc, argv, options, "a glass Stanford bunny's caustic on a checkered floor, with instanced clay bunnies (photon mapping)",
                             {.photons = true}))
            return 0;
        // The bunny is 9.66 tall with its feet at y = 0 (to 0.003): 2.1 tall here.
        // The file has no normals: smooth ones from the faces around each vertex, so the
        // glass refracts as a smooth bunny would (a faceted one breaks the caustic into
        // the facets' little images).
        MeshBuffers<float> buffers = load_obj<float>(std::filesystem::path(PRISM_ASSET_DIR) / "bunny.obj");
        buffers.normals = vertex_normals(buffers);
        const TriangleMesh<float> bunny(buffers);
        const Transform<float> big = Transform<float>::scale(Vec3<float>(0.22f)).then(Transform<float>::rotate_y(-20)).then(Transform<float>::translate({0, 0.001f, 0}));
        ObjectArray<Transformed<TriangleMesh<float>>, Diffuse<float>> clay;
        for (int i = 0; i < 12; ++i) {
            const float angle = 30.0f * float(i) + 10;
            const float a = angle * pi<float> / 180;
            const Transform<float> place = Transform<float>::scale(Vec3<float>(0.05f))
                                               .then(Transform<float>::rotate_y(-angle + 90))
                                               .then(Transform<float>::translate({2.6f * std::cos(a), 0.0002f, 2.6f * std::sin(a)}));
            const float hue = float(i) / 12;
            clay.items.emplace_back(Transformed<TriangleMesh<float>>(bunny, place),
                                    Diffuse<float>{.albedo = {.color = Rgb<float>(0.55f + 0.3f * std::cos(6.283f * hue), 0.55f + 0.3f * std::cos(6.283f * (hue - 0.33f)),
                                                                        0.55f + 0.3f * std::cos(6.283f * (hue - 0.67f)))}});
        }
        const Scene scene{
            Lights{PointLight<float>{.position = {-3, 7, -1}, .intensity = Rgb<float>(110)}},
            Object{Plane<float>({0, 1, 0}, 0),
                   Diffuse<float, Checker<float>>{.albedo = {.even = Rgb<float>(0.8f), .odd = Rgb<float>(0.45f), .size = 0.5f}, .kd = 1, .ka = 0}},
            Object{Transformed<TriangleMesh<float>>(bunny, big), Dielectric<float>{.ior = 1.5f}},
            std::move(clay),
        };
        const Camera<float> camera{.position = {4.2f, 3.6f, 6.2f}, .look_at = {0.5f, 0.6f, 0.3f}, .up = {0, 1, 0}, .fov = 45};
        examples::save(examples::render_by_method("glass_bunny", scene, camera, options), options);
        return 0;
    });
}
