#pragma once
// The definitions of pgm/transfer/replacement.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/transfer/replacement.hpp"

namespace pgm {

PGM_DECL transferred_prior minimal_replacement::operator()(const transfer_problem& problem) const {
  const std::size_t target_success = problem.success_state();
  const auto direct = direct_plan(problem), cross = cross_plan(problem);
  const auto d = expand_plan(direct, problem), c = expand_plan(cross, problem);
  const auto& prior = problem.prior_table();
  const std::size_t j = prior.child_cardinality();
  const std::size_t success = direct.child_state[target_success];
  // The prior success probability of a run of terms.
  const double* dense = prior.is_sparse() ? nullptr : prior.values().data();
  auto success_of = [&](const plan_terms& terms, std::size_t first, std::uint32_t count) {
    double p = 0;
    for (std::size_t i = first; i < first + count; ++i) {
      const auto u = std::size_t{terms.terms[i].configuration};
      p += terms.terms[i].weight * (dense ? dense[u * j + success] : prior.column(config_index(u))[success]);
    }
    return p;
  };
  const std::size_t n = d.counts.size();
  plan_terms chosen;
  chosen.counts.resize(n);
  chosen.terms.reserve(std::max(d.terms.size(), c.terms.size()));
  std::vector<replacement> via(n);
  std::size_t next_d = 0, next_c = 0;
  for (std::size_t u = 0; u < n; ++u) {
    // Eq. 9: the direct candidate only when strictly smaller; ties go to cross.
    const bool take_direct = success_of(d, next_d, d.counts[u]) < success_of(c, next_c, c.counts[u]);
    const auto& terms = take_direct ? d : c;
    const std::size_t first = take_direct ? next_d : next_c;
    for (std::size_t i = first; i < first + terms.counts[u]; ++i) chosen.terms.push_back(terms.terms[i]);
    chosen.counts[u] = terms.counts[u];
    via[u] = take_direct ? replacement::direct : replacement::cross;
    next_d += d.counts[u];
    next_c += c.counts[u];
  }
  // Both plans order the child's states alike, so either maps the chosen columns.
  auto values = mix_prior_columns(chosen, direct, prior);
  return transferred_prior(cpt<double>(problem.target_child(), problem.target_parents(), std::move(values)),
                           prior.parents(), std::move(chosen.terms), std::move(chosen.counts), std::move(via));
}

}  // namespace pgm
