// SPDX-License-Identifier: MIT
#include <prism/optics/refract.hpp>

#include "../support.hpp"

using prism::Vec3;

TEST_CASE_TEMPLATE("reflection keeps the angle and the plane", T, float, double)
{
    const Vec3<T> d = prism::normalize(Vec3<T>{1, -1, 0});
    const Vec3<T> r = prism::reflect(d, Vec3<T>{0, 1, 0});
    CHECK(r.x == doctest::Approx(d.x));
    CHECK(r.y == doctest::Approx(-d.y));
    CHECK(r.z == T(0));
}

TEST_CASE_TEMPLATE("Snell's law n1 sin1 = n2 sin2 to 1e-6 over random directions", T, float, double)
{
    // The law is checked in double from the computed vectors, so only the refraction's
    // own rounding counts.
    const auto sine = [](const Vec3<T>& a, const Vec3<T>& b) {
        const Vec3<double> c = prism::cross(Vec3<double>(a), Vec3<double>(b));
        return prism::length(c) / (prism::length(Vec3<double>(a)) * prism::length(Vec3<double>(b)));
    };
    prism::Random rng(12u, 0u);
    int refracted = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3<T> n = test::random_direction<T>(rng);
        const Vec3<T> d = -test::random_hemisphere<T>(rng, n); // arrives against n
        const T n1 = T(1) + rng.uniform<T>(), n2 = T(1) + rng.uniform<T>();
        const auto t = prism::refract(d, n, n2 / n1);
        const double sin1 = sine(d, n);
        if (!t) {
            CHECK(n1 * sin1 >= n2 * (1 - 1e-6)); // total internal reflection only past the critical angle
            continue;
        }
        ++refracted;
        CHECK(prism::length(Vec3<double>(*t)) == doctest::Approx(1).epsilon(1e-6));
        CHECK(std::abs(n1 * sin1 - n2 * sine(*t, n)) <= 1e-6);
        CHECK(prism::dot(*t, n) < T(0));                                   // goes through
        CHECK(std::abs(prism::dot(Vec3<double>(*t), Vec3<double>(prism::cross(d, n)))) <= 1e-6); // in the plane of incidence
    }
    CHECK(refracted > 10000); // n2 / n1 is random, so many of the rays are past a critical angle
}

TEST_CASE("the refraction formula's sign: straight through at normal incidence")
{
    const auto t = prism::refract(Vec3<double>{0, 0, -1}, Vec3<double>{0, 0, 1}, 1.5);
    REQUIRE(t);
    CHECK(t->z == doctest::Approx(-1));
    CHECK_FALSE(prism::refract(prism::normalize(Vec3<double>{1, 0, -1}), Vec3<double>{0, 0, 1}, 1 / 1.5)); // 45 deg > 41.8 deg
}
