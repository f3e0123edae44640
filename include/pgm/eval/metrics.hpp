#pragma once
/// \file
/// The paper's parameter metrics (Sec. IV-C) over the parameters it counts: the success
/// state's θ_{success|u} for every parent configuration u of the success node (625 for
/// 2-Stack's onTop2). Max-Difference is the largest |θ − θ*|, Mean-Difference their average, so
/// Mean ≤ Max always (docs/decisions.md: the formula read literally with both states of a binary
/// child would double the mean; the text counts 625 parameters, and we follow the text).

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"

namespace pgm {

struct parameter_difference {
  double max = 0;
  double mean = 0;
};

/// Max- and Mean-Difference of the success state's parameters between an estimate and the
/// ground truth of the same shape.
[[nodiscard]] inline parameter_difference success_parameter_difference(const cpt<double>& estimate,
                                                                       const cpt<double>& truth,
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
