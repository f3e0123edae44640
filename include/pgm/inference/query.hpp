#pragma once
/// \file
/// The vocabulary every inference engine speaks: what is observed (hard evidence, a state per
/// variable; soft evidence, a likelihood over a variable's states) and what is set (an
/// intervention do(X = x)), what comes back (a `posterior` with P(evidence), an `mpe_result`),
/// and the checks that turn names into ids with messages naming what is wrong.
///
/// An intervention do(X = x) is graph surgery: X loses its parents and its table, and is fixed
/// at x (the truncated factorisation); P(evidence) is then the probability of the observations
/// in that mutilated network. Engines that handle it say so (`handles_interventions`).
///
/// Soft evidence is likelihood (virtual) evidence, as pgmpy's `virtual_evidence` and aGrUM's
/// soft evidence: observing λ on X multiplies the joint by λ(x), so P(x | λ) ∝ P(x)·λ(x). Only
/// the ratios of λ matter for posteriors; P(evidence) is Σ_x P(x)·λ(x) with λ as given.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/core/text.hpp"
#include "pgm/inference/factor.hpp"

namespace pgm {

/// Evidence whose probability is zero under the network: nothing can be conditioned on it.
class impossible_evidence : public model_error {
 public:
  using model_error::model_error;
};

/// Observed states by variable name.
using evidence = std::map<std::string, std::string, std::less<>>;

/// Likelihoods by variable name: one non-negative weight per state, in the variable's order.
using soft_evidence = std::map<std::string, std::vector<double>, std::less<>>;

/// One observed state by id, the form the library passes around internally.
struct observation {
  variable_id variable;
  state_index state;
  friend bool operator==(const observation&, const observation&) = default;
};

/// A likelihood over one variable's states by id.
struct likelihood {
  variable_id variable;
  std::vector<double> weights;
  friend bool operator==(const likelihood&, const likelihood&) = default;
};

/// Interventions by variable name: do(X = state).
using intervention = std::map<std::string, std::string, std::less<>>;

/// Hard and soft evidence and interventions by id, each variable at most once in all.
struct evidence_set {
  std::vector<observation> hard;
  std::vector<likelihood> soft;
  /// do(X = x): X cut from its parents, its table dropped, fixed at x.
  std::vector<observation> intervened;

  [[nodiscard]] bool empty() const noexcept { return hard.empty() && soft.empty() && intervened.empty(); }
  [[nodiscard]] bool observes(variable_id id) const noexcept {
    return std::any_of(hard.begin(), hard.end(), [&](const observation& o) { return o.variable == id; }) ||
           std::any_of(soft.begin(), soft.end(), [&](const likelihood& l) { return l.variable == id; });
  }
  [[nodiscard]] bool intervenes(variable_id id) const noexcept {
    return std::any_of(intervened.begin(), intervened.end(), [&](const observation& o) { return o.variable == id; });
  }
  /// Whether `id` is in one state, observed or set (soft evidence does not fix a state).
  [[nodiscard]] bool fixes(variable_id id) const noexcept {
    return std::any_of(hard.begin(), hard.end(), [&](const observation& o) { return o.variable == id; }) ||
           intervenes(id);
  }
  friend bool operator==(const evidence_set&, const evidence_set&) = default;
};

/// A normalized distribution over `variables` (in the order asked), with P(evidence).
struct posterior {
  std::vector<variable> variables;
  /// Over the variables' network ids in the same order, values summing to one.
  factor table;
  double evidence_probability = 1.0;
  /// ln P(evidence), finite also where P(evidence) underflows a double (then 0 above).
  double log_evidence_probability = 0.0;
  /// One per value of `table` for estimates by sampling; empty for exact answers.
  std::vector<double> standard_errors;
  /// The engine that answered, e.g. "jt" (an "auto" engine names the one it chose).
  std::string engine;

  /// The probability of these states (labels, one per variable in order).
  [[nodiscard]] double probability(std::span<const std::string> states) const {
    return table.values()[index_of(states)];
  }
  [[nodiscard]] double probability(std::initializer_list<std::string> states) const {
    return probability(std::span<const std::string>(states.begin(), states.size()));
  }
  /// The standard error of probability(states); 0 for exact answers.
  [[nodiscard]] double standard_error(std::span<const std::string> states) const {
    return standard_errors.empty() ? 0.0 : standard_errors[index_of(states)];
  }

