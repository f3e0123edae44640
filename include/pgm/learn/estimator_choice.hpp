#pragma once
/// \file
/// The built-in estimators by name, as `pgm fit --estimator --prior --alpha --ess` and the
/// Python `pgm.fit(estimator=, prior=, alpha=, ess=)` choose them: "mle" (eq. 3), or "bayes"
/// (eq. 6) with a Dirichlet, K2 or BDeu prior (BDeu when none is named).

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/learn/parameter_prior.hpp"

namespace pgm {

struct estimator_choice {
  /// "mle" or "bayes".
  std::string estimator = "mle";
  /// For "bayes": "dirichlet", "k2" or "bdeu"; empty is "bdeu".
  std::string prior;
  /// The Dirichlet prior's pseudo-count per cell (default 1).
  std::optional<double> alpha;
  /// The BDeu prior's equivalent sample size (default 1).
  std::optional<double> ess;
};

/// The estimators' and the Bayesian estimator's priors' names, for messages and the command
/// line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_estimators() { return {"mle", "bayes"}; }
[[nodiscard]] inline std::vector<std::string> known_priors() { return {"dirichlet", "k2", "bdeu"}; }

/// The prior `choice` names. Throws pgm::error for an unknown name, or a prior, alpha or ess
/// that the chosen estimator does not use.
[[nodiscard]] PGM_DECL parameter_prior prior_of(const estimator_choice& choice);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/estimator_choice.ipp"
#endif
