#pragma once
// The definitions of pgm/decide/solve_decisions.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "pgm/core/mixed_radix.hpp"
#include "pgm/decide/solve_decisions.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/inference/semiring.hpp"

namespace pgm {
namespace detail {

// Utilities add (⊗ = +) and a decision takes the best (⊕ = max): the max-plus semiring,
// which log_max_product is.
using utility_semiring = log_max_product<double>;

using observed_states = std::vector<std::pair<variable_id, std::size_t>>;

/// An influence diagram's potentials during elimination: probabilities that multiply and
/// utilities that add. What they are worth, Σ_x Πφ(x) · Σψ(x), each step keeps.
struct decision_potentials {
  std::vector<factor> probabilities;
  std::vector<factor> utilities;
};

PGM_DECL factor product_of(const std::vector<factor>& parts) {
  factor total;
  for (const auto& f : parts) total = total * f;
  return total;
}

PGM_DECL factor sum_of_utilities(const std::vector<factor>& parts) {
  auto total = factor::constant(0.0);
  for (const auto& f : parts) total = combine<utility_semiring>(total, f);
  return total;
}

/// Moves the factors whose scope holds `id` out of `factors`.
PGM_DECL std::vector<factor> take_containing(std::vector<factor>& factors, variable_id id) {
  std::vector<factor> taken;
  std::vector<factor> kept;
  for (auto& f : factors) (f.contains(id) ? taken : kept).push_back(std::move(f));
  factors = std::move(kept);
  return taken;
}

/// Sums `x` out: φ' = Σ_x Πφ and ψ' = Σ_x (Πφ · Σψ) / φ' (0 where φ' is 0).
PGM_DECL void sum_out(decision_potentials& p, variable_id x) {
  const factor phi = product_of(take_containing(p.probabilities, x));
  const auto psis = take_containing(p.utilities, x);
  factor marginal = phi.sum_out(x);
  if (!psis.empty()) {
    factor reciprocal = marginal;
    for (double& v : reciprocal.mutable_values()) v = v == 0 ? 0 : 1 / v;
    p.utilities.push_back((phi * sum_of_utilities(psis)).sum_out(x) * reciprocal);
  }
  p.probabilities.push_back(std::move(marginal));
}

/// Sums out every variable of `group`, the one whose factors span the fewest cells first.
PGM_DECL void sum_out_all(decision_potentials& p, std::vector<variable_id> group) {
  while (!group.empty()) {
    auto cheapest = group.begin();
    double fewest = std::numeric_limits<double>::infinity();
    for (auto it = group.begin(); it != group.end(); ++it) {
      std::map<variable_id, std::size_t> spanned;
      for (const auto* list : {&p.probabilities, &p.utilities}) {
        for (const auto& f : *list) {
          if (!f.contains(*it)) continue;
          for (std::size_t k = 0; k < f.scope().size(); ++k) spanned[f.scope()[k]] = f.cardinalities()[k];
        }
      }
      double cells = 1;
      for (const auto& [id, cardinality] : spanned) cells *= static_cast<double>(cardinality);
      if (cells < fewest) {
        fewest = cells;
        cheapest = it;
      }
    }
    sum_out(p, *cheapest);
    group.erase(cheapest);
  }
}

/// The best action of `d` per configuration of the other variables its utilities span,
/// leaving their maximum as a utility. The probabilities do not depend on `d` by now (every
/// variable it influences is summed out), so a slice of them serves.
PGM_DECL decision_policy maximize(decision_potentials& p, variable_id d, std::size_t actions) {
  for (auto& f : take_containing(p.probabilities, d)) p.probabilities.push_back(f.reduce(d, 0));
  const factor psi = sum_of_utilities(take_containing(p.utilities, d));
  decision_policy policy{d, {}, {}};
  if (!psi.contains(d)) {  // no payoff depends on it
    policy.actions.push_back(0);
    return policy;
  }
  for (const auto id : psi.scope()) {
    if (id != d) policy.observed.push_back(id);
  }
  auto order = policy.observed;
  order.push_back(d);
  const factor arranged = psi.permuted(order);
  std::vector<std::size_t> cards;
  for (const auto id : policy.observed) cards.push_back(arranged.cardinalities()[arranged.position(id)]);
  std::vector<double> best(arranged.size() / actions);
  const auto values = arranged.values();
  for (std::size_t c = 0; c < best.size(); ++c) {
    const auto block = values.subspan(c * actions, actions);
    const auto top = std::max_element(block.begin(), block.end());  // the first of equals
    policy.actions.push_back(static_cast<std::size_t>(top - block.begin()));
    best[c] = *top;
  }
  p.utilities.emplace_back(policy.observed, std::move(cards), std::move(best));
  return policy;
}

PGM_DECL std::vector<std::size_t> cardinalities_of(const influence_diagram& diagram,
                                                   const std::vector<variable_id>& ids) {
  std::vector<std::size_t> cards;
  for (const auto id : ids) cards.push_back(diagram.at(id).cardinality());
  return cards;
}

PGM_DECL factor reduced(factor f, const observed_states& observed) {
  for (const auto& [id, state] : observed) f = f.reduce(id, state);
  return f;
}

/// The chance tables and utilities as factors, the evidence set in them.
PGM_DECL decision_potentials potentials_of(const influence_diagram& diagram, const observed_states& observed) {
  decision_potentials p;
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    const auto id = index_at<variable_id>(i);
    if (diagram.is_decision(id)) continue;
    auto scope = diagram.parents(id);
    scope.push_back(id);
    p.probabilities.push_back(reduced(factor(scope, cardinalities_of(diagram, scope), diagram.table(id)), observed));
  }
  for (const auto& u : diagram.utilities()) {
    p.utilities.push_back(reduced(factor(u.parents, cardinalities_of(diagram, u.parents), u.values), observed));
  }
  return p;
}

PGM_DECL observed_states resolve_evidence(const influence_diagram& diagram, const evidence& observed) {
  observed_states states;
  const auto decisions = diagram.decision_order();
  for (const auto& [name, label] : observed) {
    const auto id = diagram.id(name);
    if (diagram.is_decision(id)) {
      throw model_error("'" + name + "' is a decision: it is chosen, not observed");
    }
    for (const auto d : decisions) {
      if (!diagram.graph().path_between(d, id).empty()) {
        throw model_error("'" + name + "' depends on the decision '" + diagram.at(d).name() +
                          "': evidence is what is known before the first decision is taken");
      }
    }
    states.emplace_back(id, diagram.at(id).state(label).value());
  }
  return states;
}

PGM_DECL bool is_observed(const observed_states& observed, variable_id id) {
  return std::any_of(observed.begin(), observed.end(), [&](const auto& o) { return o.first == id; });
}

/// The variables to sum out: those neither observed nor in `keep`.
PGM_DECL std::vector<variable_id> unobserved_except(const influence_diagram& diagram, const observed_states& observed,
                                                    const std::vector<variable_id>& keep) {
  std::vector<variable_id> ids;
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    const auto id = index_at<variable_id>(i);
    if (!is_observed(observed, id) && std::find(keep.begin(), keep.end(), id) == keep.end()) ids.push_back(id);
  }
  return ids;
}

