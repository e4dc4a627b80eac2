// SPDX-License-Identifier: MIT
#include <prism/integrator/photon_mapper.hpp>
#include <prism/prism.hpp>

#include <doctest/doctest.h>

using namespace prism;

TEST_CASE("the photon mapper's direct light is Whitted's: one radiometric convention")
{
    // A lit floor alone: every photon bouncing off it escapes, so the global map holds
    // only direct photons (left out of the indirect estimate) and there are no caustics.
    const Scene scene{Lights{PointLight<float>{.position = {0.5f, 3, -1}, .intensity = Rgb<float>(20)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = {0.7f, 0.5f, 0.3f}}, .kd = 0.9f, .ka = 0}}};
    const Whitted whitted(scene);
    const PhotonMapper mapper(scene, {.photons = {.global_photons = 20000, .caustic_photons = 0}, .gather_rays = 0});
    Pcg32 rng(1u, 1u);
    for (float x : {-1.0f, 0.0f, 0.7f, 2.0f}) {
        const Ray<float> ray{{x, 1, 2}, normalize(Vec3<float>{0, -1, -1})};
        const Rgb<float> a = whitted.radiance(ray), b = mapper.radiance(ray, rng);
        for (int c = 0; c < 3; ++c) CHECK(b[c] == doctest::Approx(a[c]).epsilon(1e-5));
    }
}

TEST_CASE("indirect light: a white wall facing a lit red floor turns red")
{
    // A white wall 3 high at x = 0, its face toward +x; the light is high behind it at
    // (-2, 6, 0), so it never sees that face, but lights the red floor beyond x = 2
    // (past the wall's shadow). Whatever lights the face came off the floor: red.
    const Scene scene{
        Lights{PointLight<float>{.position = {-2, 6, 0}, .intensity = Rgb<float>(200)}},
        Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = {0.8f, 0.05f, 0.05f}}, .kd = 1, .ka = 0}},
        Object{Box<float>({-0.2f, 0, -5}, {0, 3, 5}), Diffuse<float>{.albedo = {.color = Rgb<float>(0.8f)}, .kd = 1, .ka = 0}}};
    const Ray<float> at_face{{3, 1, 0.3f}, normalize(Vec3<float>{-1, 0, -0.1f})};
    // Whitted, with direct light only, sees the face black.
    CHECK(Whitted(scene).radiance(at_face) == Rgb<float>(0.0f));
    const PhotonMapper mapper(scene, {.photons = {.global_photons = 200000, .caustic_photons = 0}, .global = {.radius = 0.3f, .excluded = Photon::direct | Photon::caustic}, .gather_rays = 0});
    Pcg32 rng(2u, 2u);
    const Rgb<float> wall = mapper.radiance(at_face, rng);
    CHECK(wall.x > 0.005f);
    CHECK(wall.x > 5 * wall.y); // colour bleeding: the wall takes the floor's red
    // Final gathering sees the same light.
    const PhotonMapper gathering(scene, {.photons = {.global_photons = 200000, .caustic_photons = 0}, .gather_rays = 256});
    const Rgb<float> gathered = gathering.radiance(at_face, rng);
    CHECK(gathered.x > 5 * gathered.y);
    CHECK(gathered.x == doctest::Approx(wall.x).epsilon(0.3)); // two estimates of one integral, within their noise
}
