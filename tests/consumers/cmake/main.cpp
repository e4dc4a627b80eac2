// SPDX-License-Identifier: MIT
// Renders a small scene and checks one pixel against the analytic value.
#include <prism/prism.hpp>

#include <cmath>
#include <cstdio>
#include <string_view>

// The version the package manager found (find_package's prism_VERSION, pkg-config's
// --modversion) is the one in the header.
#ifdef PRISM_EXPECTED_VERSION
static_assert(std::string_view(PRISM_VERSION_STRING) == PRISM_EXPECTED_VERSION);
#endif
static_assert(PRISM_VERSION == PRISM_VERSION_MAJOR * 10000 + PRISM_VERSION_MINOR * 100 + PRISM_VERSION_PATCH);

int main()
{
    using namespace prism;
    static_assert(PRISM_CONSTEXPR_VECTORS == 1, "the prism target defines GLM_FORCE_PURE");
    const Scene scene{Lights{PointLight<float>{.position = {0, 2, 0}, .intensity = Rgb<float>(4)}},
                      Object{Plane<float>({0, 1, 0}, 0), Diffuse<float>{.albedo = {.color = Rgb<float>(0.5f)}}}};
    const Film film = render(Camera<float>{.position = {0, 1, 0.001f}, .look_at = {0, 0, 0}, .fov = 10}, Whitted(scene),
                             {.width = 1, .height = 1, .progress = false});
    const float expected = 0.5f / 3.14159265f * 4 / 4; // albedo / pi * I / r^2 at normal incidence
    const bool ok = std::abs(film.at(0, 0).x - expected) < 1e-3f;
    std::printf("consumer: L = %g, expected %g: %s\n", film.at(0, 0).x, expected, ok ? "ok" : "wrong");
    return ok ? 0 : 1;
}