/// The policy extended to also list `listed` first (for them the action is the same).
PGM_DECL decision_policy listing(const decision_policy& policy, std::vector<variable_id> listed,
                                 const influence_diagram& diagram) {
  for (const auto id : policy.observed) {
    if (std::find(listed.begin(), listed.end(), id) == listed.end()) listed.push_back(id);
  }
  if (listed == policy.observed) return policy;
  const mixed_radix wide(cardinalities_of(diagram, listed));
  const mixed_radix narrow(cardinalities_of(diagram, policy.observed));
  std::vector<std::size_t> position;
  for (const auto id : policy.observed) {
    position.push_back(static_cast<std::size_t>(std::find(listed.begin(), listed.end(), id) - listed.begin()));
  }
  decision_policy result{policy.decision, listed, std::vector<std::size_t>(wide.size())};
  std::vector<std::size_t> states(listed.size());
  std::vector<std::size_t> own(policy.observed.size());
  for (std::size_t c = 0; c < wide.size(); ++c) {
    wide.decode(c, states);
    for (std::size_t k = 0; k < own.size(); ++k) own[k] = states[position[k]];
    result.actions[c] = policy.actions[narrow.encode(own)];
  }
  return result;
}

/// A deterministic policy as a table over (observed…, decision), the evidence set in it.
PGM_DECL factor policy_factor(const influence_diagram& diagram, const decision_policy& policy,
                              const observed_states& observed) {
  auto scope = policy.observed;
  scope.push_back(policy.decision);
  const auto actions = diagram.at(policy.decision).cardinality();
  std::vector<double> values(policy.actions.size() * actions, 0.0);
  for (std::size_t c = 0; c < policy.actions.size(); ++c) values[c * actions + policy.actions[c]] = 1;
  return reduced(factor(scope, cardinalities_of(diagram, scope), std::move(values)), observed);
}

