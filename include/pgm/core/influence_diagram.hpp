#pragma once
/// \file
/// `influence_diagram`: a Bayesian network with choices and payoffs. Three kinds of node:
///
/// | node | has | parents mean |
/// |---|---|---|
/// | chance | states and a table P(X \| parents) | what X depends on |
/// | decision | states (the actions), no table | what is known when the decision is taken |
/// | utility | no states; a real value per configuration of its parents | what the payoff depends on |
///
/// Several utility nodes add up. A utility node has no children; the chance and decision nodes
/// form a DAG. The decisions are taken in the order of the graph (a decision that is an ancestor
/// of another comes first), the file's order breaking ties. aGrUM's `InfluenceDiagram`, Hugin's
/// and SMILE's decision and utility nodes hold the same.
///
/// A table's values are numbered as `cpt` numbers them: per configuration of the parents (the
/// last parent fastest), the child's states; a utility's, one value per configuration.

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

enum class node_kind { chance, decision };

/// A payoff: one real value per configuration of `parents` (the last fastest).
struct utility_node {
  std::string name;
  std::vector<variable_id> parents;
  std::vector<double> values;
  friend bool operator==(const utility_node&, const utility_node&) = default;
};

class influence_diagram {
 public:
  /// Declares a chance variable (its table comes with set_table) or a decision. Throws
  /// model_error for a name already taken by a variable or a utility.
  PGM_DECL variable_id add_chance(variable v);
  PGM_DECL variable_id add_decision(variable v);

  /// Sets a chance variable's parents and table (per configuration of the parents, the
  /// child's probabilities, summing to 1 within 1e-6). Throws model_error for a decision, a
  /// second table, a size mismatch or a column that is not a distribution, and not_a_dag
  /// (naming the cycle) when a parent depends on the variable.
  PGM_DECL void set_table(variable_id chance, const std::vector<variable_id>& parents, std::vector<double> table);

  /// Sets what a decision observes when it is taken. Throws model_error for a chance variable
  /// and not_a_dag for a cycle.
  PGM_DECL void set_observed(variable_id decision, const std::vector<variable_id>& observed);

  /// Adds a payoff over `parents`. Throws model_error for a taken name, a size mismatch or a
  /// value that is not finite.
  PGM_DECL void add_utility(std::string name, std::vector<variable_id> parents, std::vector<double> values);

  /// Throws model_error naming a chance variable without a table, or when there is no
  /// decision or no utility.
  PGM_DECL void validate() const;

  [[nodiscard]] const std::vector<variable>& variables() const noexcept { return variables_; }
  [[nodiscard]] std::size_t size() const noexcept { return variables_.size(); }
  [[nodiscard]] const variable& at(variable_id id) const { return variables_.at(id.value()); }
  /// The id of a chance or decision variable; throws unknown_name.
  [[nodiscard]] PGM_DECL variable_id id(std::string_view name) const;
  [[nodiscard]] bool contains(std::string_view name) const { return index_.contains(name); }
  [[nodiscard]] node_kind kind(variable_id id) const { return kinds_.at(id.value()); }
  [[nodiscard]] bool is_decision(variable_id id) const { return kind(id) == node_kind::decision; }
  /// A chance variable's parents in its table's order, or what a decision observes.
  [[nodiscard]] const std::vector<variable_id>& parents(variable_id id) const { return parents_.at(id.value()); }
  /// A chance variable's table (empty before set_table).
  [[nodiscard]] const std::vector<double>& table(variable_id id) const { return tables_.at(id.value()); }
  [[nodiscard]] const std::vector<utility_node>& utilities() const noexcept { return utilities_; }
  [[nodiscard]] const dag& graph() const noexcept { return graph_; }

  /// The decisions in the order they are taken.
  [[nodiscard]] PGM_DECL std::vector<variable_id> decision_order() const;

  friend bool operator==(const influence_diagram& a, const influence_diagram& b) {
    return a.variables_ == b.variables_ && a.kinds_ == b.kinds_ && a.parents_ == b.parents_ && a.tables_ == b.tables_ &&
           a.utilities_ == b.utilities_;
  }

 private:
  variable_id add(variable v, node_kind kind);
  void check_name_free(const std::string& name) const;
  void connect(variable_id child, const std::vector<variable_id>& parents);
  [[nodiscard]] std::size_t configurations(const std::vector<variable_id>& parents, const std::string& owner) const;

  std::vector<variable> variables_;
  std::vector<node_kind> kinds_;
  std::vector<std::vector<variable_id>> parents_;
  std::vector<std::vector<double>> tables_;
  std::vector<bool> connected_;
  std::vector<utility_node> utilities_;
  std::map<std::string, variable_id, std::less<>> index_;
  dag graph_;
};

/// A deterministic policy: the action (a state of `decision`) for every configuration of
/// `observed`, numbered mixed-radix over it, the last fastest.
struct decision_policy {
  variable_id decision;
  std::vector<variable_id> observed;
  std::vector<std::size_t> actions;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/influence_diagram.ipp"
#endif
