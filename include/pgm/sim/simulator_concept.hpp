#pragma once
/// \file
/// The `Simulator` concept and the options of a simulation run. A simulator is built once
/// per thread from a task and then runs one experiment at a time: it reads the sampled
/// inputs and writes the outcomes. Sampling the inputs, seeding, threading and building the
/// data set are the driver's job (pgm/sim/run.hpp), so a back-end is only physics.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "pgm/sim/random.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

namespace detail {

/// A simulator is made from a task definition (one per thread; it may hold a physics world).
template <class S>
concept constructible_from_task = std::constructible_from<S, const task_definition&>;

/// `run(values, noise)`: `values` holds one number per task variable in the task's order
/// (categorical states as indices); run writes 0 or 1 into every outcome, drawing any noise
/// from `noise` only.
template <class S>
concept runs_one_experiment = requires(S& s, std::span<double> values, random_stream& noise) {
  s.run(values, noise);
};

/// `S::name`: the back-end's name as the user selects it ("analytic").
template <class S>
concept has_backend_name = requires {
  { S::name } -> std::convertible_to<std::string_view>;
};

}  // namespace detail

template <class S>
concept Simulator = detail::constructible_from_task<S> && detail::runs_one_experiment<S> && detail::has_backend_name<S>;

struct simulate_options {
  /// "analytic" (closed-form, header-only) or "bullet" (rigid bodies, when built).
  std::string backend = "analytic";
  std::size_t rows = 0;
  /// Experiment i draws from streams keyed by (seed, i): the same seed gives the same data
  /// whatever `threads` is.
  std::uint64_t seed = 0;
  /// The index of the first experiment: the run makes experiments first_row, …, first_row +
  /// rows − 1 of its seed, so that a long run made in blocks (`pgm simulate` writes its rows as
  /// they come) gives the same data as in one piece.
  std::uint64_t first_row = 0;
  /// Worker threads; 0 uses every hardware thread.
  unsigned threads = 0;
  /// Called now and then with the number of experiments finished so far: one call at a time
  /// (from whichever worker thread finished a chunk), increasing, the last with `rows`. May be
  /// empty.
  std::function<void(std::size_t done)> progress;
  /// Spread the rows over the processes pgm runs in (pgm::processes(), several under
  /// mpirun): each simulates its block of rows and process 0 gets the whole data set, the
  /// others an empty one. The data are the same for any number of processes.
  bool across_processes = false;
};

}  // namespace pgm::sim
