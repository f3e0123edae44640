#pragma once
/// \file
/// `bayesian_network`: a structure plus one table per node, checked to fit together: each
/// table's child and parents are the node's variable and graph parents, in graph order, with
/// the same states.

#include <algorithm>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/network_structure.hpp"

namespace pgm {

class bayesian_network {
 public:
  using table_type = cpt<double>;

  /// The empty network: no variables.
  bayesian_network() = default;

  /// One table per variable, in any order. Throws model_error if a table is missing, extra,
  /// or disagrees with the structure.
  bayesian_network(network_structure structure, std::vector<table_type> tables) : structure_(std::move(structure)) {
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
      const variable_id node(static_cast<variable_id::rep>(i));
      if (!by_node[i]) throw model_error("no table is given for '" + structure_.at(node).name() + "'");
      check_table(node, *by_node[i]);
      tables_.push_back(*by_node[i]);
    }
  }

  /// The network the tables describe: nodes in table order, edges from each table's parents.
  /// Throws model_error if a variable appears with different states in two tables.
  [[nodiscard]] static bayesian_network from_tables(std::vector<table_type> tables) {
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

  [[nodiscard]] const network_structure& structure() const noexcept { return structure_; }
  [[nodiscard]] const dag& graph() const noexcept { return structure_.graph(); }
  [[nodiscard]] const std::vector<variable>& variables() const noexcept { return structure_.variables(); }
  [[nodiscard]] std::size_t size() const noexcept { return structure_.size(); }
  [[nodiscard]] variable_id id(std::string_view name) const { return structure_.id(name); }
  [[nodiscard]] const variable& at(std::string_view name) const { return structure_.at(name); }

  [[nodiscard]] const table_type& table(variable_id node) const { return tables_.at(node.value()); }
  [[nodiscard]] const table_type& table(std::string_view name) const { return table(id(name)); }
  [[nodiscard]] const std::vector<table_type>& tables() const noexcept { return tables_; }

  /// The number of free parameters, sum over nodes of (J - 1)·|Val(Pa)|.
  [[nodiscard]] std::size_t free_parameters() const {
    std::size_t total = 0;
    for (const auto& t : tables_) total += (t.child_cardinality() - 1) * t.configurations();
    return total;
  }

  /// Whether a table is stored sparse (cpt.hpp).
  [[nodiscard]] bool has_sparse_tables() const noexcept {
    return std::any_of(tables_.begin(), tables_.end(), [](const table_type& t) { return t.is_sparse(); });
  }

  /// The same network with every table dense, for `purpose` (a format without a sparse form,
  /// say), which names it in the error: throws table_too_large when a table would exceed
  /// max_table_cells.
  [[nodiscard]] bayesian_network dense(std::string_view purpose) const {
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

  friend bool operator==(const bayesian_network&, const bayesian_network&) = default;

 private:
  void check_table(variable_id node, const table_type& table) const {
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
        throw model_error("the table of '" + own.name() + "' lists parent '" + given.name() +
                          "' where the graph has '" + expected.name() + "'");
      }
      if (given != expected) {
        throw model_error("the table of '" + own.name() + "' describes its parent '" + given.name() +
                          "' differently from the network");
      }
    }
  }

  network_structure structure_;
  std::vector<table_type> tables_;
};

}  // namespace pgm
