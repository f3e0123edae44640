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

#include "pgm/sim/container.hpp"
#include "pgm/sim/run.hpp"
#include "pgm/sim/simulator_concept.hpp"

namespace pgm::sim {

namespace detail {

/// Whether stage m of a stack stands: with cubes 0..m at positions at[0..m] (relative to
/// cubeDown, along one axis), for every contact k ≤ m the centre of mass of cubes k..m lies
/// within `half` of the cube below k (cubeDown at 0).
[[nodiscard]] inline bool stage_stands(std::span<const double> at, std::size_t m, double half) noexcept {
  double sum = 0;
  for (std::size_t k = m + 1; k-- > 0;) {
    sum += at[k];
    const double below = k == 0 ? 0.0 : at[k - 1];
    // On the edge counts as standing, so that grids ending on ±half keep their end points.
    if (std::abs(sum / static_cast<double>(m + 1 - k) - below) > half) return false;
  }
  return true;
}

/// The offsets u of cube m from cube m-1 for which stage m stands, given cubes 0..m-1 at
/// at[0..m-1]: every contact's condition is linear in u, so they intersect to [lo, hi]
/// (empty when hi <= lo).
[[nodiscard]] inline std::pair<double, double> standing_offsets(std::span<const double> at, std::size_t m,
                                                                double half) noexcept {
  const double base = m == 0 ? 0.0 : at[m - 1];
  double lo = -half, hi = half, sum = 0;
  for (std::size_t k = m; k-- > 0;) {
    sum += at[k];
    const double count = static_cast<double>(m + 1 - k);
    const double below = k == 0 ? 0.0 : at[k - 1];
    // (sum + base + u) / count - below within ±half
    lo = std::max(lo, (below - half) * count - sum - base);
    hi = std::min(hi, (below + half) * count - sum - base);
  }
  return {lo, hi};
}

/// The closed-form dropping rule: whether a sphere whose centre lands `rho` from the axis of
/// container `c` ends inside it.
[[nodiscard]] inline bool sphere_stays(const container_profile& c, const dropping_physics& p, double rho) noexcept {
  constexpr double g = standard_gravity;
  const auto touch = c.first_touch(rho);
  if (!touch.hit) return false;  // on the table
  const double r = p.sphere_diameter / 2;
  const double v0 = std::sqrt(2 * g * std::max(0.0, p.drop_height + r - touch.z));
  // Velocity (0, -v0) split along the normal n and the surface.
  const double into = -v0 * touch.normal_z;  // v · n < 0
  const double along_rho = -into * touch.normal_rho, along_z = -v0 - into * touch.normal_z;
  const double v_rho = p.impact_tangential * along_rho - p.impact_restitution * into * touch.normal_rho;
  const double v_z = p.impact_tangential * along_z - p.impact_restitution * into * touch.normal_z;
  constexpr double still = 1e-6;
  if (v_rho > still) return false;  // thrown outwards
  if (v_rho > -still) return true;  // straight up: back onto the floor
  const double inwards = -v_rho;
  // Over the far rim: its centre line is at -rim_rho.
  const double t = (rho + c.rim_rho()) / inwards;
  const double z_far = touch.z + v_z * t - g * t * t / 2;
  if (z_far > c.rim_z() + p.rim_clearance) return false;
  // Landed inside: rolling (5/7 of the speed for a sphere that starts to roll), it meets the
  // wall, keeps cos(slope) of its speed and climbs with 7/10 of v² as kinetic energy.
  // Its centre rises from the floor (wall + r) to over the rim (rim_z + wall/2 + r).
  const double rolling = 5.0 / 7.0 * inwards * std::cos(c.slope());
  return 0.7 * rolling * rolling / g <= c.rim_z() - c.wall() / 2;
}

}  // namespace detail

class analytic_simulator {
 public:
  static constexpr std::string_view name = "analytic";

  explicit analytic_simulator(const task_definition& task) : physics_(task.physics) {
    if (const auto* s = std::get_if<stacking_physics>(&physics_)) {
      for (std::size_t i = 1; i <= s->cubes; ++i) {
        const auto n = std::to_string(i);
        cubes_.push_back(
            {task.index("xOff" + n), task.index("yOff" + n), task.index("dropOff" + n), task.index("onTop" + n)});
      }
      x_at_.resize(s->cubes);
      y_at_.resize(s->cubes);
    } else {
      x_ = task.index("xOff");
      y_ = task.index("yOff");
      scale_ = task.index("scalingFactor");
      inside_ = task.index("inside");
    }
  }

  void run(std::span<double> values, random_stream& noise) {
    if (const auto* s = std::get_if<stacking_physics>(&physics_)) {
      stack(*s, values, noise);
    } else {
      drop(std::get<dropping_physics>(physics_), values, noise);
    }
  }

 private:
  struct cube_columns {
    std::size_t x, y, drop, on_top;
  };

  void stack(const stacking_physics& p, std::span<double> values, random_stream& noise) {
    const std::size_t n = cubes_.size();
    // Release noise first, for every cube in order, as the Bullet back-end draws it: the two
    // back-ends then see the same landing offsets for a seed.
    for (std::size_t i = 0; i < n; ++i) {
      const auto& c = cubes_[i];
      const double sd = p.noise_base + p.noise_per_cm * values[c.drop];
      x_at_[i] = values[c.x] + sd * noise.normal();
      y_at_[i] = values[c.y] + sd * noise.normal();
    }
    // Then where each cube settles, and its position relative to cubeDown.
    for (std::size_t i = 0; i < n; ++i) {
      const double settle = i == 0 ? p.settle_noise_first : p.settle_noise_later;
      if (settle > 0) {
        x_at_[i] += settle * noise.normal();
        y_at_[i] += settle * noise.normal();
      }
      if (i > 0) {
        x_at_[i] += x_at_[i - 1];
        y_at_[i] += y_at_[i - 1];
      }
    }
    bool standing = true;
    for (std::size_t m = 0; m < n; ++m) {
      const double half =
          p.cube_size / 2 - p.support_margin - (m == 0 ? p.tipping_margin_first : p.tipping_margin_later);
      standing = standing && stands(m, half);
      values[cubes_[m].on_top] = standing ? 1.0 : 0.0;
    }
  }

  /// Whether every contact holds once cubes 0..m are placed, on both axes.
  [[nodiscard]] bool stands(std::size_t m, double half) const {
    return detail::stage_stands(x_at_, m, half) && detail::stage_stands(y_at_, m, half);
  }

  void drop(const dropping_physics& p, std::span<double> values, random_stream& noise) const {
    double x = values[x_] + p.landing_noise * noise.normal();
    double y = values[y_] + p.landing_noise * noise.normal();
    if (p.landing_scatter > 0) {
      x += p.landing_scatter * noise.normal();
      y += p.landing_scatter * noise.normal();
    }
    const container_profile container(p, values[scale_]);
    values[inside_] = detail::sphere_stays(container, p, std::hypot(x, y)) ? 1.0 : 0.0;
  }

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
