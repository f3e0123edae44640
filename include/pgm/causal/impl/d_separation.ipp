#pragma once
// The definitions of pgm/causal/d_separation.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/causal/d_separation.hpp"

namespace pgm {

PGM_DECL std::vector<bool> d_connected(const dag& graph, std::span<const variable_id> from,
                                       std::span<const variable_id> given) {
  const auto n = graph.size();
  std::vector<char> observed(n, 0);
  for (auto z : given) observed[z.value()] = 1;
  // Phase 1: the observed nodes and their ancestors, where a collider opens.
  std::vector<char> opens(n, 0);
  std::vector<variable_id> stack(given.begin(), given.end());
  while (!stack.empty()) {
    const auto v = stack.back();
    stack.pop_back();
    if (opens[v.value()]) continue;
    opens[v.value()] = 1;
    for (auto p : graph.parents(v)) stack.push_back(p);
  }
  // Phase 2: (node, arrived from a child = up / from a parent = down).
  enum direction : int { up = 0, down = 1 };
  std::vector<char> visited(2 * n, 0);
  std::vector<std::pair<variable_id, direction>> todo;
  for (auto x : from) todo.emplace_back(x, up);
  std::vector<bool> reached(n, false);
  while (!todo.empty()) {
    const auto [v, d] = todo.back();
    todo.pop_back();
    const auto key = 2 * v.value() + static_cast<std::size_t>(d);
    if (visited[key]) continue;
    visited[key] = 1;
    if (!observed[v.value()]) reached[v.value()] = true;
    if (d == up && !observed[v.value()]) {
      for (auto p : graph.parents(v)) todo.emplace_back(p, up);
      for (auto c : graph.children(v)) todo.emplace_back(c, down);
    } else if (d == down) {
      if (!observed[v.value()]) {
        for (auto c : graph.children(v)) todo.emplace_back(c, down);
      }
      if (opens[v.value()]) {
        for (auto p : graph.parents(v)) todo.emplace_back(p, up);
      }
    }
  }
  return reached;
}

PGM_DECL bool d_separated(const dag& graph, std::span<const variable_id> x, std::span<const variable_id> y,
                          std::span<const variable_id> z) {
  // The first variable in two of the sets, named with both.
  const auto refuse_overlap = [&](std::span<const variable_id> a, const char* a_name, std::span<const variable_id> b,
                                  const char* b_name) {
    for (const auto v : a) {
      if (std::find(b.begin(), b.end(), v) != b.end()) {
        throw model_error("d-separation needs disjoint sets: '" + graph.name(v) + "' is in both " + a_name + " and " +
                          b_name);
      }
    }
  };
  refuse_overlap(x, "X", y, "Y");
  refuse_overlap(x, "X", z, "the conditioning set");
  refuse_overlap(y, "Y", z, "the conditioning set");
  const auto reached = d_connected(graph, x, z);
  return std::none_of(y.begin(), y.end(), [&](variable_id v) { return reached[v.value()]; });
}

PGM_DECL bool d_separated(const network_structure& structure, std::span<const std::string> x,
                          std::span<const std::string> y, std::span<const std::string> z) {
  const auto ids = [&](std::span<const std::string> names, const char* what) {
    std::vector<variable_id> result;
    for (const auto& name : names) result.push_back(structure.id(name));
    if (result.empty() && what) throw model_error(std::string("d-separation needs at least one variable in ") + what);
    return result;
  };
  const auto a = ids(x, "X");
  const auto b = ids(y, "Y");
  const auto c = ids(z, nullptr);
  return d_separated(structure.graph(), a, b, c);
}

}  // namespace pgm
