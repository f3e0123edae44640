#pragma once
/// \file
/// The evaluation protocol of the paper (Sec. IV-B) for one scenario: the prior is fitted once
/// (MLE) from D′; in each repetition the target data is split at random into D and
/// D_GroundTruth, D is cut into `subsets` parts, and the target node is estimated on 0, 1, …,
/// `subsets` parts by MLE and by Bayesian estimation with every strategy's transferred prior
/// and every weight (and, beyond the paper, the weight chosen from the data and the proposed
/// correspondence map). Each estimate is scored against θ* = MLE on D_GroundTruth by Max- and
/// Mean-Difference and by failure prevention, beside the oracle that prevents with θ* itself.
///
/// In stages: prepare_prior (once), prepare_target (once per target: its family, priors and
/// lines), run_repetition (the split by split_rows, then every |D|, line and metric), and
/// run_experiment, a map of run_repetition over the (target, repetition) jobs.
///
/// Counts are additive, so a repetition counts each row once: the parts of D by histogram, and
/// D_GroundTruth as all rows minus D. Every repetition is seeded by its coordinates and
/// writes its own slot of the results (pgm/detail/parallel_for.hpp spreads them over
/// threads), so the results are the same for any number of threads.
///
/// With `across_processes` the (target, repetition) jobs are split over the processes pgm runs
/// in (several under mpirun): each prepares only the targets its block of jobs needs (their
/// data simulated or read there), and process 0 gathers the points in job order, with the
/// notes of the targets it did not prepare; the others return none. The points are the same
/// for any number of processes.

#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/decide/prevent.hpp"
#include "pgm/decide/prevent_by_utility.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/detail/splitmix.hpp"
#include "pgm/eval/family_data.hpp"
#include "pgm/eval/metrics.hpp"
#include "pgm/eval/scenario.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/sim/random.hpp"
#include "pgm/transfer/network_transfer.hpp"
#include "pgm/transfer/prior_weight.hpp"
#include "pgm/transfer/propose.hpp"

namespace pgm {

/// What the protocol needs to know of a task's node.
struct task_facts {
  std::vector<std::string> parents;  ///< in the known structure
  std::map<std::string, semantic_tags, std::less<>> tags;
  std::set<std::string, std::less<>> controllable;
  /// The node's state that is success (a task's outcome: "1"); empty when it has none.
  std::string success_state;
};

/// Where data comes from: a simulator, or recorded trials.
struct task_source {
  std::function<dataset(const std::string& task, std::size_t rows, std::uint64_t seed)> data;
  std::function<task_facts(const std::string& task, const std::string& node)> facts;
  /// What the task's data are made from (e.g. the task file's checksum), so that data kept
  /// between runs are not used once it changed; may be empty.
  std::function<std::string(const std::string& task)> origin;
};

struct experiment_options {
  std::uint64_t seed = 1;
  std::size_t repetitions = 0;  ///< 0: the scenario's
  unsigned threads = 0;         ///< 0: every core
  bool automatic_lines = true;  ///< add w = auto and the proposed map
  /// Failure prevention's options; its threshold ε is each scenario's `epsilon`.
  prevention_options prevention;
  /// With these, each estimate is also scored by the rule of highest expected utility (the
  /// reward of success less what moving costs) and both rules' moves are costed (the metrics
  /// prevention_cost, utility_prevention, utility_prevention_cost). A cost of a variable that is
  /// no controllable parent of a target is left out there, with a note.
  std::optional<move_costs> costs;
  std::function<void(std::size_t done, std::size_t total)> progress;
  std::function<void(const std::string&)> note;
  /// Split the jobs over pgm::processes() (see the file comment).
  bool across_processes = false;
};

/// One measured value: a row of the tidy result table.
struct experiment_point {
  std::string scenario;
  std::string target;
  std::string strategy;  ///< mle, oracle, direct, cross, minimal, …, or "<strategy>+auto-map"
  std::string weight;    ///< "0" for MLE, a number, or "auto"
  std::size_t rows;      ///< |D|
  std::size_t repetition;
  experiment_metric metric;
  double value;
};

/// A line of the plots: MLE, or a transferred prior and how it is weighed.
struct estimator_line {
  /// Which correspondence map the prior was transferred by.
  enum class map_choice { scenario, proposed };

