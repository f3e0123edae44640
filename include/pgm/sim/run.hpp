#pragma once
/// \file
/// `run_experiments`: the driver every back-end shares. It samples each experiment's inputs
/// from the task's distributions, lets a Simulator compute the outcomes, and assembles the
/// columns. Experiment i always uses the streams keyed by (seed, first_row + i) and writes row i, and rows
/// are spread over threads in chunks (pgm/detail/parallel_for.hpp), so the result is
/// byte-identical for any thread count. With `across_processes`, each process runs its block of
/// rows and process 0 gathers them (pgm::detail::parallel_for_on, gather_slots): the same data
/// for any number of processes.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/sim/simulator_concept.hpp"

namespace pgm::sim {

/// Samples the inputs of experiment `index` into `values` (outcomes are left at 0).
PGM_DECL void sample_inputs(const task_definition& task, std::uint64_t seed, std::uint64_t index,
                            std::span<double> values);

/// Runs `options.rows` experiments of `task` with simulator S, `chunk` rows at a time.
template <Simulator S>
[[nodiscard]] dataset run_experiments(const task_definition& task, const simulate_options& options,
                                      std::size_t chunk = 4096) {
  const std::size_t rows = options.rows;
  const std::size_t width = task.variables.size();
  std::vector<std::vector<double>> columns(width, std::vector<double>(rows));

  // Each thread owns one simulator (which may hold a physics world) and writes only its rows.
  struct worker {
    std::unique_ptr<S> simulator;  // a simulator need not be movable
    std::vector<double> values;
  };
  pgm::detail::parallel_options parallel{.threads = options.threads, .chunk = chunk};
  parallel.progress = options.progress;
  auto& group = options.across_processes ? pgm::processes() : pgm::lone_process();
  if (options.progress && group.size() > 1) {
    // This process's share stands for the whole: its progress, scaled to all rows.
    const auto share = pgm::detail::process_share{group.rank(), group.size()}.of(rows).size();
    parallel.progress = [&options, share, rows](std::size_t done) {
      options.progress(done == share ? rows : share ? done * rows / share : rows);
    };
  }
  static_cast<void>(pgm::detail::parallel_for_on(
      group, rows, parallel,
      [&] {
        return worker{std::make_unique<S>(task), std::vector<double>(width)};
      },
      [&](worker& w, pgm::detail::item_range items) {
        for (std::size_t row = items.begin; row < items.end; ++row) {
          sample_inputs(task, options.seed, options.first_row + row, w.values);
          random_stream noise(options.seed, options.first_row + row, stream_purpose::noise);
          w.simulator->run(std::span<double>(w.values), noise);
          for (std::size_t k = 0; k < width; ++k) columns[k][row] = w.values[k];
        }
      }));
  pgm::detail::gather_slots(
      group, rows,
      [&](pgm::detail::byte_writer& out, std::size_t row) {
        for (std::size_t k = 0; k < width; ++k) out.put(columns[k][row]);
      },
      [&](pgm::detail::byte_reader& in, std::size_t row) {
        for (std::size_t k = 0; k < width; ++k) columns[k][row] = in.get<double>();
      });
  const std::size_t kept = group.rank() == 0 ? rows : 0;
  for (auto& column : columns) column.resize(kept);

  dataset result(task.name + " (" + std::string(S::name) + ", seed " + std::to_string(options.seed) + ")");
  for (std::size_t k = 0; k < width; ++k) {
    const auto& v = task.variables[k];
    if (v.kind == variable_kind::continuous) {
      result.add(continuous_column(v.name, std::move(columns[k]), v.tags));
    } else {
      std::vector<std::uint32_t> codes(kept);
      for (std::size_t row = 0; row < kept; ++row) codes[row] = static_cast<std::uint32_t>(columns[k][row]);
      result.add(discrete_column(v.as_variable(), codes));
    }
  }
  return result;
}

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/run.ipp"
#endif
