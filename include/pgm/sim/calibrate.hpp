#pragma once
/// \file
/// `calibrate`: fits the analytic model's own constants (the "analytic" object of a task
/// file's physics) to experiments of a reference back-end, Bullet by default, by maximum
/// likelihood. The reference's data come from simulate() with a known seed, so the release
/// (landing) noise of every row is replayed from the seed: both back-ends draw it the same
/// way. What remains is the analytic model's own randomness, which the likelihood integrates:
///
/// - stacking: P(onTop1 … onTopN | landing offsets) under the settle noise, by nested
///   Gauss–Legendre integration in probability space (closed form for the last cube);
/// - dropping: P(inside | landing point, scale) under the landing scatter, by an 8 × 8
///   Gauss–Legendre rule in probability space (the closed-form rule at each node).
///
/// Probabilities are kept within [1e-4, 1 - 1e-4], so that one row the model deems
/// impossible costs a bounded amount. The fit is a coordinate descent: each constant in turn
/// by Brent's method (boost::math::tools::brent_find_minima) over its range, until a sweep
/// gains less than 0.01 in log-likelihood.

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/sim/analytic.hpp"
#include "pgm/sim/analytic_probability.hpp"
#include "pgm/sim/container.hpp"
#include "pgm/sim/random.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

/// Experiments a calibration may fit to: the fit replays every one of them at each step, so
/// all are kept in memory with their simulated data (docs/limits.md).
inline constexpr std::size_t max_calibration_rows = 10'000'000;

struct calibration_options {
  /// The reference back-end whose experiments are fitted.
  std::string reference = "bullet";
  std::size_t rows = 20'000;
  std::uint64_t seed = 1;
  /// Threads for simulating the reference (0: every hardware thread).
  unsigned threads = 0;
  /// Progress of the simulation (see simulate_options::progress).
  std::function<void(std::size_t done)> progress;
  /// At most this many sweeps over the constants.
  int sweeps = 6;
};

/// One fitted constant, named by its path in the task file ("analytic/tipping_margin/first").
struct calibrated_constant {
  std::string name;
  double before = 0, after = 0;
};

struct calibration_result {
  /// The task with the fitted constants.
  task_definition task;
  std::vector<calibrated_constant> constants;
  /// Total log-likelihood of the reference's rows under the constants before and after.
  double log_likelihood_before = 0, log_likelihood_after = 0;
  std::size_t rows = 0;
  std::uint64_t seed = 0;
  std::string reference;
  double simulate_seconds = 0, fit_seconds = 0;
};

namespace detail {

inline constexpr double probability_floor = 1e-4;

[[nodiscard]] inline double clamped_log(double p) {
  return std::log(std::clamp(p, probability_floor, 1 - probability_floor));
}

/// A constant the fit may change: its name in the file, its range, and where it lives.
struct fitted_constant {
  std::string name;
  double lo, hi;
  std::function<double&(physics_parameters&)> at;
};

[[nodiscard]] PGM_DECL std::vector<fitted_constant> fitted_constants(const task_definition& task);

/// Nodes of E[f(Z)], Z standard normal restricted to [a, b] (in sd units): Gauss–Legendre in
/// probability space. Returns pairs (z, weight); the weights sum to P(a < Z < b).
[[nodiscard]] PGM_DECL std::vector<std::pair<double, double>> normal_nodes(double a, double b,
                                                                           const std::vector<double>& x,
                                                                           const std::vector<double>& w);

/// Log-likelihood of stacking rows: per row the replayed landing offsets of every cube and
/// how many leading outcomes are 1.
class stacking_likelihood {
 public:
  PGM_DECL stacking_likelihood(const task_definition& task, const dataset& data, std::uint64_t seed);

  [[nodiscard]] PGM_DECL double operator()(const task_definition& task) const;

 private:
  struct row_data {
    std::vector<double> x, y;  // landing offsets from the cube below
    std::size_t standing = 0;
  };

  /// P(stages 0..m-1 stand on one axis) given the landing offsets t: cube i settles at
  /// t_i + settle_i · Z_i.
  [[nodiscard]] PGM_DECL double axis(const std::vector<double>& t, std::size_t m, const std::vector<double>& half,
                                     const std::vector<double>& settle) const;

  PGM_DECL double level(std::size_t i, std::size_t m, const std::vector<double>& t, const std::vector<double>& half,
                        const std::vector<double>& settle, std::vector<double>& at) const;

  std::size_t cubes_ = 0;
  std::vector<row_data> rows_;
  std::vector<double> x_, w_;
};

/// Log-likelihood of dropping rows: per row the replayed landing point, the container at the
/// row's scale and whether the sphere stayed.
class dropping_likelihood {
 public:
  PGM_DECL dropping_likelihood(const task_definition& task, const dataset& data, std::uint64_t seed);

  [[nodiscard]] PGM_DECL double operator()(const task_definition& task) const;

 private:
  struct row_data {
    double x, y;
    container_profile container;
    bool inside;
  };
  std::vector<row_data> rows_;
  std::vector<std::pair<double, double>> nodes_;
};

[[nodiscard]] PGM_DECL double rounded(double value, int digits);

}  // namespace detail

/// Fits the analytic constants of `task` to `data`, which must be experiments 0 … n-1 of
/// simulate(task, {seed = seed, …}) on a back-end that draws release noise as the analytic
/// one does (the built-in ones do). Fitted constants are rounded to 4 significant digits.
[[nodiscard]] PGM_DECL calibration_result calibrate(const task_definition& task, const dataset& data,
                                                    std::uint64_t seed, const calibration_options& options = {});

/// Simulates options.rows experiments of `task` on options.reference and fits to them.
[[nodiscard]] PGM_DECL calibration_result calibrate(const task_definition& task, const calibration_options& options);

/// The text of a task file (`original`, as read) with the fitted constants in
/// /physics/analytic, and a note of where they come from; the rest is kept as it was.
[[nodiscard]] PGM_DECL std::string calibrated_task_text(std::string_view original, const calibration_result& result);

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/calibrate.ipp"
#endif
