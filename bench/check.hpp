#pragma once
// Every benchmark checks what its loop computed, after the loop (so that a fast wrong answer
// fails the run instead of being timed): `check` marks the run as failed, saying what was wrong.

#include <benchmark/benchmark.h>

namespace pgm::bench {

inline void check(benchmark::State& state, bool correct, const char* what) {
  if (!correct) state.SkipWithError(what);
}

}  // namespace pgm::bench
