// SPDX-License-Identifier: MIT
#include <prism/render/film.hpp>

#include <doctest/doctest.h>

#include <limits>
#include <string>
#include <thread>
#include <vector>

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

TEST_CASE("a film too large for memory says what it needs")
{
    // 48 GiB: more than these machines have (a larger machine would allocate it).
    if (prism::detail::physical_memory() > 40.0 * (1 << 30)) return;
    try {
        prism::Film film(65536, 65536);
        FAIL("a 48 GiB film was allocated");
    } catch (const std::bad_alloc& e) {
        const std::string message = e.what();
        CHECK(message.find("65536 x 65536") != std::string::npos);
        CHECK(message.find("48.0 GiB") != std::string::npos);
    }
}

TEST_CASE("threads setting pixels count the rejected values exactly")
{
    // Regression: every render thread updated a plain counter (a data race; ThreadSanitizer
    // runs this test too).
    prism::Film film(64, 64);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&film, t] {
            for (int y = t; y < 64; y += 4)
                for (int x = 0; x < 64; ++x) film.set(x, y, prism::Rgb<float>{-1.0f, std::numeric_limits<float>::quiet_NaN(), 0.5f});
        });
    for (auto& thread : threads) thread.join();
    CHECK(film.rejected() == 2 * 64 * 64);
    const prism::Film copy = film;
    CHECK(copy.rejected() == 2 * 64 * 64);
}
