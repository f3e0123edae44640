#pragma once
/// \file
/// Checking a DAG against data: every independence the DAG implies locally — each variable
/// independent of its non-descendants given its parents — tested pair by pair with chi-square,
/// G² or any registered test (pgm/learn/independence_test_registry.hpp). Each non-adjacent pair
/// {A, B} is tested once: as A ⟂ B | Pa(A) where B does not descend from A, else as
/// B ⟂ A | Pa(B). A test whose
/// p-value is at most alpha rejects the independence: the data contradict the DAG there.

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "pgm/causal/adjustment.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/learn/independence_test_registry.hpp"

namespace pgm {

struct dag_check_options {
  /// Any independence test (pgm/learn/independence_test_registry.hpp); chi2 by default.
  independence_test test;
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
[[nodiscard]] PGM_DECL dag_check check_dag(const network_structure& structure, const dataset& data,
                                           const dag_check_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/causal/impl/dag_check.ipp"
#endif
