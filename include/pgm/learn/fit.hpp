#pragma once
/// \file
/// Fitting every table of a network from a data set in one call.

#include <map>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/parameter_prior.hpp"

namespace pgm {

struct fit_options {
  /// The prior of every node without an entry in `node_priors`.
  parameter_prior prior = no_prior{};
  /// Priors of single nodes, by name (a transferred `weighted_prior`, say).
  std::map<std::string, parameter_prior, std::less<>> node_priors;
  estimate_options estimation;
  count_options counting;
  row_range rows;
};

/// The variables of a structure read off a data set: the discrete columns named by the
/// edges, in the data's column order, with their states. Throws data_error for a column that
/// is missing or continuous, not_a_dag for a cycle.
[[nodiscard]] PGM_DECL network_structure structure_from_data(const dataset& data, const std::vector<named_edge>& edges);

/// `structure` with the interval edges of the variables `intervals` names (those it lacks are
/// skipped): the intervals its discretized columns hold, kept with the model. `source` names
/// where the intervals came from. Throws data_error when a variable's states differ from the
/// intervals'.
[[nodiscard]] PGM_DECL network_structure with_intervals(network_structure structure, const discretization& intervals,
                                                        std::string_view source);

/// The count table of one node of a structure, with the structure's variables.
[[nodiscard]] PGM_DECL count_table count_node(const network_structure& structure, variable_id node, const dataset& data,
                                              const count_options& counting = {}, row_range rows = {});

namespace detail {

/// Every table of `structure`, node by node, from `counts_of(node)` (a count_table over the
/// structure's variables).
template <class CountsOf>
[[nodiscard]] bayesian_network fit_tables(const network_structure& structure, const fit_options& options,
                                          CountsOf&& counts_of) {
  for (const auto& [name, prior] : options.node_priors) {
    if (!structure.contains(name)) {
      throw model_error("a prior is given for '" + name + "', which is not in the network");
    }
  }
  std::vector<cpt<double>> tables;
  tables.reserve(structure.size());
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    const auto& counts = counts_of(node);
    const auto own = options.node_priors.find(structure.at(node).name());
    tables.push_back(
        estimate(counts, own != options.node_priors.end() ? own->second : options.prior, options.estimation));
  }
  return bayesian_network(structure, std::move(tables));
}

}  // namespace detail

/// Fits every table of `structure` from `data`. Columns must carry the states the structure
/// gives its variables.
[[nodiscard]] PGM_DECL bayesian_network fit(const network_structure& structure, const dataset& data,
                                            const fit_options& options = {});

/// Fits every table of `structure` from the counts of each node's family: `counts[i]` is node
/// i's, over the structure's variables (from count_node, or from pgm/io/csv_counts.hpp for
/// a file too large for memory). Throws model_error for a table of another family.
[[nodiscard]] PGM_DECL bayesian_network fit(const network_structure& structure, std::span<const count_table> counts,
                                            const fit_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/fit.ipp"
#endif
