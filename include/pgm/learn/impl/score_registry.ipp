#pragma once
// The definitions of pgm/learn/score_registry.hpp: inline in a header-only build, compiled once
// into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/score_registry.hpp"

namespace pgm {

PGM_DECL score_registry& scores() {
  static score_registry registry = [] {
    score_registry built_in("score");
    built_in.add("aic", detail::score_entry<aic_score>("log-likelihood less k per free parameter"));
    built_in.add("bdeu", detail::score_entry<bdeu_score>("Bayesian Dirichlet, likelihood-equivalent and uniform"));
    built_in.add("bic", detail::score_entry<bic_score>("log-likelihood less log(n)/2 per free parameter"));
    built_in.add("k2", detail::score_entry<k2_score>("Bayesian Dirichlet with one pseudo-count per cell"));
    built_in.add("loglik", detail::score_entry<loglik_score>("the log-likelihood at the MLE, unpenalised"));
    built_in.add_alias("bde", "bdeu");
    return built_in;
  }();
  return registry;
}

PGM_DECL family_score::family_score() : family_score(make_score("bic")) {}

}  // namespace pgm
