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

TEST_CASE_TEMPLATE("Snell's law n1 sin1 = n2 sin2 over random directions", T, float, double)
{
    prism::Pcg32 rng(12u, 0u);
    const T tolerance = std::is_same_v<T, float> ? T(2e-6) : T(1e-12);
    int refracted = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3<T> n = test::random_direction<T>(rng);
        const Vec3<T> d = -test::random_hemisphere<T>(rng, n); // arrives against n
        const T n1 = T(1) + rng.uniform<T>(), n2 = T(1) + rng.uniform<T>();
        const auto t = prism::refract(d, n, n2 / n1);
        const T sin1 = prism::length(prism::cross(d, n));
        if (!t) {
            CHECK(n1 * sin1 >= n2 * (T(1) - tolerance)); // total internal reflection only past the critical angle
            continue;
        }
        ++refracted;
        CHECK(prism::length(*t) == doctest::Approx(1).epsilon(tolerance * 4));
        const T sin2 = prism::length(prism::cross(*t, n));
        CHECK(std::abs(n1 * sin1 - n2 * sin2) <= tolerance * 4);
        CHECK(prism::dot(*t, n) < T(0));                                   // goes through
        CHECK(std::abs(prism::dot(*t, prism::cross(d, n))) <= tolerance * 4); // stays in the plane of incidence
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
