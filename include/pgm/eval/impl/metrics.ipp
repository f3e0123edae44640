#pragma once
// The definitions of pgm/eval/metrics.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/metrics.hpp"

namespace pgm {

PGM_DECL parameter_difference success_parameter_difference(const cpt<double>& estimate, const cpt<double>& truth,
                                                           std::size_t success_state) {
  if (estimate.configurations() != truth.configurations() ||
      estimate.child_cardinality() != truth.child_cardinality()) {
    throw model_error("the estimate and the ground truth of '" + truth.child().name() + "' differ in shape");
  }
  if (success_state >= truth.child_cardinality()) throw model_error("the success state is out of range");
  parameter_difference d;
  const std::size_t j = truth.child_cardinality();
  const auto a = estimate.values(), b = truth.values();
  for (std::size_t u = 0; u < truth.configurations(); ++u) {
    const double gap = std::abs(a[u * j + success_state] - b[u * j + success_state]);
    d.max = std::max(d.max, gap);
    d.mean += gap;
  }
  d.mean /= static_cast<double>(truth.configurations());
  return d;
}

}  // namespace pgm
