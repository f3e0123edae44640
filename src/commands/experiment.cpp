// pgm experiment: reproduce the paper's transfer scenarios (Table II) on simulated data —
// every point as a tidy CSV, the mean and spread per point, and one plot per target task.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

#include "cli/common.hpp"
#include "cli/progress.hpp"
#include "pgm/core/error.hpp"
#include "pgm/detail/file.hpp"
#include "pgm/eval/experiment.hpp"
#include "pgm/sim/simulator.hpp"
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
};

std::filesystem::path scenarios_directory(const std::vector<std::filesystem::path>& task_dirs) {
  for (const auto& dir : task_dirs) {
    if (std::filesystem::is_directory(dir / "scenarios")) return dir / "scenarios";
  }
  throw io_error("no scenarios folder under the task folders (" + detail::list_for_message([&] {
                   std::vector<std::string> names;
                   for (const auto& d : task_dirs) names.push_back(d.string());
                   return names;
                 }()) + "); give --tasks-dir");
}

std::vector<scenario> selected_scenarios(const std::string& name, const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  // One scenario is read from its own file, so that a broken file elsewhere does not stop it.
  if (name != "all" && std::filesystem::exists(dir / (name + ".json"))) {
    auto s = load_scenario(dir / (name + ".json"));
    if (s.name == name) return {s};
  }
  // The paper's order.
  const std::vector<std::string> paper{"2-stack-sim", "2-stack-reality", "2-stack-sim-to-real", "sphere-dropping", "stack-to-drop"};
  std::vector<scenario> all;
  for (const auto& f : files) all.push_back(load_scenario(f));
  std::stable_sort(all.begin(), all.end(), [&](const scenario& a, const scenario& b) {
    auto rank = [&](const std::string& n) { return std::find(paper.begin(), paper.end(), n) - paper.begin(); };
    return rank(a.name) < rank(b.name);
  });
  if (name == "all") return all;
  std::vector<std::string> known;
  for (auto& s : all) {
    if (s.name == name) return {s};
    known.push_back(s.name);
  }
  throw error("unknown scenario '" + name + "'; known: " + detail::join(known) + ", all");
}

/// Simulated data, kept for the run so that scenarios sharing a task and size share its data.
class simulated_source {
 public:
  simulated_source(std::vector<std::filesystem::path> dirs, std::string backend, unsigned threads)
      : dirs_(std::move(dirs)), backend_(std::move(backend)), threads_(threads) {}

  task_source source() {
    return {[this](const std::string& task, std::size_t rows, std::uint64_t seed) { return data(task, rows, seed); },
            [this](const std::string& task, const std::string& node) { return facts(task, node); }};
  }

 private:
  const sim::task_definition& task(const std::string& name) {
    const std::lock_guard lock(mutex_);
    auto it = tasks_.find(name);
    if (it == tasks_.end()) it = tasks_.emplace(name, sim::load_task(name, dirs_)).first;
    return it->second;
  }
  dataset data(const std::string& name, std::size_t rows, std::uint64_t seed) {
    const auto key = name + "/" + std::to_string(rows) + "/" + std::to_string(seed);
    {
      const std::lock_guard lock(mutex_);
      if (const auto it = data_.find(key); it != data_.end()) return it->second;
    }
    sim::simulate_options options;
    options.backend = backend_;
    options.rows = rows;
    options.seed = seed;
    options.threads = threads_;
    auto result = sim::simulate(task(name), options);
    const std::lock_guard lock(mutex_);
    return data_.emplace(key, std::move(result)).first->second;
  }
  task_facts facts(const std::string& name, const std::string& node) {
    const auto& t = task(name);
    task_facts f;
    if (!t.contains(node)) throw data_error("task '" + name + "' has no variable '" + node + "'");
    for (const auto& e : t.structure) {
      if (e.to == node) f.parents.push_back(e.from);
    }
    for (const auto& v : t.variables) {
      f.tags.emplace(v.name, v.tags);
      if (v.controllable) f.controllable.insert(v.name);
    }
    return f;
  }

  std::vector<std::filesystem::path> dirs_;
  std::string backend_;
  unsigned threads_;
  std::mutex mutex_;
  std::map<std::string, sim::task_definition, std::less<>> tasks_;
  std::map<std::string, dataset, std::less<>> data_;
};

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

void write_points(const std::vector<experiment_point>& points, const std::filesystem::path& path) {
  detail::write_file_atomically(path, [&](std::ostream& out) {
    out << "scenario,target,strategy,w,rows,repetition,metric,value\n";
    for (const auto& p : points) {
      out << csv_field(p.scenario) << ',' << csv_field(p.target) << ',' << csv_field(p.strategy) << ',' << p.weight << ','
          << p.rows << ',' << p.repetition << ',' << p.metric << ',' << detail::format_double(p.value) << '\n';
    }
  });
}

