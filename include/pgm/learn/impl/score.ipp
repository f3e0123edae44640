#pragma once
// The definitions of pgm/learn/score.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/dirichlet.hpp"
#include "pgm/learn/score.hpp"

namespace pgm {

PGM_DECL double family_loglik(const count_table& counts) {
  double total = 0.0;
  counts.for_each_column([&](std::size_t, std::span<const count_table::count_type> column) {
    count_table::count_type n_u = 0;
    for (auto m : column) n_u += m;
    if (n_u == 0) return;
    const double log_n_u = std::log(static_cast<double>(n_u));
    for (auto m : column) {
      if (m > 0) total += static_cast<double>(m) * (std::log(static_cast<double>(m)) - log_n_u);
    }
  });
  return total;
}

PGM_DECL double family_dirichlet(const count_table& counts, double alpha) {
  return dirichlet_log_marginal(counts, uniform_pseudo_counts{alpha, counts.child_cardinality()});
}

}  // namespace pgm
