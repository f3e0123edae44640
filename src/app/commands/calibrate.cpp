// pgm calibrate: fit the analytic model's constants to Bullet's experiments, or (--check) print
// how closely the two back-ends agree, cell by cell.

#include "pgm/sim/calibrate.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "cli/progress.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/text.hpp"
#include "pgm/sim/agreement.hpp"
#include "pgm/sim/task.hpp"
#include "pgm/sim/task_lookup.hpp"

namespace pgm::cli {
namespace {

struct calibrate_arguments {
  std::vector<std::string> tasks;
  std::string backend = "bullet";
  std::size_t rows = 20'000;
  std::size_t analytic_rows = 200'000;
  std::uint64_t seed = 1;
  unsigned threads = 0;
  std::string tasks_dir;
  std::string out;
  bool check = false;
};

std::string fixed(double value, int decimals) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string interval(const sim::agreement_axis& axis, std::size_t third) {
  return "[" + text::format_short(axis.edge(third), 3) + ", " + text::format_short(axis.edge(third + 1), 3) +
         (third == 2 ? "]" : ")");
}

void print_table(const sim::agreement_table& t, std::ostream& out) {
  out << t.task << ": " << t.outcome << ", " << t.reference_rows << " " << t.reference << " rows ("
      << fixed(t.reference_seconds, 1) << " s) vs " << t.analytic_rows << " analytic rows ("
      << fixed(t.analytic_seconds, 1) << " s)\n";
  for (const auto& axis : t.axes) {
    std::string name = axis.variable;
    name.resize(std::max<std::size_t>(name.size(), 16), ' ');
    out << "  " << name;
  }
  out << "  " << t.reference << " rows  " << t.reference << "  analytic  |diff|\n";
  for (const auto& cell : t.cells) {
    for (std::size_t i = 0; i < t.axes.size(); ++i) {
      auto text = interval(t.axes[i], cell.third[i]);
      text.resize(std::max<std::size_t>(std::max(text.size(), t.axes[i].variable.size()), 16), ' ');
      out << "  " << text;
    }
    char line[96];
    std::snprintf(line, sizeof line, "  %11zu  %6.3f  %8.3f  %6.3f\n", cell.reference_rows, cell.reference_rate,
                  cell.analytic_rate, std::abs(cell.reference_rate - cell.analytic_rate));
    out << line;
  }
  out << "mean |diff| over " << t.cells.size() << " cells: " << fixed(t.mean_abs_difference, 3)
      << " (sampling noise alone: " << fixed(t.noise_mean_abs_difference, 3) << "); overall: " << t.reference << " "
      << fixed(t.reference_rate, 3) << ", analytic " << fixed(t.analytic_rate, 3) << " (difference "
      << fixed(t.analytic_rate - t.reference_rate, 3) << " ± " << fixed(t.overall_standard_error, 3) << ")\n";
}

std::vector<std::filesystem::path> task_directories(const calibrate_arguments& args) {
  if (!args.tasks_dir.empty()) return {args.tasks_dir};
  return sim::default_task_directories();
}

void run_check(const calibrate_arguments& args) {
  std::vector<sim::task_definition> tasks;
  for (const auto& name : args.tasks) tasks.push_back(sim::load_task(name, task_directories(args)));
  // Containers of dropping tasks, with both back-ends' overall rates, for the ordering.
  struct ranked {
    std::string container;
    double reference, analytic;
  };
  std::vector<ranked> containers;
  for (const auto& task : tasks) {
    sim::agreement_options options;
    options.reference = args.backend;
    options.reference_rows = args.rows;
    options.analytic_rows = args.analytic_rows;
    options.seed = args.seed;
    options.threads = args.threads;
    progress_bar bar("simulating " + task.name + " (" + args.backend + ")");
    options.progress = [&bar, rows = args.rows](std::size_t done) { bar.update(done, rows); };
    const auto table = sim::agreement(task, options);
    bar.finish();
    print_table(table, std::cout);
    if (const auto* d = std::get_if<sim::dropping_physics>(&task.physics)) {
      containers.push_back({d->container, table.reference_rate, table.analytic_rate});
    }
  }
  if (containers.size() < 2) return;
  auto order = [&](double ranked::*rate) {
    auto sorted = containers;
    std::stable_sort(sorted.begin(), sorted.end(), [&](const ranked& a, const ranked& b) { return a.*rate > b.*rate; });
    std::string text;
    for (const auto& c : sorted) text += (text.empty() ? "" : " > ") + c.container;
    return text;
  };
  const auto reference = order(&ranked::reference);
  const auto analytic = order(&ranked::analytic);
  std::cout << "ordering by success: " << args.backend << " " << reference << "; analytic " << analytic
            << (reference == analytic ? " (the same)" : " (different)") << '\n';
}

void run_fit(const calibrate_arguments& args) {
  if (args.tasks.size() != 1) throw error("give one --task to calibrate (several only with --check)");
  if (!args.out.empty()) {
    require_extension(args.out, {".json"});
    pgm::check_output_path(args.out);
  }
  const auto task = sim::load_task(args.tasks.front(), task_directories(args));
  sim::calibration_options options;
  options.reference = args.backend;
  options.rows = args.rows;
  options.seed = args.seed;
  options.threads = args.threads;
  progress_bar bar("simulating " + task.name + " (" + args.backend + ")");
  options.progress = [&bar, rows = args.rows](std::size_t done) { bar.update(done, rows); };
  const auto result = sim::calibrate(task, options);
  bar.finish();
  const auto text = sim::calibrated_task_text(pgm::read_file(task.source), result);
  // The summary goes to stdout with --out, else to stderr so that stdout is the task file.
  std::ostringstream summary;
  summary << "calibrated " << task.name << " on " << result.rows << " " << result.reference << " experiments (seed "
          << result.seed << "): simulated in " << fixed(result.simulate_seconds, 1) << " s, fitted in "
          << fixed(result.fit_seconds, 1) << " s\n";
  summary << "log-likelihood: " << fixed(result.log_likelihood_before, 1) << " before, "
          << fixed(result.log_likelihood_after, 1) << " after (per experiment "
          << fixed(result.log_likelihood_before / static_cast<double>(result.rows), 4) << " -> "
          << fixed(result.log_likelihood_after / static_cast<double>(result.rows), 4) << ")\n";
  for (const auto& c : result.constants) {
    auto name = "physics/analytic/" + c.name;
    name.resize(std::max<std::size_t>(name.size(), 40), ' ');
    summary << "  " << name << text::format_short(c.before, 4) << " -> " << text::format_short(c.after, 4) << '\n';
  }
  if (args.out.empty()) {
    std::cerr << summary.str();
    std::cout << text;
  } else {
    pgm::write_file_atomically(
        args.out, [&](std::ostream& out) { out << text; },
        summary_before_replacing(summary.str() + "wrote " + args.out + "\n", args.out));
  }
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto args = std::make_shared<calibrate_arguments>();
  auto* cmd = app.add_subcommand(
      "calibrate",
      "Fit the analytic model's constants to Bullet's experiments by maximum likelihood, or with --check print how "
      "closely the two back-ends agree");
  cmd->add_option("--task", args->tasks, "Task name (several with --check), e.g. 2-stack, drop-glass")->required();
  cmd->add_option("--rows", args->rows,
                  "Experiments simulated on the reference back-end (a fit keeps them all in memory: at most " +
                      std::to_string(sim::max_calibration_rows) + "; with --check they are counted as they come)")
      ->check(whole_number(1, 1'000'000'000))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Random seed of the experiments")
      ->check(whole_number(0, UINT64_MAX))
      ->capture_default_str();
  cmd->add_option("--out", args->out,
                  "Write the task file with the fitted constants here (.json, atomically); without it the task file "
                  "is printed");
  cmd->add_flag("--check", args->check,
                "Print the agreement table: success rates per cell of a 3 x 3 (x 3) grid over the offsets' (and "
                "scalingFactor's) range, both back-ends");
  cmd->add_option("--analytic-rows", args->analytic_rows, "With --check: experiments on the analytic back-end")
      ->check(whole_number(1, 1'000'000'000))
      ->capture_default_str();
  cmd->add_option("--backend", args->backend, "Reference back-end")->capture_default_str();
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(whole_number(0, 1024))
      ->capture_default_str();
  cmd->add_option("--tasks-dir", args->tasks_dir,
                  "Directory of task files (default: $PGM_TASKS_DIR, then the source tree's tasks/)");
  cmd->callback([args] {
    if (args->check) {
      if (!args->out.empty()) throw error("--out writes calibrated constants; --check only prints a table");
      run_check(*args);
    } else {
      run_fit(*args);
    }
  });
}

}  // namespace pgm::cli
