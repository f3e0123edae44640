#pragma once
// The definitions of pgm/learn/structure_learner.hpp: inline in a header-only build, compiled once
// into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/dag.hpp"
#include "pgm/learn/orientation.hpp"
#include "pgm/learn/structure_learner.hpp"

namespace pgm {

PGM_DECL structure_result dag_result(const std::vector<std::string>& names, std::vector<named_edge> edges) {
  dag graph(names);
  for (const auto& e : edges) graph.add_edge(e.from, e.to);
  structure_result result;
  result.edges = std::move(edges);
  result.graph = cpdag_of(graph);
  return result;
}

}  // namespace pgm
