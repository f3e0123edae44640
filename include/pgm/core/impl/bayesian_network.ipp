#pragma once
// The definitions of pgm/core/bayesian_network.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <optional>
#include <string>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/text.hpp"

namespace pgm {

PGM_DECL bayesian_network::bayesian_network(network_structure structure, std::vector<table_type> tables)
    : structure_(std::move(structure)) {
  std::vector<const table_type*> by_node(structure_.size(), nullptr);
  for (const auto& table : tables) {
    const auto& name = table.child().name();
    if (!structure_.contains(name)) {
      throw model_error("a table is given for '" + name + "', which is not in the network");
    }
    auto& slot = by_node[structure_.id(name).value()];
    if (slot) throw model_error("two tables are given for '" + name + "'");
    slot = &table;
  }
  tables_.reserve(structure_.size());
  for (std::size_t i = 0; i < by_node.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    if (!by_node[i]) throw model_error("no table is given for '" + structure_.at(node).name() + "'");
    check_table(node, *by_node[i]);
    tables_.push_back(*by_node[i]);
  }
}

PGM_DECL bayesian_network bayesian_network::from_tables(std::vector<table_type> tables) {
  std::vector<variable> variables;
  std::map<std::string, std::size_t, std::less<>> seen;
  for (const auto& table : tables) {
    seen.emplace(table.child().name(), variables.size());
    variables.push_back(table.child());
  }
  network_structure structure(variables);
  for (const auto& table : tables) {
    for (const auto& parent : table.parents()) {
      const auto it = seen.find(parent.name());
      if (it == seen.end()) {
        throw model_error("'" + parent.name() + "' is a parent of '" + table.child().name() +
                          "' but has no table of its own");
      }
      structure.add_edge(parent.name(), table.child().name());
    }
  }
  return bayesian_network(std::move(structure), std::move(tables));
}

PGM_DECL std::size_t bayesian_network::free_parameters() const {
  std::size_t total = 0;
  for (const auto& t : tables_) total += (t.child_cardinality() - 1) * t.configurations();
  return total;
}

PGM_DECL bayesian_network bayesian_network::dense(std::string_view purpose) const {
  std::vector<table_type> tables;
  tables.reserve(tables_.size());
  for (const auto& t : tables_) {
    if (t.is_sparse() && t.size() > max_table_cells) {
      throw table_too_large(std::string(purpose) + " needs every table dense, and the table of '" + t.child().name() +
                            "', stored sparse (" + std::to_string(t.stored_configurations().size()) + " of " +
                            std::to_string(t.configurations()) + " parent configurations), would have " +
                            std::to_string(t.size()) + " cells, more than pgm's limit of " +
                            std::to_string(max_table_cells) + " (docs/limits.md)");
    }
    tables.push_back(t.dense());
  }
  return bayesian_network(structure_, std::move(tables));
}

PGM_DECL void bayesian_network::check_table(variable_id node, const table_type& table) const {
  const auto& own = structure_.at(node);
  if (table.child() != own) {
    throw model_error("the table of '" + own.name() +
                      "' describes the variable differently "
                      "from the network (states, intervals or tags differ)");
  }
  const auto parents = structure_.parents(node);
  if (parents.size() != table.parents().size()) {
    throw model_error("the table of '" + own.name() + "' has " + std::to_string(table.parents().size()) +
                      " parents, the graph " + std::to_string(parents.size()));
  }
  for (std::size_t i = 0; i < parents.size(); ++i) {
    const auto& expected = structure_.at(parents[i]);
    const auto& given = table.parents()[i];
    if (given.name() != expected.name()) {
      throw model_error("the table of '" + own.name() + "' lists parent '" + given.name() + "' where the graph has '" +
                        expected.name() + "'");
    }
    if (given != expected) {
      throw model_error("the table of '" + own.name() + "' describes its parent '" + given.name() +
                        "' differently from the network");
    }
  }
}

PGM_DECL factor_table bayesian_network::factor(std::size_t f) const {
  const auto& stored = tables_.at(f);
  if (stored.is_sparse() && stored.size() > max_table_cells) {
    throw table_too_large("the table of '" + stored.child().name() +
                          "' is stored sparse, and as a factor it would have " + std::to_string(stored.size()) +
                          " cells, more than pgm's limit of " + std::to_string(max_table_cells) + " (docs/limits.md)");
  }
  const auto densified = stored.is_sparse() ? std::optional(stored.dense()) : std::nullopt;
  const auto& table = densified ? *densified : stored;
  std::vector<std::size_t> cards = table.parent_radix().radices();
  cards.push_back(table.child_cardinality());
  return factor_table(factor_scope(f), std::move(cards),
                      std::vector<double>(table.values().begin(), table.values().end()));
}

PGM_DECL variable_id node_of(const bayesian_network& network, std::string_view name) {
  if (!network.structure().contains(name)) {
    std::vector<std::string> names;
    for (const auto& v : network.variables()) names.push_back(v.name());
    throw model_error("the network has no variable '" + std::string(name) +
                      "' (variables: " + text::list_for_message(names) + ")");
  }
  return network.id(name);
}

}  // namespace pgm