void write_summary(const std::vector<aggregated_point>& summary, const std::filesystem::path& path) {
  detail::write_file_atomically(path, [&](std::ostream& out) {
    out << "scenario,target,strategy,w,rows,metric,mean,sd,repetitions\n";
    for (const auto& p : summary) {
      out << csv_field(p.scenario) << ',' << csv_field(p.target) << ',' << csv_field(p.strategy) << ',' << p.weight << ','
          << p.rows << ',' << p.metric << ',' << detail::format_double(p.mean) << ','
          << detail::format_double(p.standard_deviation) << ',' << p.repetitions << '\n';
    }
  });
}

/// A gnuplot script in the layout of the paper's figures: one column per strategy, rows
/// Max-Difference, Mean-Difference and failure prevention; one line per weight, MLE in blue,
/// the oracle in grey.
std::string plot_script(const scenario& s, const std::string& target, const std::vector<aggregated_point>& summary,
                        const std::filesystem::path& stem) {
  std::map<std::string, std::map<std::string, std::vector<const aggregated_point*>>> lines;  // metric → line → points
  const std::vector<std::string>& columns = s.strategies;
  for (const auto& p : summary) {
    if (p.scenario != s.name || p.target != target || p.metric == "chosen_w") continue;
    lines[p.metric][p.strategy + "|" + p.weight].push_back(&p);
  }
  std::ostringstream g;
  std::size_t block = 0;
  std::map<std::string, std::string> block_of;
  for (const auto& [metric, by_line] : lines) {
    for (const auto& [line, points] : by_line) {
      const std::string name = "$d" + std::to_string(block++);
      block_of[metric + "#" + line] = name;
      g << name << " << EOD\n";
      for (const auto* p : points) g << p->rows << ' ' << detail::format_double(p->mean) << ' ' << detail::format_double(p->standard_deviation) << '\n';
      g << "EOD\n";
    }
  }
  // The paper's colours by rank: the smallest weight green, then red, then yellow.
  std::map<std::string, std::string> colour{{"auto", "#000000"}};
  const std::vector<std::string> palette{"#2ca02c", "#d62728", "#e6b800", "#8c564b", "#17becf"};
  std::size_t rank = 0;
  for (double w : s.weights) {
    if (w > 0) colour.emplace(detail::format_short(w), palette[std::min(rank++, palette.size() - 1)]);
  }
  const std::vector<std::pair<std::string, std::string>> metrics{
      {"max_difference", "Max-Difference"}, {"mean_difference", "Mean-Difference"}, {"failure_prevention", "success after prevention"}};
  const auto width = std::max<std::size_t>(1, columns.size()) * 420;
  auto render = [&](const std::string& terminal, const std::string& file) {
    g << "set terminal " << terminal << " size " << width << ",900\nset output '" << file << "'\n";
    g << "set multiplot layout 3," << std::max<std::size_t>(1, columns.size()) << " title '" << s.title << ": " << target << "'\n";
    g << "set key top right font ',8'\nset grid\nset xlabel '|D|'\n";
    for (const auto& [metric, label] : metrics) {
      for (const auto& column : columns) {
        g << "set title '" << column << "'\nset ylabel '" << label << "'\n";
        if (metric == "failure_prevention") g << "set yrange [0:1]\n"; else g << "set yrange [0:*]\n";
        std::vector<std::string> plots;
        auto add = [&](const std::string& line, const std::string& title, const std::string& style) {
          const auto it = block_of.find(metric + "#" + line);
          if (it != block_of.end()) plots.push_back(it->second + " using 1:2 with lines " + style + " title '" + title + "'");
        };
        add("mle|0", "MLE", "lw 2 lc rgb '#1f77b4'");
        for (const auto& [line, points] : lines[metric]) {
          const auto bar = line.find('|');
          const auto strategy = line.substr(0, bar), weight = line.substr(bar + 1);
          if (strategy == column) {
            const auto c = colour.find(weight);
            add(line, "w = " + weight, std::string("lw 2 ") + (weight == "auto" ? "dt 2 " : "") + "lc rgb '" +
                                            (c == colour.end() ? std::string("#9467bd") : c->second) + "'");
          } else if (strategy == column + "+auto-map") {
            add(line, "auto map, w = " + weight, "lw 2 dt 3 lc rgb '#9467bd'");
          }
        }
        if (metric == "failure_prevention") add("oracle|0", "oracle", "lw 1 dt 4 lc rgb '#7f7f7f'");
        g << "plot " << detail::join(plots, ", \\\n     ") << "\n";
      }
    }
    g << "unset multiplot\n";
  };
  render("pngcairo", stem.string() + ".png");
  render("svg", stem.string() + ".svg");
  return g.str();
}

bool have_gnuplot() { return std::system("gnuplot --version > /dev/null 2>&1") == 0; }

