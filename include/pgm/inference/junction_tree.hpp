#pragma once
/// \file
/// `junction_tree`: a network compiled for exact inference, once. The moral graph is
/// triangulated by greedy elimination (triangulation.hpp: min-fill by default, or min-weight);
/// the elimination cliques, linked each to the clique of its first-eliminated neighbour and with
/// the non-maximal ones merged into the clique that contains them, form a tree with the running
/// intersection property. Every node's table (its family) is assigned to the smallest clique that
/// holds the family, and every variable has a home: the smallest clique that holds it, where its
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
#include "pgm/core/error.hpp"
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

  /// Compiles `network`. Throws table_too_large when the tree would exceed options.max_cells.
  explicit junction_tree(const bayesian_network& network, const junction_tree_options& options = {}) {
    const auto cards = cardinalities_of(network);
    cardinalities_ = cards;
    const auto triangulated = greedy_elimination(moral_graph(network), cards, options.heuristic);
    build_cliques(triangulated, cards);
    check_size(options.max_cells);
    assign_families(network);
    root_and_number();
  }

  [[nodiscard]] const std::vector<clique>& cliques() const noexcept { return cliques_; }
  [[nodiscard]] const std::vector<edge>& edges() const noexcept { return edges_; }
  /// The clique whose table holds node i's table.
  [[nodiscard]] std::size_t family_clique(variable_id node) const { return family_clique_.at(node.value()); }
  /// The smallest clique holding the variable.
  [[nodiscard]] std::size_t home(variable_id node) const { return home_.at(node.value()); }
  [[nodiscard]] std::size_t cardinality(variable_id node) const { return cardinalities_.at(node.value()); }
  [[nodiscard]] std::size_t variable_count() const noexcept { return cardinalities_.size(); }
  /// The cliques' tables together, in cells.
  [[nodiscard]] std::size_t total_cells() const noexcept { return total_cells_; }
  [[nodiscard]] std::size_t largest_clique_cells() const noexcept {
    std::size_t largest = 0;
    for (const auto& c : cliques_) largest = std::max(largest, c.cells);
    return largest;
  }
  /// The largest clique's variable count minus one.
  [[nodiscard]] std::size_t treewidth() const noexcept {
    std::size_t width = 0;
    for (const auto& c : cliques_) width = std::max(width, c.variables.size());
    return width == 0 ? 0 : width - 1;
  }

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
  [[nodiscard]] std::size_t position(std::size_t c, variable_id node) const noexcept {
    const auto& vars = cliques_[c].variables;
    const auto it = std::lower_bound(vars.begin(), vars.end(), node);
    return it != vars.end() && *it == node ? static_cast<std::size_t>(it - vars.begin()) : vars.size();
  }
  /// Clique c's stride along each of its variables in the numbering of `scope` (ascending or
  /// not; 0 where `scope` lacks the variable).
  [[nodiscard]] std::vector<std::size_t> strides_into(std::size_t c, std::span<const variable_id> scope) const {
    std::vector<std::size_t> result(cliques_[c].variables.size(), 0);
    std::size_t stride = 1;
    for (std::size_t k = scope.size(); k-- > 0;) {
      const auto p = position(c, scope[k]);
      if (p < result.size()) result[p] = stride;
      stride *= cardinalities_[scope[k].value()];
    }
    return result;
  }

 private:
  void build_cliques(const elimination& triangulated, const std::vector<std::size_t>& cards) {
    const auto n = triangulated.order.size();
    std::vector<std::size_t> position_of(n);
    for (std::size_t k = 0; k < n; ++k) position_of[triangulated.order[k]] = k;
    // Parent of elimination clique k: the clique of its first-eliminated neighbour.
    constexpr auto none = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> parent(n, none);
    std::vector<std::vector<std::size_t>> children(n);
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t first = none;
      for (auto v : triangulated.cliques[k]) {
        if (v != triangulated.order[k] && (first == none || position_of[v] < first)) first = position_of[v];
      }
      parent[k] = first;
      if (first != none) children[first].push_back(k);
    }
    // A non-maximal clique is contained in one of its children (which eliminate earlier): it
    // takes that child's representative, contracting the edge between them.
    std::vector<std::size_t> representative(n);
    for (std::size_t k = 0; k < n; ++k) {
      representative[k] = k;
      const auto& mine = triangulated.cliques[k];
      for (auto c : children[k]) {
        const auto& theirs = triangulated.cliques[representative[c]];
        if (std::includes(theirs.begin(), theirs.end(), mine.begin(), mine.end())) {
          representative[k] = representative[c];
          break;
        }
      }
    }
    std::vector<std::size_t> index(n, none);
    for (std::size_t k = 0; k < n; ++k) {
      if (representative[k] != k) continue;
      index[k] = cliques_.size();
      clique c;
      for (auto v : triangulated.cliques[k]) {
        c.variables.push_back(variable_id(static_cast<variable_id::rep>(v)));
        c.cardinalities.push_back(cards[v]);
        c.cells = detail::saturating_multiply(c.cells, cards[v]);
      }
      cliques_.push_back(std::move(c));
    }
    std::vector<std::size_t> roots;
    for (std::size_t k = 0; k < n; ++k) {
      const auto from = index[representative[k]];
      if (parent[k] == none) {
        roots.push_back(from);  // one per connected part: its last-eliminated clique
        continue;
      }
      const auto to = index[representative[parent[k]]];
      if (from != to) add_edge(from, to);
    }
    // Disconnected parts: each further root hangs from the first by an empty separator.
    for (std::size_t r = 1; r < roots.size(); ++r) add_edge(roots[r], roots[0]);
    for (auto& c : cliques_) {
      for (std::size_t k = 0; k < c.edges.size(); ++k) {
        auto same = std::find_if(c.groups.begin(), c.groups.end(), [&](const std::vector<std::size_t>& g) {
          return edges_[c.edges[g.front()]].separator == edges_[c.edges[k]].separator;
        });
        if (same == c.groups.end()) {
          c.groups.push_back({k});
        } else {
          same->push_back(k);
        }
      }
    }
  }

  void add_edge(std::size_t a, std::size_t b) {
    edge e{a, b, {}, 1};
    std::set_intersection(cliques_[a].variables.begin(), cliques_[a].variables.end(), cliques_[b].variables.begin(),
                          cliques_[b].variables.end(), std::back_inserter(e.separator));
    for (auto v : e.separator) e.cells *= cardinalities_[v.value()];
    const auto id = edges_.size();
    edges_.push_back(std::move(e));
    for (auto c : {a, b}) {
      cliques_[c].edges.push_back(id);
      cliques_[c].strides.push_back(strides_into(c, edges_[id].separator));
    }
  }

  void check_size(std::size_t max_cells) {
    total_cells_ = 0;
    for (const auto& c : cliques_) total_cells_ = detail::saturating_add(total_cells_, c.cells);
    if (total_cells_ > max_cells) {
      throw table_too_large("the junction tree of this network needs " + std::to_string(total_cells_) +
                            " cells (largest clique " + std::to_string(largest_clique_cells()) +
                            "), more than the limit of " + std::to_string(max_cells) +
                            "; use an approximate engine (lw, gibbs) or auto");
    }
  }

  void assign_families(const bayesian_network& network) {
    const auto n = network.size();
    std::vector<std::vector<std::size_t>> holding(n);
    for (std::size_t c = 0; c < cliques_.size(); ++c) {
      for (auto v : cliques_[c].variables) holding[v.value()].push_back(c);
    }
    home_.resize(n);
    family_clique_.resize(n);
    auto smaller = [&](std::size_t a, std::size_t b) { return cliques_[a].cells < cliques_[b].cells; };
    for (std::size_t i = 0; i < n; ++i) {
      const auto& candidates = holding[i];
      PGM_ASSERT(!candidates.empty(), "every variable is in a clique");
      home_[i] = *std::min_element(candidates.begin(), candidates.end(), smaller);
      const auto parents = network.graph().parents(variable_id(static_cast<variable_id::rep>(i)));
      std::size_t best = cliques_.size();
      for (auto c : candidates) {
        const bool holds = std::all_of(parents.begin(), parents.end(),
                                       [&](variable_id p) { return position(c, p) < cliques_[c].variables.size(); });
        if (holds && (best == cliques_.size() || smaller(c, best))) best = c;
      }
      PGM_ASSERT(best < cliques_.size(), "a moral graph's family lies in one clique");
      family_clique_[i] = best;
    }
  }

  void root_and_number() {
    const auto m = cliques_.size();
    first_.assign(m, 0);
    last_.assign(m, 0);
    parent_edge_.assign(m, edges_.size());
    preorder_.clear();
    if (m == 0) return;
    // Orient every edge away from clique 0 and number subtrees by a depth-first walk.
    std::vector<std::pair<std::size_t, std::size_t>> stack{{0, 0}};  // (clique, next incident edge)
    std::vector<char> seen(m, 0);
    seen[0] = 1;
    std::size_t counter = 0;
    first_[0] = counter++;
    preorder_.push_back(0);
    while (!stack.empty()) {
      auto& [c, next] = stack.back();
      if (next == cliques_[c].edges.size()) {
        last_[c] = counter;
        stack.pop_back();
        continue;
      }
      const auto e = cliques_[c].edges[next++];
      const auto other = across(e, c);
      if (seen[other]) continue;
      seen[other] = 1;
      if (edges_[e].child != other) std::swap(edges_[e].child, edges_[e].parent);
      parent_edge_[other] = e;
      first_[other] = counter++;
      preorder_.push_back(other);
      stack.emplace_back(other, 0);
    }
  }

  std::vector<std::size_t> cardinalities_;
  std::vector<clique> cliques_;
  std::vector<edge> edges_;
  std::vector<std::size_t> family_clique_;
  std::vector<std::size_t> home_;
  std::vector<std::size_t> first_;
  std::vector<std::size_t> last_;
  std::vector<std::size_t> parent_edge_;
  std::vector<std::size_t> preorder_;
  std::size_t total_cells_ = 0;
};

}  // namespace pgm
