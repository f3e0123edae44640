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
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/success_event.hpp"
#include "pgm/decide/assignment.hpp"
#include "pgm/inference/evidence_scope.hpp"
#include "pgm/inference/inference_engine.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

struct prediction_options {
  /// Sum out unassigned parents of the success variable instead of reporting them.
  bool marginalize_missing = false;
  elimination_heuristic heuristic = elimination_heuristic::min_fill;
};

/// The parents of the success variable that `planned` leaves unassigned, in table order.
[[nodiscard]] PGM_DECL std::vector<std::string> unassigned_parents(const bayesian_network& network,
                                                                   const success_event& success,
                                                                   const assignment& planned);

namespace detail {

[[noreturn]] PGM_DECL void throw_missing(const success_event& success, const std::vector<std::string>& missing);

/// Whether any assigned variable is a descendant of `node` (then the node's table alone is
/// not the conditional distribution).
[[nodiscard]] PGM_DECL bool observes_descendant(const bayesian_network& network, variable_id node,
                                                std::span<const observation> observed);

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
    for (std::size_t s = 0; s < table.child().cardinality(); ++s) sum += table(index_at<state_index>(s), column);
    return table(state, column) / sum;
  }
  const evidence_scope scope(engine, {observed, {}});
  const variable_id query_ids[] = {target};
  try {
    return engine.joint(query_ids).table.values()[state.value()];
  } catch (const impossible_evidence&) {
    throw impossible_evidence("the assignment has probability 0 under the network");
  }
}

/// The same with variable elimination on `network`.
[[nodiscard]] PGM_DECL double predict_success(const bayesian_network& network, const success_event& success,
                                              const assignment& planned, const prediction_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/predict.ipp"
#endif