void run_experiment_command(const experiment_arguments& args) {
  auto dirs = args.tasks_dir.empty() ? sim::default_task_directories() : std::vector<std::filesystem::path>{args.tasks_dir};
  const auto scenarios = selected_scenarios(args.scenario, scenarios_directory(dirs));
  // Checked before any work, created only once there is something to write in it.
  const std::filesystem::path out_dir(args.out);
  if (args.out.empty()) throw error("--out needs a folder");
  if (std::filesystem::exists(out_dir) && !std::filesystem::is_directory(out_dir)) {
    throw io_error("'" + args.out + "' is a file, not a folder");
  }
  const auto parent = out_dir.has_parent_path() ? out_dir.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent)) throw io_error("the folder '" + parent.string() + "' does not exist");
  simulated_source data(dirs, args.backend, args.threads);
  experiment_options options;
  options.seed = args.seed;
  options.repetitions = args.repetitions;
  options.threads = args.threads;
  options.automatic_lines = !args.no_automatic;
  options.prevention.metric = args.distance == "units" ? prevention_options::distance::units : prevention_options::distance::steps;
  options.note = [](const std::string& text) { note(text); };
  std::vector<experiment_point> points;
  const bool plots = have_gnuplot();
  if (!plots) note("gnuplot is not installed: writing the plot scripts (.gp) without rendering them");
  for (const auto& s : scenarios) {
    progress_bar bar(s.name);
    options.progress = [&bar](std::size_t done, std::size_t total) { bar.update(done, total); };
    std::vector<experiment_point> mine;
    try {
      mine = run_experiment(s, data.source(), options);
    } catch (const error& e) {
      throw error(s.source.string() + ": " + e.what());
    }
    bar.finish();
    std::filesystem::create_directory(out_dir);
    const auto summary = aggregate(mine);
    for (const auto& t : s.targets) {
      const auto stem = std::filesystem::path(args.out) / (s.name + "-" + t.task);
      const auto script = plot_script(s, t.task, summary, stem);
      detail::write_file_atomically(stem.string() + ".gp", [&](std::ostream& out) { out << script; });
      if (plots) {
        const auto command = "gnuplot '" + stem.string() + ".gp' 2>&1";
        if (std::system(command.c_str()) != 0) note("gnuplot failed on " + stem.string() + ".gp");
      }
    }
    // The headline numbers at |D| = 0, as the paper reports them; there every w > 0 gives the
    // prior itself, so one weight per strategy says it all.
    for (const auto& t : s.targets) {
      std::cout << s.title << ", " << t.task << ": success after prevention at |D| = 0:";
      std::set<std::string> shown;
      for (const auto& p : summary) {
        if (p.target != t.task || p.rows != 0 || p.metric != "failure_prevention" || !shown.insert(p.strategy).second) continue;
        std::cout << "  " << p.strategy << " " << detail::format_short(100 * p.mean, 3) << "%";
      }
      std::cout << '\n';
    }
    points.insert(points.end(), mine.begin(), mine.end());
  }
  write_points(points, std::filesystem::path(args.out) / "points.csv");
  write_summary(aggregate(points), std::filesystem::path(args.out) / "summary.csv");
  std::cout << points.size() << " points -> " << (std::filesystem::path(args.out) / "points.csv").string() << ", summary.csv"
            << (plots ? " and plots" : "") << '\n';
}

}  // namespace

void add_experiment_command(CLI::App& app) {
  auto args = std::make_shared<experiment_arguments>();
  auto* cmd = app.add_subcommand("experiment", "Reproduce the paper's transfer scenarios: metrics as CSV and plots");
  cmd->add_option("--scenario", args->scenario,
                  "2-stack-sim, 2-stack-reality, 2-stack-sim-to-real, sphere-dropping, stack-to-drop (files in tasks/scenarios), or all")
      ->capture_default_str();
  cmd->add_option("--backend", args->backend, "Simulator: analytic or bullet")->capture_default_str();
  cmd->add_option("--reps", args->repetitions, "Repetitions (default: the scenario's, 20)")->check(whole_number(1, 100000));
  cmd->add_option("--seed", args->seed, "Seed of the data and the splits")
      ->check(whole_number(0, UINT64_MAX))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")->check(whole_number(0, 1024))->capture_default_str();
  cmd->add_option("--distance", args->distance, "Failure prevention's distance: steps (bins) or units")
      ->check(CLI::IsMember({"steps", "units"}))
      ->capture_default_str();
  cmd->add_flag("--no-auto", args->no_automatic, "Leave out the lines of w = auto and of the proposed map");
  cmd->add_option("--tasks-dir", args->tasks_dir, "Folder with the task files and scenarios/ (default: the installed tasks)");
  cmd->add_option("--out", args->out, "Folder for points.csv, summary.csv and the plots")->capture_default_str();
  cmd->callback([args] { run_experiment_command(*args); });
}

}  // namespace pgm::cli
