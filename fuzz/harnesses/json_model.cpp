// JSON models and discretizations (pgm/io/json_model.hpp): the same bytes go to both readers.

#include "pgm/io/json_model.hpp"

#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = pgm::fuzz::text_of(data, size);
  pgm::fuzz::expect_value_or_error([&] { static_cast<void>(pgm::parse_model_json(text, "fuzz.json")); });
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_discretization_json(text, "fuzz.json")); });
}
