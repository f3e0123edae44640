#pragma once
// The definitions of pgm/learn/learn_structure.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/learn_structure.hpp"

namespace pgm {

PGM_DECL std::string to_string(structure_algorithm algorithm) {
  switch (algorithm) {
    case structure_algorithm::pc:
      return "pc";
    case structure_algorithm::hc:
      return "hc";
    case structure_algorithm::tabu:
      return "tabu";
    case structure_algorithm::mmhc:
      return "mmhc";
  }
  return "?";
}

PGM_DECL structure_result learn_structure(const dataset& data, std::span<const std::string> names,
                                          const structure_choice& choice) {
  std::vector<const discrete_column*> columns;
  for (const auto& name : names) columns.push_back(&data.discrete(name));
  const std::vector<std::string> order(names.begin(), names.end());
  structure_result result;
  result.algorithm = choice.algorithm;
  auto pc = choice.pc;
  pc.knowledge = choice.knowledge;
  pc.threads = choice.threads;
  if (choice.algorithm == structure_algorithm::pc) {
    auto learned = pc_stable(columns, pc);
    result.graph = learned.graph;
    result.edges = extend_to_dag(learned.graph, true, &result.relaxed);
    result.pc = std::move(learned);
    return result;
  }
  auto search = choice.search;
  search.knowledge = choice.knowledge;
  search.threads = choice.threads;
  if (choice.algorithm == structure_algorithm::tabu && search.tabu == 0) search.tabu = 10;
  if (choice.algorithm != structure_algorithm::tabu) search.tabu = 0;
  if (choice.start_from_pc) {
    if (choice.algorithm == structure_algorithm::pc) throw model_error("a start from PC applies to hc, tabu and mmhc");
    search.start = extend_to_dag(pc_stable(columns, pc).graph, true);
  }
  if (choice.algorithm == structure_algorithm::mmhc) {
    // The restrict phase: PC-stable's skeleton; the maximize phase: hill climbing within it.
    const edge_constraints constraints(pc.knowledge, order);
    const auto skeleton = pc_skeleton(columns, constraints, pc);
    const std::size_t n = columns.size();
    search.candidates.assign(n * n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        if (i != j && skeleton.graph.adjacent(detail::node(i), detail::node(j))) search.candidates[i * n + j] = 1;
      }
    }
  }
  auto learned = hill_climb(columns, search);
  result.edges = learned.edges;
  dag graph(order);
  for (const auto& e : result.edges) graph.add_edge(e.from, e.to);
  result.graph = cpdag_of(graph);
  result.search = std::move(learned);
  return result;
}

}  // namespace pgm
