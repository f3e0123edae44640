#pragma once
/// \file
/// Counterfactuals on a structural model (pgm/core/structural_model.hpp): "had xOff1 been 0,
/// would the tower have stood, given that it fell with xOff1 = 2?", P(Y_{do(x')} = y | e).
///
/// Answered on the twin network (Balke & Pearl, "Probabilistic evaluation of counterfactual
/// queries", AAAI 1994): the factual world and the world where the intervention was done, side
/// by side, sharing the noises. Evidence enters the factual world; the query is read in the
/// other. Only what the intervention reaches gets a copy (its descendants), and only their noises
/// appear as nodes: everything else is one node in both worlds with its network's table. The
/// answer is exact inference on that network, so it equals abduction, action and prediction
/// over every noise value (tests/causal/counterfactual_test.cpp enumerates them).
///
/// A causal network does not identify counterfactuals. `monotone_structural_model` makes one
/// structural model of it under a stated assumption, the one under which Pearl's monotonicity
/// holds: every variable draws its state from one uniform noise U by its cumulative table,
///
///     V = the first state s with U < P(V ≤ s | parents),
///
/// the same U for every configuration of the parents. A unit keeps its rank when the parents
/// change: for two states, no unit that has y under a configuration loses it under one where y
/// is likelier. The states' order is the variable's. The model implies the network exactly.

#include <span>
#include <string>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/structural_model.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

/// The network's tables as structural equations under the monotone assumption above: a
/// variable's noise has a state per gap between the distinct cumulative probabilities of all its
/// columns (at most configurations × (states − 1) + 1). Throws model_error (table_too_large)
/// when a function's table would exceed max_table_cells.
[[nodiscard]] PGM_DECL structural_model monotone_structural_model(const bayesian_network& network);

/// The factual and the intervened world of a structural model in one Bayesian network.
struct twin_network {
  bayesian_network network;
  /// Per variable of the model (by id), its node in the intervened world: its copy where the
  /// intervention reaches it, else its one node. A variable's factual node has its own name.
  std::vector<variable_id> intervened;
};

/// The twin network of `model` under do(`set`). Copies are named "X*" and noises "U_X" (with
/// more '*' or '_' where a name is taken). Throws model_error for an unknown variable or state.
[[nodiscard]] PGM_DECL twin_network make_twin_network(const structural_model& model, const intervention& set);

/// The twin network of monotone_structural_model(network), making the equations of only what
/// the intervention reaches: a large table elsewhere costs nothing.
[[nodiscard]] PGM_DECL twin_network make_monotone_twin_network(const bayesian_network& network,
                                                               const intervention& set);

/// P(`names` in the world where `set` had been done | `observed` in this one), a table over the
/// model's variables of those names (the last fastest); its evidence_probability is P(observed).
/// A query variable that is observed and that the intervention does not reach keeps its observed
/// state. Throws model_error for unknown names or states, an empty query or one naming a
/// variable twice, and impossible_evidence when P(observed) = 0.
[[nodiscard]] PGM_DECL posterior counterfactual_query(const structural_model& model, std::span<const std::string> names,
                                                      const evidence& observed, const intervention& set);

/// The same on monotone_structural_model(network), through make_monotone_twin_network.
[[nodiscard]] PGM_DECL posterior monotone_counterfactual_query(const bayesian_network& network,
                                                               std::span<const std::string> names,
                                                               const evidence& observed, const intervention& set);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/causal/impl/counterfactual.ipp"
#endif
