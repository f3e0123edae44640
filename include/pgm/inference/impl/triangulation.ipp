#pragma once
// The definitions of pgm/inference/triangulation.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/triangulation.hpp"

namespace pgm {

PGM_DECL interaction_graph moral_graph(const bayesian_network& network) {
  interaction_graph graph(network.size());
  for (std::size_t i = 0; i < network.size(); ++i) {
    const auto parents = network.graph().parents(index_at<variable_id>(i));
    for (std::size_t a = 0; a < parents.size(); ++a) {
      if (!boost::edge(i, parents[a].value(), graph).second) boost::add_edge(i, parents[a].value(), graph);
      for (std::size_t b = a + 1; b < parents.size(); ++b) {
        if (!boost::edge(parents[a].value(), parents[b].value(), graph).second) {
          boost::add_edge(parents[a].value(), parents[b].value(), graph);
        }
      }
    }
  }
  return graph;
}

PGM_DECL interaction_graph interaction_graph_of(std::size_t n, std::span<const std::vector<variable_id>> scopes) {
  interaction_graph graph(n);
  for (const auto& scope : scopes) {
    for (std::size_t a = 0; a < scope.size(); ++a) {
      for (std::size_t b = a + 1; b < scope.size(); ++b) {
        const auto u = scope[a].value();
        const auto w = scope[b].value();
        if (!boost::edge(u, w, graph).second) boost::add_edge(u, w, graph);
      }
    }
  }
  return graph;
}

}  // namespace pgm
