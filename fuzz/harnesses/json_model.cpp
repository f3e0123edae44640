// JSON models (pgm/io/json_model.hpp, read through the format registry) and discretizations:
// the same bytes go to both readers.

#include "pgm/io/json_model.hpp"

#include "network_format_harness.hpp"

PGM_FUZZ_HARNESS(json_model) {
  pgm::fuzz::read_as_network_format("json", data, size);
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_discretization_json(pgm::fuzz::text_of(data, size), "fuzz.json")); });
}
