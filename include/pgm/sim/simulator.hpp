#pragma once
/// \file
/// `simulate`: runs experiments of a task with a back-end chosen by name and returns the raw
/// data — continuous columns for continuous variables, discrete columns for colours and
/// outcomes (states "0", "1"), in the task file's order. The back-ends are those of the
/// registry (pgm/sim/registry.hpp): "analytic" always, "bullet" when the program links the
/// pgm_bullet plugin, and any a user registers.

#include <string>
#include <vector>

#include "pgm/data/dataset.hpp"
#include "pgm/sim/registry.hpp"
#include "pgm/sim/simulator_concept.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

/// The names of the available back-ends, sorted.
[[nodiscard]] inline std::vector<std::string> backends() { return backend_registry::instance().names(); }

/// Runs `options.rows` experiments of `task` with `options.backend`. Deterministic for a
/// seed whatever the thread count. Throws data_error for an unknown back-end.
[[nodiscard]] inline dataset simulate(const task_definition& task, const simulate_options& options) {
  return backend_registry::instance().at(options.backend)(task, options);
}

}  // namespace pgm::sim
