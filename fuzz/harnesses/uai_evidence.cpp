// UAI evidence, query and result files (pgm/io/uai.hpp) against a small model: every reading
// returns checked ids and states or throws a pgm::error.

#include "harness.hpp"
#include "pgm/io/uai.hpp"

namespace {

const pgm::markov_network& small_model() {
  static const auto model =
      pgm::parse_uai("MARKOV\n3\n2 3 2\n2\n2 0 1\n1 2\n6\n1 2 3 4 5 6\n2\n0.5 1\n", "small.uai").model;
  return model;
}

}  // namespace

PGM_FUZZ_HARNESS(uai_evidence) {
  const auto text = pgm::fuzz::text_of(data, size);
  pgm::fuzz::expect_value_or_error([&] {
    for (const auto& sample : pgm::parse_uai_evidence(text, "e.evid", small_model())) {
      for (const auto& [variable, state] : sample) {
        if (state >= small_model().variables().at(variable.value()).cardinality()) {
          pgm::fuzz::violated("an evidence state out of range was accepted");
        }
      }
    }
  });
  pgm::fuzz::expect_value_or_error([&] { static_cast<void>(pgm::parse_uai_query(text, "q.query", small_model())); });
  return pgm::fuzz::expect_value_or_error([&] { static_cast<void>(pgm::parse_uai_result(text, "r.MAR")); });
}
