#pragma once
/// \file
/// One node's family (the node and its parents) read off a task's raw data: continuous parents
/// are binned into quantile intervals fitted on that data (the paper's discretization), a parent
/// with no more distinct values than bins keeps its values as states (the reality grid), and a
/// parent that never varies is left out with a note, since it cannot explain anything. Every row
/// becomes one cell index u·J + x, computed by the counting kernel of
/// pgm/learn/sufficient_statistics.hpp, so that counts of any subset of rows are a histogram.

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

namespace pgm {

struct family_data {
  variable child;
  std::vector<variable> parents;
  std::vector<std::uint32_t> cell;              ///< per row: u·J + x
  std::vector<discrete_column> parent_columns;  ///< per parent: its binned codes
  std::vector<std::string> notes;

  [[nodiscard]] std::size_t rows() const noexcept { return cell.size(); }
  [[nodiscard]] count_table empty_counts() const { return count_table(child, parents); }
  [[nodiscard]] network_structure structure() const {
    std::vector<variable> variables = parents;
    variables.push_back(child);
    std::vector<named_edge> edges;
    for (const auto& p : parents) edges.push_back({p.name(), child.name()});
    return network_structure(std::move(variables), edges);
  }
  /// Adds the counts of `rows` (indices into the data) to `counts`.
  template <class Rows>
  void add_counts(const Rows& rows, count_table& counts) const {
    auto cells = counts.counts();
    for (auto r : rows) ++cells[cell[r]];
  }
  /// The MLE network of the family over all rows: parents as roots with their marginals.
  [[nodiscard]] bayesian_network fit_all() const {
    std::vector<cpt<double>> tables;
    for (const auto& column : parent_columns) {
      tables.push_back(estimate_mle(count_family(column, {}, {.threads = 1})));
    }
    auto counts = empty_counts();
    for (auto c : cell) ++counts.counts()[c];
    tables.push_back(estimate_mle(counts));
    return bayesian_network::from_tables(std::move(tables));
  }
};

/// Reads the family of `node` (parents as given, in order) from raw data.
[[nodiscard]] inline family_data read_family(const dataset& data, const std::string& node,
                                             const std::vector<std::string>& parent_names, std::size_t bins,
                                             const std::map<std::string, semantic_tags, std::less<>>& tags = {}) {
  family_data family{data.discrete(node).var(), {}, {}, {}, {}};
  const auto rows = data.rows();
  for (const auto& name : parent_names) {
    const auto tag = tags.find(name);
    const semantic_tags t = tag == tags.end() ? semantic_tags{} : tag->second;
    std::vector<std::uint32_t> codes(rows);
    variable v("?", {"?"});
    if (!data.is_discrete(name)) {
      const auto& x = data.continuous(name).values();
      std::set<double> distinct;
      for (double value : x) {
        if (distinct.insert(value).second && distinct.size() > bins) break;
      }
      if (distinct.size() <= 1) {
        family.notes.push_back("'" + name + "' never varies in this data; it is left out of '" + node + "''s parents");
        continue;
      }
      if (distinct.size() <= bins) {
        std::vector<double> levels(distinct.begin(), distinct.end());
        std::vector<std::string> labels;
        for (double level : levels) labels.push_back(detail::format_short(level));
        v = variable(name, labels, t);
        for (std::size_t r = 0; r < rows; ++r) {
          codes[r] = static_cast<std::uint32_t>(std::lower_bound(levels.begin(), levels.end(), x[r]) - levels.begin());
        }
      } else {
        v = variable::intervals(name, quantile_edges(x, bins, name), t);
        for (std::size_t r = 0; r < rows; ++r) codes[r] = v.bin(x[r]).value();
      }
    } else {
      const auto& column = data.discrete(name);
      v = column.var().with_tags(t);
      for (std::size_t r = 0; r < rows; ++r) codes[r] = column.code(r);
    }
    family.parents.push_back(v);
    family.parent_columns.emplace_back(std::move(v), codes);
  }
  // The cells by the counting kernel, in the layout of the family's count table.
  std::vector<const discrete_column*> parents;
  for (const auto& column : family.parent_columns) parents.push_back(&column);
  const auto columns = detail::columns_of(family.empty_counts(), data.discrete(node), parents);
  family.cell.resize(rows);
  detail::row_cells(columns.columns, columns.strides, 0, rows, family.cell.data());
  return family;
}

}  // namespace pgm
