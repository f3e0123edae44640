#pragma once
// The definitions of pgm/causal/adjustment.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/causal/adjustment.hpp"

namespace pgm::detail {

PGM_DECL dag without_edges_out_of(const dag& graph, std::span<const variable_id> nodes) {
  dag result = graph;
  for (auto v : nodes) {
    for (auto c : graph.children(v)) result.remove_edge(v, c);
  }
  return result;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL bool satisfies_backdoor(const dag& graph, std::span<const variable_id> x, std::span<const variable_id> y,
                                 std::span<const variable_id> z) {
  const auto below = detail::descendants(graph, x);
  if (std::any_of(z.begin(), z.end(), [&](variable_id v) { return below[v.value()]; })) return false;
  return d_separated(detail::without_edges_out_of(graph, x), x, y, z);
}

PGM_DECL bool satisfies_frontdoor(const dag& graph, std::span<const variable_id> x, std::span<const variable_id> y,
                                  std::span<const variable_id> m) {
  // (i) Every directed path from X to Y meets M: Y is not reached from X avoiding M.
  std::vector<char> blocked(graph.size(), 0);
  for (auto v : m) blocked[v.value()] = 1;
  std::vector<char> seen(graph.size(), 0);
  std::vector<variable_id> stack(x.begin(), x.end());
  while (!stack.empty()) {
    const auto v = stack.back();
    stack.pop_back();
    if (seen[v.value()]) continue;
    seen[v.value()] = 1;
    for (auto c : graph.children(v)) {
      if (std::find(y.begin(), y.end(), c) != y.end()) return false;
      if (!blocked[c.value()]) stack.push_back(c);
    }
  }
  // (ii) No back-door path from X to M is open; (iii) X blocks every back-door path from M to Y.
  return d_separated(detail::without_edges_out_of(graph, x), x, m) &&
         d_separated(detail::without_edges_out_of(graph, m), m, y, x);
}

PGM_DECL backdoor_sets minimal_backdoor_sets(const dag& graph, std::span<const variable_id> x,
                                             std::span<const variable_id> y, std::size_t limit) {
  std::vector<variable_id> both(x.begin(), x.end());
  both.insert(both.end(), y.begin(), y.end());
  const auto above = detail::ancestors(graph, both);
  const auto below = detail::descendants(graph, x);
  std::vector<variable_id> candidates;
  for (std::size_t i = 0; i < graph.size(); ++i) {
    const variable_id v = index_at<variable_id>(i);
    const bool in_xy = std::find(both.begin(), both.end(), v) != both.end();
    if (above[i] && !below[i] && !in_xy) candidates.push_back(v);
  }
  const auto mutilated = detail::without_edges_out_of(graph, x);
  backdoor_sets result;
  const auto n = candidates.size();
  std::vector<std::size_t> pick;
  for (std::size_t size = 0; size <= n; ++size) {
    // Subsets of `size` candidates in lexicographic order of positions.
    pick.resize(size);
    for (std::size_t k = 0; k < size; ++k) pick[k] = k;
    while (true) {
      if (result.examined == limit) {
        result.complete = false;
        return result;
      }
      ++result.examined;
      std::vector<variable_id> z;
      for (auto k : pick) z.push_back(candidates[k]);
      const bool has_smaller = std::any_of(result.sets.begin(), result.sets.end(), [&](const auto& found) {
        return std::includes(z.begin(), z.end(), found.begin(), found.end());
      });
      if (!has_smaller && d_separated(mutilated, x, y, z)) result.sets.push_back(std::move(z));
      // Next combination.
      std::size_t k = size;
      while (k > 0 && pick[k - 1] == n - size + k - 1) --k;
      if (k == 0) break;
      ++pick[k - 1];
      for (std::size_t j = k; j < size; ++j) pick[j] = pick[j - 1] + 1;
    }
  }
  return result;
}

PGM_DECL adjusted_estimate adjust(const dataset& data, const std::string& x, const std::string& y,
                                  std::span<const std::string> z, const count_options& options) {
  if (x == y) throw model_error("the treatment and the outcome are the same variable '" + x + "'");
  if (std::find(z.begin(), z.end(), x) != z.end() || std::find(z.begin(), z.end(), y) != z.end()) {
    throw model_error("the adjustment set holds the treatment or the outcome");
  }
  std::vector<std::string> parents(z.begin(), z.end());
  parents.push_back(x);
  const auto counts = count_family(data, y, parents, options);
  adjusted_estimate result;
  result.x_states = data.discrete(x).var().cardinality();
  result.y_states = counts.child_cardinality();
  result.rows = counts.total();
  if (result.rows == 0) throw data_error("no rows to estimate from");
  const std::size_t strata = counts.configurations() / result.x_states;
  const auto nx = result.x_states;
  const auto ny = result.y_states;
  result.values.assign(nx * ny, 0.0);
  result.unsupported.assign(nx, 0.0);
  std::vector<double> supported(nx, 0.0);
  for (std::size_t s = 0; s < strata; ++s) {
    double stratum = 0.0;  // rows in z
    for (std::size_t xi = 0; xi < nx; ++xi) stratum += static_cast<double>(counts.total(config_index(s * nx + xi)));
    if (stratum == 0.0) continue;
    const double weight = stratum / static_cast<double>(result.rows);
    for (std::size_t xi = 0; xi < nx; ++xi) {
      const config_index u(s * nx + xi);  // X is the last parent, so it runs fastest
      const auto here = static_cast<double>(counts.total(u));
      if (here == 0.0) {
        result.unsupported[xi] += weight;
        continue;
      }
      supported[xi] += weight;
      for (std::size_t yi = 0; yi < ny; ++yi) {
        result.values[xi * ny + yi] += weight * static_cast<double>(counts(index_at<state_index>(yi), u)) / here;
      }
    }
  }
  for (std::size_t xi = 0; xi < nx; ++xi) {
    for (std::size_t yi = 0; yi < ny; ++yi) {
      auto& value = result.values[xi * ny + yi];
      value = supported[xi] > 0.0 ? value / supported[xi] : 1.0 / static_cast<double>(ny);
    }
  }
  return result;
}

}  // namespace pgm
