#pragma once
// The definitions of pgm/learn/score_registry.hpp: inline in a header-only build, compiled once
// into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/score_registry.hpp"

namespace pgm {

PGM_DECL score_registry& scores() {
  static score_registry registry = [] {
    score_registry built_in("score");
    built_in.add("aic", component_entry<family_score, aic_score>("log-likelihood less k per free parameter"));
    built_in.add("bdeu",
                 component_entry<family_score, bdeu_score>("Bayesian Dirichlet, likelihood-equivalent and uniform"));
    built_in.add("bic", component_entry<family_score, bic_score>("log-likelihood less log(n)/2 per free parameter"));
    built_in.add("k2", component_entry<family_score, k2_score>("Bayesian Dirichlet with one pseudo-count per cell"));
    built_in.add("loglik", component_entry<family_score, loglik_score>("the log-likelihood at the MLE, unpenalised"));
    built_in.add_alias("bde", "bdeu");
    return built_in;
  }();
  return registry;
}

PGM_DECL family_score::family_score() : family_score(make_score("bic")) {}

}  // namespace pgm
