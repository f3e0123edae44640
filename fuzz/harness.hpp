#pragma once
// The contract every harness checks: a parser given any bytes returns or throws a pgm::error
// with a message. Anything else (another exception, a crash, a sanitizer report, a hang) is a
// bug. Each harness defines LLVMFuzzerTestOneInput; libFuzzer drives it under PGM_FUZZ, and
// replay.cpp feeds it the seed corpus and the saved crashers in every build.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "pgm/core/error.hpp"

namespace pgm::fuzz {

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
