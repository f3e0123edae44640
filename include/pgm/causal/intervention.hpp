#pragma once
/// \file
/// Interventions as graph surgery. `intervene(network, do)` is the mutilated network, as
/// bnlearn's `mutilated()`: each intervened variable loses its parents and gets the point
/// distribution at its state, every other table kept — a network to write, draw or query with
/// any tool. To query under an intervention, set it on an engine instead
/// (`set_evidence(engine, evidence, soft, do)`, docs/causal.md): the engines apply the surgery
/// as a view, copying no table.

#include <string>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

/// The network with do(X = x) for each entry of `set`. Throws model_error for an unknown
/// variable or state (naming the known ones).
[[nodiscard]] inline bayesian_network intervene(const bayesian_network& network, const intervention& set) {
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
