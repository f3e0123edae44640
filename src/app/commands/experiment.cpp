// pgm experiment: reproduce the paper's transfer scenarios (Table II) on simulated data —
// every point as a tidy CSV, the mean and spread per point, and one plot per target task.

#include <filesystem>
#include <iostream>
#include <optional>

#include "cli/common.hpp"
#include "cli/external_programs.hpp"
#include "cli/move_cost_options.hpp"
#include "cli/progress.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/eval/cached_source.hpp"
#include "pgm/eval/disk_cache.hpp"
#include "pgm/eval/run_scenarios.hpp"
#include "pgm/eval/scenario_catalog.hpp"
#include "pgm/eval/simulated_source.hpp"
#include "pgm/sim/task_lookup.hpp"

namespace pgm::cli {
namespace {

struct experiment_arguments {
  std::string scenario = "all";
  std::string backend = "analytic";
  std::size_t repetitions = 0;
  std::uint64_t seed = 1;
  unsigned threads = 0;
  std::string distance = "steps";
  bool no_automatic = false;
  std::string tasks_dir;
  std::string out = "results";
  std::string data_cache;
  move_cost_arguments utility;
};

void run_experiment_command(const experiment_arguments& args) {
  const auto task_folders =
      args.tasks_dir.empty() ? sim::default_task_directories() : std::vector<std::filesystem::path>{args.tasks_dir};
  const auto scenarios = select_scenarios(args.scenario, find_scenario_folder(task_folders));
  if (args.out.empty()) throw error("--out needs a folder");
  run_scenarios_options options;
  options.experiment.seed = args.seed;
  options.experiment.repetitions = args.repetitions;
  options.experiment.threads = args.threads;
  options.experiment.automatic_lines = !args.no_automatic;
  options.experiment.across_processes = true;  // under mpirun, the jobs are split over the processes
  options.experiment.prevention.metric = parse_distance(args.distance);
  options.experiment.costs = move_costs_of(args.utility);
  // One bar per scenario, ended when its last repetition is done so that the next notes start a line.
  std::optional<progress_bar> bar;
  options.progress = [&bar](const scenario& s, std::size_t done, std::size_t total) {
    if (!bar) bar.emplace(s.name);
    bar->update(done, total);
    if (done == total) bar.reset();
  };
  options.note = [](const std::string& text) { note(text); };
  options.render_plots = gnuplot_renderer(options.note);
  options.headline = [](const std::string& line) { std::cout << line << '\n'; };
  // The simulation phase: one bar per data set, with the time left.
  std::optional<progress_bar> simulating;
  auto source = simulated_source({task_folders, args.backend, args.threads,
                                  [&simulating](const std::string& task, std::size_t done, std::size_t total) {
                                    if (!simulating) simulating.emplace("simulating " + task);
                                    simulating->update(done, total);
                                    if (done == total) simulating.reset();
                                  }});
  if (!args.data_cache.empty()) source = disk_cached(std::move(source), {args.data_cache, args.backend, options.note});
  const auto files = run_scenarios(scenarios, cached(std::move(source)), args.out, options);
  std::cout << files.points << " points -> " << files.points_csv.string() << ", summary.csv"
            << (files.plots_rendered ? " and plots" : "") << '\n';
}

}  // namespace

void add_experiment_command(CLI::App& app) {
  auto args = std::make_shared<experiment_arguments>();
  auto* cmd = app.add_subcommand("experiment", "Reproduce the paper's transfer scenarios: metrics as CSV and plots");
  cmd->add_option("--scenario", args->scenario,
                  "2-stack-sim, 2-stack-reality, 2-stack-sim-to-real, sphere-dropping, stack-to-drop (files in "
                  "tasks/scenarios), or all")
      ->capture_default_str();
  cmd->add_option("--backend", args->backend, "Simulator: analytic or bullet")->capture_default_str();
  cmd->add_option("--reps", args->repetitions, "Repetitions (default: the scenario's, 20)")
      ->check(whole_number(1, max_repetitions));
  cmd->add_option("--seed", args->seed, "Seed of the data and the splits")
      ->check(whole_number(0, UINT64_MAX))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_option("--distance", args->distance, "Failure prevention's distance: steps (bins) or units")
      ->check(CLI::IsMember(known_distances()))
      ->capture_default_str();
  add_move_cost_options(*cmd, args->utility,
                        "Also prevent by the move of highest expected utility (success worth this much, failure 0, "
                        "less what moving costs) and cost both rules' moves: the metrics prevention_cost, "
                        "utility_prevention and utility_prevention_cost (docs/decide.md)");
  cmd->add_flag("--no-auto", args->no_automatic, "Leave out the lines of w = auto and of the proposed map");
  cmd->add_option("--tasks-dir", args->tasks_dir,
                  "Folder with the task files and scenarios/ (default: the installed tasks)");
  cmd->add_option("--out", args->out, "Folder for points.csv, summary.csv and the plots")->capture_default_str();
  cmd->add_option("--data-cache", args->data_cache,
                  "Folder keeping each task's simulated data between runs (one file per task, back-end, seed and "
                  "rows); without it nothing but the results is written");
  cmd->callback([args] { run_experiment_command(*args); });
}

}  // namespace pgm::cli
