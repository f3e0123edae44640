#pragma once
/// \file
/// Checking a DAG against data: every independence the DAG implies locally — each variable
/// independent of its non-descendants given its parents — tested pair by pair with the
/// chi-square or G² test of learn/independence_test.hpp. Each non-adjacent pair {A, B} is tested
/// once: as A ⟂ B | Pa(A) where B does not descend from A, else as B ⟂ A | Pa(B). A test whose
/// p-value is at most alpha rejects the independence: the data contradict the DAG there.

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "pgm/causal/adjustment.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/learn/independence_test.hpp"

namespace pgm {

struct dag_check_options {
  ci_test_options test;
  double alpha = 0.05;
  /// Threads, the calling one included; 0 uses every hardware thread. The result is the same.
  unsigned threads = 0;
};

/// One implied independence and its test.
struct implied_independence {
  std::string x;
  std::string y;
  std::vector<std::string> given;
  ci_result result;
};

struct dag_check {
  /// Every implied independence tested, the smallest p-value first (ties: in pair order).
  std::vector<implied_independence> tests;
  double alpha = 0.05;

  [[nodiscard]] std::size_t rejected() const {
    return static_cast<std::size_t>(std::count_if(
        tests.begin(), tests.end(), [&](const implied_independence& t) { return !t.result.independent(alpha); }));
  }
};

/// Tests the DAG of `structure` against `data`, which holds every variable of the structure as
/// a discrete column (more columns are ignored). Throws data_error for a missing or continuous
/// column, model_error for an alpha outside (0, 1).
[[nodiscard]] inline dag_check check_dag(const network_structure& structure, const dataset& data,
                                         const dag_check_options& options = {}) {
  if (!(options.alpha > 0.0 && options.alpha < 1.0)) {
    throw model_error("alpha must lie strictly between 0 and 1, got " + detail::format_double(options.alpha));
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
    const variable_id v(static_cast<variable_id::rep>(i));
    const variable_id one[] = {v};
    below[i] = detail::descendants(graph, one);
  }
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      const variable_id va(static_cast<variable_id::rep>(a));
      const variable_id vb(static_cast<variable_id::rep>(b));
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
