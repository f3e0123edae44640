#pragma once
/// \file
/// One node's family (the node and its parents) read off a task's raw data by the rule of
/// `pgm discretize`, so that the experiment's numbers are those of `pgm discretize | pgm fit |
/// pgm transfer` on the same data: a continuous parent with more distinct values than bins is
/// cut into quantile intervals fitted on that data (the paper's discretization), one with
/// fewer keeps its values as states (the reality grid) as `pgm fit` reads them back
/// (values_as_states, pgm/data/bin_columns.hpp), and a parent that never varies is left out
/// with a note, since it cannot explain anything. Every row becomes one cell index u·J + x,
/// computed by the counting kernel of pgm/data/sufficient_statistics.hpp, so that counts of
/// any subset of rows are a histogram.

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/bin_columns.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/family_source.hpp"
#include "pgm/pipeline/fit_pipeline.hpp"

namespace pgm {

struct family_data {
  variable child;
  std::vector<variable> parents;
  std::vector<std::uint32_t> cell;  ///< per row: u·J + x
  dataset table;                    ///< the family's columns as counted: the parents, then the child
  std::vector<std::string> notes;

  [[nodiscard]] std::size_t rows() const noexcept { return cell.size(); }
  [[nodiscard]] count_table empty_counts() const { return count_table(child, parents); }
  [[nodiscard]] PGM_DECL std::vector<named_edge> edges() const;
  [[nodiscard]] PGM_DECL network_structure structure() const;
  /// Adds the counts of `rows` (indices into the data) to `counts`.
  template <class Rows>
  void add_counts(const Rows& rows, count_table& counts) const {
    auto cells = counts.counts();
    for (auto r : rows) ++cells[cell[r]];
  }
  /// The MLE network of the family over all rows (parents as roots with their marginals), as
  /// `pgm fit --edges` gives it: through the library's one fit pipeline, every state kept.
  [[nodiscard]] PGM_DECL bayesian_network fit_all() const;
};

/// Reads the family of `node` (parents as given, in order) from raw data.
[[nodiscard]] PGM_DECL family_data read_family(const dataset& data, const std::string& node,
                                               const std::vector<std::string>& parent_names, std::size_t bins,
                                               const std::map<std::string, semantic_tags, std::less<>>& tags = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/family_data.ipp"
#endif
