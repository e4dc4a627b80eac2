// SPDX-License-Identifier: MIT
#include <prism/core/offset.hpp>

#include "../support.hpp"

#include <limits>

TEST_CASE_TEMPLATE("gamma(n) bounds n roundings (Higham)", T, float, double)
{
    const T u = std::numeric_limits<T>::epsilon() / 2;
    CHECK(prism::gamma<T>(1) > u);
    CHECK(prism::gamma<T>(1) < T(1.000001) * u);
    CHECK(prism::gamma<T>(5) == doctest::Approx(5 * u / (1 - 5 * u)));
}

TEST_CASE_TEMPLATE("the offset origin lies beyond the error box, on the side of the new direction", T, float, double)
{
    prism::Random rng(3u, 1u);
    for (int i = 0; i < 10000; ++i) {
        const prism::Vec3<T> p = test::random_point<T>(rng, T(1000));
        const prism::Vec3<T> n = test::random_direction<T>(rng);
        const prism::Vec3<T> error = prism::abs(p) * prism::gamma<T>(5);
        const prism::Vec3<T> w = test::random_direction<T>(rng);
        const prism::Vec3<T> o = prism::offset_ray_origin(p, error, n, w);
        // Distance along the normal, in double, exceeds the projected error bound.
        const double along = (double(o.x) - p.x) * n.x + (double(o.y) - p.y) * n.y + (double(o.z) - p.z) * n.z;
        const double bound = prism::dot(prism::abs(n), error);
        if (prism::dot(w, n) < 0) CHECK(along <= -bound * 0.999);
        else CHECK(along >= bound * 0.999);
    }
}

TEST_CASE_TEMPLATE("next_float_up and next_float_down step exactly one ulp, like std::nextafter", T, float, double)
{
    for (T v : {T(0), T(-0.0), T(1), T(-1), T(1e-30), T(-3.5e20), std::numeric_limits<T>::denorm_min(), -std::numeric_limits<T>::max()}) {
        CHECK(prism::next_float_up(v) == std::nextafter(v, prism::infinity<T>));
        CHECK(prism::next_float_down(v) == std::nextafter(v, -prism::infinity<T>));
    }
    CHECK(prism::next_float_up(prism::infinity<T>) == prism::infinity<T>);
}
