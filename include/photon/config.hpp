// SPDX-License-Identifier: MIT
#pragma once
// Library-wide macros. Every macro photon defines starts with PHOTON_.

#include <cstdio>
#include <cstdlib>

/// PHOTON_ASSERT checks internal preconditions. It is on in debug builds and wherever
/// PHOTON_ENABLE_ASSERTS is defined (the test suite defines it), and compiles to nothing otherwise.
/// Bad user input is never an assertion: it is an exception with a message.
#if !defined(PHOTON_ENABLE_ASSERTS) && !defined(NDEBUG)
#define PHOTON_ENABLE_ASSERTS 1
#endif

#if defined(PHOTON_ENABLE_ASSERTS) && PHOTON_ENABLE_ASSERTS
#define PHOTON_ASSERT(cond)                                                                   \
    do {                                                                                      \
        if (!(cond)) {                                                                        \
            std::fprintf(stderr, "%s:%d: photon assertion failed: %s\n", __FILE__, __LINE__, \
                         #cond);                                                              \
            std::abort();                                                                     \
        }                                                                                     \
    } while (false)
#else
#define PHOTON_ASSERT(cond) static_cast<void>(0)
#endif

#if defined(__GNUC__) || defined(__clang__)
#define PHOTON_FORCEINLINE inline __attribute__((always_inline))
#define PHOTON_FORCEINLINE_LAMBDA __attribute__((always_inline))  // after a lambda's parameters
#define PHOTON_RESTRICT __restrict__
#else
#define PHOTON_FORCEINLINE inline
#define PHOTON_FORCEINLINE_LAMBDA
#define PHOTON_RESTRICT
#endif
