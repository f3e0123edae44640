#pragma once
/// \file
/// What a fit learned from its data, kept beside the network so that new data can be added
/// later without the old rows: each family's counts M[x, u], the rows they came from, and the
/// prior and options each table was estimated with. Counts are additive, so updating with new
/// rows and estimating again gives, to the last bit, the network fitted on all the rows at once
/// (with the same prior; a weight w chosen automatically is kept at its first value). A decay
/// λ < 1 multiplies the old counts first, so that old trials weigh less than new ones (a task
/// that drifts); the counts are then no longer whole numbers.

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/parameter_prior.hpp"

namespace pgm {

struct fit_statistics {
  /// Rows counted (after a decay, the decayed sum).
  double rows = 0.0;
  /// Each node's counts, in node order, over the network's variables.
  std::vector<expected_count_table> counts;
  /// The prior each node's table was estimated with, in node order.
  std::vector<parameter_prior> priors;
  estimate_options estimation;
};

namespace detail {

template <class Count>
[[nodiscard]] expected_count_table as_expected(const basic_count_table<Count>& counts) {
  expected_count_table result(counts.child(), counts.parents());
  auto cells = result.counts();
  const auto from = counts.counts();
  for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = static_cast<double>(from[c]);
  return result;
}

}  // namespace detail

/// The statistics of a fit of `structure` from `counts` (one table per node, in node order)
/// over `rows` rows, with the priors and options of `options`.
template <class Count>
[[nodiscard]] fit_statistics statistics_of(const network_structure& structure,
                                           std::span<const basic_count_table<Count>> counts, double rows,
                                           const fit_options& options) {
  if (counts.size() != structure.size()) {
    throw model_error("statistics need one count table per node: " + std::to_string(structure.size()) + " nodes, " +
                      std::to_string(counts.size()) + " tables");
  }
  fit_statistics result;
  result.rows = rows;
  result.estimation = options.estimation;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    const auto& child = structure.at(node);
    const auto own = options.node_priors.find(child.name());
    const auto& prior = own != options.node_priors.end() ? own->second : options.prior;
    result.counts.push_back(detail::as_expected(counts[i]));
    result.priors.push_back(prior);
  }
  return result;
}

/// The network the statistics give: each table estimated from its counts under its prior.
[[nodiscard]] PGM_DECL bayesian_network estimate_network(const network_structure& structure,
                                                         const fit_statistics& statistics);

/// The statistics after new data: decay · the old counts + the new counts (one table per node,
/// in node order, over the same families and states). `decay` is in (0, 1]; 1 keeps every old
/// row at full weight, so that the update equals a fit on all the rows.
template <class Count>
[[nodiscard]] fit_statistics updated(const fit_statistics& old, std::span<const basic_count_table<Count>> more,
                                     double more_rows, double decay = 1.0) {
  if (!(decay > 0.0 && decay <= 1.0)) {
    throw model_error("the decay must be in (0, 1], got " + text::format_double(decay));
  }
  if (more.size() != old.counts.size()) {
    throw model_error("the new counts have " + std::to_string(more.size()) + " tables, the model " +
                      std::to_string(old.counts.size()));
  }
  fit_statistics result = old;
  result.rows = decay * old.rows + more_rows;
  for (std::size_t i = 0; i < more.size(); ++i) {
    auto& counts = result.counts[i];
    if (more[i].child() != counts.child() || more[i].parents() != counts.parents()) {
      throw model_error("the new counts of '" + more[i].child().name() +
                        "' are over another family or other states than the model's");
    }
    auto cells = counts.counts();
    const auto added = more[i].counts();
    for (std::size_t c = 0; c < cells.size(); ++c) {
      cells[c] = (decay == 1.0 ? cells[c] : decay * cells[c]) + static_cast<double>(added[c]);
    }
  }
  return result;
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/fit_statistics.ipp"
#endif
