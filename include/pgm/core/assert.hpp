#pragma once
/// \file
/// PGM_ASSERT: a debug-only check of a programmer's precondition. Bad user input is never
/// asserted; it is reported with an exception from pgm/core/error.hpp.

#include <cstdio>
#include <cstdlib>

#ifdef NDEBUG
#define PGM_ASSERT(condition, message) static_cast<void>(0)
#else
#define PGM_ASSERT(condition, message)                                                                     \
  do {                                                                                                     \
    if (!(condition)) {                                                                                    \
      std::fprintf(stderr, "%s:%d: assertion failed: %s (%s)\n", __FILE__, __LINE__, #condition, message); \
      std::abort();                                                                                        \
    }                                                                                                      \
  } while (false)
#endif
