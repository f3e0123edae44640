#pragma once
// The definitions of pgm/learn/cpdag.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/cpdag.hpp"

namespace pgm {

PGM_DECL cpdag::cpdag(std::vector<std::string> names)
    : names_(std::move(names)), marks_(names_.size() * names_.size(), 0) {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i].empty()) throw model_error("a node needs a name");
    if (!index_.emplace(names_[i], i).second) {
      throw model_error("node '" + names_[i] + "' is already in the graph");
    }
  }
}

PGM_DECL variable_id cpdag::id(std::string_view name) const {
  const auto it = index_.find(name);
  if (it == index_.end()) {
    throw model_error("unknown variable '" + std::string(name) + "' (known: " + text::list_for_message(names_) + ")");
  }
  return index_at<variable_id>(it->second);
}

PGM_DECL void cpdag::add_undirected(variable_id a, variable_id b) {
  PGM_ASSERT(a != b, "no self-loops");
  set(a, b, 1);
  set(b, a, 1);
}

PGM_DECL void cpdag::add_directed(variable_id a, variable_id b) {
  PGM_ASSERT(a != b, "no self-loops");
  set(a, b, 1);
  set(b, a, 0);
}

PGM_DECL bool cpdag::has_directed_path(variable_id a, variable_id b) const {
  std::vector<char> seen(size(), 0);
  std::vector<variable_id> stack{a};
  seen[a.value()] = 1;
  while (!stack.empty()) {
    const auto node = stack.back();
    stack.pop_back();
    if (node == b) return true;
    for (auto next : children(node)) {
      if (!seen[next.value()]) {
        seen[next.value()] = 1;
        stack.push_back(next);
      }
    }
  }
  return false;
}

PGM_DECL std::vector<named_edge> cpdag::directed_edges() const {
  std::vector<named_edge> result;
  for_pairs([&](variable_id a, variable_id b) {
    if (directed(a, b)) result.push_back({name(a), name(b)});
  });
  return result;
}

PGM_DECL std::vector<named_edge> cpdag::undirected_edges() const {
  std::vector<named_edge> result;
  for_pairs([&](variable_id a, variable_id b) {
    if (a < b && undirected(a, b)) result.push_back({name(a), name(b)});
  });
  return result;
}

PGM_DECL std::size_t cpdag::edge_count() const {
  std::size_t count = 0;
  for_pairs([&](variable_id a, variable_id b) { count += a < b && adjacent(a, b); });
  return count;
}

PGM_DECL std::vector<named_edge> extend_to_dag(const cpdag& graph, bool relaxed, std::size_t* relaxed_steps) {
  cpdag rest = graph;
  std::vector<char> removed(graph.size(), 0);
  std::vector<named_edge> edges;
  auto id = [](std::size_t i) { return index_at<variable_id>(i); };
  for (std::size_t round = 0; round < graph.size(); ++round) {
    std::size_t pick = graph.size();
    std::size_t first_sink = graph.size();
    for (std::size_t i = 0; i < graph.size() && pick == graph.size(); ++i) {
      if (removed[i]) continue;
      const auto x = id(i);
      if (!rest.children(x).empty()) continue;
      if (first_sink == graph.size()) first_sink = i;
      const auto around = rest.adjacent_nodes(x);
      bool ok = true;
      for (auto y : rest.undirected_neighbours(x)) {
        for (auto z : around) {
          if (z != y && !rest.adjacent(y, z)) ok = false;
        }
      }
      if (ok) pick = i;
    }
    if (pick == graph.size()) {
      if (!relaxed || first_sink == graph.size()) {
        throw model_error(first_sink == graph.size()
                              ? "the graph's directed edges form a cycle; it has no extension to a DAG"
                              : "the graph has no extension to a DAG without a new v-structure "
                                "(conflicting orientations)");
      }
      pick = first_sink;
      if (relaxed_steps) ++*relaxed_steps;
    }
    const auto x = id(pick);
    for (auto y : rest.adjacent_nodes(x)) {
      edges.push_back({graph.name(y), graph.name(x)});
      rest.remove(x, y);
    }
    removed[pick] = 1;
  }
  // Group by source as the core's dag lists its edges.
  std::stable_sort(edges.begin(), edges.end(), [&](const named_edge& a, const named_edge& b) {
    return graph.id(a.from) < graph.id(b.from) || (a.from == b.from && graph.id(a.to) < graph.id(b.to));
  });
  return edges;
}

}  // namespace pgm
