#pragma once
/// \file
/// d-separation on a network's DAG: whether every path between two sets of variables is blocked
/// given a third. Reachability as Koller & Friedman's algorithm 3.1 finds it ("Bayes-ball"): a
/// walk over (node, direction) pairs from X that passes a chain or fork through an unobserved
/// node and a collider whose descendants include an observed one; Y is d-separated from X given
/// Z when the walk reaches no node of Y.

#include <algorithm>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"

namespace pgm {

/// The nodes d-connected to `from` given `given` (the nodes of `from` included, `given`
/// excluded): what a trail from `from` can reach without being blocked.
[[nodiscard]] inline std::vector<bool> d_connected(const dag& graph, std::span<const variable_id> from,
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

/// Whether `x` and `y` are d-separated given `z` (disjoint sets of nodes). Throws model_error
/// when the sets overlap.
[[nodiscard]] inline bool d_separated(const dag& graph, std::span<const variable_id> x, std::span<const variable_id> y,
                                      std::span<const variable_id> z = {}) {
  const auto overlap = [&](std::span<const variable_id> a, std::span<const variable_id> b) {
    return std::any_of(a.begin(), a.end(), [&](variable_id v) { return std::find(b.begin(), b.end(), v) != b.end(); });
  };
  if (overlap(x, y) || overlap(x, z) || overlap(y, z)) {
    throw model_error("d-separation needs disjoint sets: a variable is in two of them");
  }
  const auto reached = d_connected(graph, x, z);
  return std::none_of(y.begin(), y.end(), [&](variable_id v) { return reached[v.value()]; });
}

/// The same by names. Throws model_error for an unknown name (naming the known ones), an empty
/// set X or Y, or overlapping sets.
[[nodiscard]] inline bool d_separated(const network_structure& structure, std::span<const std::string> x,
                                      std::span<const std::string> y, std::span<const std::string> z = {}) {
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
