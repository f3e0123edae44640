#pragma once
// The definitions of pgm/eval/family_data.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/family_data.hpp"

namespace pgm {

PGM_DECL std::vector<named_edge> family_data::edges() const {
  std::vector<named_edge> result;
  for (const auto& p : parents) result.push_back({p.name(), child.name()});
  return result;
}

PGM_DECL network_structure family_data::structure() const {
  std::vector<variable> variables = parents;
  variables.push_back(child);
  return network_structure(std::move(variables), edges());
}

PGM_DECL bayesian_network family_data::fit_all() const {
  fit_request request;
  request.structure = edges();
  for (const auto& name : table.names()) request.states.insert_or_assign(name, table.discrete(name).var());
  dataset_source source(table);
  return fit(source, request).network;
}

PGM_DECL family_data read_family(const dataset& data, const std::string& node,
                                 const std::vector<std::string>& parent_names, std::size_t bins,
                                 const std::map<std::string, semantic_tags, std::less<>>& tags) {
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
