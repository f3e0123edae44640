#pragma once
// The definitions of pgm/learn/fit_statistics.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/fit_statistics.hpp"

namespace pgm {

PGM_DECL bayesian_network estimate_network(const network_structure& structure, const fit_statistics& statistics) {
  if (statistics.counts.size() != structure.size() || statistics.priors.size() != structure.size()) {
    throw model_error("the statistics hold " + std::to_string(statistics.counts.size()) +
                      " count tables for a network of " + std::to_string(structure.size()) + " nodes");
  }
  std::vector<cpt<double>> tables;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    tables.push_back(estimate(statistics.counts[i], statistics.priors[i], statistics.estimation));
  }
  return bayesian_network(structure, std::move(tables));
}

}  // namespace pgm
