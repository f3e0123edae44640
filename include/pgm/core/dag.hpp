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

#include "pgm/core/error.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/detail/text.hpp"

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
  variable_id add_node(const std::string& name) {
    if (name.empty()) throw model_error("a node needs a name");
    if (index_.contains(name)) throw model_error("node '" + name + "' is already in the graph");
    const auto vertex = boost::add_vertex(name, graph_);
    index_.emplace(name, vertex);
    return to_id(vertex);
  }

  [[nodiscard]] std::size_t size() const noexcept { return boost::num_vertices(graph_); }
  [[nodiscard]] std::size_t edge_count() const noexcept { return boost::num_edges(graph_); }
  [[nodiscard]] bool contains(std::string_view name) const { return index_.find(name) != index_.end(); }

  /// The id of a node; throws model_error naming the unknown node and the known ones.
  [[nodiscard]] variable_id id(std::string_view name) const {
    const auto it = index_.find(name);
    if (it == index_.end()) {
      std::vector<std::string> known;
      for (const auto& [node, vertex] : index_) known.push_back(node);
      throw model_error("unknown variable '" + std::string(name) + "' (known: " + detail::list_for_message(known) +
                        ")");
    }
    return to_id(it->second);
  }
  [[nodiscard]] const std::string& name(variable_id node) const {
    check(node);
    return graph_[to_vertex(node)];
  }
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (auto vertex : boost::make_iterator_range(boost::vertices(graph_))) result.push_back(graph_[vertex]);
    return result;
  }

  /// Adds `from -> to`. Throws not_a_dag if it closes a cycle (a self-loop included) and
  /// model_error if the edge exists already.
  void add_edge(variable_id from, variable_id to) {
    check(from);
    check(to);
    if (has_edge(from, to)) {
      throw model_error("edge " + name(from) + " -> " + name(to) + " is given twice");
    }
    if (from == to) throw not_a_dag({name(from), name(to)});
    if (auto path = path_between(to, from); !path.empty()) {
      std::vector<std::string> cycle{name(from), name(to)};
      for (auto node : path) cycle.push_back(name(node));
      throw not_a_dag(std::move(cycle));
    }
    boost::add_edge(to_vertex(from), to_vertex(to), graph_);
  }
  void add_edge(std::string_view from, std::string_view to) { add_edge(id(from), id(to)); }

  /// Removes `from -> to` if present; returns whether it was.
  bool remove_edge(variable_id from, variable_id to) {
    check(from);
    check(to);
    if (!has_edge(from, to)) return false;
    boost::remove_edge(to_vertex(from), to_vertex(to), graph_);
    return true;
  }

  [[nodiscard]] bool has_edge(variable_id from, variable_id to) const {
    return boost::edge(to_vertex(from), to_vertex(to), graph_).second;
  }

  [[nodiscard]] std::vector<variable_id> parents(variable_id node) const {
    check(node);
    std::vector<variable_id> result;
    for (auto edge : boost::make_iterator_range(boost::in_edges(to_vertex(node), graph_))) {
      result.push_back(to_id(boost::source(edge, graph_)));
    }
    return result;
  }
  [[nodiscard]] std::vector<variable_id> children(variable_id node) const {
    check(node);
    std::vector<variable_id> result;
    for (auto edge : boost::make_iterator_range(boost::out_edges(to_vertex(node), graph_))) {
      result.push_back(to_id(boost::target(edge, graph_)));
    }
    return result;
  }

  /// Every edge as (from, to), grouped by source node in node order.
  [[nodiscard]] std::vector<std::pair<variable_id, variable_id>> edges() const {
    std::vector<std::pair<variable_id, variable_id>> result;
    for (auto edge : boost::make_iterator_range(boost::edges(graph_))) {
      result.emplace_back(to_id(boost::source(edge, graph_)), to_id(boost::target(edge, graph_)));
    }
    return result;
  }

  /// Nodes ordered so that every parent comes before its children.
  [[nodiscard]] std::vector<variable_id> topological_order() const {
    std::vector<vertex_type> reversed;
    boost::topological_sort(graph_, std::back_inserter(reversed));
    std::vector<variable_id> order;
    for (auto it = reversed.rbegin(); it != reversed.rend(); ++it) order.push_back(to_id(*it));
    return order;
  }

  /// A directed path from `from` to `to` (excluding `from`, ending at `to`), or empty if none.
  [[nodiscard]] std::vector<variable_id> path_between(variable_id from, variable_id to) const {
    if (from == to) return {to};
    std::vector<vertex_type> predecessor(size());
    for (std::size_t i = 0; i < predecessor.size(); ++i) predecessor[i] = i;
    boost::breadth_first_search(
        graph_, to_vertex(from),
        boost::visitor(boost::make_bfs_visitor(boost::record_predecessors(
            boost::make_iterator_property_map(predecessor.begin(), boost::get(boost::vertex_index, graph_)),
            boost::on_tree_edge()))));
    const auto target = to_vertex(to);
    if (predecessor[target] == target) return {};
    std::vector<variable_id> path;
    for (auto vertex = target; vertex != to_vertex(from); vertex = predecessor[vertex]) {
      path.push_back(to_id(vertex));
    }
    std::reverse(path.begin(), path.end());
    return path;
  }

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
  static variable_id to_id(vertex_type vertex) noexcept { return variable_id(static_cast<variable_id::rep>(vertex)); }
  void check(variable_id node) const {
    if (node.value() >= size()) {
      throw model_error("node id " + std::to_string(node.value()) + " is not in the graph");
    }
  }

  graph_type graph_;
  std::map<std::string, vertex_type, std::less<>> index_;
};

}  // namespace pgm
