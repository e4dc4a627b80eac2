// SPDX-License-Identifier: MIT
// thin_films: soap bubbles (a water film with air on both sides, draining thinner
// towards the top) beside the same bubbles without interference, and anodised titanium
// (an oxide film 0-150 nm thick); each film by Airy's exact sum per wavelength,
// integrated against the CIE observer.
#include "cli.hpp"
#include "scenes/sphere_row.hpp"

#include <prism/prism.hpp>

#include <cmath>
#include <complex>

namespace {

using T = float;

/// A soap film's thickness: about 800 nm at the bottom of a bubble, 80 nm at the top
/// (water drains down), with swirls of +-60 nm (the film's flow). Within [20, 900] nm.
struct DrainingFilm {
    prism::Vec3<T> center;
    T radius;
    T operator()(const prism::Vec3<T>& p) const
    {
        const prism::Vec3<T> q = (p - center) / radius; // on the unit sphere
        const T swirl = T(60) * std::sin(T(7) * q.x + T(3) * std::sin(T(5) * q.z)) * std::cos(T(4) * q.z - T(2) * q.y);
        return T(440) - T(360) * q.y + swirl;
    }
};

using SoapFilm = prism::ThicknessTexture<T, DrainingFilm>;

/// The same film without interference: its two faces reflecting incoherently, grey,
/// R_film = 2 R / (1 + R) with R the air-water Fresnel reflectance (a user material).
struct IncoherentFilm {
    using scalar_type = T;
    static constexpr bool has_diffuse = false;
    static constexpr bool reflects = true;
    static constexpr bool transmits = true;
    prism::Homogeneous<T> air{};

    [[nodiscard]] T refractive_index() const noexcept { return T(1); }
    [[nodiscard]] T fresnel(T cos_i, T, T) const noexcept
    {
        const T r = prism::fresnel_dielectric(cos_i, T(1.33));
        return T(2) * r / (T(1) + r);
    }
    [[nodiscard]] prism::Rgb<T> reflection_tint() const noexcept { return prism::Rgb<T>(T(1)); }
    [[nodiscard]] prism::Rgb<T> transmission_tint() const noexcept { return prism::Rgb<T>(T(1)); }
    [[nodiscard]] const prism::Homogeneous<T>& medium() const noexcept { return air; }
    void validate() const {}
};

template <class Bubble>
auto bubble_scene(const Bubble& big, const Bubble& small)
{
    using namespace prism;
    Scene scene{
        Lights{DirectionalLight<T>{.direction = {T(-0.3), T(-0.7), T(0.65)}, .irradiance = Rgb<T>(T(3))}},
        Object{Plane<T>({T(0), T(1), T(0)}, T(0)),
               Diffuse<T, Checker<T>>{.albedo = {.even = Rgb<T>(T(0.08)), .odd = Rgb<T>(T(0.3)), .size = T(1)}}},
        Object{Sphere<T>({T(-0.6), T(1.9), T(0)}, T(1.4)), big},
        Object{Sphere<T>({T(1.7), T(1.2), T(-0.8)}, T(0.7)), small},
        // Bright panels behind the camera, for the bubbles to reflect (as a window would).
        Object{Sphere<T>({T(-4), T(4), T(14)}, T(5)), Diffuse<T>{.albedo = {.color = Rgb<T>(T(1))}}},
        Object{Sphere<T>({T(5), T(3), T(12)}, T(3)), Diffuse<T>{.albedo = {.color = {T(1), T(0.95), T(0.85)}}}},
    };
    scene.background = {T(0.02), T(0.025), T(0.04)};
    scene.ambient = Rgb<T>(T(0.25));
    return scene;
}

} // namespace

int main(int argc, char** argv)
{
    return examples::run([&] {
        examples::Options options;
        options.images = {"soap_bubble", "soap_bubble_plain", "anodised"}; // checked before rendering, written together after
        options.render.width = 640;
        options.render.height = 480;
        options.render.spp = 4;
        if (!examples::parse(argc, argv, options, "soap bubbles and anodised titanium by thin-film interference, beside them without"))
            return 0;
        using namespace prism;
        const Camera<T> bubble_camera{.position = {0, 2.2f, 7}, .look_at = {0.2f, 1.6f, 0}, .up = {0, 1, 0}, .fov = 45};
        const DrainingFilm big_film{{T(-0.6), T(1.9), T(0)}, T(1.4)}, small_film{{T(1.7), T(1.2), T(-0.8)}, T(0.7)};
        using Bubble = CoatedDielectric<T, SoapFilm>;
        const Bubble big(T(1), T(1.33), SoapFilm{big_film, T(20), T(900)}), small(T(1), T(1.33), SoapFilm{small_film, T(20), T(900)});
        const auto bubbles = bubble_scene(big, small);
        const Whitted bubble_integrator(bubbles, {.max_depth = 12});
        examples::save(examples::timed_render("soap_bubble", bubble_camera, bubble_integrator, options), options);
        const auto plain_bubbles = bubble_scene(IncoherentFilm{}, IncoherentFilm{});
        const Whitted plain_bubble_integrator(plain_bubbles, {.max_depth = 12});
        examples::save(examples::timed_render("soap_bubble_plain", bubble_camera, plain_bubble_integrator, options), options);

        // Anodised titanium: a titanium dioxide film (n = 2.4) 0, 60, 100 and 150 nm thick
        // over titanium (n = 2.16 + 2.93 i at 550 nm, Johnson & Christy 1974, one index for
        // every wavelength: prism has no spectral table for titanium).
        const Camera<T> row_camera = scenes::sphere_row_camera();
        using Anodised = Conductor<T, ThinFilmConductor<T>>;
        const std::complex<double> titanium(2.16, 2.93);
        const Anodised anodised[4] = {
            Anodised{ThinFilmConductor<T>(T(2.4), UniformThickness<T>{0}, titanium)},
            Anodised{ThinFilmConductor<T>(T(2.4), UniformThickness<T>{60}, titanium)},
            Anodised{ThinFilmConductor<T>(T(2.4), UniformThickness<T>{100}, titanium)},
            Anodised{ThinFilmConductor<T>(T(2.4), UniformThickness<T>{150}, titanium)}};
        const auto row = scenes::sphere_row(anodised);
        const Whitted row_integrator(row);
        examples::save(examples::timed_render("anodised", row_camera, row_integrator, options), options);
        return 0;
    });
}
