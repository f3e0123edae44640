// Task files (pgm/sim/task_file.hpp).

#include "harness.hpp"
#include "pgm/sim/task_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::sim::parse_task(pgm::fuzz::text_of(data, size), "fuzz.json")); });
}
