#pragma once
// The definitions of pgm/learn/dynamic_statistics.hpp: inline in a header-only build, compiled
// once into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/learn/dynamic_statistics.hpp"

namespace pgm {

PGM_DECL dynamic_fit_statistics dynamic_statistics_of(const dynamic_structure& structure, const dynamic_counts& counts,
                                                      const dynamic_fit_options& options) {
  const auto& templates = structure.variables();
  if (counts.initial.size() != templates.size() || counts.transition.size() != templates.size()) {
    throw model_error("the statistics of a dynamic network of " + std::to_string(templates.size()) +
                      " template variables need as many count tables for each slice");
  }
  fit_options first = options.fit;
  first.node_priors = options.initial_priors;
  dynamic_fit_statistics result;
  result.initial = statistics_of(structure.initial, std::span<const count_table>(counts.initial),
                                 static_cast<double>(counts.episodes), first);
  result.transition.rows = static_cast<double>(counts.steps - counts.episodes);
  result.transition.estimation = options.fit.estimation;
  for (std::size_t i = 0; i < templates.size(); ++i) {
    const auto own = options.fit.node_priors.find(templates[i].name());
    result.transition.counts.push_back(detail::as_expected(counts.transition[i]));
    result.transition.priors.push_back(own != options.fit.node_priors.end() ? own->second : options.fit.prior);
  }
  return result;
}

PGM_DECL dynamic_network estimate_dynamic(const dynamic_structure& structure,
                                          const dynamic_fit_statistics& statistics) {
  const auto& templates = structure.variables();
  const auto& transition = statistics.transition;
  if (transition.counts.size() != templates.size() || transition.priors.size() != templates.size()) {
    throw model_error("the statistics hold " + std::to_string(transition.counts.size()) +
                      " transition count tables for a dynamic network of " + std::to_string(templates.size()) +
                      " template variables");
  }
  auto initial = estimate_network(structure.initial, statistics.initial);
  std::vector<cpt<double>> tables;
  for (std::size_t i = 0; i < templates.size(); ++i) {
    const variable_id now = index_at<variable_id>(templates.size() + i);
    const auto& counts = transition.counts[i];
    if (counts.child() != structure.transition.at(now) ||
        counts.parents() != structure.transition.parent_variables(now)) {
      throw model_error("the transition counts of '" + templates[i].name() + "' are not of its family in the network");
    }
    tables.push_back(estimate(counts, transition.priors[i], transition.estimation));
  }
  return dynamic_network(std::move(initial), std::move(tables));
}

PGM_DECL dynamic_fit_statistics updated(const dynamic_fit_statistics& old, const dynamic_counts& more, double decay) {
  return {updated(old.initial, std::span<const count_table>(more.initial), static_cast<double>(more.episodes), decay),
          updated(old.transition, std::span<const count_table>(more.transition),
                  static_cast<double>(more.steps - more.episodes), decay)};
}

}  // namespace pgm
