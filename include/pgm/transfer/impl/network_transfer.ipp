#pragma once
// The definitions of pgm/transfer/network_transfer.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/transfer/network_transfer.hpp"

namespace pgm {

PGM_DECL void check_transferred_pair(const correspondence& map, const std::string& prior_node,
                                     const network_structure& target, const std::string& target_node) {
  const auto entry = "map entry '" + target_node + "=" + prior_node + "': ";
  for (const auto& parent : target.parent_variables(target.id(target_node))) {
    const auto related = map.related_to(parent.name());
    if (map.identical_to(parent.name()) == prior_node || (related && *related == prior_node)) {
      throw model_error(entry + "the prior's '" + prior_node + "' already stands for '" + parent.name() +
                        "', a parent of '" + target_node + "'; a transferred node needs the prior's counterpart " +
                        "of itself, e.g. 'onTop2=onTop1'");
    }
  }
}

PGM_DECL void check_correspondence(const correspondence& map, const bayesian_network& prior,
                                   const network_structure& target) {
  auto in_target = [&](const std::string& name, const char* kind) {
    if (!target.contains(name))
      throw model_error("the map's " + std::string(kind) + " '" + name + "' is not a variable of the target network");
  };
  auto in_prior = [&](const std::string& name, const char* kind) {
    if (!prior.structure().contains(name))
      throw model_error("the map's " + std::string(kind) + " '" + name + "' is not a variable of the prior network");
  };
  for (const auto& [t, p] : map.transferred) in_target(t, "transferred node"), in_prior(p, "transferred node");
  for (const auto& [t, p] : map.identical) in_target(t, "identical variable"), in_prior(p, "identical variable");
  for (const auto& [t, p] : map.related) in_target(t, "related variable"), in_prior(p, "related variable");
  for (const auto& [p, pin] : map.pinned) in_prior(p, "pinned variable");
  for (const auto& [t, p] : map.transferred) check_transferred_pair(map, p, target, t);
}

PGM_DECL std::map<std::string, transferred_prior, std::less<>> transfer_priors(const bayesian_network& prior,
                                                                               const network_structure& target,
                                                                               const correspondence& map,
                                                                               const any_prior_transfer& strategy,
                                                                               const transfer_options& options) {
  check_correspondence(map, prior, target);
  std::map<std::string, transferred_prior, std::less<>> priors;
  for (const auto& [target_node, prior_node] : map.transferred) {
    const auto id = target.id(target_node);
    const transfer_problem problem(prior, prior_node, target.at(id), target.parent_variables(id), map, options);
    priors.emplace(target_node, strategy(problem));
  }
  return priors;
}

PGM_DECL void use_transferred_priors(fit_options& options,
                                     const std::map<std::string, transferred_prior, std::less<>>& priors,
                                     const std::map<std::string, double, std::less<>>& weights) {
  for (const auto& [node, prior] : priors) {
    options.node_priors.insert_or_assign(node, weighted_prior{prior.table(), weights.at(node)});
  }
}

}  // namespace pgm
