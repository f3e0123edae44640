#pragma once
/// \file
/// Had the prevention's change been made, would a run that failed have succeeded? The
/// counterfactual P(success had the controllable variables been at the target | the plan was
/// carried out and failed), beside the change prevention suggests. The plan is carried out
/// (do(), not observed), and the network is read as a structural model under the monotone
/// assumption (pgm/causal/counterfactual.hpp): a run keeps its rank in the success table when
/// the controllable variables move. The estimate P(success | target) asks about any run; this
/// asks about the run that failed, and is the larger of the two where the change helps.

#include <optional>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/decide/assignment.hpp"
#include "pgm/decide/explain.hpp"

namespace pgm {

/// The counterfactual success of `why`'s target for a run of `planned` that failed; nothing when
/// the plan cannot fail or `why` moves nothing.
[[nodiscard]] PGM_DECL std::optional<double> counterfactual_success(const bayesian_network& network,
                                                                    const explanation& why, const assignment& planned);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/counterfactual_success.ipp"
#endif
