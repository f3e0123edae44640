#pragma once
// The definitions of pgm/sim/analytic.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/analytic.hpp"

namespace pgm::sim::detail {

PGM_DECL bool stage_stands(std::span<const double> at, std::size_t m, double half) noexcept {
  double sum = 0;
  for (std::size_t k = m + 1; k-- > 0;) {
    sum += at[k];
    const double below = k == 0 ? 0.0 : at[k - 1];
    // On the edge counts as standing, so that grids ending on ±half keep their end points.
    if (std::abs(sum / static_cast<double>(m + 1 - k) - below) > half) return false;
  }
  return true;
}

PGM_DECL std::pair<double, double> standing_offsets(std::span<const double> at, std::size_t m, double half) noexcept {
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

PGM_DECL bool sphere_stays(const container_profile& c, const dropping_physics& p, double rho) noexcept {
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

}  // namespace pgm::sim::detail

namespace pgm::sim {

PGM_DECL analytic_simulator::analytic_simulator(const task_definition& task) : physics_(task.physics) {
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

PGM_DECL void analytic_simulator::run(std::span<double> values, random_stream& noise) {
  if (const auto* s = std::get_if<stacking_physics>(&physics_)) {
    stack(*s, values, noise);
  } else {
    drop(std::get<dropping_physics>(physics_), values, noise);
  }
}

PGM_DECL void analytic_simulator::stack(const stacking_physics& p, std::span<double> values, random_stream& noise) {
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
    const double half = p.cube_size / 2 - p.support_margin - (m == 0 ? p.tipping_margin_first : p.tipping_margin_later);
    standing = standing && stands(m, half);
    values[cubes_[m].on_top] = standing ? 1.0 : 0.0;
  }
}

PGM_DECL void analytic_simulator::drop(const dropping_physics& p, std::span<double> values,
                                       random_stream& noise) const {
  double x = values[x_] + p.landing_noise * noise.normal();
  double y = values[y_] + p.landing_noise * noise.normal();
  if (p.landing_scatter > 0) {
    x += p.landing_scatter * noise.normal();
    y += p.landing_scatter * noise.normal();
  }
  const container_profile container(p, values[scale_]);
  values[inside_] = detail::sphere_stays(container, p, std::hypot(x, y)) ? 1.0 : 0.0;
}

}  // namespace pgm::sim
