// SPDX-License-Identifier: MIT
#include <prism/core/check.hpp>

#include <doctest/doctest.h>

#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

TEST_CASE("validation names the parameter and the value")
{
    CHECK_THROWS_WITH_AS(prism::detail::require_positive("Sphere radius", -2.0), "prism: Sphere radius must be finite and > 0, got -2",
                         std::invalid_argument);
    CHECK_THROWS_AS(prism::detail::require_finite("x", std::numeric_limits<float>::quiet_NaN()), std::invalid_argument);
    CHECK_THROWS_AS(prism::detail::require_nonzero("n", prism::Vec3<float>(0.0f)), std::invalid_argument);
    CHECK_NOTHROW(prism::detail::require_non_negative("c", prism::Vec3<double>(0.0)));
}

namespace {

/// What a stream with precision 9 prints for these parts: how messages read before they
/// were built without <sstream>, and the twin their text is held to.
template <class... Parts>
std::string streamed(const Parts&... parts)
{
    std::ostringstream out;
    out.precision(9);
    out << "prism: ";
    (out << ... << parts);
    return out.str();
}

template <class... Parts>
std::string thrown(const Parts&... parts)
{
    try {
        prism::detail::throw_invalid(parts...);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "did not throw";
}

enum class Level : unsigned char { low = 3 };

} // namespace

TEST_CASE("a message reads as a stream with precision 9 would print it, for every kind of part")
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (const double v : {0.0, -0.0, 1.0, -2.0, 0.1, 1.0 / 3.0, 1e20, 1.5e-300, 4.9e-324, 123456789.0, 1234567890123.0, inf, -inf,
                           std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::max()}) {
        CAPTURE(v);
        CHECK(thrown("x ", v) == streamed("x ", v));
        CHECK(thrown("x ", float(v)) == streamed("x ", float(v)));
    }
    CHECK(thrown("count ", 42, ", index ", -7L, ", size ", std::size_t(1) << 40, ", u ", 7u) == streamed("count ", 42, ", index ", -7L, ", size ", std::size_t(1) << 40, ", u ", 7u));
    CHECK(thrown(std::string("name"), std::string_view(" is "), 'c', " or ", true, false) == streamed(std::string("name"), std::string_view(" is "), 'c', " or ", true, false));
    CHECK(thrown("level ", Level::low) == "prism: level 3");
    CHECK(prism::detail::describe(prism::Vec3<float>(0.1f, -2.0f, 1e30f)) == "(0.100000001, -2, 1.00000002e+30)");
}
