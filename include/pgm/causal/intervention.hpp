#pragma once
/// \file
/// Interventions as graph surgery. `intervene(network, do)` is the mutilated network, as
/// bnlearn's `mutilated()`: each intervened variable loses its parents and gets the point
/// distribution at its state, every other table kept — a network to write, draw or query with
/// any tool. To query under an intervention, set it on an engine instead
/// (`set_evidence(engine, evidence, soft, do)`, docs/causal.md): the engines apply the surgery
/// as a view, copying no table.

#include <string>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

/// The network with do(X = x) for each entry of `set`. Throws model_error for an unknown
/// variable or state (naming the known ones).
[[nodiscard]] PGM_DECL bayesian_network intervene(const bayesian_network& network, const intervention& set);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/causal/impl/intervention.ipp"
#endif
