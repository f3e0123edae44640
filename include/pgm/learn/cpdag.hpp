#pragma once
/// \file
/// `cpdag`: a partially directed graph over named nodes — what constraint-based structure
/// learning finds: directed edges where the data (and background knowledge) fix the
/// direction, undirected ones where every direction is equally supported. `extend_to_dag`
/// picks one DAG of the class (Dor & Tarsi 1992), so that a learned structure can be fitted.

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

class cpdag {
 public:
  cpdag() = default;
  /// The nodes, without edges. Throws model_error on an empty or repeated name.
  PGM_DECL explicit cpdag(std::vector<std::string> names);

  [[nodiscard]] std::size_t size() const noexcept { return names_.size(); }
  [[nodiscard]] const std::vector<std::string>& names() const noexcept { return names_; }
  [[nodiscard]] const std::string& name(variable_id node) const { return names_.at(node.value()); }
  /// Throws model_error naming an unknown node.
  [[nodiscard]] PGM_DECL variable_id id(std::string_view name) const;

  [[nodiscard]] bool adjacent(variable_id a, variable_id b) const { return mark(a, b) || mark(b, a); }
  /// a -> b.
  [[nodiscard]] bool directed(variable_id a, variable_id b) const { return mark(a, b) && !mark(b, a); }
  /// a - b.
  [[nodiscard]] bool undirected(variable_id a, variable_id b) const { return mark(a, b) && mark(b, a); }

  PGM_DECL void add_undirected(variable_id a, variable_id b);
  PGM_DECL void add_directed(variable_id a, variable_id b);
  /// Turns a - b (or b -> a) into a -> b.
  void orient(variable_id a, variable_id b) {
    PGM_ASSERT(adjacent(a, b), "orienting a missing edge");
    add_directed(a, b);
  }
  void remove(variable_id a, variable_id b) {
    set(a, b, 0);
    set(b, a, 0);
  }

  /// Every node adjacent to `a`, in node order.
  [[nodiscard]] std::vector<variable_id> adjacent_nodes(variable_id a) const {
    return select(a, [&](variable_id b) { return adjacent(a, b); });
  }
  /// Nodes b with a - b.
  [[nodiscard]] std::vector<variable_id> undirected_neighbours(variable_id a) const {
    return select(a, [&](variable_id b) { return undirected(a, b); });
  }
  /// Nodes b with b -> a.
  [[nodiscard]] std::vector<variable_id> parents(variable_id a) const {
    return select(a, [&](variable_id b) { return directed(b, a); });
  }
  /// Nodes b with a -> b.
  [[nodiscard]] std::vector<variable_id> children(variable_id a) const {
    return select(a, [&](variable_id b) { return directed(a, b); });
  }

  /// Whether a directed path a -> … -> b exists (directed edges only; a == b counts).
  [[nodiscard]] PGM_DECL bool has_directed_path(variable_id a, variable_id b) const;

  /// The directed edges, by source then target node order.
  [[nodiscard]] PGM_DECL std::vector<named_edge> directed_edges() const;
  /// The undirected edges as {first, second} with first before second in node order.
  [[nodiscard]] PGM_DECL std::vector<named_edge> undirected_edges() const;
  [[nodiscard]] PGM_DECL std::size_t edge_count() const;

  friend bool operator==(const cpdag& a, const cpdag& b) { return a.names_ == b.names_ && a.marks_ == b.marks_; }

 private:
  [[nodiscard]] bool mark(variable_id a, variable_id b) const {
    PGM_ASSERT(a.value() < size() && b.value() < size(), "node out of range");
    return marks_[a.value() * size() + b.value()] != 0;
  }
  void set(variable_id a, variable_id b, unsigned char value) {
    PGM_ASSERT(a.value() < size() && b.value() < size(), "node out of range");
    marks_[a.value() * size() + b.value()] = value;
  }
  template <class Predicate>
  [[nodiscard]] std::vector<variable_id> select(variable_id a, Predicate keep) const {
    std::vector<variable_id> result;
    for (std::size_t b = 0; b < size(); ++b) {
      const variable_id node = index_at<variable_id>(b);
      if (node != a && keep(node)) result.push_back(node);
    }
    return result;
  }
  template <class Visit>
  void for_pairs(Visit visit) const {
    for (std::size_t a = 0; a < size(); ++a) {
      for (std::size_t b = 0; b < size(); ++b) {
        if (a != b) visit(index_at<variable_id>(a), index_at<variable_id>(b));
      }
    }
  }

  std::vector<std::string> names_;
  std::map<std::string, std::size_t, std::less<>> index_;
  // marks_[a * n + b] != 0: the edge between a and b has no arrowhead at a's side, i.e. it
  // allows a -> b. Undirected: both marks; a -> b: only (a, b).
  std::vector<unsigned char> marks_;
};

/// One DAG whose skeleton is the CPDAG's, keeping its directed edges and adding no
/// v-structure it lacks (Dor & Tarsi 1992): repeatedly take a node x with no outgoing
/// directed edge whose undirected neighbours are each adjacent to all other nodes adjacent
/// to x, direct its undirected edges into x, and drop x. The lowest such node is taken
/// first, so the result is deterministic.
///
/// Learned graphs with orientation conflicts may have no such extension. Then, with
/// `relaxed`, the lowest node with no outgoing directed edge is taken anyway (adding a
/// v-structure, but keeping every directed edge) and `*relaxed_steps` counts how often;
/// without it, model_error is thrown. Only a directed cycle among the directed edges makes
/// even the relaxed extension fail.
[[nodiscard]] PGM_DECL std::vector<named_edge> extend_to_dag(const cpdag& graph, bool relaxed = false,
                                                             std::size_t* relaxed_steps = nullptr);

/// The extension as a structure over `variables` (named as the CPDAG's nodes, in any order).
[[nodiscard]] inline network_structure extend_to_structure(const cpdag& graph, std::vector<variable> variables) {
  return network_structure(std::move(variables), extend_to_dag(graph));
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/cpdag.ipp"
#endif
