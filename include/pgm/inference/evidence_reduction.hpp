#pragma once
/// \file
/// Hard evidence entered into a model's factors before anything is compiled: each factor sliced
/// at the observed states, and the observed variables taken out of the model, as libDAI and
/// Merlin do before they triangulate. The junction tree is then built on the unobserved
/// variables' graph only, so its cliques, its order search and its memory shrink with the
/// evidence (the 37 observed variables of Pedigree_11), rather than every clique keeping its
/// observed variables' states at zero.

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "pgm/core/graphical_model.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/semiring.hpp"

namespace pgm {

/// A model with hard evidence entered: its unobserved variables, renumbered in id order, and
/// its factors sliced at the observed states.
struct evidence_reduced_model {
  markov_network model;
  /// original[i]: the id in the first model of the reduced model's variable i.
  std::vector<variable_id> original;
  /// ln of the product of the factors left over no variable (their scope all observed).
  double log_constant = 0.0;
  /// Whether one of those factors is 0: the evidence is impossible.
  bool impossible = false;
};

/// `model` with `observed`'s hard evidence entered, or nothing where there is nothing to take
/// out, or where the evidence is more than hard observations (soft evidence and interventions
/// stay with the engines that know them), or where it observes every variable.
template <GraphicalModel M>
[[nodiscard]] std::optional<evidence_reduced_model> reduce_by_evidence(const M& model, const evidence_set& observed) {
  if (observed.hard.empty() || !observed.soft.empty() || !observed.intervened.empty()) return std::nullopt;
  constexpr std::size_t kept_out = static_cast<std::size_t>(-1);
  std::vector<std::size_t> state(model.size(), kept_out);
  for (const auto& o : observed.hard) state[o.variable.value()] = o.state.value();
  evidence_reduced_model reduced;
  std::vector<variable_id> renumbered(model.size());
  std::vector<variable> variables;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (state[i] != kept_out) continue;
    renumbered[i] = index_at<variable_id>(variables.size());
    reduced.original.push_back(index_at<variable_id>(i));
    variables.push_back(model.variables()[i]);
  }
  if (variables.empty()) return std::nullopt;
  std::vector<factor_table> factors;
  for (std::size_t f = 0; f < model.factor_count(); ++f) {
    auto sliced = detail::model_factor<sum_product<double>>(model, f);
    for (auto id : model.factor_scope(f)) {
      if (state[id.value()] != kept_out) sliced = sliced.reduce(id, state[id.value()]);
    }
    if (sliced.scope().empty()) {
      const double constant = sliced.values().front();
      if (constant == 0.0) reduced.impossible = true;
      reduced.log_constant += std::log(constant);
      continue;
    }
    std::vector<variable_id> scope;
    for (auto id : sliced.scope()) scope.push_back(renumbered[id.value()]);
    factors.emplace_back(std::move(scope), sliced.cardinalities(),
                         std::vector<double>(sliced.values().begin(), sliced.values().end()));
  }
  reduced.model = markov_network(std::move(variables), std::move(factors));
  return reduced;
}

}  // namespace pgm
