// Scenario files (pgm/eval/scenario.hpp).

#include "pgm/eval/scenario.hpp"

#include "harness.hpp"

PGM_FUZZ_HARNESS(scenario) {
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_scenario(pgm::fuzz::text_of(data, size), "fuzz.json")); });
}
