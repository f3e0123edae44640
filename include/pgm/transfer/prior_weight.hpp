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

#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

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
[[nodiscard]] inline double log_evidence(const count_table& counts, const cpt<double>& prior, double weight,
                                         double floor = 1e-3) {
  const std::size_t j = counts.child_cardinality();
  const double uniform = floor / static_cast<double>(j);
  double total = 0;
  for (std::size_t u = 0; u < counts.configurations(); ++u) {
    const config_index c(static_cast<config_index::rep>(u));
    const auto m = counts.column(c);
    const auto f = prior.column(c);
    double n = 0;
    for (std::size_t x = 0; x < j; ++x) {
      if (m[x] == 0) continue;
      const double alpha = weight * ((1 - floor) * f[x] + uniform);
      total += boost::math::lgamma(alpha + static_cast<double>(m[x])) - boost::math::lgamma(alpha);
      n += static_cast<double>(m[x]);
    }
    if (n > 0) total += boost::math::lgamma(weight) - boost::math::lgamma(weight + n);
  }
  return total;
}

/// The grid weight of highest evidence, with the evidence along the grid and a sentence why.
[[nodiscard]] inline prior_weight_choice choose_prior_weight(const count_table& counts, const cpt<double>& prior,
                                                             const prior_weight_search& search = {}) {
  if (counts.parents().size() != prior.parents().size() || counts.child_cardinality() != prior.child_cardinality() ||
      counts.configurations() != prior.configurations()) {
    throw model_error("the prior table of '" + prior.child().name() + "' does not have the shape of its counts");
  }
  if (!(search.smallest > 0) || !(search.largest > search.smallest) || search.steps_per_decade == 0) {
    throw model_error("the prior-weight grid needs 0 < smallest < largest and at least one step per decade");
  }
  prior_weight_choice choice{search.without_data, 0, {}, {}, {}};
  const double decades = std::log10(search.largest / search.smallest);
  const auto steps = static_cast<std::size_t>(std::ceil(decades * static_cast<double>(search.steps_per_decade)));
  for (std::size_t k = 0; k <= steps; ++k) {
    choice.grid.push_back(search.smallest *
                          std::pow(10.0, static_cast<double>(k) / static_cast<double>(search.steps_per_decade)));
  }
  if (counts.total() == 0) {
    choice.reason =
        "no target data: every w > 0 gives the prior itself; w = " + detail::format_short(search.without_data);
    choice.log_evidence_on_grid.assign(choice.grid.size(), 0.0);
    return choice;
  }
  std::size_t best = 0;
  for (std::size_t k = 0; k < choice.grid.size(); ++k) {
    choice.log_evidence_on_grid.push_back(log_evidence(counts, prior, choice.grid[k], search.floor));
    if (choice.log_evidence_on_grid[k] > choice.log_evidence_on_grid[best]) best = k;
  }
  choice.weight = choice.grid[best];
  choice.log_evidence = choice.log_evidence_on_grid[best];
  choice.reason = "w = " + detail::format_short(choice.weight, 3) + " maximizes the marginal likelihood of the " +
                  std::to_string(counts.total()) + " target rows (log evidence " +
                  detail::format_short(choice.log_evidence, 6) + ")";
  if (best == 0 || best + 1 == choice.grid.size()) {
    choice.reason += best == 0 ? "; at the grid's low end: the data trusts the prior little"
                               : "; at the grid's high end: the data agrees with the prior closely";
  } else {
    auto relative = [&](std::size_t k) {
      return detail::format_short(choice.log_evidence_on_grid[k] - choice.log_evidence, 3);
    };
    choice.reason += "; neighbours w = " + detail::format_short(choice.grid[best - 1], 3) + " (" + relative(best - 1) +
                     ") and w = " + detail::format_short(choice.grid[best + 1], 3) + " (" + relative(best + 1) + ")";
  }
  return choice;
}

}  // namespace pgm
