#pragma once
/// \file
/// The Bullet back-end (plugin pgm_bullet): rigid-body simulation of the task, experiments
/// spread over threads, one physics world per thread that is emptied and reset before each
/// experiment. Linking the pgm_bullet object library registers it as "bullet" for
/// pgm::sim::simulate(); this header is only for calling it directly.

#include <array>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "pgm/data/dataset.hpp"
#include "pgm/sim/random.hpp"
#include "pgm/sim/simulator_concept.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

/// Runs `options.rows` experiments of `task` in Bullet (options.backend is ignored).
dataset simulate_bullet(const task_definition& task, const simulate_options& options);

/// The Bullet back-end as a Simulator: one world, reused for every experiment it runs. An
/// experiment's outcome depends only on its inputs and noise, not on the experiments run
/// before it.
class bullet_simulator {
 public:
  static constexpr std::string_view name = "bullet";

  explicit bullet_simulator(const task_definition& task);
  ~bullet_simulator();
  bullet_simulator(bullet_simulator&&) noexcept;
  bullet_simulator& operator=(bullet_simulator&&) noexcept;

  /// Runs one experiment: reads the inputs in `values` (task order), writes the outcomes.
  void run(std::span<double> values, random_stream& noise);

  /// Where the last experiment left its moving bodies (x, y, z, then the rotation as a
  /// quaternion x, y, z, w): the cubes placed, in order, or the sphere.
  [[nodiscard]] std::vector<std::array<double, 7>> final_poses() const;

 private:
  struct model;
  std::unique_ptr<model> model_;
};

}  // namespace pgm::sim
