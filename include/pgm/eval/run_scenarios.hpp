#pragma once
/// \file
/// The main job in one call: run each scenario's protocol (pgm::run_experiment) on a task
/// source and write the results into a folder (pgm::report_writer): points.csv, summary.csv,
/// one plot per target task, and the headline numbers. `pgm experiment` is this call with
/// pgm::select_scenarios and pgm::cached(pgm::simulated_source(…)).

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/process_group.hpp"
#include "pgm/eval/experiment.hpp"
#include "pgm/eval/report_writer.hpp"
#include "pgm/eval/scenario.hpp"

namespace pgm {

struct run_scenarios_options {
  /// The protocol's options (seed, repetitions, threads, extra lines, prevention); its
  /// `progress` and `note` are replaced by the ones below.
  experiment_options experiment;
  /// Renders each plot script (pgm::plot_renderer); without one only the scripts are written.
  plot_renderer render_plots;
  /// Repetitions finished of the scenario running.
  std::function<void(const scenario&, std::size_t done, std::size_t total)> progress;
  /// Notes of the protocol ("<scenario>: …") and of the writer.
  std::function<void(const std::string&)> note;
  /// Each target's headline line, once its scenario is done.
  std::function<void(const std::string&)> headline;
};

/// One scenario's points by the protocol (pgm::run_experiment); an error is prefixed with the
/// scenario's file.
[[nodiscard]] PGM_DECL std::vector<experiment_point> run_scenario(const scenario& s, const task_source& source,
                                                                  const experiment_options& options);

/// Runs the scenarios in order into `folder`. The folder is checked before any work and made
/// once the first scenario is done; an error in a scenario is prefixed with its file.
/// With `experiment.across_processes`, the jobs are split over the processes and process 0
/// alone writes (the others return empty report_files).
PGM_DECL report_files run_scenarios(const std::vector<scenario>& scenarios, const task_source& source,
                                    const std::filesystem::path& folder, const run_scenarios_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/run_scenarios.ipp"
#endif
