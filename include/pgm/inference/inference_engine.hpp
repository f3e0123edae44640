#pragma once
/// \file
/// The `InferenceEngine` concept: what an engine must do for pgm to use it — give its model
/// (`model()`, any GraphicalModel, or `network()`, a Bayesian network), hold evidence by id
/// and answer a joint query by id with a `posterior`, with P(evidence). An engine that also
/// finds the most probable explanation models `MpeEngine`; one that answers many marginals
/// better than one by one offers `marginals(ids)`. The built-in engines: `variable_elimination`
/// ("ve") and `junction_tree_engine` ("jt") over any model, `belief_propagation_engine` ("bp"),
/// `likelihood_weighting` ("lw") and `gibbs_sampling` ("gibbs") over a Bayesian network,
/// `factor_gibbs_engine` ("gibbs") over another; `engine_registry.hpp` picks them by name.
///
/// The free functions below speak names (variables, states) for any engine, so a user's engine
/// needs nothing but the concept.

#include <concepts>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

namespace detail {

/// The model an engine answers over: its model() when it has one, else its network().
template <class E>
[[nodiscard]] const auto& model_of(const E& engine) {
  if constexpr (requires { engine.model(); }) {
    return engine.model();
  } else {
    return engine.network();
  }
}

template <class E>
concept NamedEngine = requires(const E& engine) {
  { engine.name() } -> std::convertible_to<std::string_view>;
  { model_of(engine) } -> HasNamedVariables;
};

template <class E>
concept HoldsEvidence = requires(E& engine, const E& held, evidence_set observed) {
  engine.set_evidence(observed);
  { held.evidence() } -> std::convertible_to<const evidence_set&>;
};

template <class E>
concept AnswersJointQueries = requires(E& engine, std::span<const variable_id> query) {
  { engine.joint(query) } -> std::same_as<posterior>;
  { engine.log_probability_of_evidence() } -> std::same_as<double>;
};

template <class E>
concept AnswersManyMarginals = requires(E& engine, std::span<const variable_id> nodes) {
  { engine.marginals(nodes) } -> std::same_as<std::vector<posterior>>;
};

/// An engine that reads `evidence_set::intervened` (graph surgery) says so with
/// `static constexpr bool handles_interventions = true;`.
template <class E>
concept HandlesInterventions = requires {
  { E::handles_interventions } -> std::convertible_to<bool>;
  requires E::handles_interventions;
};

}  // namespace detail

/// An engine: named, over one network, holding evidence, answering P(query | evidence) and
/// ln P(evidence). Queries on an observed variable and unknown ids are the caller's to refuse
/// (the functions below do). Interventions are optional: see detail::HandlesInterventions.
template <class E>
concept InferenceEngine = detail::NamedEngine<E> && detail::HoldsEvidence<E> && detail::AnswersJointQueries<E>;

/// An engine that also finds the most probable joint state of some variables (all unobserved
/// ones for an empty span).
template <class E>
concept MpeEngine = InferenceEngine<E> && requires(E& engine, std::span<const variable_id> variables) {
  { engine.mpe(variables) } -> std::same_as<mpe_result>;
};

namespace detail {

/// The marginals of `nodes`: the engine's own way when it has one, else one query each.
template <InferenceEngine E>
[[nodiscard]] std::vector<posterior> marginals_of(E& engine, std::span<const variable_id> nodes) {
  if constexpr (AnswersManyMarginals<E>) {
    return engine.marginals(nodes);
  } else {
    std::vector<posterior> result;
    for (auto id : nodes) {
      const variable_id one[] = {id};
      result.push_back(engine.joint(one));
    }
    return result;
  }
}

}  // namespace detail

/// Sets hard and soft evidence and interventions by name (see resolve_evidence for what is
/// refused). Throws model_error for interventions on an engine that does not handle them.
template <InferenceEngine E>
void set_evidence(E& engine, const evidence& hard, const soft_evidence& soft = {}, const intervention& set = {}) {
  auto observed = resolve_evidence(detail::model_of(engine), hard, soft, set);
  if constexpr (!detail::HandlesInterventions<E>) {
    if (!observed.intervened.empty()) {
      throw model_error("the engine '" + std::string(engine.name()) + "' does not handle interventions (do)");
    }
  }
  engine.set_evidence(std::move(observed));
}

/// P(variables | the engine's evidence), the joint over the variables in the order given.
template <InferenceEngine E>
[[nodiscard]] posterior query(E& engine, std::span<const std::string> variables) {
  return engine.joint(resolve_query(detail::model_of(engine), variables, engine.evidence()));
}

/// P(variable | the engine's evidence).
template <InferenceEngine E>
[[nodiscard]] posterior marginal(E& engine, std::string_view variable) {
  const std::string names[] = {std::string(variable)};
  return query(engine, names);
}

/// The marginal of every variable the evidence does not fix, in network order.
template <InferenceEngine E>
[[nodiscard]] std::vector<posterior> marginals(E& engine) {
  std::vector<variable_id> nodes;
  for (std::size_t i = 0; i < detail::model_of(engine).size(); ++i) {
    const variable_id id = index_at<variable_id>(i);
    if (!engine.evidence().fixes(id)) nodes.push_back(id);
  }
  return detail::marginals_of(engine, nodes);
}

/// The most probable joint state of `variables` (every unobserved variable when empty) given
/// the engine's evidence, the other unobserved variables summed out.
template <MpeEngine E>
[[nodiscard]] mpe_result most_probable(E& engine, std::span<const std::string> variables = {}) {
  if (variables.empty()) return engine.mpe({});
  return engine.mpe(resolve_query(detail::model_of(engine), variables, engine.evidence()));
}

}  // namespace pgm
