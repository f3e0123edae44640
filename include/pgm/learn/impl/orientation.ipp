#pragma once
// The definitions of pgm/learn/orientation.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/orientation.hpp"

namespace pgm {

PGM_DECL std::size_t separation_sets::key(variable_id a, variable_id b) const {
  const auto lo = std::min(a.value(), b.value());
  const auto hi = std::max(a.value(), b.value());
  return std::size_t{lo} * size_ + hi;
}

}  // namespace pgm

namespace pgm::detail {

PGM_DECL bool orient_if_acyclic(cpdag& graph, variable_id a, variable_id b, const char* why,
                                std::vector<std::string>& conflicts) {
  if (graph.has_directed_path(b, a)) {
    conflicts.push_back(why + std::string(": ") + graph.name(a) + " -> " + graph.name(b) +
                        " would close a directed cycle; left undirected");
    return false;
  }
  graph.orient(a, b);
  return true;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL void orient_by_knowledge(cpdag& graph, const edge_constraints& constraints) {
  for (std::size_t i = 0; i < graph.size(); ++i) {
    for (std::size_t j = 0; j < graph.size(); ++j) {
      const auto a = detail::node(i);
      const auto b = detail::node(j);
      if (i == j || !graph.undirected(a, b)) continue;
      if (constraints.required(i, j) || !constraints.allowed(j, i)) graph.orient(a, b);
    }
  }
}

PGM_DECL void orient_v_structures(cpdag& graph, const separation_sets& sepsets, std::vector<std::string>& conflicts) {
  const auto skeleton = graph;  // unshielded triples are those of the skeleton
  for (std::size_t k = 0; k < graph.size(); ++k) {
    const auto c = detail::node(k);
    const auto around = skeleton.adjacent_nodes(c);
    for (std::size_t x = 0; x < around.size(); ++x) {
      for (std::size_t y = x + 1; y < around.size(); ++y) {
        const auto a = around[x];
        const auto b = around[y];
        if (skeleton.adjacent(a, b) || sepsets.separates(a, b, c)) continue;
        for (auto end : {a, b}) {
          if (graph.undirected(end, c)) {
            detail::orient_if_acyclic(graph, end, c, "v-structure", conflicts);
          } else if (graph.directed(c, end)) {
            conflicts.push_back("v-structure " + graph.name(a) + " -> " + graph.name(c) + " <- " + graph.name(b) +
                                ": " + graph.name(c) + " -> " + graph.name(end) + " is already oriented");
          }
        }
      }
    }
  }
}

PGM_DECL void apply_meek_rules(cpdag& graph, std::vector<std::string>& conflicts) {
  const auto n = graph.size();
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        const auto a = detail::node(i);
        const auto b = detail::node(j);
        if (i == j || !graph.undirected(a, b)) continue;
        bool orient = false;
        for (auto c : graph.parents(a)) {
          if (c != b && !graph.adjacent(c, b)) orient = true;
        }
        if (!orient) {
          for (auto c : graph.children(a)) {
            if (graph.directed(c, b)) orient = true;
          }
        }
        if (!orient) {
          const auto into_b = graph.parents(b);
          for (std::size_t x = 0; x < into_b.size() && !orient; ++x) {
            for (std::size_t y = x + 1; y < into_b.size() && !orient; ++y) {
              const auto c = into_b[x];
              const auto d = into_b[y];
              orient = graph.undirected(a, c) && graph.undirected(a, d) && !graph.adjacent(c, d);
            }
          }
        }
        if (!orient) {
          for (auto c : graph.parents(b)) {
            if (c == a || !graph.adjacent(a, c)) continue;
            for (auto d : graph.parents(c)) {
              if (d != a && d != b && graph.adjacent(a, d) && !graph.adjacent(b, d)) orient = true;
            }
          }
        }
        if (orient && detail::orient_if_acyclic(graph, a, b, "Meek's rules", conflicts)) changed = true;
      }
    }
  }
}

PGM_DECL cpdag cpdag_of(const dag& graph) {
  cpdag result(graph.names());
  for (auto [from, to] : graph.edges()) result.add_undirected(from, to);
  for (std::size_t k = 0; k < graph.size(); ++k) {
    const auto c = detail::node(k);
    const auto parents = graph.parents(c);
    for (std::size_t x = 0; x < parents.size(); ++x) {
      for (std::size_t y = x + 1; y < parents.size(); ++y) {
        if (!result.adjacent(parents[x], parents[y])) {
          result.orient(parents[x], c);
          result.orient(parents[y], c);
        }
      }
    }
  }
  std::vector<std::string> conflicts;  // none: a DAG's orientations are consistent
  apply_meek_rules(result, conflicts);
  return result;
}

}  // namespace pgm
