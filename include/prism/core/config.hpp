// SPDX-License-Identifier: MIT
// prism configuration: the PRISM_ macros and the one place GLM is included.
//
// GLM 0.9.9.8 makes vector construction and arithmetic constexpr only when its SIMD
// architecture bit is off. That bit is set when GLM_FORCE_INTRINSICS, or any of
// GLM_FORCE_SSE2 ... GLM_FORCE_AVX2, is defined, and GLM_FORCE_PURE overrides them all
// (checked here on Debian's libglm-dev 0.9.9.8 with g++ 12: a plain include is
// constexpr; one with GLM_FORCE_INTRINSICS is not). prism defines GLM_FORCE_PURE when
// it is first to include GLM, and its CMake and meson targets define it for every
// translation unit, so all of them see the same GLM. When a user included GLM earlier
// with intrinsics forced, prism still compiles and renders the same bits; only its
// constant-expression features are off, and PRISM_CONSTEXPR_VECTORS says so (0).
#pragma once

#if !defined(GLM_VERSION) && !defined(GLM_FORCE_PURE)
#define GLM_FORCE_PURE
#endif

#include <prism/version.hpp>

#include <glm/glm.hpp>

#include <cstdio>
#include <cstdlib>

#if GLM_HAS_CONSTEXPR
/// 1 when GLM vector construction and arithmetic are usable in constant expressions.
#define PRISM_CONSTEXPR_VECTORS 1
#else
#define PRISM_CONSTEXPR_VECTORS 0
#endif

/// 1 when the compiler has GCC's vector extensions (GCC and Clang do): the BVH's node
/// test and the triangle blocks' edge test use them. Without them, or with
/// PRISM_NO_VECTOR_EXTENSIONS defined, both take their scalar twins, the same arithmetic
/// lane by lane, with the same bits.
#if defined(__GNUC__) && !defined(PRISM_NO_VECTOR_EXTENSIONS)
#define PRISM_VECTOR_EXTENSIONS 1
#else
#define PRISM_VECTOR_EXTENSIONS 0
#endif

namespace prism::detail {

[[noreturn]] inline void assert_fail(const char* expression, const char* file, int line) noexcept
{
    std::fprintf(stderr, "%s:%d: prism assertion failed: %s\n", file, line, expression);
    std::abort();
}

} // namespace prism::detail

/// Precondition check: compiled out with NDEBUG unless PRISM_ENABLE_ASSERTIONS is
/// defined (an optimised build that still checks, as the test suite's sanitizer and
/// thread-sanitizer runs are); in a constant expression a failed check is a compile error
/// (assert_fail is not constexpr). PRISM_ASSERTIONS_ENABLED says which (1 or 0).
#if defined(NDEBUG) && !defined(PRISM_ENABLE_ASSERTIONS)
#define PRISM_ASSERTIONS_ENABLED 0
#define PRISM_ASSERT(condition) ((void)0)
#else
#define PRISM_ASSERTIONS_ENABLED 1
#define PRISM_ASSERT(condition) \
    ((condition) ? (void)0 : ::prism::detail::assert_fail(#condition, __FILE__, __LINE__))
#endif
