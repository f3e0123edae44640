#pragma once
/// \file
/// `container_profile`: the shape of a dropping task's container at one scale, as both
/// back-ends see it. The container is a solid of revolution: every point within half a wall's
/// thickness of a profile curve in the (distance from the axis ρ, height z) plane. The curve
/// runs along the middle of the floor, turns up through a fillet and follows the wall to the
/// rim, where it ends, so the rim is rounded:
///
/// - the inner floor is flat at z = w (the wall's thickness, min(0.8 cm, H/3)) out to
///   floor_fraction · R, where the inner wall starts and runs straight to the rim (R, H);
/// - the inner corner between them is rounded with the sphere's radius (less if the floor or
///   the wall is shorter), so that a sphere touches it at one point, never two faces at once.
///
/// Because the shape is round, the nearest point of the container to a sphere's centre lies
/// in the centre's meridian plane: contacts are computed in two dimensions, exactly.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "pgm/sim/task.hpp"

namespace pgm::sim {

/// Gravity in the simulators' units (cm/s²).
inline constexpr double standard_gravity = 981.0;

class container_profile {
 public:
  /// The container of `p` at `scale` (its opening's radius is scale · diameter_at_scale_1 / 2).
  container_profile(const dropping_physics& p, double scale)
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

  /// The opening's radius R and the rim's height H (cm).
  [[nodiscard]] double radius() const noexcept { return radius_; }
  [[nodiscard]] double height() const noexcept { return height_; }
  /// The wall's (and floor's) thickness (cm).
  [[nodiscard]] double wall() const noexcept { return wall_; }
  /// Distance from the profile curve at which the sphere touches: its radius + half the wall.
  [[nodiscard]] double reach() const noexcept { return sphere_radius_ + wall_ / 2; }
  /// The end of the profile curve at the rim (ρ, z): the rounded rim's centre line.
  [[nodiscard]] double rim_rho() const noexcept { return rim_[0]; }
  [[nodiscard]] double rim_z() const noexcept { return rim_[1]; }
  /// Height of the sphere's centre resting on the floor.
  [[nodiscard]] double floor_centre() const noexcept { return wall_ + sphere_radius_; }
  /// The wall's slope from the horizontal (radians; π/2 for vertical walls).
  [[nodiscard]] double slope() const noexcept { return slope_; }
  /// Farthest extent from the axis, and the top (cm).
  [[nodiscard]] double extent() const noexcept { return std::max(radius_, rim_[0]) + wall_ / 2; }
  [[nodiscard]] double top() const noexcept { return rim_[1] + wall_ / 2; }

  /// Where a sphere falling straight down at distance `rho` from the axis first touches the
  /// container: its centre's height and the contact's normal in the (ρ, z) plane (pointing
  /// from the container to the sphere). `hit` is false when it misses and falls on the table.
  struct touch {
    bool hit = false;
    double z = 0, normal_rho = 0, normal_z = 1;
  };
  [[nodiscard]] touch first_touch(double rho) const noexcept {
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

  /// A local minimum of the distance from a point to the profile curve.
  struct nearest_point {
    double rho, z;                ///< on the curve
    double normal_rho, normal_z;  ///< unit, from the curve towards the point
    double distance;
  };
  /// The local minima of the distance from (rho ≥ 0, z) to the curve closer than `within`
  /// (at most three: floor, fillet or wall, rim); returns how many were written.
  int nearest(double rho, double z, double within, std::array<nearest_point, 3>& found) const noexcept {
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

 private:
  static constexpr double max_wall = 0.8;     // cm
  static constexpr double min_fillet = 0.05;  // cm
  static constexpr double arc_from = -std::numbers::pi / 2;

  double sphere_radius_, radius_, height_, wall_;
  double slope_ = 0, fillet_rho_ = 0, fillet_z_ = 0, arc_radius_ = 0, arc_to_ = 0;
  double out_rho_ = 0, out_z_ = 0;
  std::array<double, 2> wall_from_{}, rim_{};
};

}  // namespace pgm::sim
