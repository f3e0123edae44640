#pragma once
/// \file
/// `agreement`: how closely the analytic model follows a reference back-end (Bullet by
/// default), cell by cell. The cells split each grid variable's range into thirds: the two
/// offsets of the first and the last cube along x for a stack of several cubes (the axis on
/// which the pair's centre of mass couples them; y behaves the same), xOff1 × yOff1 for one
/// cube, and xOff × yOff × scalingFactor for dropping (27 cells). Both back-ends simulate with
/// the same seed; the table gives each cell's success rates, the mean |difference| over the
/// cells and what sampling noise alone would give, so that the two can be compared.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

struct agreement_options {
  std::string reference = "bullet";
  std::size_t reference_rows = 20'000;
  std::size_t analytic_rows = 200'000;
  std::uint64_t seed = 1;
  unsigned threads = 0;
  /// Progress of the reference's simulation (see simulate_options::progress).
  std::function<void(std::size_t done)> progress;
};

/// A grid variable and the range split into thirds.
struct agreement_axis {
  std::string variable;
  double lo = 0, hi = 0;
  [[nodiscard]] double edge(std::size_t k) const { return lo + (hi - lo) * static_cast<double>(k) / 3; }
};

struct agreement_cell {
  std::vector<std::size_t> third;  ///< per axis, 0 … 2
  std::size_t reference_rows = 0, analytic_rows = 0;
  double reference_rate = 0, analytic_rate = 0;
};

struct agreement_table {
  std::string task, reference, outcome;
  std::vector<agreement_axis> axes;
  std::vector<agreement_cell> cells;
  std::size_t reference_rows = 0, analytic_rows = 0;
  double reference_rate = 0, analytic_rate = 0;
  /// Mean over the cells (with rows in both) of |reference rate - analytic rate|.
  double mean_abs_difference = 0;
  /// The expected mean |difference| if both back-ends had each cell's pooled rate: what
  /// sampling noise alone gives at these sizes.
  double noise_mean_abs_difference = 0;
  /// Standard error of the overall difference.
  double overall_standard_error = 0;
  double reference_seconds = 0, analytic_seconds = 0;
};

namespace detail {

PGM_DECL agreement_axis grid_axis(const task_definition& task, const std::string& name);

}  // namespace detail

/// The grid variables of a task (see the file comment).
[[nodiscard]] PGM_DECL std::vector<agreement_axis> agreement_axes(const task_definition& task);

/// Simulates `task` on options.reference and on the analytic back-end and compares the
/// success rates per cell.
[[nodiscard]] PGM_DECL agreement_table agreement(const task_definition& task, const agreement_options& options);

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/agreement.ipp"
#endif
