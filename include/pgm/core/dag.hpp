#pragma once
/// \file
/// `dag`: a directed acyclic graph with named nodes on Boost.Graph. Acyclicity is an invariant:
/// an edge that would close a cycle is refused with `not_a_dag`, which names the cycle.
/// `graph()` exposes the Boost adjacency_list so Boost algorithms run on it directly.

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/topological_sort.hpp>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/text.hpp"

namespace pgm {

class dag {
 public:
  /// Out- and in-edges kept in insertion order (vecS): a node's parents come in the order
  /// their edges were added, which fixes the parent order of its table.
  using graph_type = boost::adjacency_list<boost::vecS, boost::vecS, boost::bidirectionalS, std::string>;
  using vertex_type = graph_type::vertex_descriptor;

  dag() = default;
  explicit dag(const std::vector<std::string>& nodes) {
    for (const auto& node : nodes) add_node(node);
  }

  /// Adds a node; throws model_error if the name is taken or empty.
  PGM_DECL variable_id add_node(const std::string& name);

  [[nodiscard]] std::size_t size() const noexcept { return boost::num_vertices(graph_); }
  [[nodiscard]] std::size_t edge_count() const noexcept { return boost::num_edges(graph_); }
  [[nodiscard]] bool contains(std::string_view name) const { return index_.find(name) != index_.end(); }

  /// The id of a node; throws model_error naming the unknown node and the known ones.
  [[nodiscard]] PGM_DECL variable_id id(std::string_view name) const;
  [[nodiscard]] const std::string& name(variable_id node) const {
    check(node);
    return graph_[to_vertex(node)];
  }
  [[nodiscard]] PGM_DECL std::vector<std::string> names() const;

  /// Adds `from -> to`. Throws not_a_dag if it closes a cycle (a self-loop included) and
  /// model_error if the edge exists already.
  PGM_DECL void add_edge(variable_id from, variable_id to);
  void add_edge(std::string_view from, std::string_view to) { add_edge(id(from), id(to)); }

  /// Removes `from -> to` if present; returns whether it was.
  PGM_DECL bool remove_edge(variable_id from, variable_id to);

  [[nodiscard]] bool has_edge(variable_id from, variable_id to) const {
    return boost::edge(to_vertex(from), to_vertex(to), graph_).second;
  }

  [[nodiscard]] PGM_DECL std::vector<variable_id> parents(variable_id node) const;
  [[nodiscard]] PGM_DECL std::vector<variable_id> children(variable_id node) const;

  /// Every edge as (from, to), grouped by source node in node order.
  [[nodiscard]] PGM_DECL std::vector<std::pair<variable_id, variable_id>> edges() const;

  /// Nodes ordered so that every parent comes before its children.
  [[nodiscard]] PGM_DECL std::vector<variable_id> topological_order() const;

  /// A directed path from `from` to `to` (excluding `from`, ending at `to`), or empty if none.
  [[nodiscard]] PGM_DECL std::vector<variable_id> path_between(variable_id from, variable_id to) const;

  [[nodiscard]] const graph_type& graph() const noexcept { return graph_; }

  /// Same node names in the same order and the same set of edges.
  friend bool operator==(const dag& a, const dag& b) {
    if (a.names() != b.names()) return false;
    auto ea = a.edges();
    auto eb = b.edges();
    std::sort(ea.begin(), ea.end());
    std::sort(eb.begin(), eb.end());
    return ea == eb;
  }

 private:
  // The one place where pgm ids and Boost vertex descriptors meet.
  static vertex_type to_vertex(variable_id node) noexcept { return node.value(); }
  static variable_id to_id(vertex_type vertex) noexcept { return index_at<variable_id>(vertex); }
  PGM_DECL void check(variable_id node) const;

  graph_type graph_;
  std::map<std::string, vertex_type, std::less<>> index_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/dag.ipp"
#endif
