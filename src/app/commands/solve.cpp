// pgm solve: the UAI competitions' four tasks (PR, MAR, MAP, MMAP) on a model, written in the
// competition's result format (pgm/inference/solve.hpp, pgm/io/uai.hpp).

#include "pgm/inference/solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "cli/common.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/uai.hpp"

namespace pgm::cli {
namespace {

struct solve_arguments {
  std::string model;
  std::string task;
  std::string evidence;
  std::size_t evidence_sample = 0;
  std::string query;
  std::string engine = "auto";
  std::string heuristic = "min-fill";
  std::uint64_t memory_limit = 4096;
  std::size_t restarts = solve_options{}.search.restarts;
  std::uint64_t seed = solve_options{}.search.seed;
  std::string out;
  std::string schedule = "residual";
  double damping = 0.0;
  double tolerance = 1e-9;
  std::size_t iterations = 1000;
  double time_limit = std::numeric_limits<double>::infinity();
  std::size_t sweeps = 10'000;
  std::size_t burn_in = 1'000;
};

evidence_set evidence_of(const solve_arguments& args, const markov_network& model) {
  evidence_set observed;
  if (args.evidence.empty()) return observed;
  const auto samples = parse_uai_evidence(read_model_text(args.evidence), args.evidence, model);
  if (args.evidence_sample >= samples.size()) {
    throw data_error("'" + args.evidence + "' holds " + std::to_string(samples.size()) + " evidence sample" +
                     (samples.size() == 1 ? "" : "s") + ", so --evidence-sample " +
                     std::to_string(args.evidence_sample) + " does not exist (they are numbered from 0)");
  }
  if (samples.size() > 1) {
    note("'" + args.evidence + "' holds " + std::to_string(samples.size()) + " evidence samples; this answers sample " +
         std::to_string(args.evidence_sample) + " (--evidence-sample)");
  }
  for (const auto& [variable, state] : samples[args.evidence_sample]) {
    observed.hard.push_back({variable, index_at<state_index>(state)});
  }
  return observed;
}

/// Ends the process when --time-limit passes before the answer is computed: an exact engine
/// cannot stop half way with an answer, and nothing has been written yet. bp and gibbs are given
/// the time left less a margin, so they stop on their own with what they have; asked for by
/// name, they are stopped only if still at work a grace period later (on a starved machine the
/// margin alone can be too short to reduce their messages to marginals).
class time_limit_guard {
 public:
  time_limit_guard(double seconds, bool stops_on_its_own) : seconds_(seconds), stops_on_its_own_(stops_on_its_own) {
    if (std::isfinite(seconds)) watcher_ = std::thread([this] { watch(); });
  }
  time_limit_guard(const time_limit_guard&) = delete;
  time_limit_guard& operator=(const time_limit_guard&) = delete;
  ~time_limit_guard() {
    finished();
    if (watcher_.joinable()) watcher_.join();
  }

  /// The answer is computed: from here on the limit no longer applies (writing it is quick).
  void finished() {
    const std::lock_guard lock(mutex_);
    done_ = true;
    done_changed_.notify_all();
  }

  /// What an engine that stops on its own may spend: the time left less a margin for the rest.
  [[nodiscard]] double for_an_engine() const {
    if (!std::isfinite(seconds_)) return seconds_;
    const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - started_;
    return std::max(0.0, 0.9 * seconds_ - spent.count());
  }

 private:
  void watch() {
    const double grace = stops_on_its_own_ ? std::max(1.0, seconds_) : 0.0;
    std::unique_lock lock(mutex_);
    if (done_changed_.wait_for(lock, std::chrono::duration<double>(seconds_ + grace), [this] { return done_; })) {
      return;
    }
    std::cerr << "pgm: error: solve did not finish within --time-limit " << text::format_short(seconds_) << " s";
    if (stops_on_its_own_) std::cerr << " (and a grace of " << text::format_short(grace) << " s)";
    std::cerr << ", so nothing was written; bp and gibbs stop at the limit with the answer they have (--engine bp)"
              << std::endl;
    std::_Exit(1);
  }

