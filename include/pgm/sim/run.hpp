#pragma once
/// \file
/// `run_experiments`: the driver every back-end shares. It samples each experiment's inputs
/// from the task's distributions, lets a Simulator compute the outcomes, and assembles the
/// columns. Experiment i always uses the streams keyed by (seed, i), and rows are handed out
/// in chunks from a shared counter, so the result is byte-identical for any thread count.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/sim/simulator_concept.hpp"

namespace pgm::sim {

/// Samples the inputs of experiment `index` into `values` (outcomes are left at 0).
inline void sample_inputs(const task_definition& task, std::uint64_t seed, std::uint64_t index,
                          std::span<double> values) {
  random_stream inputs(seed, index, stream_purpose::inputs);
  for (std::size_t k = 0; k < task.variables.size(); ++k) {
    const auto& v = task.variables[k];
    values[k] = v.kind == variable_kind::outcome ? 0.0 : v.sampling.sample(inputs);
  }
}

/// Runs `options.rows` experiments of `task` with simulator S, `chunk` rows at a time.
template <Simulator S>
[[nodiscard]] dataset run_experiments(const task_definition& task, const simulate_options& options,
                                      std::size_t chunk = 4096) {
  const std::size_t rows = options.rows;
  const std::size_t width = task.variables.size();
  chunk = std::max<std::size_t>(1, chunk);
  std::vector<std::vector<double>> columns(width, std::vector<double>(rows));

  const std::size_t chunks = (rows + chunk - 1) / chunk;
  unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(threads, chunks)));

  std::atomic<std::size_t> next_chunk{0};
  std::atomic<std::size_t> done{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  // Each worker owns one simulator (which may hold a physics world) and writes only its rows.
  auto work = [&](bool report) {
    try {
      S simulator(task);
      std::vector<double> values(width);
      for (;;) {
        const auto c = next_chunk.fetch_add(1);
        if (c >= chunks) break;
        const std::size_t begin = c * chunk;
        const std::size_t end = std::min(rows, begin + chunk);
        for (std::size_t row = begin; row < end; ++row) {
          sample_inputs(task, options.seed, row, values);
          random_stream noise(options.seed, row, stream_purpose::noise);
          simulator.run(std::span<double>(values), noise);
          for (std::size_t k = 0; k < width; ++k) columns[k][row] = values[k];
        }
        const auto finished = done.fetch_add(end - begin) + (end - begin);
        if (report && options.progress) options.progress(finished);
      }
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next_chunk.store(chunks);  // stop the others early
    }
  };
  {
    std::vector<std::jthread> helpers;
    for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work, false);
    work(true);  // the calling thread works too, and is the only one that reports progress
  }
  if (failure) std::rethrow_exception(failure);
  if (options.progress) options.progress(rows);

  dataset result(task.name + " (" + std::string(S::name) + ", seed " + std::to_string(options.seed) + ")");
  for (std::size_t k = 0; k < width; ++k) {
    const auto& v = task.variables[k];
    if (v.kind == variable_kind::continuous) {
      result.add(continuous_column(v.name, std::move(columns[k]), v.tags));
    } else {
      std::vector<std::uint32_t> codes(rows);
      for (std::size_t row = 0; row < rows; ++row) codes[row] = static_cast<std::uint32_t>(columns[k][row]);
      result.add(discrete_column(v.as_variable(), codes));
    }
  }
  return result;
}

}  // namespace pgm::sim