/// P(evidence) and E[U | evidence] with the decisions acting by `policies` (tables over
/// (observed…, decision)).
PGM_DECL std::pair<double, double> evaluate(const influence_diagram& diagram, const observed_states& observed,
                                            const std::vector<factor>& policies) {
  auto p = potentials_of(diagram, observed);
  p.probabilities.insert(p.probabilities.end(), policies.begin(), policies.end());
  sum_out_all(p, unobserved_except(diagram, observed, {}));
  const double chance = product_of(p.probabilities).values()[0];
  if (!(chance > 0)) throw model_error("the evidence has probability 0");
  return {chance, sum_of_utilities(p.utilities).values()[0]};
}

PGM_DECL decision_solution solve_with_recall(const influence_diagram& diagram, const observed_states& observed) {
  const auto order = diagram.decision_order();
  // What each decision learns that no earlier one knew; what none learns is summed first.
  std::vector<bool> known(diagram.size(), false);
  std::vector<std::vector<variable_id>> learned(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    known[order[k].value()] = true;
    for (const auto parent : diagram.parents(order[k])) {
      if (known[parent.value()] || is_observed(observed, parent)) continue;
      known[parent.value()] = true;
      learned[k].push_back(parent);
    }
  }
  std::vector<variable_id> never;
  for (const auto id : unobserved_except(diagram, observed, {})) {
    if (!known[id.value()]) never.push_back(id);
  }
  auto p = potentials_of(diagram, observed);
  sum_out_all(p, never);
  decision_solution solution;
  solution.policies.resize(order.size());
  for (std::size_t k = order.size(); k-- > 0;) {
    const auto d = order[k];
    auto best = maximize(p, d, diagram.at(d).cardinality());
    std::vector<variable_id> parents;
    for (const auto parent : diagram.parents(d)) {
      if (!is_observed(observed, parent)) parents.push_back(parent);
    }
    solution.policies[k] = listing(best, std::move(parents), diagram);
    sum_out_all(p, learned[k]);
  }
  if (!(product_of(p.probabilities).values()[0] > 0)) throw model_error("the evidence has probability 0");
  solution.meu = sum_of_utilities(p.utilities).values()[0];
  return solution;
}

/// Single policy updating: each decision in turn, the last first, takes its best answer to
/// the others' policies, until a round changes none.
PGM_DECL decision_solution solve_limited_memory(const influence_diagram& diagram, const observed_states& observed) {
  const auto order = diagram.decision_order();
  decision_solution solution;
  std::vector<factor> tables;
  for (const auto d : order) {
    decision_policy policy{d, {}, {}};
    for (const auto parent : diagram.parents(d)) {
      if (!is_observed(observed, parent)) policy.observed.push_back(parent);
    }
    auto scope = policy.observed;
    scope.push_back(d);
    const auto cards = cardinalities_of(diagram, scope);
    const mixed_radix configurations(cardinalities_of(diagram, policy.observed));
    policy.actions.assign(configurations.size(), 0);
    solution.policies.push_back(std::move(policy));
    const auto actions = cards.back();
    tables.emplace_back(scope, cards,
                        std::vector<double>(configurations.size() * actions, 1.0 / static_cast<double>(actions)));
  }
  solution.start_expected_utility = evaluate(diagram, observed, tables).second;
  const auto base = potentials_of(diagram, observed);  // the tables and utilities, built once
  bool uniform = true;
  for (bool changed = true; changed; uniform = false) {
    changed = false;
    ++solution.rounds;
    for (std::size_t k = order.size(); k-- > 0;) {
      auto& policy = solution.policies[k];
      auto p = base;
      for (std::size_t j = 0; j < tables.size(); ++j) {
        if (j != k) p.probabilities.push_back(tables[j]);
      }
      auto family = policy.observed;
      family.push_back(policy.decision);
      sum_out_all(p, unobserved_except(diagram, observed, family));
      // Q(observed, d): what acting d there is worth; a table of ones spans the whole family.
      const auto cards = cardinalities_of(diagram, family);
      const factor span(family, cards, std::vector<double>(mixed_radix(cards).size(), 1.0));
      const factor worth = (span * product_of(p.probabilities) * sum_of_utilities(p.utilities)).permuted(family);
      const auto actions = cards.back();
      const auto values = worth.values();
      for (std::size_t c = 0; c < policy.actions.size(); ++c) {
        const auto block = values.subspan(c * actions, actions);
        const auto top = static_cast<std::size_t>(std::max_element(block.begin(), block.end()) - block.begin());
        const auto& now = policy.actions[c];
        // A change must gain more than rounding, or two equal actions could alternate forever.
        const double margin = 1e-12 * std::max(1.0, std::abs(block[top]));
        if (uniform || block[top] > block[now] + margin) {
          changed = changed || policy.actions[c] != top || uniform;
          policy.actions[c] = top;
        }
      }
      tables[k] = policy_factor(diagram, policy, {});
    }
  }
  solution.meu = evaluate(diagram, observed, tables).second;
  solution.local_optimum = true;
  return solution;
}

}  // namespace detail