  std::string strategy;  ///< "mle", or a strategy of the transfer registry
  map_choice map = map_choice::scenario;
  std::optional<double> weight;        ///< w; none: chosen from the counts (choose_prior_weight)
  const cpt<double>* prior = nullptr;  ///< null for MLE

  /// The `strategy` column: the strategy, "+auto-map" with the proposed map.
  [[nodiscard]] std::string strategy_label() const {
    return map == map_choice::proposed ? strategy + "+auto-map" : strategy;
  }
  /// The `weight` column: "0" for MLE, the weight, or "auto".
  [[nodiscard]] std::string weight_label() const {
    return !prior ? "0" : weight ? text::format_short(*weight) : "auto";
  }
};

/// The prior task's side, fitted once (MLE on D′) and shared by every target.
struct prepared_prior {
  bayesian_network network;
  correspondence map;
};

/// Everything about one target task that stays fixed over repetitions.
struct prepared_target {
  std::string task;
  family_data family;
  std::size_t train_rows = 0;
  std::vector<std::uint8_t> controllable;  ///< per parent of the family
  std::size_t success_state = 0;
  /// The transferred priors, by map: the scenario's for each strategy, and the proposed map's.
  std::map<std::string, transferred_prior, std::less<>> priors;
  std::vector<estimator_line> lines;
  /// experiment_options::costs less those of variables that are no controllable parent here.
  std::optional<move_costs> costs;
};

namespace detail {

[[nodiscard]] PGM_DECL std::uint64_t seed_of(std::string_view text);

/// The seed under which `task`'s data are drawn.
[[nodiscard]] inline std::uint64_t data_seed(std::uint64_t base_seed, std::string_view task) {
  return mix_seed(base_seed, seed_of(task));
}

/// The costs of moving the target's controllable parents; a cost of any other variable is left
/// out with a note.
[[nodiscard]] PGM_DECL move_costs costs_of_target(const prepared_target& target, const move_costs& costs,
                                                  const std::function<void(const std::string&)>& note);

/// Thrown to skip the preparation of a process that has no jobs.
struct nothing_to_prepare {};

}  // namespace detail

/// The prior: the family of the scenario's prior node read off D′ and fitted by MLE.
[[nodiscard]] PGM_DECL prepared_prior prepare_prior(const scenario& s, const task_source& source,
                                                    std::uint64_t base_seed,
                                                    const std::function<void(const std::string&)>& note);

/// Target `index` of the scenario: its data read into the target node's family, its
/// transferred priors and the lines to estimate with.
[[nodiscard]] PGM_DECL prepared_target prepare_target(const scenario& s, std::size_t index, const task_source& source,
                                                      const prepared_prior& prior, std::uint64_t base_seed,
                                                      bool automatic_lines,
                                                      const std::function<void(const std::string&)>& note);

/// The rows of a target's data that repetition `repetition` trains on: a uniform random subset
/// of `train_rows` (a partial Fisher–Yates shuffle), in random order, followed by the rest.
/// The draws come from pgm's own SplitMix64 stream, so the split is the same with any standard
/// library.
[[nodiscard]] PGM_DECL std::vector<std::uint32_t> split_rows(std::size_t rows, std::size_t train_rows,
                                                             std::uint64_t seed);

/// One repetition on one target: the split, θ* on D_GroundTruth, and every line's estimate on
/// 0, 1, …, `subsets` parts of D, scored by every metric; points in the order (|D|, line, metric).
[[nodiscard]] PGM_DECL std::vector<experiment_point> run_repetition(const scenario& s, const prepared_target& target,
                                                                    std::size_t repetition, std::uint64_t base_seed,
                                                                    const prevention_options& prevention);

/// Runs the protocol, a map of run_repetition over the (target, repetition) jobs; the points
/// come in a fixed order (target, repetition, |D|, line, metric).
[[nodiscard]] PGM_DECL std::vector<experiment_point> run_experiment(const scenario& s, const task_source& source,
                                                                    const experiment_options& options = {});

/// Mean and sample standard deviation over repetitions of every (target, strategy, weight,
/// |D|, metric).
struct aggregated_point {
  std::string scenario, target, strategy, weight;
  std::size_t rows;
  experiment_metric metric;
  double mean, standard_deviation;
  std::size_t repetitions;
};

[[nodiscard]] PGM_DECL std::vector<aggregated_point> aggregate(const std::vector<experiment_point>& points);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/experiment.ipp"
#endif
