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

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/factor_table.hpp"
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
  PGM_DECL bayesian_network(network_structure structure, std::vector<table_type> tables);

  /// The network the tables describe: nodes in table order, edges from each table's parents.
  /// Throws model_error if a variable appears with different states in two tables.
  [[nodiscard]] PGM_DECL static bayesian_network from_tables(std::vector<table_type> tables);

  [[nodiscard]] const network_structure& structure() const noexcept { return structure_; }
  [[nodiscard]] const dag& graph() const noexcept { return structure_.graph(); }
  [[nodiscard]] const std::vector<variable>& variables() const noexcept { return structure_.variables(); }
  [[nodiscard]] std::size_t size() const noexcept { return structure_.size(); }
  [[nodiscard]] variable_id id(std::string_view name) const { return structure_.id(name); }
  [[nodiscard]] const variable& at(std::string_view name) const { return structure_.at(name); }

  [[nodiscard]] const table_type& table(variable_id node) const { return tables_.at(node.value()); }
  [[nodiscard]] const table_type& table(std::string_view name) const { return table(id(name)); }
  [[nodiscard]] const std::vector<table_type>& tables() const noexcept { return tables_; }

  /// As a GraphicalModel (graphical_model.hpp): factor i is node i's table, over (its parents…,
  /// node) in graph order, the node fastest.
  [[nodiscard]] std::size_t factor_count() const noexcept { return size(); }
  [[nodiscard]] std::vector<variable_id> factor_scope(std::size_t f) const {
    const variable_id node = index_at<variable_id>(f);
    auto scope = graph().parents(node);
    scope.push_back(node);
    return scope;
  }
  /// Node f's table as a dense factor; throws table_too_large for a sparse table past the limit.
  [[nodiscard]] PGM_DECL factor_table factor(std::size_t f) const;

  /// The number of free parameters, sum over nodes of (J - 1)·|Val(Pa)|.
  [[nodiscard]] PGM_DECL std::size_t free_parameters() const;

  /// Whether a table is stored sparse (cpt.hpp).
  [[nodiscard]] bool has_sparse_tables() const noexcept {
    return std::any_of(tables_.begin(), tables_.end(), [](const table_type& t) { return t.is_sparse(); });
  }

  /// The same network with every table dense, for `purpose` (a format without a sparse form,
  /// say), which names it in the error: throws table_too_large when a table would exceed
  /// max_table_cells.
  [[nodiscard]] PGM_DECL bayesian_network dense(std::string_view purpose) const;

  friend bool operator==(const bayesian_network&, const bayesian_network&) = default;

 private:
  PGM_DECL void check_table(variable_id node, const table_type& table) const;

  network_structure structure_;
  std::vector<table_type> tables_;
};

/// The node id of `name`, throwing model_error naming an unknown one and the known ones.
[[nodiscard]] PGM_DECL variable_id node_of(const bayesian_network& network, std::string_view name);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/bayesian_network.ipp"
#endif
