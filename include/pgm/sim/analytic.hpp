#pragma once
/// \file
/// The analytic back-end: closed-form physics, fast enough for millions of experiments per
/// second on one core (docs/simulators.md gives the model and its constants).
///
/// Stacking: cube i lands at its intended offset from the cube below plus release noise
/// N(0, base + per_cm_drop * dropOff_i) per axis. A contact holds when the centre of mass of
/// everything above it lies over the supporting face, shrunk by `support_margin`. onTop1 is
/// read when cubeUp1 has settled, before cubeUp2 is released; onTop2 needs cubeUp2 to rest on
/// cubeUp1 and the pair to rest on cubeDown.
///
/// Dropping: the sphere (radius r) lands at its offset plus N(0, landing_noise) per axis. It
/// falls in when its centre lands within R - r of the axis (R: the opening's radius,
/// scalingFactor * d/2); landing on the rim (R - r to R) it falls in with probability
/// rim_catch * clamp((R - r) / r, 0, 1), as a sphere that barely fits tends to bounce off;
/// beyond R it misses. Once in, it bounces out with probability
/// bounce_max * exp(-height / bounce_depth_scale), so shallow containers (the plate) lose more
/// spheres than deep ones.

#include <algorithm>
#include <cmath>
#include <span>
#include <string_view>
#include <vector>

#include "pgm/sim/run.hpp"
#include "pgm/sim/simulator_concept.hpp"

namespace pgm::sim {

class analytic_simulator {
 public:
  static constexpr std::string_view name = "analytic";

  explicit analytic_simulator(const task_definition& task) : physics_(task.physics) {
    if (const auto* s = std::get_if<stacking_physics>(&physics_)) {
      for (std::size_t i = 1; i <= s->cubes; ++i) {
        const auto n = std::to_string(i);
        cubes_.push_back({task.index("xOff" + n), task.index("yOff" + n), task.index("dropOff" + n),
                          task.index("onTop" + n)});
      }
    } else {
      x_ = task.index("xOff");
      y_ = task.index("yOff");
      scale_ = task.index("scalingFactor");
      inside_ = task.index("inside");
    }
  }

  void run(std::span<double> values, random_stream& noise) const {
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

  void stack(const stacking_physics& p, std::span<double> values, random_stream& noise) const {
    const double half = p.cube_size / 2 - p.support_margin;
    // Landing offset of each cube from the one below, and the stack's state so far.
    double below_x = 0;  // landing offset of cube i-1 from cubeDown
    double below_y = 0;
    bool standing = true;
    for (std::size_t i = 0; i < cubes_.size(); ++i) {
      const auto& c = cubes_[i];
      const double sd = p.noise_base + p.noise_per_cm * values[c.drop];
      const double x = values[c.x] + sd * noise.normal();
      const double y = values[c.y] + sd * noise.normal();
      bool holds = standing && std::abs(x) < half && std::abs(y) < half;
      if (i == 1) {
        // The pair's centre of mass over cubeDown: cube 1 at below, cube 2 at below + (x, y).
        holds = holds && std::abs(below_x + x / 2) < half && std::abs(below_y + y / 2) < half;
      }
      // More than two cubes would need every contact's load; the task files stop at two.
      values[c.on_top] = holds ? 1.0 : 0.0;
      standing = holds;
      below_x = x;
      below_y = y;
    }
  }

  void drop(const dropping_physics& p, std::span<double> values, random_stream& noise) const {
    const double s = values[scale_];
    const double radius = s * p.diameter_at_scale_1 / 2;
    const double height = s * p.height_at_scale_1;
    const double x = values[x_] + p.landing_noise * noise.normal();
    const double y = values[y_] + p.landing_noise * noise.normal();
    const double r = p.sphere_diameter / 2;
    const double landing = x * x + y * y;
    const double core = std::max(0.0, radius - r);
    const double rim_catch = p.rim_catch * std::clamp((radius - r) / r, 0.0, 1.0);
    const double u = noise.uniform();
    const bool caught = landing < core * core || (landing < radius * radius && u < rim_catch);
    const bool bounced = noise.uniform() < p.bounce_max * std::exp(-height / p.bounce_depth_scale);
    values[inside_] = caught && !bounced ? 1.0 : 0.0;
  }

  physics_parameters physics_;
  std::vector<cube_columns> cubes_;
  std::size_t x_ = 0, y_ = 0, scale_ = 0, inside_ = 0;
};

static_assert(Simulator<analytic_simulator>);

/// Runs the analytic back-end (what simulate() calls for backend "analytic").
[[nodiscard]] inline dataset simulate_analytic(const task_definition& task, const simulate_options& options) {
  return run_experiments<analytic_simulator>(task, options, 8192);
}

}  // namespace pgm::sim
