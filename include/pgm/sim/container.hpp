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

#include "pgm/core/compilation.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

/// Gravity in the simulators' units (cm/s²).
inline constexpr double standard_gravity = 981.0;

class container_profile {
 public:
  /// The container of `p` at `scale` (its opening's radius is scale · diameter_at_scale_1 / 2).
  PGM_DECL container_profile(const dropping_physics& p, double scale);

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
  [[nodiscard]] PGM_DECL touch first_touch(double rho) const noexcept;

  /// A local minimum of the distance from a point to the profile curve.
  struct nearest_point {
    double rho, z;                ///< on the curve
    double normal_rho, normal_z;  ///< unit, from the curve towards the point
    double distance;
  };
  /// The local minima of the distance from (rho ≥ 0, z) to the curve closer than `within`
  /// (at most three: floor, fillet or wall, rim); returns how many were written.
  PGM_DECL int nearest(double rho, double z, double within, std::array<nearest_point, 3>& found) const noexcept;

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

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/container.ipp"
#endif
