#pragma once
// The definitions of pgm/inference/variable_elimination.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/variable_elimination.hpp"

namespace pgm::detail {

PGM_DECL std::vector<bool> ancestral_set(const bayesian_network& network, std::span<const variable_id> targets,
                                         const evidence_set& observed) {
  std::vector<bool> in(network.size(), false);
  std::vector<variable_id> stack(targets.begin(), targets.end());
  while (!stack.empty()) {
    const auto node = stack.back();
    stack.pop_back();
    if (in[node.value()]) continue;
    in[node.value()] = true;
    if (observed.intervenes(node)) continue;
    for (auto parent : network.graph().parents(node)) stack.push_back(parent);
  }
  return in;
}

PGM_DECL std::vector<bool> relevant_set(const bayesian_network& network, std::span<const variable_id> query,
                                        const evidence_set& observed) {
  std::vector<variable_id> targets(query.begin(), query.end());
  for (const auto& o : observed.hard) targets.push_back(o.variable);
  for (const auto& l : observed.soft) targets.push_back(l.variable);
  for (const auto& o : observed.intervened) targets.push_back(o.variable);
  return ancestral_set(network, targets, observed);
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL factor joint_with_evidence(const bayesian_network& network, std::span<const variable_id> query,
                                    std::span<const observation> observed, elimination_heuristic heuristic) {
  evidence_set set;
  set.hard.assign(observed.begin(), observed.end());
  return joint_in<sum_product<double>>(network, query, set, heuristic);
}

PGM_DECL posterior query(const bayesian_network& network, std::span<const std::string> variables,
                         const evidence& observed, elimination_heuristic heuristic) {
  variable_elimination engine(borrowed(network), {heuristic});
  engine.set_evidence(resolve_evidence(network, observed));
  return engine.joint(resolve_query(network, variables, engine.evidence()));
}

PGM_DECL posterior query(const bayesian_network& network, std::initializer_list<std::string> variables,
                         const evidence& observed, elimination_heuristic heuristic) {
  return query(network, std::span<const std::string>(variables.begin(), variables.end()), observed, heuristic);
}

}  // namespace pgm

#if defined(PGM_SEPARATE_COMPILATION)
namespace pgm {
template class variable_elimination<bayesian_network>;
template class variable_elimination<markov_network>;
}  // namespace pgm
#endif
