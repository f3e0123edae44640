#pragma once
// The definitions of pgm/learn/fit.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/fit.hpp"

namespace pgm {

PGM_DECL network_structure structure_from_data(const dataset& data, const std::vector<named_edge>& edges) {
  std::set<std::string, std::less<>> named;
  for (const auto& edge : edges) {
    for (const auto* name : {&edge.from, &edge.to}) {
      if (named.insert(*name).second) static_cast<void>(data.discrete(*name));  // exists, discrete
    }
  }
  std::vector<variable> variables;
  for (const auto& name : data.names()) {
    if (named.contains(name)) variables.push_back(data.discrete(name).var());
  }
  return network_structure(std::move(variables), edges);
}

PGM_DECL network_structure with_intervals(network_structure structure, const discretization& intervals,
                                          std::string_view source) {
  for (const auto& [name, binned] : intervals) {
    if (!structure.contains(name)) continue;
    const auto& own = structure.at(name);
    if (own.states() != binned.states()) {
      throw data_error("'" + std::string(source) + "' gives '" + name + "' the states {" +
                       text::list_for_message(binned.states()) + "}, the data {" +
                       text::list_for_message(own.states()) + "}" +
                       (own.cardinality() > binned.cardinality() ? "; are the columns still raw? bin them first" : ""));
    }
    structure.update_variable(variable::with_edges(name, own.states(), binned.edges(), binned.tags()));
  }
  return structure;
}

PGM_DECL count_table count_node(const network_structure& structure, variable_id node, const dataset& data,
                                const count_options& counting, row_range rows) {
  const auto& child = structure.at(node);
  const auto parents = structure.parent_variables(node);
  auto column_of = [&](const variable& v) -> const discrete_column& {
    const auto& column = data.discrete(v.name());
    if (column.var().states() != v.states()) {
      throw data_error((data.source().empty() ? std::string() : data.source() + ": ") + "column '" + v.name() +
                       "' has the states {" + text::join(column.var().states()) + "} but the model expects {" +
                       text::join(v.states()) + "}");
    }
    return column;
  };
  std::vector<const discrete_column*> parent_columns;
  for (const auto& p : parents) parent_columns.push_back(&column_of(p));
  // Same codes, the structure's own variables (which may carry intervals and tags).
  return count_family(column_of(child), parent_columns, counting, rows).with_variables(child, parents);
}

PGM_DECL bayesian_network fit(const network_structure& structure, const dataset& data, const fit_options& options) {
  return detail::fit_tables(structure, options, [&](variable_id node) {
    return count_node(structure, node, data, options.counting, options.rows);
  });
}

PGM_DECL bayesian_network fit(const network_structure& structure, std::span<const count_table> counts,
                              const fit_options& options) {
  if (counts.size() != structure.size()) {
    throw model_error("fitting " + std::to_string(structure.size()) + " tables needs as many count tables, got " +
                      std::to_string(counts.size()));
  }
  return detail::fit_tables(structure, options, [&](variable_id node) -> const count_table& {
    const auto& table = counts[node.value()];
    if (table.child() != structure.at(node) || table.parents() != structure.parent_variables(node)) {
      throw model_error("the count table given for '" + structure.at(node).name() +
                        "' is not of its family in the network");
    }
    return table;
  });
}

}  // namespace pgm
