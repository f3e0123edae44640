#pragma once
// The definitions of pgm/sim/container.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/container.hpp"

namespace pgm::sim {

PGM_DECL container_profile::container_profile(const dropping_physics& p, double scale)
    : sphere_radius_(p.sphere_diameter / 2),
      radius_(scale * p.diameter_at_scale_1 / 2),
      height_(scale * p.height_at_scale_1),
      wall_(std::min(max_wall, height_ / 3)) {
  const double half = wall_ / 2;
  const double floor_radius = p.floor_fraction * radius_;
  // The inner wall from the floor's edge (floor_radius, wall) to the rim (radius, height).
  const double run = radius_ - floor_radius;
  const double rise = height_ - wall_;
  const double length = std::hypot(run, rise);
  slope_ = std::atan2(rise, run);
  const double tangent = std::tan(slope_ / 2);
  const double fillet = std::max(min_fillet, std::min({sphere_radius_, floor_radius / tangent, length / tangent}));
  fillet_rho_ = std::max(0.0, floor_radius - fillet * tangent);
  fillet_z_ = wall_ + fillet;
  arc_radius_ = fillet + half;
  out_rho_ = rise / length;  // the wall's outward normal
  out_z_ = -run / length;
  arc_to_ = std::atan2(out_z_, out_rho_);
  wall_from_ = {fillet_rho_ + arc_radius_ * out_rho_, fillet_z_ + arc_radius_ * out_z_};
  rim_ = {radius_ + half * out_rho_, height_ + half * out_z_};
}

PGM_DECL container_profile::touch container_profile::first_touch(double rho) const noexcept {
  touch best;
  best.z = -std::numeric_limits<double>::infinity();
  const double reach = this->reach();
  auto consider = [&](double z, double n_rho, double n_z) {
    if (z > best.z) best = {true, z, n_rho, n_z};
  };
  // A point of the curve: touched where the centre is `reach` above it.
  auto point = [&](double q_rho, double q_z) {
    const double d = rho - q_rho;
    if (std::abs(d) < reach) {
      const double up = std::sqrt(reach * reach - d * d);
      consider(q_z + up, d / reach, up / reach);
    }
  };
  if (rho <= fillet_rho_) consider(wall_ / 2 + reach, 0, 1);  // the level floor
  // The fillet, from inside: the centre at reach from the arc lies on a circle of radius
  // arc_radius - reach around the fillet's centre.
  if (const double k = arc_radius_ - reach; k > 1e-9 && std::abs(rho - fillet_rho_) <= k) {
    const double z = fillet_z_ - std::sqrt(k * k - (rho - fillet_rho_) * (rho - fillet_rho_));
    const double angle = std::atan2(z - fillet_z_, rho - fillet_rho_);
    if (angle >= arc_from && angle <= arc_to_) consider(z, -std::cos(angle), -std::sin(angle));
  } else if (k <= 1e-9) {
    // A sphere too big for the fillet touches its ends first.
    point(fillet_rho_, wall_ / 2);
    point(wall_from_[0], wall_from_[1]);
  }
  // The wall's inner side, a straight line: its foot must lie between the fillet and the rim.
  const double in_rho = -out_rho_, in_z = -out_z_;
  const double dr = rim_[0] - wall_from_[0], dz = rim_[1] - wall_from_[1];
  if (std::abs(dr) > 1e-12) {
    const double u = (rho - reach * in_rho - wall_from_[0]) / dr;
    if (u >= 0 && u <= 1) consider(wall_from_[1] + u * dz + reach * in_z, in_rho, in_z);
  }
  point(rim_[0], rim_[1]);  // the rounded rim
  if (!best.hit) best = {};
  return best;
}

PGM_DECL int container_profile::nearest(double rho, double z, double within,
                                        std::array<nearest_point, 3>& found) const noexcept {
  int n = 0;
  auto keep = [&](double q_rho, double q_z) {
    const double d_rho = rho - q_rho, d_z = z - q_z;
    const double d = std::hypot(d_rho, d_z);
    if (d >= within || d <= 1e-9 || n == 3) return;
    found[static_cast<std::size_t>(n++)] = {q_rho, q_z, d_rho / d, d_z / d, d};
  };
  // The floor continues across the axis; its foot past the fillet's start belongs to the arc.
  if (fillet_rho_ > 0 && rho < fillet_rho_) keep(rho, wall_ / 2);
  const double angle = std::atan2(z - fillet_z_, rho - fillet_rho_);
  if (angle >= arc_from && angle <= arc_to_) {
    keep(fillet_rho_ + arc_radius_ * std::cos(angle), fillet_z_ + arc_radius_ * std::sin(angle));
  }
  // The wall up to the rim, where the curve ends (the rounded rim is the distance to its end).
  const double dr = rim_[0] - wall_from_[0], dz = rim_[1] - wall_from_[1];
  if (const double length2 = dr * dr + dz * dz; length2 > 1e-12) {
    const double u = ((rho - wall_from_[0]) * dr + (z - wall_from_[1]) * dz) / length2;
    if (u > 0) keep(wall_from_[0] + std::min(u, 1.0) * dr, wall_from_[1] + std::min(u, 1.0) * dz);
  }
  return n;
}

}  // namespace pgm::sim
