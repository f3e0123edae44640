// Structural models (pgm/io/structural_file.hpp): a model read back from its own JSON is the same
// model, and a small one answers a counterfactual without any error but a pgm::error.

#include <cstdint>

#include "harness.hpp"
#include "pgm/causal/counterfactual.hpp"
#include "pgm/io/structural_file.hpp"

PGM_FUZZ_HARNESS(structural) {
  const auto read =
      pgm::fuzz::outcome_of([&] { return pgm::parse_structural_json(pgm::fuzz::text_of(data, size), "fuzz.json"); });
  if (!read.value) return 0;
  const auto& model = *read.value;
  pgm::fuzz::expect_same(
      read, pgm::fuzz::outcome_of([&] { return pgm::parse_structural_json(pgm::to_json(model).dump(), "fuzz.json"); }),
      "a structural model read back from its own JSON differs");
  double cells = 1;
  for (std::size_t i = 0; i < model.size(); ++i) {
    const auto id = pgm::index_at<pgm::variable_id>(i);
    cells *= static_cast<double>(model.at(id).cardinality() * model.equation(id).noise.size());
  }
  if (model.size() > 0 && cells <= 1e5) {
    const auto& first = model.variables().front();
    const auto& last = model.variables().back();
    const std::string asked[] = {last.name()};
    static_cast<void>(pgm::fuzz::outcome_of([&] {
      return pgm::counterfactual_query(model, asked, {{last.name(), last.states().back()}},
                                       {{first.name(), first.states().front()}})
          .evidence_probability;
    }));
  }
  return 0;
}
