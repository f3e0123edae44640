#pragma once
// The contract every harness checks: a parser given any bytes returns or throws a pgm::error
// with a message. Anything else (another exception, a crash, a sanitizer report, a hang) is a
// bug. Each harness defines its entry point with PGM_FUZZ_HARNESS(name): libFuzzer's
// LLVMFuzzerTestOneInput under PGM_FUZZ, or, in the replay program (PGM_FUZZ_REPLAY), a
// function registered under its name, so that one program, compiled once, feeds every harness
// its seed corpus and saved crashers in every build.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "pgm/core/error.hpp"

namespace pgm::fuzz {

using harness_function = int (*)(const std::uint8_t* data, std::size_t size);

/// The replay program's harnesses by name.
inline std::map<std::string_view, harness_function>& replay_harnesses() {
  static std::map<std::string_view, harness_function> harnesses;
  return harnesses;
}

inline bool add_replay_harness(std::string_view name, harness_function harness) {
  replay_harnesses().emplace(name, harness);
  return true;
}

[[nodiscard]] inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Fails the run (abort, which libFuzzer and ctest both report) with `why`.
[[noreturn]] inline void violated(const char* why) {
  std::fprintf(stderr, "fuzz harness: %s\n", why);
  std::abort();
}

/// Runs `parse`; a pgm::error is an accepted outcome, so long as it says something.
template <class Parse>
int expect_value_or_error(Parse&& parse) {
  try {
    parse();
  } catch (const pgm::error& e) {
    if (std::string_view(e.what()).empty()) violated("a pgm::error with an empty message");
  }
  return 0;
}

/// What a parse gave: its value, or the message of the pgm::error it threw.
template <class T>
struct outcome {
  std::optional<T> value;
  std::string error;
};

template <class Parse>
auto outcome_of(Parse&& parse) -> outcome<decltype(parse())> {
  try {
    return {parse(), {}};
  } catch (const pgm::error& e) {
    if (std::string_view(e.what()).empty()) violated("a pgm::error with an empty message");
    return {std::nullopt, e.what()};
  }
}

/// Fails the run unless two readings of the same input agree: the same value or the same error.
template <class T>
void expect_same(const outcome<T>& a, const outcome<T>& b, const char* what) {
  if (a.value.has_value() != b.value.has_value() || a.error != b.error || (a.value && !(*a.value == *b.value))) {
    violated(what);
  }
}

}  // namespace pgm::fuzz

#ifdef PGM_FUZZ_REPLAY
#define PGM_FUZZ_HARNESS(name)                                                    \
  static int pgm_fuzz_harness_##name(const std::uint8_t* data, std::size_t size); \
  [[maybe_unused]] static const bool pgm_fuzz_registered_##name =                 \
      pgm::fuzz::add_replay_harness(#name, pgm_fuzz_harness_##name);              \
  static int pgm_fuzz_harness_##name(const std::uint8_t* data, std::size_t size)
#else
#define PGM_FUZZ_HARNESS(name) extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
#endif
