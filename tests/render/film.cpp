// SPDX-License-Identifier: MIT
#include <prism/render/film.hpp>

#include <doctest/doctest.h>

#include <limits>

TEST_CASE("the film never stores NaN, Inf or negative radiance")
{
    prism::Film film(2, 1);
    film.set(0, 0, prism::Rgb<double>{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -1.0});
    film.set(1, 0, prism::Rgb<double>{0.5, 1e300, 2.0}); // 1e300 overflows float: Inf
    CHECK(film.at(0, 0) == prism::Rgb<float>(0.0f));
    CHECK(film.at(1, 0).x == 0.5f);
    CHECK(film.at(1, 0).y == 0.0f);
    CHECK(film.at(1, 0).z == 2.0f);
    CHECK(film.rejected() == 4);
    CHECK_THROWS_AS(prism::Film(0, 3), std::invalid_argument);
}