  double seconds_;
  bool stops_on_its_own_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  std::condition_variable done_changed_;
  bool done_ = false;
  std::thread watcher_;
};

template <GraphicalModel M>
std::string solve(const M& model, const markov_network& ids, const solve_arguments& args, solve_report& report,
                  const time_limit_guard& limit) {
  const auto observed = evidence_of(args, ids);
  solve_options options;
  options.engine = parse_solve_engine(args.engine);
  options.memory_limit_bytes = static_cast<std::size_t>(args.memory_limit) << 20;
  options.heuristic = parse_elimination_heuristic(args.heuristic);
  options.bp = {.schedule = parse_bp_schedule(args.schedule),
                .damping = args.damping,
                .tolerance = args.tolerance,
                .max_iterations = args.iterations,
                .time_limit_seconds = limit.for_an_engine()};
  options.search.restarts = args.restarts;
  options.search.seed = args.seed;
  options.gibbs = {
      .sweeps = args.sweeps, .burn_in = args.burn_in, .seed = args.seed, .time_limit_seconds = limit.for_an_engine()};
  if (args.task == "PR") {
    return uai_pr_text(log_partition(model, observed, options, &report) / std::numbers::ln10);
  }
  if (args.task == "MAR") return uai_mar_text(all_marginals(model, observed, options, &report));
  if (args.task == "MAP") {
    const auto states = most_probable_assignment(model, observed, options, &report);
    return uai_assignment_text("MAP", states);
  }
  const auto query = parse_uai_query(read_model_text(args.query), args.query, ids);
  const auto states = marginal_map(model, query, observed, options, &report);
  return uai_assignment_text("MMAP", states);
}

void run_solve(const solve_arguments& args) {
  if (args.task == "MMAP" && args.query.empty()) {
    throw error("--task MMAP needs --query: the file of the query variables (.query)");
  }
  if (args.task != "MMAP" && !args.query.empty()) {
    throw error("--query names the variables of MMAP; --task " + args.task + " takes none");
  }
  pgm::check_output_path(args.out);
  const auto started = std::chrono::steady_clock::now();
  const auto engine = parse_solve_engine(args.engine);
  time_limit_guard limit(args.time_limit, engine == solve_engine::bp || engine == solve_engine::gibbs);
  solve_report report;
  std::string text;
  if (is_uai(args.model)) {
    const auto file = read_uai(args.model);
    text = solve(file.model, file.model, args, report, limit);
  } else {
    // Another format holds a Bayesian network; its UAI numbering is its node order.
    const auto network = read_network_file(args.model);
    const markov_network ids(network.variables(), {});
    text = solve(network, ids, args, report, limit);
  }
  limit.finished();
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - started;
  if (!report.note.empty()) note(report.note);
  std::cerr << "pgm: solve: " << args.task << " by " << report.engine;
  if (report.exact) {
    std::cerr << ", exact, in " << (report.log_space ? "logarithms" : "probabilities") << "; junction tree of "
              << report.total_cells << " cells, largest table " << report.largest_table_cells << " cells";
  } else if (report.engine == "gibbs") {
    std::cerr << ", approximate, " << report.iterations << " sweeps";
  } else {
    std::cerr << ", approximate, " << (report.converged ? "converged" : "not converged") << " after "
              << report.iterations << " iterations (last change " << text::format_short(report.residual, 3) << ")";
  }
  if (report.timed_out) std::cerr << ", stopped at the time limit";
  std::cerr << "; " << text::format_short(took.count(), 3) << " s\n";
  pgm::write_file_atomically(
      args.out, [&](std::ostream& out) { out << text; },
      summary_before_replacing("wrote " + args.task + " of " + args.model + " to " + args.out + "\n", args.out));
}

}  // namespace

void add_solve_command(CLI::App& app) {
  auto args = std::make_shared<solve_arguments>();
  auto* cmd = app.add_subcommand(
      "solve",
      "Solve one of the UAI competitions' tasks on a model and write the answer in the competition's format: PR "
      "(log10 of the partition function, P(evidence) for a Bayesian network), MAR (every variable's marginal), MAP "
      "(the most probable assignment) or MMAP (the most probable assignment of the query variables, the rest summed "
      "out). Exact, by a junction tree or variable elimination.\nExample: pgm solve --model Grids_11.uai --evidence "
      "Grids_11.uai.evid --task MAR --out Grids_11.uai.MAR");
  cmd->add_option("--model", args->model,
                  "The model: a .uai file (MARKOV or BAYES, .uai.gz read compressed) or a Bayesian network in " +
                      network_file_kinds())
      ->required();
  cmd->add_option("--task", args->task, "PR, MAR, MAP or MMAP")
      ->required()
      ->check(CLI::IsMember({"PR", "MAR", "MAP", "MMAP"}));
  cmd->add_option("--evidence", args->evidence,
                  "A .evid file: the 2014 one-line form (k, then k pairs of variable and state) or the older form "
                  "(a number of samples, then each)");
  cmd->add_option("--evidence-sample", args->evidence_sample,
                  "Which sample of an older multi-sample .evid file to answer, from 0 (default 0)")
      ->check(whole_number(0, 1'000'000));
  cmd->add_option("--query", args->query, "A .query file: the query variables of MMAP");
  cmd->add_option("--engine", args->engine,
                  "jt (junction tree), ve (variable elimination), bp (loopy belief propagation: PR and MAR, "
                  "approximate), gibbs (Gibbs sampling: MAR) or auto (jt when its tree fits in --memory-limit, else "
                  "bp; the default)")
      ->check(CLI::IsMember(known_solve_engines()));
  cmd->add_option("--schedule", args->schedule,
                  "bp's schedule: residual (the factor whose messages would change most first, the default) or "
                  "parallel (all at once)")
      ->check(CLI::IsMember(known_bp_schedules()));
  cmd->add_option("--damping", args->damping, "bp's damping, from 0 (none, the default) to below 1")
      ->check(number_between(0.0, 1.0, false, true));
  cmd->add_option("--tolerance", args->tolerance,
                  "bp stops when no message would change a probability by more than this (default 1e-9)")
      ->check(number_between(0.0, 1.0, true, false));
  cmd->add_option("--iterations", args->iterations, "bp's iteration limit (default 1000)")
      ->check(whole_number(1, 1'000'000));
  cmd->add_option("--sweeps", args->sweeps, "gibbs's sweeps kept after the burn-in (default 10000)")
      ->check(whole_number(1, 100'000'000));
  cmd->add_option("--burn-in", args->burn_in, "gibbs's sweeps left out first (default 1000)")
      ->check(whole_number(0, 100'000'000));
  cmd->add_option("--time-limit", args->time_limit,
                  "Seconds the run may take: bp and gibbs stop before it with the answer they have; an exact engine "
                  "still at work is stopped and nothing is written (default: none)")
      ->check(number_between(0.0, std::numeric_limits<double>::infinity(), true, true));
  cmd->add_option("--memory-limit", args->memory_limit,
                  "MiB the exact engines' tables may take, checked before any is allocated (default 4096, the "
                  "competition's budget)")
      ->check(whole_number(1, std::uint64_t{1} << 24));
  cmd->add_option("--heuristic", args->heuristic,
                  "The greedy elimination order's cost: min-fill (fewest new edges, default), min-degree or "
                  "min-weight (smallest table)")
      ->check(CLI::IsMember(known_elimination_heuristics()));
  cmd->add_option("--order-restarts", args->restarts,
                  "Greedy elimination orders tried after the first, ties broken at random, the smallest "
                  "junction tree kept; fewer when the search would take longer than the propagation it could "
                  "shorten (default " +
                      std::to_string(args->restarts) + ")")
      ->check(whole_number(0, 100'000));
  cmd->add_option("--seed", args->seed,
                  "The seed of the order search's restarts and of gibbs's chain (default 1): one seed, one answer")
      ->check(whole_number(0, std::numeric_limits<std::uint64_t>::max()));
  cmd->add_option("--out", args->out, "The result file to write, atomically")->required();
  cmd->callback([args] { run_solve(*args); });
}

}  // namespace pgm::cli
