#pragma once
// The definitions of pgm/learn/estimator_choice.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/estimator_choice.hpp"

namespace pgm {

PGM_DECL parameter_prior prior_of(const estimator_choice& choice) {
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
