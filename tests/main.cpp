// SPDX-License-Identifier: MIT
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "support.hpp"

#include <algorithm>
#include <cstdlib>
#include <new>

#if !PRISM_TEST_SANITIZED
#if defined(__GNUC__) && !defined(__clang__)
// GCC inlines these into code whose memory it saw come from operator new, and calls free
// on it a mismatch: it is this operator new's own memory.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
// operator new, counting against test::allocation_budget where a test sets one (a reader
// out of memory, without running out of it). Sanitizers keep their own.
void* operator new(std::size_t size)
{
    if (test::allocation_budget >= 0) {
        if (static_cast<long long>(size) > test::allocation_budget) {
            // As a machine out of memory still has the little a message needs.
            test::allocation_budget = std::max(test::allocation_budget, 1LL << 20);
            throw std::bad_alloc();
        }
        test::allocation_budget -= static_cast<long long>(size);
    }
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#endif
