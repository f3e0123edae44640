// JSON models (pgm/io/json_model.hpp, read through the format registry), Markov and dynamic
// networks in the same format, and discretizations: the same bytes go to every reader, and a
// Markov or dynamic network read back from what it writes is the same network.

#include "pgm/io/json_model.hpp"

#include <sstream>

#include "network_format_harness.hpp"

PGM_FUZZ_HARNESS(json_model) {
  pgm::fuzz::read_as_network_format("json", data, size);
  const auto text = pgm::fuzz::text_of(data, size);
  const auto markov = pgm::fuzz::outcome_of([&] { return pgm::parse_markov_json(text, "fuzz.json"); });
  if (markov.value) {
    const auto again = pgm::fuzz::outcome_of([&] {
      std::ostringstream out;
      pgm::write_markov_json(out, *markov.value);
      return pgm::parse_markov_json(out.str(), "fuzz.json");
    });
    pgm::fuzz::expect_same(markov, again, "a Markov network read back from its own JSON differs");
  }
  const auto dynamic = pgm::fuzz::outcome_of([&] { return pgm::parse_dynamic_json(text, "fuzz.json"); });
  if (dynamic.value) {
    const auto again = pgm::fuzz::outcome_of(
        [&] { return pgm::parse_dynamic_json(pgm::to_json(*dynamic.value).dump(), "fuzz.json"); });
    pgm::fuzz::expect_same(dynamic, again, "a dynamic network read back from its own JSON differs");
    static_cast<void>(pgm::fuzz::outcome_of([&] { return dynamic.value->unroll(3); }));
  }
  return pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::parse_discretization_json(text, "fuzz.json")); });
}
