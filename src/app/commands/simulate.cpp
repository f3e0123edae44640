// pgm simulate: run experiments of a task with a simulator back-end and write the raw data.

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli/common.hpp"
#include "cli/progress.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/process_group.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task_episodes.hpp"
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
  bool long_form = false;
};

/// Rows simulated and written at a time: memory stays that of one block (a few tens of MB)
/// however many rows are asked for; the data are those of one run (simulate_options::first_row).
constexpr std::size_t block_rows = std::size_t{1} << 18;

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
  // Checked before any work: a task without numbered actions has no steps.
  const auto layout = args.long_form ? std::optional(sim::episode_layout_of(task)) : std::nullopt;
  sim::simulate_options options;
  options.backend = args.backend;
  options.seed = args.seed;
  options.threads = args.threads;
  options.across_processes = true;  // under mpirun, each process simulates a share of each block
  progress_bar bar("simulating");
  std::size_t successes = 0;
  // Every process runs the blocks (their collective steps); process 0 has the data and writes them.
  const auto run_blocks = [&](std::ostream* out) {
    for (std::size_t done = 0; done < args.rows; done += options.rows) {
      options.first_row = done;
      options.rows = std::min(block_rows, args.rows - done);
      options.progress = [&bar, done, rows = args.rows](std::size_t block_done) {
        bar.update(done + block_done, rows);
      };
      const auto data = sim::simulate(task, options);
      if (out == nullptr) continue;
      const auto written = layout ? sim::episodes_of(data, task, *layout, done) : dataset();
      const auto& rows = layout ? written : data;
      if (done == 0) {
        write_csv(rows, *out);
      } else {
        write_csv_rows(rows, *out);
      }
      const auto& success = data.discrete(task.success);
      for (std::size_t row = 0; row < data.rows(); ++row) successes += success.code(row);
    }
  };
  if (processes().rank() != 0) {
    run_blocks(nullptr);
    return;
  }
  pgm::write_file_atomically(
      args.out, [&](std::ostream& out) { run_blocks(&out); },
      [&] {
        bar.finish();
        summary_before_replacing(
            "simulated " + std::to_string(args.rows) + " experiments of " + task.name +
                (layout ? " as episodes of " + std::to_string(layout->steps) + " steps" : std::string()) + " (" +
                args.backend + ", seed " + std::to_string(args.seed) + "): " + task.success + " = 1 in " +
                text::format_short(static_cast<double>(successes) / static_cast<double>(args.rows), 4) + " -> " +
                args.out + "\n",
            args.out)();
      });
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
         "Simulator back-end: " + text::join(sim::backends()) + " (analytic: closed-form; bullet: rigid bodies)")
      ->capture_default_str();
  cmd->add_option("--variant", args->variant,
                  "sim, or reality: the stacking tasks' stand-in for the real robot (not real data)")
      ->check(CLI::IsMember(sim::known_task_variants()))
      ->capture_default_str();
  cmd->add_option("--rows", args->rows,
                  "Number of experiments (written as they are made: memory does not grow with them)")
      ->check(whole_number(1, 1'000'000'000))
      ->required();
  cmd->add_option("--seed", args->seed, "Random seed; the same seed gives the same data for any --threads")
      ->check(whole_number(0, UINT64_MAX))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_option("--tasks-dir", args->tasks_dir,
                  "Directory of task files (default: $PGM_TASKS_DIR, then the source tree's tasks/)");
  cmd->add_option("--out", args->out, "Output CSV file (written atomically)")->required();
  cmd->add_flag("--long-form", args->long_form,
                "Write each experiment as an episode of the task's actions, one row per step (columns episode, t and "
                "the numbered variables without their number: xOff1, xOff2 become xOff at t = 0, 1), as pgm fit "
                "--dynamic reads it; for tasks of numbered actions (the stacking tasks)");
  cmd->callback([args] { run_simulate(*args); });
}

}  // namespace pgm::cli
