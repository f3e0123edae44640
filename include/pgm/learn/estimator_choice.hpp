#pragma once
/// \file
/// The built-in estimators by name, as `pgm fit --estimator --prior --alpha --ess` and the
/// Python `pgm.fit(estimator=, prior=, alpha=, ess=)` choose them: "mle" (eq. 3), or "bayes"
/// (eq. 6) with a Dirichlet, K2 or BDeu prior (BDeu when none is named).

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

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
[[nodiscard]] inline parameter_prior prior_of(const estimator_choice& choice) {
  if (choice.estimator == "mle") {
    if (!choice.prior.empty() || choice.alpha || choice.ess) {
      throw error("prior, alpha and ess apply to the bayes estimator, not mle");
    }
    return no_prior{};
  }
  if (choice.estimator != "bayes") throw unknown_name("estimator", choice.estimator, known_estimators());
  const auto prior = choice.prior.empty() ? std::string("bdeu") : choice.prior;
  if (const auto known = known_priors(); std::find(known.begin(), known.end(), prior) == known.end()) {
    throw unknown_name("prior", prior, known);
  }
  if (choice.alpha && prior != "dirichlet") throw error("alpha applies to the dirichlet prior");
  if (choice.ess && prior != "bdeu") throw error("ess applies to the bdeu prior");
  for (const auto& [value, what] : {std::pair{choice.alpha, "alpha"}, std::pair{choice.ess, "ess"}}) {
    if (value) detail::check_pseudo_count(*value, what);
  }
  if (prior == "dirichlet") return dirichlet_prior{choice.alpha.value_or(1.0)};
  if (prior == "k2") return k2_prior{};
  return bdeu_prior{choice.ess.value_or(1.0)};
}

}  // namespace pgm
