#pragma once
/// \file
/// `simulate`: runs experiments of a task with a named back-end and returns the raw data —
/// continuous columns for continuous variables, discrete columns for colours and outcomes
/// (states "0", "1"), in the task file's order. Also the `Simulator` concept back-ends model.
///
/// Back-ends are found in a registry: "analytic" is always there; "bullet" is added when the
/// program links the pgm_bullet library (which defines PGM_WITH_BULLET for its users), and a
/// user may register more with register_backend().

#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/sim/analytic.hpp"
#include "pgm/sim/simulator_concept.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

#if defined(PGM_WITH_BULLET)
/// Defined in the pgm_bullet library (plugins/bullet).
dataset simulate_bullet(const task_definition& task, const simulate_options& options);
#endif

using backend_function = std::function<dataset(const task_definition&, const simulate_options&)>;

namespace detail {

struct backend_registry {
  backend_registry() {
    backends.emplace("analytic", &simulate_analytic);
#if defined(PGM_WITH_BULLET)
    backends.emplace("bullet", &simulate_bullet);
#endif
  }
  std::mutex mutex;
  std::map<std::string, backend_function, std::less<>> backends;
};

inline backend_registry& registry() {
  static backend_registry instance;
  return instance;
}

}  // namespace detail

/// Adds (or replaces) a back-end under `name`.
inline void register_backend(std::string name, backend_function run) {
  auto& r = detail::registry();
  const std::lock_guard lock(r.mutex);
  r.backends.insert_or_assign(std::move(name), std::move(run));
}

/// The names of the available back-ends, sorted.
[[nodiscard]] inline std::vector<std::string> backends() {
  auto& r = detail::registry();
  const std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& entry : r.backends) names.push_back(entry.first);
  return names;
}

/// Runs `options.rows` experiments of `task` with `options.backend`. Deterministic for a
/// seed whatever the thread count. Throws data_error for an unknown back-end.
[[nodiscard]] inline dataset simulate(const task_definition& task, const simulate_options& options) {
  backend_function run;
  {
    auto& r = detail::registry();
    const std::lock_guard lock(r.mutex);
    if (const auto it = r.backends.find(options.backend); it != r.backends.end()) run = it->second;
  }
  if (!run) {
    if (options.backend == "bullet") {
      throw data_error("the bullet back-end was not built (configure with -DPGM_BUILD_BULLET=ON and "
                       "libbullet-dev installed, and link pgm_bullet)");
    }
    throw data_error("unknown simulator back-end '" + options.backend +
                     "' (available: " + pgm::detail::join(backends()) + ")");
  }
  return run(task, options);
}

}  // namespace pgm::sim
