// SPDX-License-Identifier: MIT
// Input validation for constructors: a clear std::invalid_argument naming the parameter.
//
// These run when a scene is built, never on a hot path. In a constant expression a
// failed check is a compile error, since a throw cannot be constant-evaluated.
#pragma once

#include <prism/core/math.hpp>

#include <limits>

#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace prism::detail {

template <class... Parts>
[[noreturn]] inline void throw_invalid(const Parts&... parts)
{
    std::ostringstream message;
    message.precision(9);
    message << "prism: ";
    (message << ... << parts);
    throw std::invalid_argument(message.str());
}

template <Scalar T>
inline std::string describe(const Vec3<T>& v)
{
    std::ostringstream out;
    out.precision(9);
    out << '(' << v.x << ", " << v.y << ", " << v.z << ')';
    return out.str();
}

template <Scalar T>
constexpr void require_finite(std::string_view name, T value)
{
    if (!is_finite(value)) throw_invalid(name, " must be finite, got ", value);
}

template <Scalar T>
constexpr void require_finite(std::string_view name, const Vec3<T>& value)
{
    if (!is_finite(value)) throw_invalid(name, " must be finite, got ", describe(value));
}

template <Scalar T>
constexpr void require_positive(std::string_view name, T value)
{
    if (!(is_finite(value) && value > T(0))) throw_invalid(name, " must be finite and > 0, got ", value);
}

template <Scalar T>
constexpr void require_non_negative(std::string_view name, T value)
{
    if (!(is_finite(value) && value >= T(0))) throw_invalid(name, " must be finite and >= 0, got ", value);
}

template <Scalar T>
constexpr void require_non_negative(std::string_view name, const Vec3<T>& value)
{
    if (!(is_finite(value) && value.x >= T(0) && value.y >= T(0) && value.z >= T(0)))
        throw_invalid(name, " must be finite and >= 0 in every channel, got ", describe(value));
}

/// The lengths a shape may have in T: their squares, and squares of distances a few
/// times as large, must be normal numbers (float: about 1.7e-18 to 1.2e18).
template <Scalar T>
inline constexpr T smallest_length = T(16) * prism::sqrt(std::numeric_limits<T>::min());
template <Scalar T>
inline constexpr T largest_length = prism::sqrt(std::numeric_limits<T>::max()) / T(16);

/// A length (a radius, a semi-axis) within [smallest_length, largest_length].
template <Scalar T>
constexpr void require_length(std::string_view name, T value)
{
    if (!(value >= smallest_length<T> && value <= largest_length<T>))
        throw_invalid(name, " must be in [", smallest_length<T>, ", ", largest_length<T>, "] for this precision (its square must be a normal number), got ", value);
}

template <Scalar T>
constexpr void require_nonzero(std::string_view name, const Vec3<T>& value)
{
    require_finite(name, value);
    if (value.x == T(0) && value.y == T(0) && value.z == T(0)) throw_invalid(name, " must not be the zero vector");
}

} // namespace prism::detail
