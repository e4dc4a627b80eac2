// SPDX-License-Identifier: MIT
// Input validation for constructors: a clear std::invalid_argument naming the parameter,
// and an allocation_error saying what was asked for when it cannot fit in memory.
//
// These run when a scene is built, never on a hot path. In a constant expression a
// failed check is a compile error, since a throw cannot be constant-evaluated.
#pragma once

#include <prism/core/math.hpp>

#include <cstdio>
#include <limits>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#if __has_include(<unistd.h>)
#include <unistd.h>
#endif

namespace prism {

/// Thrown when memory for something the user asked for cannot be had: a std::bad_alloc
/// that says what was asked for and how much memory it needs.
class allocation_error : public std::bad_alloc {
public:
    /// An error that says what was asked for and how much memory it needed.
    explicit allocation_error(std::string message) : message_(std::move(message)) {}
    /// The message given at construction.
    [[nodiscard]] const char* what() const noexcept override { return message_.c_str(); }

private:
    std::string message_;
};

} // namespace prism

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

/// The machine's physical memory in bytes (0 where it cannot be told).
[[nodiscard]] inline double physical_memory() noexcept
{
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGESIZE)
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0) return double(pages) * double(page);
#endif
    return 0;
}

/// "12.0 GiB", "40.5 MiB", "812 bytes": a byte count for messages.
[[nodiscard]] inline std::string describe_bytes(double bytes)
{
    char text[64];
    if (bytes >= 1024.0 * 1024.0 * 1024.0) std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
    else if (bytes >= 1024.0 * 1024.0) std::snprintf(text, sizeof text, "%.1f MiB", bytes / (1024.0 * 1024.0));
    else if (bytes >= 1024.0) std::snprintf(text, sizeof text, "%.1f KiB", bytes / 1024.0);
    else std::snprintf(text, sizeof text, "%.0f bytes", bytes);
    return text;
}

/// Refuse, before allocating, what needs more than the machine's physical memory: such
/// an allocation may succeed lazily and end the process later, when its pages are
/// touched. `what` says what was asked for.
inline void require_memory(const std::string& what, double bytes)
{
    if (const double memory = physical_memory(); memory > 0 && bytes > memory)
        throw allocation_error("prism: " + what + " needs " + describe_bytes(bytes) + ", more than this machine's " + describe_bytes(memory));
}

} // namespace prism::detail
