// SPDX-License-Identifier: MIT
#include <prism/core/random.hpp>
#include <prism/optics/fresnel.hpp>
#include <prism/optics/refract.hpp>

#include <doctest/doctest.h>

#include <cmath>

using doctest::Approx;

namespace {
double radians(double degrees) { return degrees * std::acos(-1.0) / 180; }
} // namespace

#if PRISM_CONSTEXPR_VECTORS
static_assert(prism::fresnel_dielectric(1.0, 1.5) > 0.0399 && prism::fresnel_dielectric(1.0, 1.5) < 0.0401);
#endif

TEST_CASE_TEMPLATE("glass n = 1.5 against textbook values", T, float, double)
{
    // Normal incidence: ((n - 1) / (n + 1))^2 = 0.04.
    CHECK(prism::fresnel_dielectric(T(1), T(1.5)) == Approx(0.04).epsilon(1e-6));
    // Brewster's angle atan(1.5) = 56.31 deg: R_p vanishes, R_s = 0.1479.
    const auto brewster = prism::fresnel_dielectric_polarised(T(std::cos(radians(56.309932474))), T(1.5));
    CHECK(brewster.p < T(1e-7));
    CHECK(brewster.s == Approx(0.14793).epsilon(1e-3));
    // 45 degrees: R_s = 0.0920, R_p = 0.00847 (Hecht, Optics, fig. 4.49 values).
    const auto at45 = prism::fresnel_dielectric_polarised(T(std::cos(radians(45))), T(1.5));
    CHECK(at45.s == Approx(0.0920).epsilon(2e-3));
    CHECK(at45.p == Approx(0.00847).epsilon(5e-3));
    // Grazing incidence reflects everything.
    CHECK(prism::fresnel_dielectric(T(0), T(1.5)) == Approx(1));
}

TEST_CASE_TEMPLATE("total internal reflection beyond the critical angle 41.81 deg going out of glass", T, float, double)
{
    const T eta = T(1) / T(1.5);
    CHECK(prism::fresnel_dielectric(T(std::cos(radians(41.9))), eta) == T(1));
    CHECK(prism::fresnel_dielectric(T(std::cos(radians(60))), eta) == T(1));
    CHECK(prism::fresnel_dielectric(T(std::cos(radians(41.7))), eta) < T(1));
    // Going in there is no critical angle.
    CHECK(prism::fresnel_dielectric(T(std::cos(radians(89))), T(1.5)) < T(1));
}

TEST_CASE("Stokes reciprocity: reflectance is the same both ways through an interface")
{
    for (double degrees = 0; degrees < 89.5; degrees += 2.5) {
        const double cos_i = std::cos(radians(degrees));
        const double sin_t = std::sin(radians(degrees)) / 1.5;
        const double cos_t = std::sqrt(1 - sin_t * sin_t);
        CHECK(prism::fresnel_dielectric(cos_i, 1.5) == Approx(prism::fresnel_dielectric(cos_t, 1 / 1.5)).epsilon(1e-12));
    }
}

TEST_CASE("Schlick stays within its known error of the exact equations, both ways")
{
    // Brute-force maximum over cos in [0, 1] for n = 1.5 is 0.0357 (at grazing angles);
    // going out it must use cos_t, otherwise the error near the critical angle is 0.96.
    double worst_in = 0, worst_out = 0, worst_naive = 0;
    const double eta = 1.5;
    const double r0 = 0.04;
    for (int i = 0; i <= 100000; ++i) {
        const double c = i / 100000.0;
        worst_in = std::max(worst_in, std::abs(prism::fresnel_schlick(c, eta) - prism::fresnel_dielectric(c, eta)));
        worst_out = std::max(worst_out, std::abs(prism::fresnel_schlick(c, 1 / eta) - prism::fresnel_dielectric(c, 1 / eta)));
        const double naive = r0 + (1 - r0) * std::pow(1 - c, 5); // Schlick with cos_i going out
        worst_naive = std::max(worst_naive, std::abs(naive - prism::fresnel_dielectric(c, 1 / eta)));
    }
    CHECK(worst_in == Approx(0.0357).epsilon(0.01));
    CHECK(worst_out == Approx(0.0357).epsilon(0.01));
    CHECK(worst_naive > 0.9);
    CHECK(prism::fresnel_schlick(std::cos(radians(50.0)), 1 / eta) == 1.0); // TIR
    CHECK(prism::fresnel_schlick(1.0, eta) == Approx(0.04));
}

TEST_CASE("conductor Fresnel with a complex index")
{
    // Normal incidence: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2); gold-like n = 0.47, k = 2.83 gives 0.8151.
    CHECK(prism::fresnel_conductor(1.0, std::complex<double>(0.47, 2.83)) == Approx(0.8151389).epsilon(1e-6));
    // With k = 0 it is the dielectric formula.
    for (double c : {0.1, 0.5, 0.9})
        CHECK(prism::fresnel_conductor(c, std::complex<double>(1.5, 0)) == Approx(prism::fresnel_dielectric(c, 1.5)));
    // Metals brighten toward grazing incidence, after a shallow dip of R_p near the
    // principal angle (about 83 deg for n = 1.2, k = 7).
    const std::complex<double> aluminium(1.2, 7.0);
    CHECK(prism::fresnel_conductor(0.12, aluminium) < prism::fresnel_conductor(1.0, aluminium));
    CHECK(prism::fresnel_conductor(0.002, aluminium) > prism::fresnel_conductor(1.0, aluminium));
    CHECK(prism::fresnel_conductor(0.0, aluminium) == Approx(1));
}

TEST_CASE_TEMPLATE("with cos_t from refraction(), both policies give the very bits of their cos_i-only forms", T, float, double)
{
    // The fast path (Snell's cos_t found once, by refraction) against its slow twin.
    prism::Random rng(12u, 12u);
    int differ = 0, refracted = 0;
    for (int i = 0; i < 200000; ++i) {
        const T u = rng.uniform<T>();
        const prism::Vec3<T> n{T(0), T(1), T(0)};
        const prism::Vec3<T> d = prism::normalize(prism::Vec3<T>{u, -(T(1) - u) - T(1e-3) * rng.uniform<T>(), rng.uniform<T>() - T(0.5)});
        for (const T eta : {T(1.5), T(1) / T(1.5), T(1.333), T(2.4), T(1) / T(2.4)}) {
            const auto r = prism::refraction(d, n, eta);
            if (!r) continue;
            ++refracted;
            const T cos_i = prism::clamp(-prism::dot(d, n), T(0), T(1));
            differ += prism::ExactFresnel::reflectance(cos_i, r->cos_t, eta) != prism::ExactFresnel::reflectance(cos_i, eta);
            differ += prism::SchlickFresnel::reflectance(cos_i, r->cos_t, eta) != prism::SchlickFresnel::reflectance(cos_i, eta);
            differ += !(r->cos_t == doctest::Approx(-prism::dot(r->direction, n)).epsilon(1e-5));
        }
    }
    CHECK(refracted > 500000);
    CHECK(differ == 0);
}
