#pragma once
/// \file
/// Success prediction: the probability that the task succeeds (the success variable takes its
/// success state) for a planned assignment. With every parent of the success variable assigned
/// it is one lookup in the node's table, normalized by its column; otherwise — by request only,
/// since a forgotten value should not pass silently — the inference engine sums out the
/// unassigned variables (variable elimination unless an engine is given).

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/decide/assignment.hpp"
#include "pgm/inference/inference_engine.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

/// Which variable and state mean "the task succeeded", e.g. onTop2 = 1.
struct success_event {
  std::string variable;
  std::string state;
  friend bool operator==(const success_event&, const success_event&) = default;
};

/// The default success event: the unique node that has parents, no children and a state
/// labelled "1". Throws model_error when there is no such node or more than one, naming them.
[[nodiscard]] inline success_event default_success_event(const bayesian_network& network) {
  std::vector<std::string> sinks;
  for (std::size_t i = 0; i < network.size(); ++i) {
    const variable_id node(static_cast<variable_id::rep>(i));
    const auto& v = network.variables()[i];
    if (network.graph().children(node).empty() && !network.graph().parents(node).empty() && v.find_state("1")) {
      sinks.push_back(v.name());
    }
  }
  if (sinks.size() == 1) return {sinks.front(), "1"};
  if (sinks.empty()) {
    throw model_error("no variable without children has a state '1'; name the success event, e.g. onTop2=1");
  }
  throw model_error("several variables could be the success variable (" + detail::list_for_message(sinks) +
                    "); name one, e.g. " + sinks.front() + "=1");
}

/// Parses "variable=state" and checks it against the network.
[[nodiscard]] inline success_event parse_success_event(std::string_view text, const bayesian_network& network) {
  const auto equals = text.find('=');
  const auto name = detail::trim(text.substr(0, equals));
  const auto state = equals == std::string_view::npos ? std::string_view{} : detail::trim(text.substr(equals + 1));
  if (name.empty() || state.empty()) {
    throw model_error("the success event '" + std::string(text) + "' is not of the form variable=state");
  }
  const auto& v = network.structure().at(node_of(network, name));
  static_cast<void>(v.state(state));
  return {std::string(name), std::string(state)};
}

struct prediction_options {
  /// Sum out unassigned parents of the success variable instead of reporting them.
  bool marginalize_missing = false;
  elimination_heuristic heuristic = elimination_heuristic::min_fill;
};

/// The parents of the success variable that `planned` leaves unassigned, in table order.
[[nodiscard]] inline std::vector<std::string> unassigned_parents(const bayesian_network& network,
                                                                 const success_event& success,
                                                                 const assignment& planned) {
  std::vector<std::string> missing;
  for (const auto& parent : network.table(node_of(network, success.variable)).parents()) {
    if (!planned.contains(parent.name())) missing.push_back(parent.name());
  }
  return missing;
}

namespace detail {

[[noreturn]] inline void throw_missing(const success_event& success, const std::vector<std::string>& missing) {
  throw model_error("no value is given for " + std::string(missing.size() == 1 ? "" : "the parents ") +
                    list_for_message(missing) + (missing.size() == 1 ? ", a parent" : "") + " of '" + success.variable +
                    "'; assign " + (missing.size() == 1 ? "it" : "them") + " or ask to marginalize");
}

/// Whether any assigned variable is a descendant of `node` (then the node's table alone is
/// not the conditional distribution).
[[nodiscard]] inline bool observes_descendant(const bayesian_network& network, variable_id node,
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

}  // namespace detail

/// P(success | planned), by `engine` where a lookup does not do (its evidence is restored
/// afterwards). Throws model_error for unknown variables or states, numbers that cannot be
/// binned, an assigned success variable, or (unless marginalizing) unassigned parents;
/// impossible_evidence if the assignment has probability zero.
template <InferenceEngine Engine>
[[nodiscard]] double predict_success(Engine& engine, const success_event& success, const assignment& planned,
                                     const prediction_options& options = {}) {
  const auto& network = engine.network();
  const auto target = node_of(network, success.variable);
  const auto state = network.at(success.variable).state(success.state);
  if (planned.contains(success.variable)) {
    throw model_error("the success variable '" + success.variable + "' is assigned; it is what is predicted");
  }
  const auto observed = resolve(network, planned);
  const auto missing = unassigned_parents(network, success, planned);
  if (!missing.empty() && !options.marginalize_missing) detail::throw_missing(success, missing);
  if (missing.empty() && !detail::observes_descendant(network, target, observed)) {
    const auto& table = network.table(target);
    std::vector<std::size_t> codes;
    for (const auto& parent : table.parents())
      codes.push_back(state_of(parent, planned.find(parent.name())->second).value());
    // The column as stored may miss 1 by rounding (published tables are printed to a few
    // digits); the answer is the normalized entry, as the engines read the column.
    const auto column = table.configuration(codes);
    double sum = 0.0;
    for (std::size_t s = 0; s < table.child().cardinality(); ++s)
      sum += table(state_index(static_cast<state_index::rep>(s)), column);
    return table(state, column) / sum;
  }
  const evidence_set before = engine.evidence();
  engine.set_evidence({observed, {}});
  const variable_id query_ids[] = {target};
  posterior answer;
  try {
    answer = engine.joint(query_ids);
  } catch (const impossible_evidence&) {
    engine.set_evidence(before);
    throw impossible_evidence("the assignment has probability 0 under the network");
  } catch (...) {
    engine.set_evidence(before);
    throw;
  }
  engine.set_evidence(before);
  return answer.table.values()[state.value()];
}

/// The same with variable elimination on `network`.
[[nodiscard]] inline double predict_success(const bayesian_network& network, const success_event& success,
                                            const assignment& planned, const prediction_options& options = {}) {
  variable_elimination engine(network, {options.heuristic});
  return predict_success(engine, success, planned, options);
}

}  // namespace pgm
