#pragma once
/// \file
/// Simulator back-ends by name, for `simulate()` and the program's `--backend`. "analytic" is
/// built in; any other back-end — Bullet's, or a user's — joins with one line in its own
/// translation unit:
///
///     static const pgm::sim::register_simulator<my_simulator> registered;  // models Simulator
///     static const pgm::sim::register_backend registered("mine", &simulate_mine);  // own loop
///
/// The translation unit must be linked as an object file (an OBJECT library, or a source of
/// the program itself), not from a static library, whose unreferenced objects the linker
/// drops.

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/named_registry.hpp"
#include "pgm/sim/analytic.hpp"
#include "pgm/sim/run.hpp"
#include "pgm/sim/simulator_concept.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

/// Runs `options.rows` experiments of a task; `options.backend` is already resolved.
using backend_function = std::function<dataset(const task_definition&, const simulate_options&)>;

class backend_registry {
 public:
  /// The program-wide registry, holding "analytic" from the start.
  [[nodiscard]] static backend_registry& instance() {
    static backend_registry registry = [] {
      backend_registry r;
      r.add(std::string(analytic_simulator::name), &simulate_analytic);
      return r;
    }();
    return registry;
  }

  /// Adds a back-end; an empty name, a name taken already or an empty function is a model_error.
  void add(std::string name, backend_function run) {
    if (!run) throw model_error("the simulator back-end '" + name + "' has no function to run");
    backends_.add(std::move(name), std::move(run));
  }

  /// The back-end of that name, or a data_error listing the available ones (and, for
  /// "bullet", how to build it).
  [[nodiscard]] PGM_DECL backend_function at(std::string_view name) const;

  [[nodiscard]] bool contains(std::string_view name) const { return backends_.find(name).has_value(); }

  /// The names, sorted.
  [[nodiscard]] std::vector<std::string> names() const { return backends_.names(); }

 private:
  pgm::detail::named_registry<backend_function> backends_{"simulator back-end"};
};

/// Registers the Simulator S under `S::name` when the program starts:
/// `static const register_simulator<S> registered;`. The shared driver (run_experiments)
/// samples the inputs, seeds, threads and builds the data set; `chunk` experiments go to a
/// thread at a time (small for slow physics, so that threads finish together).
template <Simulator S>
struct register_simulator {
  explicit register_simulator(std::size_t chunk = 4096) {
    backend_registry::instance().add(std::string(S::name),
                                     [chunk](const task_definition& task, const simulate_options& options) {
                                       return run_experiments<S>(task, options, chunk);
                                     });
  }
};

/// Registers a back-end that drives its own loop, as a function, when the program starts:
/// `static const register_backend registered("mine", &simulate_mine);`. Called as a
/// function it registers at once.
struct register_backend {
  register_backend(std::string name, backend_function run) {
    backend_registry::instance().add(std::move(name), std::move(run));
  }
};

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/registry.ipp"
#endif