PGM_DECL decision_solution solve_decisions(const influence_diagram& diagram, const evidence& observed,
                                           const decision_options& options) {
  diagram.validate();
  const auto states = detail::resolve_evidence(diagram, observed);
  return options.limited_memory ? detail::solve_limited_memory(diagram, states)
                                : detail::solve_with_recall(diagram, states);
}

PGM_DECL double expected_utility(const influence_diagram& diagram, const std::vector<decision_policy>& policies,
                                 const evidence& observed) {
  diagram.validate();
  const auto states = detail::resolve_evidence(diagram, observed);
  std::vector<factor> tables;
  for (const auto d : diagram.decision_order()) {
    const auto policy = std::find_if(policies.begin(), policies.end(), [&](const auto& q) { return q.decision == d; });
    const auto& name = diagram.at(d).name();
    if (policy == policies.end()) throw model_error("no policy for the decision '" + name + "'");
    const mixed_radix configurations(detail::cardinalities_of(diagram, policy->observed));
    if (policy->actions.size() != configurations.size()) {
      throw model_error("the policy of '" + name + "' has " + std::to_string(policy->actions.size()) + " actions for " +
                        std::to_string(configurations.size()) + " configurations");
    }
    for (const auto action : policy->actions) {
      if (action >= diagram.at(d).cardinality()) throw model_error("the policy of '" + name + "' names no action");
    }
    tables.push_back(detail::policy_factor(diagram, *policy, states));
  }
  return detail::evaluate(diagram, states, tables).second;
}

PGM_DECL influence_diagram observing(const influence_diagram& diagram, variable_id chance, variable_id decision) {
  const auto& name = diagram.at(chance).name();
  const auto& decision_name = diagram.at(decision).name();
  if (diagram.is_decision(chance)) throw model_error("'" + name + "' is a decision, not a chance variable");
  if (!diagram.is_decision(decision)) throw model_error("'" + decision_name + "' is not a decision");
  if (!diagram.graph().path_between(decision, chance).empty()) {
    throw model_error("'" + name + "' depends on the decision '" + decision_name +
                      "', so it cannot be known before it");
  }
  influence_diagram result;
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    const auto id = index_at<variable_id>(i);
    diagram.is_decision(id) ? result.add_decision(diagram.at(id)) : result.add_chance(diagram.at(id));
  }
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    const auto id = index_at<variable_id>(i);
    if (!diagram.is_decision(id)) {
      result.set_table(id, diagram.parents(id), diagram.table(id));
      continue;
    }
    auto parents = diagram.parents(id);
    if (id == decision && std::find(parents.begin(), parents.end(), chance) == parents.end()) parents.push_back(chance);
    result.set_observed(id, parents);
  }
  for (const auto& u : diagram.utilities()) result.add_utility(u.name, u.parents, u.values);
  return result;
}

PGM_DECL double value_of_information(const influence_diagram& diagram, std::string_view chance,
                                     std::string_view decision, const evidence& observed,
                                     const decision_options& options) {
  const auto informed = observing(diagram, diagram.id(chance), diagram.id(decision));
  return solve_decisions(informed, observed, options).meu - solve_decisions(diagram, observed, options).meu;
}

}  // namespace pgm
