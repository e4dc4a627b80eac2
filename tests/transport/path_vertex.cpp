// SPDX-License-Identifier: MIT
#include <prism/transport/path_vertex.hpp>
#include <prism/prism.hpp>

#include "../effort.hpp"
#include "guide_material.hpp" // docs/guide.md's recipe for a material (ClearCoat)

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace prism;

namespace {

/// A crossing of the plane z = 0 at the origin, its normal +z, by a path arriving along d
/// (from above when d.z < 0: entering).
template <Scalar T>
Crossing<T> crossing_for(const Vec3<T>& d)
{
    return Crossing<T>::flat(T(1), {0, 0, 0}, {0, 0, 0}, {0, 0, 1}, d.z < 0);
}

/// Checks a material's vertex against itself and against the vertex of the reversed path,
/// over `count` draws from an arrival at `theta` degrees: every non-delta draw's weight is
/// value's f cos / pdf and its densities value's; the reverse density of each direction is
/// the forward density of the path that arrives along it (reciprocity of the draws'
/// bookkeeping, not of the BSDF); and the non-delta densities integrate, over uniform
/// directions on the sphere, to the share of draws that give a non-delta direction (a
/// draw that fails its side test has no density anywhere).
template <class M>
void check_vertex(const M& material, double theta, const std::string& name, int count = 20000)
{
    using T = typename M::scalar_type;
    CAPTURE(name);
    CAPTURE(theta);
    const double t = theta * pi<double> / 180;
    const Vec3<T> d{T(std::sin(t)), T(0), T(-std::cos(t))};
    const Crossing<T> c = crossing_for(d);
    Random rng(11, 3);
    int smooth = 0, drawn = 0;
    for (const Transport mode : {Transport::radiance, Transport::importance}) {
        const SurfaceVertex<M> vertex(material, c, d, mode);
        for (int i = 0; i < count; ++i) {
            const auto s = vertex.sample(rng);
            if (!s) continue;
            if (mode == Transport::radiance) ++drawn;
            if (s->delta) {
                if (mode == Transport::radiance) ++smooth;
                CHECK(s->pdf_forward == 1.0);
                continue;
            }
            const VertexValue<T> v = vertex.value(s->direction);
            REQUIRE(v.pdf_forward > 0);
            const double eps = sizeof(T) == 4 ? 1e-4 : 1e-9;
            CHECK(s->pdf_forward == doctest::Approx(v.pdf_forward).epsilon(eps));
            CHECK(s->pdf_reverse == doctest::Approx(v.pdf_reverse).epsilon(eps));
            for (int k = 0; k < 3; ++k) CHECK(s->weight[k] == doctest::Approx(v.f[k] * v.cos / v.pdf_forward).epsilon(eps));
            // The reversed path: it arrives along -direction (from the side it leaves to).
            const Crossing<T> back = crossing_for<T>(-s->direction);
            const SurfaceVertex<M> reversed(material, back, -s->direction, mode);
            CHECK(reversed.value(-d).pdf_forward == doctest::Approx(v.pdf_reverse).epsilon(eps));
        }
    }
    // The densities' integral over the sphere, by the midpoint rule in (theta, phi).
    const SurfaceVertex<M> vertex(material, c, d, Transport::radiance);
    double integral = 0;
    const int nt = 1500, nphi = 400; // (a quadrature: its resolution is not an effort to cut under sanitizers)
    for (int i = 0; i < nt; ++i)
        for (int j = 0; j < nphi; ++j) {
            const double a = (i + 0.5) * pi<double> / nt, phi = (j + 0.5) * 2 * pi<double> / nphi;
            const Vec3<T> w(T(std::sin(a) * std::cos(phi)), T(std::sin(a) * std::sin(phi)), T(std::cos(a)));
            integral += double(vertex.value(w).pdf_forward) * std::sin(a) * (pi<double> / nt) * (2 * pi<double> / nphi);
        }
    CHECK(integral == doctest::Approx(double(drawn - smooth) / double(count)).epsilon(test::resolved(0.02)));
}

} // namespace

TEST_CASE("a path vertex's draws, values and densities agree, both ways, for diffuse, glossy, frosted glass and a diffuse lobe beside a mirror")
{
    for (const double theta : {0.0, 40.0, 75.0}) {
        check_vertex(Diffuse<double>{.albedo = {.color = Rgb<double>(0.6)}, .kd = 1, .ka = 0}, theta, "diffuse");
        check_vertex(RoughConductor<double>{.fresnel = {.kr = Rgb<double>(0.9)}, .roughness = 0.3}, theta, "rough metal");
        check_vertex(RoughDielectric<double>{.ior = 1.5, .roughness = 0.4}, theta, "frosted glass");
        check_vertex(CoatedDiffuse<double>({.color = Rgb<double>(0.5)}, {.ior = 1.5, .roughness = 0.0}), theta, "diffuse under a smooth coat");
        check_vertex(ClearCoat{.base = Rgb<float>(0.4f), .coat = 0.3f}, theta, "the guide's diffuse lobe beside a mirror (ClearCoat)");
    }
}

TEST_CASE("a path vertex on a mirror or clean glass has no non-delta lobe: not connectible, every draw a delta")
{
    const Vec3<double> d = normalize(Vec3<double>{0.3, 0, -1});
    const Crossing<double> c = crossing_for(d);
    Random rng(2, 2);
    const Dielectric<double> glass{.ior = 1.5};
    const SurfaceVertex<Dielectric<double>> vertex(glass, c, d, Transport::radiance);
    CHECK_FALSE(vertex.connectible());
    CHECK(vertex.value({0, 0, 1}).black());
    int reflected = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const auto s = vertex.sample(rng);
        REQUIRE(s);
        CHECK(s->delta);
        reflected += s->direction.z > 0;
    }
    // Reflected with the probability of Fresnel's reflectance at this angle (4.0 % near normal incidence).
    const double f = 0.04;
    CHECK(double(reflected) / n == doctest::Approx(f).epsilon(0.25));
}

TEST_CASE("a path vertex on dispersive glass refracts at its wavelength's index (Snell's law with Sellmeier's n), and white light at n_d")
{
    const Vec3<double> d = normalize(Vec3<double>{0.6, 0, -1});
    const Crossing<double> c = crossing_for(d);
    const DispersiveDielectric<double> flint{.glass = glass::f2<double>};
    for (const double nm : {0.0, 420.0, 650.0}) {
        CAPTURE(nm);
        const double n = nm > 0 ? glass::f2<double>.index(nm) : glass::f2<double>.index(fraunhofer::d);
        const Vec3<double> want = *refract(d, c.facing_normal(), n);
        const SurfaceVertex<DispersiveDielectric<double>> vertex(flint, c, d, Transport::radiance, 1.0, nm);
        Random rng(3, 3);
        int refracted = 0;
        for (int i = 0; i < 200; ++i) {
            const auto s = vertex.sample(rng);
            REQUIRE(s);
            if (s->direction.z > 0) continue;
            ++refracted;
            CHECK(s->direction.x == doctest::Approx(want.x).epsilon(1e-12));
            CHECK(s->direction.z == doctest::Approx(want.z).epsilon(1e-12));
        }
        CHECK(refracted > 150);
    }
    // The two wavelengths bend apart: blue more than red.
    const auto bent = [&](double nm) { return refract(d, c.facing_normal(), glass::f2<double>.index(nm))->x; };
    CHECK(bent(420) < bent(650) - 0.005);
}
