#pragma once
/// \file
/// The analytic back-end: closed-form physics, fast enough for millions of experiments per
/// second on one core, calibrated against Bullet (pgm calibrate; docs/simulators.md gives the
/// model and its constants).
///
/// Stacking (any number of cubes): cube i lands at its intended offset from the cube below
/// plus release noise N(0, base + per_cm_drop · dropOff_i) per axis, then comes to rest with
/// extra settle noise. When cube m has been placed, every contact below it holds if the centre
/// of mass of the cubes it carries lies over the supporting face, shrunk by support_margin and
/// by the tipping margin (for the first cube on the fixed cubeDown, or later ones). onTop_m is
/// read then, before the next cube is released, and needs the stack to have stood so far.
///
/// Dropping: the sphere's centre lands at its offset plus landing noise (and scatter). Falling
/// straight down, it first touches the container's floor, wall or rim, or misses it
/// (container_profile::first_touch). The bounce keeps `restitution` of the speed into the
/// surface and `tangential` of the speed along it. Moving outwards, it leaves; straight up, it
/// falls back in; inwards, it leaves if it passes over the far rim, or if it lands and rolls
/// with enough energy to climb the wall (a wall of slope β keeps cos β of its speed).

#include <algorithm>
#include <cmath>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/sim/container.hpp"
#include "pgm/sim/run.hpp"
#include "pgm/sim/simulator_concept.hpp"

namespace pgm::sim {

namespace detail {

/// Whether stage m of a stack stands: with cubes 0..m at positions at[0..m] (relative to
/// cubeDown, along one axis), for every contact k ≤ m the centre of mass of cubes k..m lies
/// within `half` of the cube below k (cubeDown at 0).
[[nodiscard]] PGM_DECL bool stage_stands(std::span<const double> at, std::size_t m, double half) noexcept;

/// The offsets u of cube m from cube m-1 for which stage m stands, given cubes 0..m-1 at
/// at[0..m-1]: every contact's condition is linear in u, so they intersect to [lo, hi]
/// (empty when hi <= lo).
[[nodiscard]] PGM_DECL std::pair<double, double> standing_offsets(std::span<const double> at, std::size_t m,
                                                                  double half) noexcept;

/// The closed-form dropping rule: whether a sphere whose centre lands `rho` from the axis of
/// container `c` ends inside it.
[[nodiscard]] PGM_DECL bool sphere_stays(const container_profile& c, const dropping_physics& p, double rho) noexcept;

}  // namespace detail

class analytic_simulator {
 public:
  static constexpr std::string_view name = "analytic";

  PGM_DECL explicit analytic_simulator(const task_definition& task);

  PGM_DECL void run(std::span<double> values, random_stream& noise);

 private:
  struct cube_columns {
    std::size_t x, y, drop, on_top;
  };

  PGM_DECL void stack(const stacking_physics& p, std::span<double> values, random_stream& noise);

  /// Whether every contact holds once cubes 0..m are placed, on both axes.
  [[nodiscard]] bool stands(std::size_t m, double half) const {
    return detail::stage_stands(x_at_, m, half) && detail::stage_stands(y_at_, m, half);
  }

  PGM_DECL void drop(const dropping_physics& p, std::span<double> values, random_stream& noise) const;

  physics_parameters physics_;
  std::vector<cube_columns> cubes_;
  std::vector<double> x_at_, y_at_;  // landing offsets, then positions relative to cubeDown
  std::size_t x_ = 0, y_ = 0, scale_ = 0, inside_ = 0;
};

static_assert(Simulator<analytic_simulator>);

/// Runs the analytic back-end (what simulate() calls for backend "analytic").
[[nodiscard]] inline dataset simulate_analytic(const task_definition& task, const simulate_options& options) {
  return run_experiments<analytic_simulator>(task, options, 8192);
}

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/analytic.ipp"
#endif
