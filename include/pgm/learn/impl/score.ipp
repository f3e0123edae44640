#pragma once
// The definitions of pgm/learn/score.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/log_gamma_ratio.hpp"
#include "pgm/learn/score.hpp"

namespace pgm {

PGM_DECL double family_loglik(const count_table& counts) {
  double total = 0.0;
  for (std::size_t u = 0; u < counts.configurations(); ++u) {
    const auto column = counts.column(config_index(static_cast<config_index::rep>(u)));
    count_table::count_type n_u = 0;
    for (auto m : column) n_u += m;
    if (n_u == 0) continue;
    const double log_n_u = std::log(static_cast<double>(n_u));
    for (auto m : column) {
      if (m > 0) total += static_cast<double>(m) * (std::log(static_cast<double>(m)) - log_n_u);
    }
  }
  return total;
}

PGM_DECL double family_dirichlet(const count_table& counts, double alpha) {
  const detail::log_gamma_ratio of_alpha(alpha);
  const detail::log_gamma_ratio of_alpha_u(alpha * static_cast<double>(counts.child_cardinality()));
  double total = 0.0;
  for (std::size_t u = 0; u < counts.configurations(); ++u) {
    const auto column = counts.column(config_index(static_cast<config_index::rep>(u)));
    count_table::count_type n_u = 0;
    for (auto m : column) n_u += m;
    if (n_u == 0) continue;  // an unseen configuration contributes lgamma(a_u) - lgamma(a_u) = 0
    total += -of_alpha_u(static_cast<double>(n_u));
    for (auto m : column) {
      if (m > 0) total += of_alpha(static_cast<double>(m));
    }
  }
  return total;
}

}  // namespace pgm
