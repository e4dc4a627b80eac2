// SPDX-License-Identifier: MIT
// How many samples a statistical test can afford in this build. An optimised build takes a
// test's full count. Under a sanitizer, where the suite checks memory and threads and runs
// ten to fifty times slower, a test takes an eighth of it, with the tolerance that the count
// resolves widened by sqrt(8), so that it stays the same number of standard errors. A
// tolerance set by something else (quadrature, a known bias, rounding) stays as it is.
#pragma once

#include <cmath>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define PRISM_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define PRISM_TEST_SANITIZED 1
#endif
#endif
#ifndef PRISM_TEST_SANITIZED
#define PRISM_TEST_SANITIZED 0
#endif

namespace test {

/// By how much a statistical test divides its sample count in this build.
inline constexpr long effort_divisor = PRISM_TEST_SANITIZED ? 8 : 1;

/// A statistical test's sample count n in this build (at least 1).
constexpr long samples(long n) { return n / effort_divisor > 0 ? n / effort_divisor : 1; }

/// A tolerance that samples(n) resolve to as many standard errors as n do in an optimised
/// build: `tolerance` there, sqrt(effort_divisor) times it here.
inline double resolved(double tolerance) { return tolerance * std::sqrt(double(effort_divisor)); }

} // namespace test
