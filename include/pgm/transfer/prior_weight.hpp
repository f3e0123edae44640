#pragma once
/// \file
/// Choosing the prior weight w of eq. 8 from the target data, where the paper leaves it to the
/// user: the w on a log-spaced grid that maximizes the closed-form Dirichlet-multinomial
/// marginal likelihood of the target counts under the prior Dirichlet(w·f):
///
///   log P(D | w) = Σ_u [ lnΓ(w) − lnΓ(w + M[u]) + Σ_x lnΓ(w·f_x|u + M[x,u]) − lnΓ(w·f_x|u) ].
///
/// A prior that puts probability 0 on an outcome the target data shows would make every w
/// impossible, so f is first mixed with the uniform distribution by `floor` (1e-3): such a
/// prior is then merely very wrong, which favours small weights as it should. With no target
/// data every w gives the prior itself (eq. 8 with M[u] = 0), so the choice cannot matter; we
/// report the paper's best weight, 5.

#include <cmath>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/dirichlet.hpp"

namespace pgm {

struct prior_weight_search {
  double smallest = 0.1;
  double largest = 10'000;
  std::size_t steps_per_decade = 8;
  double floor = 1e-3;
  /// Reported when the target data is empty.
  double without_data = 5;
};

struct prior_weight_choice {
  double weight;
  double log_evidence;  ///< at `weight`; 0 without data
  std::vector<double> grid;
  std::vector<double> log_evidence_on_grid;
  std::string reason;
};

/// log P(D | w, f) of eq. above for counts M and prior table f of the same shape.
[[nodiscard]] PGM_DECL double log_evidence(const count_table& counts, const cpt<double>& prior, double weight,
                                           double floor = 1e-3);

/// The grid weight of highest evidence, with the evidence along the grid and a sentence why.
[[nodiscard]] PGM_DECL prior_weight_choice choose_prior_weight(const count_table& counts, const cpt<double>& prior,
                                                               const prior_weight_search& search = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/transfer/impl/prior_weight.ipp"
#endif