 private:
  [[nodiscard]] PGM_DECL std::size_t index_of(std::span<const std::string> states) const;
};

/// The most probable joint state of some variables given the evidence (the most probable
/// explanation when they are all the unobserved ones).
struct mpe_result {
  std::vector<variable> variables;
  /// One state index per variable, in order.
  std::vector<state_index> states;
  /// P(states | evidence); `log_probability` stays finite where this underflows to 0.
  double probability = 0.0;
  double log_probability = 0.0;
  /// P(states, evidence) and its logarithm.
  double joint_probability = 0.0;
  double log_joint_probability = 0.0;
  std::string engine;

  /// The state label of each variable, by name.
  [[nodiscard]] PGM_DECL evidence assignment() const;
};

/// The id of `name` in any other model than a Bayesian network (pgm/core/bayesian_network.hpp) (its id() names the
/// known variables when it throws).
template <detail::HasNamedVariables M>
requires(!std::same_as<M, bayesian_network>) [[nodiscard]] variable_id node_of(const M& model, std::string_view name) {
  return model.id(name);
}

namespace detail {

/// "a=s, b=t, do(c=u)" for messages, the variables a model's.
[[nodiscard]] PGM_DECL std::string describe(const std::vector<variable>& variables, const evidence_set& observed);

[[nodiscard]] inline std::string describe(const bayesian_network& network, const evidence_set& observed) {
  return describe(network.variables(), observed);
}

/// `weights` as soft evidence on `v`: throws model_error for the wrong length, a negative or
/// non-finite weight, or every weight 0.
[[nodiscard]] PGM_DECL std::vector<double> checked_likelihood(const variable& v, const std::vector<double>& weights);

/// Any model but a Bayesian network (a Markov network, a user's) is "the model" in the message.
template <HasNamedVariables M>
[[noreturn]] void throw_impossible(const M& model, const evidence_set& observed) {
  throw impossible_evidence("the evidence " + describe(model.variables(), observed) +
                            " has probability 0 under the model");
}

[[noreturn]] inline void throw_impossible(const bayesian_network& network, const evidence_set& observed) {
  throw impossible_evidence("the evidence " + describe(network, observed) + " has probability 0 under the network");
}

}  // namespace detail

/// Hard and soft evidence and interventions by name resolved to ids, in any model. Throws
/// model_error for an unknown variable or state (naming the known ones), a variable observed
/// both ways or both observed and intervened on, or a likelihood of the wrong length, with a
/// negative or non-finite weight, or with every weight 0.
template <detail::HasNamedVariables M>
[[nodiscard]] evidence_set resolve_evidence(const M& model, const evidence& hard, const soft_evidence& soft = {},
                                            const intervention& set = {}) {
  evidence_set result;
  for (const auto& [name, state] : set) {
    const auto id = node_of(model, name);
    if (hard.contains(name) || soft.contains(name)) {
      throw model_error("'" + name + "' is both intervened on and observed; do(" + name + "=" + state +
                        ") sets it, so there is nothing to observe");
    }
    result.intervened.push_back({id, model.variables()[id.value()].state(state)});
  }
  for (const auto& [name, state] : hard) {
    const auto id = node_of(model, name);
    result.hard.push_back({id, model.variables()[id.value()].state(state)});
  }
  for (const auto& [name, weights] : soft) {
    const auto id = node_of(model, name);
    if (hard.contains(name)) throw model_error("'" + name + "' has both hard and soft evidence");
    result.soft.push_back({id, detail::checked_likelihood(model.variables()[id.value()], weights)});
  }
  return result;
}

/// The ids of query variables by name. Throws model_error for an unknown variable, an empty
/// list, a variable asked twice, one observed in a state or one intervened on (soft evidence on
/// a queried variable is fine: its posterior is the prior reweighted).
template <detail::HasNamedVariables M>
[[nodiscard]] std::vector<variable_id> resolve_query(const M& model, std::span<const std::string> names,
                                                     const evidence_set& observed = {}) {
  if (names.empty()) throw model_error("the query names no variable");
  std::vector<variable_id> ids;
  for (const auto& name : names) {
    const auto id = node_of(model, name);
    if (std::find(ids.begin(), ids.end(), id) != ids.end()) throw model_error("the query names '" + name + "' twice");
    if (observed.intervenes(id)) {
      throw model_error("'" + name +
                        "' is intervened on, so its distribution is the point it is set to; query "
                        "another variable");
    }
    if (observed.fixes(id)) throw model_error("'" + name + "' is both queried and observed");
    ids.push_back(id);
  }
  return ids;
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/query.ipp"
#endif
