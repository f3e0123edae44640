// pgm simulate: run experiments of a task with a simulator back-end and write the raw data.

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "cli/common.hpp"
#include "cli/progress.hpp"
#include "pgm/core/error.hpp"
#include "pgm/data/csv.hpp"
#include "pgm/detail/process_group.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task_lookup.hpp"
#include "pgm/sim/task_variant.hpp"

namespace pgm::cli {
namespace {

struct simulate_arguments {
  std::string task;
  std::string backend = "analytic";
  std::string variant = "sim";
  std::size_t rows = 0;
  std::uint64_t seed = 0;
  unsigned threads = 0;
  std::string tasks_dir;
  std::string out;
};

void run_simulate(const simulate_arguments& args) {
  require_extension(args.out, {".csv"});
  if (args.rows == 0) throw error("--rows must be positive");
  std::vector<std::filesystem::path> directories;
  if (!args.tasks_dir.empty()) {
    directories.emplace_back(args.tasks_dir);
  } else {
    directories = sim::default_task_directories();
  }
  const auto task = sim::load_task_variant(args.task, args.variant, directories);
  sim::simulate_options options;
  options.backend = args.backend;
  options.rows = args.rows;
  options.seed = args.seed;
  options.threads = args.threads;
  options.across_processes = true;  // under mpirun, each process simulates a block of rows
  progress_bar bar("simulating");
  options.progress = [&bar, rows = args.rows](std::size_t done) { bar.update(done, rows); };
  const auto data = sim::simulate(task, options);
  bar.finish();
  if (detail::processes().rank() != 0) return;  // process 0 has the data and writes it
  write_csv(data, std::filesystem::path(args.out));
  const auto& success = data.discrete(task.success);
  std::size_t successes = 0;
  for (std::size_t row = 0; row < data.rows(); ++row) successes += success.code(row);
  std::cout << "simulated " << data.rows() << " experiments of " << task.name << " (" << args.backend << ", seed "
            << args.seed << "): " << task.success << " = 1 in "
            << detail::format_short(static_cast<double>(successes) / static_cast<double>(data.rows()), 4) << " -> "
            << args.out << '\n';
  if (task.variant == "reality") note("'" + task.name + "' is a stand-in for the real robot, not real data");
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto args = std::make_shared<simulate_arguments>();
  auto* cmd = app.add_subcommand("simulate", "Run experiments of a task in a simulator and write the raw data as CSV");
  cmd->add_option("--task", args->task, "Task name, e.g. 1-stack, 2-stack, drop-plate, drop-bowl, drop-glass")
      ->required();
  // The back-ends this build has registered (analytic always; bullet and users' when linked).
  cmd->add_option(
         "--backend", args->backend,
         "Simulator back-end: " + detail::join(sim::backends()) + " (analytic: closed-form; bullet: rigid bodies)")
      ->capture_default_str();
  cmd->add_option("--variant", args->variant,
                  "sim, or reality: the stacking tasks' stand-in for the real robot (not real data)")
      ->check(CLI::IsMember({"sim", "reality"}))
      ->capture_default_str();
  cmd->add_option("--rows", args->rows, "Number of experiments")->check(whole_number(1, 1'000'000'000))->required();
  cmd->add_option("--seed", args->seed, "Random seed; the same seed gives the same data for any --threads")
      ->check(whole_number(0, UINT64_MAX))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_option("--tasks-dir", args->tasks_dir,
                  "Directory of task files (default: $PGM_TASKS_DIR, then the source tree's tasks/)");
  cmd->add_option("--out", args->out, "Output CSV file (written atomically)")->required();
  cmd->callback([args] { run_simulate(*args); });
}

}  // namespace pgm::cli
