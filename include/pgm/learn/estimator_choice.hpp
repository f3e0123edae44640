#pragma once
/// \file
/// The estimators by name, as `pgm fit --estimator --prior --alpha --ess` and the Python
/// `pgm.fit(estimator=, prior=, alpha=, ess=)` choose them: "mle" (eq. 3), or "bayes" (eq. 6)
/// with a prior of the registry (pgm/learn/parameter_prior_registry.hpp), bdeu unless another
/// is named.

#include <optional>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/learn/parameter_prior.hpp"
#include "pgm/learn/parameter_prior_registry.hpp"

namespace pgm {

struct estimator_choice {
  /// "mle" or "bayes".
  std::string estimator = "mle";
  /// For "bayes": a prior of the registry, written NAME or NAME[KEY=VALUE,...].
  std::string prior = std::string(default_parameter_prior);
  /// Options given apart from the prior's text, as `--alpha 2` (dirichlet's alpha) and `--ess
  /// 10` (bdeu's ess) are.
  std::vector<component_setting> settings;
};

/// The estimators' names, for messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_estimators() { return {"mle", "bayes"}; }

/// The prior `choice` names. Throws pgm::error for an unknown name, a prior or a setting given
/// to mle, or a setting the prior does not declare or whose value its declaration refuses.
[[nodiscard]] PGM_DECL parameter_prior prior_of(const estimator_choice& choice);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/estimator_choice.ipp"
#endif
