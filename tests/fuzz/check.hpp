// SPDX-License-Identifier: MIT
// The check every fuzz target makes: abort with a message, so that libFuzzer (and the
// corpus driver in the test suite) report the input that broke it.
#pragma once

#include <cstdio>
#include <cstdlib>

/// Abort with a message (libFuzzer keeps the input as a crash).
#define FUZZ_CHECK(condition)                                                                                 \
    do {                                                                                                      \
        if (!(condition)) {                                                                                   \
            std::fprintf(stderr, "fuzz check failed at %s:%d: %s\n", __FILE__, __LINE__, #condition);         \
            std::abort();                                                                                     \
        }                                                                                                     \
    } while (false)
