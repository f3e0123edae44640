#pragma once
// The definitions of pgm/transfer/prior_weight.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/transfer/prior_weight.hpp"

namespace pgm {

PGM_DECL double log_evidence(const count_table& counts, const cpt<double>& prior, double weight, double floor) {
  return dirichlet_log_marginal(counts, weighted_pseudo_counts{&prior, weight, floor});
}

PGM_DECL prior_weight_choice choose_prior_weight(const count_table& counts, const cpt<double>& prior,
                                                 const prior_weight_search& search) {
  if (counts.parents().size() != prior.parents().size() || counts.child_cardinality() != prior.child_cardinality() ||
      counts.configurations() != prior.configurations()) {
    throw model_error("the prior table of '" + prior.child().name() + "' does not have the shape of its counts");
  }
  if (!(search.smallest > 0) || !(search.largest > search.smallest) || search.steps_per_decade == 0) {
    throw model_error("the prior-weight grid needs 0 < smallest < largest and at least one step per decade");
  }
  prior_weight_choice choice{search.without_data, 0, {}, {}, {}};
  const double decades = std::log10(search.largest / search.smallest);
  const auto steps = static_cast<std::size_t>(std::ceil(decades * static_cast<double>(search.steps_per_decade)));
  for (std::size_t k = 0; k <= steps; ++k) {
    choice.grid.push_back(search.smallest *
                          std::pow(10.0, static_cast<double>(k) / static_cast<double>(search.steps_per_decade)));
  }
  if (counts.total() == 0) {
    choice.reason =
        "no target data: every w > 0 gives the prior itself; w = " + text::format_short(search.without_data);
    choice.log_evidence_on_grid.assign(choice.grid.size(), 0.0);
    return choice;
  }
  std::size_t best = 0;
  for (std::size_t k = 0; k < choice.grid.size(); ++k) {
    choice.log_evidence_on_grid.push_back(log_evidence(counts, prior, choice.grid[k], search.floor));
    if (choice.log_evidence_on_grid[k] > choice.log_evidence_on_grid[best]) best = k;
  }
  choice.weight = choice.grid[best];
  choice.log_evidence = choice.log_evidence_on_grid[best];
  choice.reason = "w = " + text::format_short(choice.weight, 3) + " maximizes the marginal likelihood of the " +
                  std::to_string(counts.total()) + " target rows (log evidence " +
                  text::format_short(choice.log_evidence, 6) + ")";
  if (best == 0 || best + 1 == choice.grid.size()) {
    choice.reason += best == 0 ? "; at the grid's low end: the data trusts the prior little"
                               : "; at the grid's high end: the data agrees with the prior closely";
  } else {
    auto relative = [&](std::size_t k) {
      return text::format_short(choice.log_evidence_on_grid[k] - choice.log_evidence, 3);
    };
    choice.reason += "; neighbours w = " + text::format_short(choice.grid[best - 1], 3) + " (" + relative(best - 1) +
                     ") and w = " + text::format_short(choice.grid[best + 1], 3) + " (" + relative(best + 1) + ")";
  }
  return choice;
}

}  // namespace pgm
