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
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
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

// A message is built by appending its parts as a stream with precision 9 would print them
// (numbers as printf's %.9g, integers in decimal, a bool as 1 or 0), without <sstream>:
// parsing the iostreams cost every scene a third of a second to compile, and every set of
// part types an instantiation of them.
inline void append_part(std::string& out, std::string_view part) { out += part; }
inline void append_part(std::string& out, char part) { out += part; }
inline void append_part(std::string& out, bool part) { out += part ? '1' : '0'; }
inline void append_part(std::string& out, double part)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", part);
    out += text;
}
inline void append_part(std::string& out, long long part) { out += std::to_string(part); }
inline void append_part(std::string& out, unsigned long long part) { out += std::to_string(part); }

template <class Part>
void append_any(std::string& out, const Part& part)
{
    if constexpr (std::is_same_v<Part, bool> || std::is_same_v<Part, char>) append_part(out, part);
    else if constexpr (std::is_enum_v<Part>) append_any(out, std::underlying_type_t<Part>(part));
    else if constexpr (std::is_floating_point_v<Part>) append_part(out, double(part));
    else if constexpr (std::is_integral_v<Part> && std::is_signed_v<Part>) append_part(out, static_cast<long long>(part));
    else if constexpr (std::is_integral_v<Part>) append_part(out, static_cast<unsigned long long>(part));
    else append_part(out, std::string_view(part));
}

[[noreturn]] inline void throw_invalid_message(const std::string& message) { throw std::invalid_argument(message); }

template <class... Parts>
[[noreturn]] inline void throw_invalid(const Parts&... parts)
{
    std::string message = "prism: ";
    (append_any(message, parts), ...);
    throw_invalid_message(message);
}

template <Scalar T>
inline std::string describe(const Vec3<T>& v)
{
    std::string out = "(";
    append_part(out, double(v.x));
    out += ", ";
    append_part(out, double(v.y));
    out += ", ";
    append_part(out, double(v.z));
    out += ')';
    return out;
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

/// The indices of refraction prism refracts by: 0.01 to 100. (Glass, water, diamond and
/// germanium lie between 1 and 4; at 10^-45 the relative index 1 / n is not a float and
/// refraction gives NaN.)
inline constexpr double least_index = 0.01, greatest_index = 100.0;

template <Scalar T>
constexpr void require_index(std::string_view name, T value)
{
    if (!(value >= T(least_index) && value <= T(greatest_index))) throw_invalid(name, " must be an index of refraction from 0.01 to 100, got ", value);
}

/// The sharpest cosine-power lobe prism draws: cos^n with n up to 10^6 (a lobe about 0.1
/// degrees wide). A sharper one is narrower than a float's steps of the cosine near 1
/// (6e-8) resolve, and its highlight would vanish: that is a mirror.
inline constexpr double greatest_lobe_exponent = 1e6;

template <Scalar T>
constexpr void require_lobe_exponent(std::string_view name, T value)
{
    if (!(value >= T(0) && value <= T(greatest_lobe_exponent)))
        throw_invalid(name, " must be from 0 to 1e6 (a sharper lobe is a mirror: use Mirror), got ", value);
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
