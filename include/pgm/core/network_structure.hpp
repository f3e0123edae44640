#pragma once
/// \file
/// `network_structure`: the variables of a network and the DAG over them, without tables —
/// what a structure learner produces and what a fit consumes. Node i of the DAG is variable i.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

/// A directed edge given by node names, as in "xOff1->onTop1".
struct named_edge {
  std::string from;
  std::string to;
  friend bool operator==(const named_edge&, const named_edge&) = default;
};

class network_structure {
 public:
  network_structure() = default;

  /// The variables with no edges yet. Throws model_error on a repeated name.
  explicit network_structure(std::vector<variable> variables) : variables_(std::move(variables)) {
    for (const auto& v : variables_) graph_.add_node(v.name());
  }

  network_structure(std::vector<variable> variables, const std::vector<named_edge>& edges)
      : network_structure(std::move(variables)) {
    for (const auto& edge : edges) add_edge(edge.from, edge.to);
  }

  /// Throws model_error for an unknown node, not_a_dag for a cycle.
  void add_edge(std::string_view from, std::string_view to) { graph_.add_edge(from, to); }
  bool remove_edge(std::string_view from, std::string_view to) { return graph_.remove_edge(id(from), id(to)); }

  [[nodiscard]] std::size_t size() const noexcept { return variables_.size(); }
  [[nodiscard]] const std::vector<variable>& variables() const noexcept { return variables_; }
  [[nodiscard]] const dag& graph() const noexcept { return graph_; }
  [[nodiscard]] variable_id id(std::string_view name) const { return graph_.id(name); }
  [[nodiscard]] bool contains(std::string_view name) const { return graph_.contains(name); }
  [[nodiscard]] const variable& at(variable_id node) const { return variables_.at(node.value()); }
  [[nodiscard]] const variable& at(std::string_view name) const { return at(id(name)); }

  [[nodiscard]] std::vector<variable_id> parents(variable_id node) const { return graph_.parents(node); }
  /// The parents' variables, in the order of the node's table.
  [[nodiscard]] PGM_DECL std::vector<variable> parent_variables(variable_id node) const;

  [[nodiscard]] PGM_DECL std::vector<named_edge> edges() const;

  /// Replaces a variable by one of the same name and cardinality (to attach interval edges
  /// or semantic tags).
  PGM_DECL void update_variable(variable replacement);

  friend bool operator==(const network_structure&, const network_structure&) = default;

 private:
  std::vector<variable> variables_;
  dag graph_;
};

}  // namespace pgm

namespace pgm {

/// Parses "a->b, c->b" (whitespace allowed). Throws model_error naming the piece that is not
/// of the form "from->to".
[[nodiscard]] PGM_DECL std::vector<named_edge> parse_edge_list(std::string_view text);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/network_structure.ipp"
#endif
