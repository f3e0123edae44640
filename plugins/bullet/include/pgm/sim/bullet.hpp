#pragma once
/// \file
/// The Bullet back-end (plugin pgm_bullet): rigid-body simulation of the task, one
/// btDiscreteDynamicsWorld per experiment, experiments spread over threads. Linking the
/// pgm_bullet object library registers it as "bullet" for pgm::sim::simulate(); this header
/// is only for calling it directly.

#include "pgm/data/dataset.hpp"
#include "pgm/sim/simulator_concept.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

/// Runs `options.rows` experiments of `task` in Bullet (options.backend is ignored).
dataset simulate_bullet(const task_definition& task, const simulate_options& options);

}  // namespace pgm::sim
