#pragma once
// The definitions of pgm/learn/parameter_prior_registry.hpp: inline in a header-only build,
// compiled once into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/parameter_prior_registry.hpp"

namespace pgm {

PGM_DECL parameter_prior_registry& parameter_priors() {
  static parameter_prior_registry registry = [] {
    parameter_prior_registry built_in("prior");
    built_in.add("bdeu", component_entry<parameter_prior, bdeu_prior>(
                             "Bayesian Dirichlet equivalent uniform: N'/(J·|Val(Pa)|) in every cell"));
    built_in.add("dirichlet", component_entry<parameter_prior, dirichlet_prior>("the same pseudo-count in every cell"));
    built_in.add("k2", component_entry<parameter_prior, k2_prior>("Cooper and Herskovits' K2: 1 in every cell"));
    built_in.add("none", component_entry<parameter_prior, no_prior>("no prior: maximum likelihood"));
    return built_in;
  }();
  return registry;
}

}  // namespace pgm
