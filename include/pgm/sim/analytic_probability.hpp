#pragma once
/// \file
/// Noise-free ground truth from the analytic model: the probability of success given that
/// some variables lie in intervals ("boxes", e.g. one discretized parent configuration),
/// integrating over the sampling distributions restricted to the box and over the model's
/// noise. Deterministic numerical integration, no sampling:
///
/// - release heights and container scales: Gauss–Legendre in probability space (the
///   variable's CDF), 8 nodes for release heights (one when the release noise does not
///   depend on the height), 24 for scales;
/// - landing positions: the density of "sampled offset + Gaussian noise" in closed form
///   (a truncated normal, a uniform or a grid convolved with a normal), on a grid of 256
///   (stacking) or 1024 (dropping) intervals, integrated by the trapezoidal rule;
/// - stacks: nested sums over the cubes' offsets, the last cube's in closed form;
/// - dropping: the intervals of landing distance from the axis where the sphere stays (a
///   scan refined by bisection), each over the landing density in polar form.
///
/// Against finer integration the result differs by less than 1e-3 on Table I's boxes (2e-3
/// for three cubes; tests/sim/analytic_test.cpp), and all 625 onTop2 boxes of 2-Stack take
/// about 0.1 s on one core (bench_sim ground_truth_625).

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/sim/analytic.hpp"
#include "pgm/sim/container.hpp"
#include "pgm/sim/distribution.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

/// Intervals [lo, hi) by variable name.
using variable_box = std::map<std::string, std::pair<double, double>, std::less<>>;

/// Resolution of the integration; the defaults give the accuracy stated above.
struct integration_options {
  std::size_t height_nodes = 8;
  std::size_t scale_nodes = 24;
  std::size_t stacking_grid = 256;
  std::size_t dropping_grid = 1024;
  std::size_t angle_nodes = 128;
  /// Steps of the scan for where a dropped sphere's outcome changes with its landing distance.
  std::size_t radial_steps = 2048;
};

namespace detail {

/// Gauss–Legendre nodes and weights on [-1, 1] (Newton's method on the Legendre recurrence).
PGM_DECL std::pair<std::vector<double>, std::vector<double>> gauss_legendre(std::size_t n);

/// A variable's distribution restricted to [lo, hi), as quadrature nodes whose weights sum
/// to one, and the probability of the interval.
struct restricted {
  std::vector<double> values;
  std::vector<double> weights;
  double mass = 0.0;
  const distribution* dist = nullptr;
  double lo = 0.0, hi = 0.0;  ///< the continuous support inside the box
};

PGM_DECL restricted restrict_to(const distribution& d, double lo, double hi, std::size_t nodes);

/// Density at t of X + N(0, sd²), X drawn from `r` (closed form for normal and uniform).
PGM_DECL double noisy_density(const restricted& r, double sd, double t);

/// The density of a noisy position on a uniform grid over [lo, hi], with its integral.
class noisy_axis {
 public:
  PGM_DECL noisy_axis(const restricted& r, double sd, double lo, double hi, std::size_t intervals);
  [[nodiscard]] double density(std::size_t k) const { return density_[k]; }
  [[nodiscard]] double at(std::size_t k) const { return lo_ + step_ * static_cast<double>(k); }
  [[nodiscard]] std::size_t intervals() const { return density_.size() - 1; }
  [[nodiscard]] double step() const { return step_; }
  /// ∫ density from the grid's start to t (t clamped to the grid), linearly interpolated.
  [[nodiscard]] double cumulative(double t) const { return interpolate(cumulative_, t); }
  [[nodiscard]] double density_at(double t) const { return interpolate(density_, t); }

 private:
  PGM_DECL double interpolate(const std::vector<double>& table, double t) const;

  double lo_, step_;
  std::vector<double> density_, cumulative_;
};

PGM_DECL restricted restricted_variable(const task_definition& task, const variable_box& box, const std::string& name,
                                        std::size_t nodes);

/// One axis of a stack: ∫ Π density_i(t_i) · 1[every stage stands] dt over the cubes'
/// landing offsets t_i (from the cube below), by nested trapezoidal sums over t_0 … t_{n-2}
/// and the closed-form cumulative of the last one. Stage m (cubes 0..m placed) stands when,
/// for every k ≤ m, the centre of mass of cubes k..m lies within `half[m]` of cube k-1.
class stack_axis_integral {
 public:
  stack_axis_integral(std::vector<const noisy_axis*> axes, std::vector<double> half)
      : axes_(std::move(axes)), half_(std::move(half)), at_(axes_.size()) {}

  [[nodiscard]] double operator()() { return level(0); }

 private:
  // at_[j]: where cube j sits relative to cubeDown.
  PGM_DECL double level(std::size_t i);

  std::vector<const noisy_axis*> axes_;
  std::vector<double> half_;
  std::vector<double> at_;
};

PGM_DECL double stacking_probability(const task_definition& task, const stacking_physics& p, std::size_t cubes,
                                     const variable_box& box, const integration_options& o);

/// The intervals of distance from the axis where a landing sphere stays in container `c`:
/// a scan in `steps` steps, each change of outcome refined by bisection.
PGM_DECL std::vector<std::pair<double, double>> staying_intervals(const container_profile& c, const dropping_physics& p,
                                                                  std::size_t steps);

PGM_DECL double dropping_probability(const task_definition& task, const dropping_physics& p, const variable_box& box,
                                     const integration_options& o);

}  // namespace detail

/// P(outcome = 1 | each named variable lies in its interval [lo, hi)) under the analytic
/// model; unnamed variables range over their whole distribution. Throws data_error for a
/// name that is not a continuous variable of the task, or an interval of probability 0.
[[nodiscard]] PGM_DECL double analytic_outcome_probability(const task_definition& task, std::string_view outcome,
                                                           const variable_box& box,
                                                           const integration_options& options = {});

/// P(success | box): analytic_outcome_probability for the task's success variable.
[[nodiscard]] inline double analytic_success_probability(const task_definition& task, const variable_box& box) {
  return analytic_outcome_probability(task, task.success, box);
}

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/analytic_probability.ipp"
#endif
