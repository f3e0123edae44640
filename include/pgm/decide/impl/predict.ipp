#pragma once
// The definitions of pgm/decide/predict.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/decide/predict.hpp"

namespace pgm {

PGM_DECL std::vector<std::string> unassigned_parents(const bayesian_network& network, const success_event& success,
                                                     const assignment& planned) {
  std::vector<std::string> missing;
  for (const auto& parent : network.table(node_of(network, success.variable)).parents()) {
    if (!planned.contains(parent.name())) missing.push_back(parent.name());
  }
  return missing;
}

}  // namespace pgm

namespace pgm::detail {

PGM_DECL void throw_missing(const success_event& success, const std::vector<std::string>& missing) {
  throw model_error("no value is given for " + std::string(missing.size() == 1 ? "" : "the parents ") +
                    text::list_for_message(missing) + (missing.size() == 1 ? ", a parent" : "") + " of '" +
                    success.variable + "'; assign " + (missing.size() == 1 ? "it" : "them") + " or ask to marginalize");
}

PGM_DECL bool observes_descendant(const bayesian_network& network, variable_id node,
                                  std::span<const observation> observed) {
  std::vector<bool> below(network.size(), false);
  std::vector<variable_id> stack = network.graph().children(node);
  while (!stack.empty()) {
    const auto n = stack.back();
    stack.pop_back();
    if (below[n.value()]) continue;
    below[n.value()] = true;
    for (auto c : network.graph().children(n)) stack.push_back(c);
  }
  return std::any_of(observed.begin(), observed.end(), [&](const observation& o) { return below[o.variable.value()]; });
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL double predict_success(const bayesian_network& network, const success_event& success,
                                const assignment& planned, const prediction_options& options) {
  variable_elimination engine(borrowed(network), {options.heuristic});
  return predict_success(engine, success, planned, options);
}

}  // namespace pgm
