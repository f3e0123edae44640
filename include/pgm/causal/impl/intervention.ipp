#pragma once
// The definitions of pgm/causal/intervention.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/causal/intervention.hpp"

namespace pgm {

PGM_DECL bayesian_network intervene(const bayesian_network& network, const intervention& set) {
  auto structure = network.structure();
  std::vector<cpt<double>> tables;
  for (const auto& [name, state] : set) {
    const auto id = node_of(network, name);
    for (auto parent : network.graph().parents(id)) {
      structure.remove_edge(network.variables()[parent.value()].name(), name);
    }
  }
  for (std::size_t i = 0; i < network.size(); ++i) {
    const auto& v = network.variables()[i];
    const auto it = set.find(v.name());
    if (it == set.end()) {
      tables.push_back(network.tables()[i]);
      continue;
    }
    std::vector<double> point(v.cardinality(), 0.0);
    point[v.state(it->second).value()] = 1.0;
    tables.emplace_back(v, std::vector<variable>{}, std::move(point));
  }
  return bayesian_network(std::move(structure), std::move(tables));
}

}  // namespace pgm
