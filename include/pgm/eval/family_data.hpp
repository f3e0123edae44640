#pragma once
/// \file
/// One node's family (the node and its parents) read off a task's raw data by the rule of
/// `pgm discretize`, so that the experiment's numbers are those of `pgm discretize | pgm fit |
/// pgm transfer` on the same data: a continuous parent with more distinct values than bins is
/// cut into quantile intervals fitted on that data (the paper's discretization), one with
/// fewer keeps its values as states (the reality grid) as `pgm fit` reads them back
/// (values_as_states, pgm/data/bin_columns.hpp), and a parent that never varies is left out
/// with a note, since it cannot explain anything. Every row becomes one cell index u·J + x,
/// computed by the counting kernel of pgm/learn/sufficient_statistics.hpp, so that counts of
/// any subset of rows are a histogram.

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/bin_columns.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/family_source.hpp"
#include "pgm/learn/fit_pipeline.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

namespace pgm {

struct family_data {
  variable child;
  std::vector<variable> parents;
  std::vector<std::uint32_t> cell;  ///< per row: u·J + x
  dataset table;                    ///< the family's columns as counted: the parents, then the child
  std::vector<std::string> notes;

  [[nodiscard]] std::size_t rows() const noexcept { return cell.size(); }
  [[nodiscard]] count_table empty_counts() const { return count_table(child, parents); }
  [[nodiscard]] std::vector<named_edge> edges() const {
    std::vector<named_edge> result;
    for (const auto& p : parents) result.push_back({p.name(), child.name()});
    return result;
  }
  [[nodiscard]] network_structure structure() const {
    std::vector<variable> variables = parents;
    variables.push_back(child);
    return network_structure(std::move(variables), edges());
  }
  /// Adds the counts of `rows` (indices into the data) to `counts`.
  template <class Rows>
  void add_counts(const Rows& rows, count_table& counts) const {
    auto cells = counts.counts();
    for (auto r : rows) ++cells[cell[r]];
  }
  /// The MLE network of the family over all rows (parents as roots with their marginals), as
  /// `pgm fit --edges` gives it: through the library's one fit pipeline, every state kept.
  [[nodiscard]] bayesian_network fit_all() const {
    fit_request request;
    request.structure = edges();
    for (const auto& name : table.names()) request.states.insert_or_assign(name, table.discrete(name).var());
    dataset_source source(table);
    return fit(source, request).network;
  }
};

/// Reads the family of `node` (parents as given, in order) from raw data.
[[nodiscard]] inline family_data read_family(const dataset& data, const std::string& node,
                                             const std::vector<std::string>& parent_names, std::size_t bins,
                                             const std::map<std::string, semantic_tags, std::less<>>& tags = {}) {
  family_data family{data.discrete(node).var(), {}, {}, dataset(data.source()), {}};
  for (const auto& name : parent_names) {
    const auto tag = tags.find(name);
    const semantic_tags t = tag == tags.end() ? semantic_tags{} : tag->second;
    std::optional<discrete_column> column;
    if (!data.is_discrete(name)) {
      const auto& values = data.continuous(name);
      std::set<double> distinct;
      for (double value : values.values()) {
        if (distinct.insert(value).second && distinct.size() > bins) break;
      }
      if (distinct.size() <= 1) {
        family.notes.push_back("'" + name + "' never varies in this data; it is left out of '" + node + "''s parents");
        continue;
      }
      if (distinct.size() <= bins) {
        column = values_as_states(values);
      } else {
        const std::vector<std::string> one{name};
        column = discretize(values, fit_discretization(data, one, binning::quantile, bins).at(name));
      }
    } else {
      column = data.discrete(name);
    }
    auto tagged = column->with_variable(column->var().with_tags(t));
    family.parents.push_back(tagged.var());
    family.table.add(std::move(tagged));
  }
  family.table.add(data.discrete(node));
  // The cells by the counting kernel, in the layout of the family's count table.
  std::vector<const discrete_column*> parents;
  for (const auto& p : family.parents) parents.push_back(&family.table.discrete(p.name()));
  const auto columns = detail::columns_of(family.empty_counts(), family.table.discrete(node), parents);
  family.cell.resize(data.rows());
  detail::row_cells(columns.columns, columns.strides, 0, data.rows(), family.cell.data());
  return family;
}

}  // namespace pgm
