#pragma once
/// \file
/// `junction_tree`: a model (any GraphicalModel: a Bayesian network, a Markov network) compiled
/// for exact inference, once. The graph of its factors' interactions (a Bayesian network's moral
/// graph) is triangulated by greedy elimination (triangulation.hpp: min-fill by default, or min-weight);
/// the elimination cliques, linked each to the clique of its first-eliminated neighbour and with
/// the non-maximal ones merged into the clique that contains them, form a tree with the running
/// intersection property. Every factor (a node's table, in a Bayesian network) is assigned to the
/// smallest clique that holds its scope, and every variable has a home: the smallest clique that holds it, where its
/// evidence is entered and its marginal read. Disconnected parts are joined by empty separators.
///
/// A clique's table is numbered mixed-radix over its variables in ascending id, last fastest, as
/// factors are; so is a separator's. For every clique and each of its edges the tree keeps the
/// clique's stride along each of its variables in the separator's numbering (0 where the
/// separator lacks it), the one thing propagation needs to move between the two.
///
/// The tree is rooted at clique 0; `first`/`last` number each subtree as one interval of a
/// depth-first walk, so "is clique c below edge e" is two comparisons.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/inference/triangulation.hpp"

namespace pgm {

struct junction_tree_options {
  elimination_heuristic heuristic = elimination_heuristic::min_fill;
  /// Compiling refuses a tree with more cells in all (its cliques' tables together).
  std::size_t max_cells = std::size_t{1} << 27;
  /// Answer a one-off query by eliminating its relevant part when that is cheaper than the
  /// messages it needs (junction_tree_engine.hpp); false always propagates.
  bool prune = true;
  /// Restarts of the elimination order's search (triangulation.hpp): 0 takes the greedy order.
  order_search search;
};

class junction_tree {
 public:
  struct clique {
    std::vector<variable_id> variables;  ///< ascending
    std::vector<std::size_t> cardinalities;
    std::size_t cells = 1;
    /// Incident edges, in the order they were made.
    std::vector<std::size_t> edges;
    /// strides[k]: this clique's stride along each of its variables in edges[k]'s separator.
    std::vector<std::vector<std::size_t>> strides;
    /// The edges' positions grouped by equal separators: their messages are multiplied
    /// together in the separator's small table before one pass over the clique's (a clique
    /// many neighbours share one variable with, as pathfinder's disease node, costs one pass).
    std::vector<std::vector<std::size_t>> groups;
  };
  struct edge {
    std::size_t child;                   ///< the endpoint further from the root
    std::size_t parent;                  ///< the endpoint nearer the root
    std::vector<variable_id> separator;  ///< ascending
    std::size_t cells = 1;
  };

  /// Compiles `model`. Throws table_too_large when the tree would exceed options.max_cells.
  template <GraphicalModel M>
  explicit junction_tree(const M& model, const junction_tree_options& options = {})
      : junction_tree(cardinalities_of(model), scopes_of(model), options) {}

  /// Compiles the model of variables with these cardinalities and factors over these scopes.
  PGM_DECL junction_tree(std::vector<std::size_t> cardinalities, const std::vector<std::vector<variable_id>>& scopes,
                         const junction_tree_options& options = {});

  [[nodiscard]] const std::vector<clique>& cliques() const noexcept { return cliques_; }
  [[nodiscard]] const std::vector<edge>& edges() const noexcept { return edges_; }
  /// The clique whose table holds factor f.
  [[nodiscard]] std::size_t factor_clique(std::size_t f) const { return factor_clique_.at(f); }
  /// The clique whose table holds a Bayesian network's node's table (its factor).
  [[nodiscard]] std::size_t family_clique(variable_id node) const { return factor_clique(node.value()); }
  [[nodiscard]] std::size_t factor_count() const noexcept { return factor_clique_.size(); }
  /// The smallest clique holding the variable.
  [[nodiscard]] std::size_t home(variable_id node) const { return home_.at(node.value()); }
  [[nodiscard]] std::size_t cardinality(variable_id node) const { return cardinalities_.at(node.value()); }
  [[nodiscard]] std::size_t variable_count() const noexcept { return cardinalities_.size(); }
  /// The cliques' tables together, in cells.
  [[nodiscard]] std::size_t total_cells() const noexcept { return total_cells_; }
  [[nodiscard]] PGM_DECL std::size_t largest_clique_cells() const noexcept;
  /// The largest clique's variable count minus one.
  [[nodiscard]] PGM_DECL std::size_t treewidth() const noexcept;

  /// The edge's other endpoint.
  [[nodiscard]] std::size_t across(std::size_t e, std::size_t from) const noexcept {
    return edges_[e].child == from ? edges_[e].parent : edges_[e].child;
  }
  /// Whether clique c lies in the subtree below edge e (the child's side).
  [[nodiscard]] bool below(std::size_t c, std::size_t e) const noexcept {
    const auto child = edges_[e].child;
    return first_[child] <= first_[c] && first_[c] < last_[child];
  }
  /// The edge from c to its parent, or edges().size() for the root.
  [[nodiscard]] std::size_t parent_edge(std::size_t c) const noexcept { return parent_edge_[c]; }
  /// The cliques in depth-first order from the root (parents before children).
  [[nodiscard]] const std::vector<std::size_t>& preorder() const noexcept { return preorder_; }

  /// The position of `node` in clique c's variables, or its size if absent.
  [[nodiscard]] PGM_DECL std::size_t position(std::size_t c, variable_id node) const noexcept;
  /// Clique c's stride along each of its variables in the numbering of `scope` (ascending or
  /// not; 0 where `scope` lacks the variable).
  [[nodiscard]] PGM_DECL std::vector<std::size_t> strides_into(std::size_t c, std::span<const variable_id> scope) const;

 private:
  PGM_DECL void build_cliques(const elimination& triangulated, const std::vector<std::size_t>& cards);

  PGM_DECL void add_edge(std::size_t a, std::size_t b);

  PGM_DECL void check_size(std::size_t max_cells);

  PGM_DECL void assign_factors(const std::vector<std::vector<variable_id>>& scopes);

  PGM_DECL void root_and_number();

  std::vector<std::size_t> cardinalities_;
  std::vector<clique> cliques_;
  std::vector<edge> edges_;
  std::vector<std::size_t> factor_clique_;
  std::vector<std::size_t> home_;
  std::vector<std::size_t> first_;
  std::vector<std::size_t> last_;
  std::vector<std::size_t> parent_edge_;
  std::vector<std::size_t> preorder_;
  std::size_t total_cells_ = 0;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/junction_tree.ipp"
#endif
