// Task files (pgm/sim/task_file.hpp).

#include "harness.hpp"
#include "pgm/sim/task_file.hpp"

PGM_FUZZ_HARNESS(task) {
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::sim::parse_task(pgm::fuzz::text_of(data, size), "fuzz.json")); });
}
