#pragma once
// The definitions of pgm/causal/dag_check.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/causal/dag_check.hpp"

namespace pgm {

PGM_DECL dag_check check_dag(const network_structure& structure, const dataset& data,
                             const dag_check_options& options) {
  if (!(options.alpha > 0.0 && options.alpha < 1.0)) {
    throw model_error("alpha must lie strictly between 0 and 1, got " + text::format_double(options.alpha));
  }
  const auto& graph = structure.graph();
  const auto n = structure.size();
  for (const auto& v : structure.variables()) static_cast<void>(data.discrete(v.name()));
  struct pair_test {
    variable_id x, y;
  };
  std::vector<pair_test> pairs;
  std::vector<std::vector<bool>> below(n);
  for (std::size_t i = 0; i < n; ++i) {
    const variable_id v = index_at<variable_id>(i);
    const variable_id one[] = {v};
    below[i] = detail::descendants(graph, one);
  }
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      const variable_id va = index_at<variable_id>(a);
      const variable_id vb = index_at<variable_id>(b);
      if (graph.has_edge(va, vb) || graph.has_edge(vb, va)) continue;
      pairs.push_back(below[a][b] ? pair_test{vb, va} : pair_test{va, vb});
    }
  }
  dag_check result;
  result.alpha = options.alpha;
  result.tests.resize(pairs.size());
  detail::parallel_options parallel;
  parallel.threads = options.threads;
  detail::parallel_for(pairs.size(), parallel, [&](detail::item_range range) {
    for (std::size_t k = range.begin; k < range.end; ++k) {
      auto& t = result.tests[k];
      t.x = structure.at(pairs[k].x).name();
      t.y = structure.at(pairs[k].y).name();
      for (auto p : graph.parents(pairs[k].x)) t.given.push_back(structure.at(p).name());
      t.result = test_independence(data, t.x, t.y, t.given, options.test);
    }
  });
  std::stable_sort(result.tests.begin(), result.tests.end(),
                   [](const auto& a, const auto& b) { return a.result.p_value < b.result.p_value; });
  return result;
}

}  // namespace pgm
