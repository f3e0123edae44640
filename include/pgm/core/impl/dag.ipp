#pragma once
// The definitions of pgm/core/dag.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/dag.hpp"

namespace pgm {

PGM_DECL variable_id dag::add_node(const std::string& name) {
  if (name.empty()) throw model_error("a node needs a name");
  if (index_.contains(name)) throw model_error("node '" + name + "' is already in the graph");
  const auto vertex = boost::add_vertex(name, graph_);
  index_.emplace(name, vertex);
  return to_id(vertex);
}

PGM_DECL variable_id dag::id(std::string_view name) const {
  const auto it = index_.find(name);
  if (it == index_.end()) {
    std::vector<std::string> known;
    for (const auto& [node, vertex] : index_) known.push_back(node);
    throw model_error("unknown variable '" + std::string(name) + "' (known: " + text::list_for_message(known) + ")");
  }
  return to_id(it->second);
}

PGM_DECL std::vector<std::string> dag::names() const {
  std::vector<std::string> result;
  for (auto vertex : boost::make_iterator_range(boost::vertices(graph_))) result.push_back(graph_[vertex]);
  return result;
}

PGM_DECL void dag::add_edge(variable_id from, variable_id to) {
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

PGM_DECL bool dag::remove_edge(variable_id from, variable_id to) {
  check(from);
  check(to);
  if (!has_edge(from, to)) return false;
  boost::remove_edge(to_vertex(from), to_vertex(to), graph_);
  return true;
}

PGM_DECL std::vector<variable_id> dag::parents(variable_id node) const {
  check(node);
  std::vector<variable_id> result;
  for (auto edge : boost::make_iterator_range(boost::in_edges(to_vertex(node), graph_))) {
    result.push_back(to_id(boost::source(edge, graph_)));
  }
  return result;
}

PGM_DECL std::vector<variable_id> dag::children(variable_id node) const {
  check(node);
  std::vector<variable_id> result;
  for (auto edge : boost::make_iterator_range(boost::out_edges(to_vertex(node), graph_))) {
    result.push_back(to_id(boost::target(edge, graph_)));
  }
  return result;
}

PGM_DECL std::vector<std::pair<variable_id, variable_id>> dag::edges() const {
  std::vector<std::pair<variable_id, variable_id>> result;
  for (auto edge : boost::make_iterator_range(boost::edges(graph_))) {
    result.emplace_back(to_id(boost::source(edge, graph_)), to_id(boost::target(edge, graph_)));
  }
  return result;
}

PGM_DECL std::vector<variable_id> dag::topological_order() const {
  std::vector<vertex_type> reversed;
  boost::topological_sort(graph_, std::back_inserter(reversed));
  std::vector<variable_id> order;
  for (auto it = reversed.rbegin(); it != reversed.rend(); ++it) order.push_back(to_id(*it));
  return order;
}

PGM_DECL std::vector<variable_id> dag::path_between(variable_id from, variable_id to) const {
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

PGM_DECL void dag::check(variable_id node) const {
  if (node.value() >= size()) {
    throw model_error("node id " + std::to_string(node.value()) + " is not in the graph");
  }
}

}  // namespace pgm
