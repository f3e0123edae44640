#pragma once
/// \file
/// Expectation–maximization for the tables of a network whose data have gaps: values missing
/// in some rows (missing at random), and latent variables, which are in the structure but in no
/// column and so are missing in every row.
///
/// Each iteration's E-step takes the expected counts E[M[x, u]] under the current tables from an
/// inference engine: the rows are grouped by their pattern of observed values, so each distinct
/// pattern is one set of evidence and one query per family it leaves incomplete; a family the
/// pattern observes whole adds its count as complete data does. The M-step is the complete-data
/// estimator on the expected counts, with the same priors (a transferred weighted prior, eq. 8,
/// makes it MAP-EM with the paper's prior). Hard EM instead completes each pattern with its most
/// probable values (max-product) and counts the completed rows.
///
/// What rises at every iteration is the objective: ln P(data | θ) plus the prior's term
/// Σ α[x, u] ln θ[x, u] (0 without a prior, where the objective is the log-likelihood), because
/// the estimate (α + E[M]) / (α_u + E[M_u]) maximizes it given the expected counts. For hard EM
/// the objective is that of the completed data, which rises too.
///
/// Start: every family that some rows observe whole starts from its available-case estimate
/// with one pseudo-count more per cell (so that no row is impossible at the start: the MLE of
/// the complete rows alone can rule out a value seen only in rows with a gap, and EM never
/// brings back a probability of 0); a family with a latent variable starts from a random table (each column 0.5 + U[0,
/// 1), normalized, from a std::mt19937_64 seeded by the seed and the restart), and `restarts` such starts run, the one
/// with the highest objective kept. Without latent variables there is one start. It stops when the objective changes by
/// at most `tolerance` times its size, or after `max_iterations` M-steps.
///
/// The patterns are cut into at most 64 blocks (a number that depends on the patterns, not on
/// the threads), each summed on its own and the blocks added in order, so the result is the
/// same to the last bit for any number of threads.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/inference/inference_engine.hpp"
#include "pgm/inference/junction_tree_engine.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/parameter_prior.hpp"

namespace pgm {

enum class em_kind {
  soft,  ///< expected counts from posteriors
  hard,  ///< each incomplete row completed by its most probable values
};

/// One iteration's numbers, for progress and tests.
struct em_step {
  std::size_t restart = 0;
  /// 0 for the start, then one per M-step.
  std::size_t iteration = 0;
  /// ln P(observed data | tables) under the tables of this iteration.
  double log_likelihood = 0.0;
  /// What EM raises: the log-likelihood (hard EM: of the completed data) plus the prior's term.
  double objective = 0.0;
};

struct em_options {
  em_kind kind = em_kind::soft;
  /// Stops when |objective - previous| <= tolerance · |previous|.
  double tolerance = 1e-6;
  std::size_t max_iterations = 100;
  /// Random starts of the latent variables' tables; the best objective is kept.
  std::size_t restarts = 1;
  std::uint64_t seed = 0;
  /// Tables to start from instead (a warm start; the structure must be the same): one start.
  const bayesian_network* start = nullptr;
  /// E-step threads; 0 uses every hardware thread. The result is the same for any number.
  unsigned threads = 0;
  /// Called after every E-step (each start and iteration) when set.
  std::function<void(const em_step&)> on_step;
};

struct em_result {
  bayesian_network network;
  /// ln P(observed data | network).
  double log_likelihood = 0.0;
  double objective = 0.0;
  /// M-steps of the start kept, and whether it stopped by the tolerance.
  std::size_t iterations = 0;
  bool converged = false;
  std::size_t restart = 0;
  std::size_t rows = 0;
  /// Distinct patterns of observed values, and how many of them miss a value.
  std::size_t patterns = 0;
  std::size_t incomplete_patterns = 0;
  /// The expected counts under the network's last E-step, node by node.
  std::vector<expected_count_table> expected_counts;
};

/// One line on how EM went, as `pgm fit --missing em` and pgm.fit print it.
[[nodiscard]] PGM_DECL std::string summary_of(const em_result& em);

/// The pseudo-counts α[x, u] a prior adds to a family's counts, laid out like its table.
[[nodiscard]] PGM_DECL std::vector<double> pseudo_counts_of(const parameter_prior& prior, const variable& child,
                                                            const std::vector<variable>& parents);

namespace detail {

/// Rows grouped by their values over the structure's nodes (`absent` where missing or latent).
struct observed_patterns {
  static constexpr std::uint32_t absent = std::numeric_limits<std::uint32_t>::max();
  std::size_t nodes = 0;
  /// Pattern p's values are codes[p·nodes, (p+1)·nodes).
  std::vector<std::uint32_t> codes;
  std::vector<double> rows;

  [[nodiscard]] std::size_t size() const noexcept { return rows.size(); }
  [[nodiscard]] std::span<const std::uint32_t> of(std::size_t p) const { return {codes.data() + p * nodes, nodes}; }
};

[[nodiscard]] PGM_DECL observed_patterns patterns_of(const network_structure& structure, const dataset& data);

/// A family's members: node ids, the child first, then its parents in order.
[[nodiscard]] PGM_DECL std::vector<std::vector<variable_id>> family_members(const network_structure& structure);

/// The cell of a family's table for its members' values (child first).
[[nodiscard]] PGM_DECL std::size_t cell_of(const expected_count_table& table, std::span<const std::size_t> values);

[[nodiscard]] PGM_DECL std::vector<expected_count_table> empty_counts(const network_structure& structure);

PGM_DECL void add_counts(std::vector<expected_count_table>& to, const std::vector<expected_count_table>& from);

/// Σ α ln θ over every cell with α > 0.
[[nodiscard]] PGM_DECL double prior_term(const bayesian_network& network,
                                         const std::vector<std::vector<double>>& alpha);

/// One E-step's sums.
struct expectation {
  std::vector<expected_count_table> counts;
  double log_likelihood = 0.0;
  /// Hard EM: ln P of the completed data.
  double completed_log_likelihood = 0.0;
};

template <class Engine>
class em_runner {
 public:
  em_runner(const network_structure& structure, const dataset& data, const fit_options& fitting,
            const em_options& options)
      : structure_(&structure),
        fitting_(&fitting),
        options_(&options),
        patterns_(patterns_of(structure, data)),
        families_(family_members(structure)),
        rows_(data.rows()) {
    for (std::size_t i = 0; i < structure.size(); ++i) {
      const variable_id node = index_at<variable_id>(i);
      require_dense(structure, node);
      alpha_.push_back(pseudo_counts_of(prior_of(node), structure.at(node), structure.parent_variables(node)));
      latent_family_.push_back(std::any_of(families_[i].begin(), families_[i].end(), [&](variable_id member) {
        return !data.contains(structure.at(member).name());
      }));
    }
    fixed_ = empty_counts(structure);
    for (std::size_t p = 0; p < patterns_.size(); ++p) {
      const auto values = patterns_.of(p);
      const bool complete =
          std::none_of(values.begin(), values.end(), [](auto v) { return v == observed_patterns::absent; });
      if (!complete) incomplete_.push_back(p);
      for (std::size_t i = 0; i < families_.size(); ++i) {
        if (family_observed(values, i)) fixed_[i].counts()[cell_of(values, i)] += patterns_.rows[p];
      }
    }
    has_latent_ = std::any_of(latent_family_.begin(), latent_family_.end(), [](bool b) { return b; });
  }

  [[nodiscard]] em_result run() {
    em_result best;
    bool have_best = false;
    const std::size_t starts = has_latent_ && !options_->start ? std::max<std::size_t>(1, options_->restarts) : 1;
    for (std::size_t restart = 0; restart < starts; ++restart) {
      auto result = run_from(start(restart), restart);
      if (!have_best || result.objective > best.objective) {
        best = std::move(result);
        have_best = true;
      }
    }
    best.rows = rows_;
    best.patterns = patterns_.size();
    best.incomplete_patterns = incomplete_.size();
    return best;
  }

 private:
  [[nodiscard]] const parameter_prior& prior_of(variable_id node) const {
    const auto own = fitting_->node_priors.find(structure_->at(node).name());
    return own != fitting_->node_priors.end() ? own->second : fitting_->prior;
  }

  /// The E-step reads every value of each table through a junction tree, so EM holds every
  /// table dense: refused here, naming the family, rather than by an allocation that fails.
  static void require_dense(const network_structure& structure, variable_id node) {
    std::size_t cells = structure.at(node).cardinality();
    for (const auto& parent : structure.parent_variables(node)) {
      cells = detail::saturating_multiply(cells, parent.cardinality());
    }
    if (cells > max_table_cells) {
      throw table_too_large(
          "EM holds every table dense, and the table of '" + structure.at(node).name() + "' with " +
          std::to_string(structure.parent_variables(node).size()) + " parents has " +
          (cells == std::numeric_limits<std::size_t>::max() ? std::string("more than 2^64") : std::to_string(cells)) +
          " cells, more than pgm's limit of " + std::to_string(max_table_cells) +
          " (docs/limits.md): fit it without --missing em, or with fewer parents");
    }
  }

  [[nodiscard]] bool family_observed(std::span<const std::uint32_t> values, std::size_t node) const {
    return std::all_of(families_[node].begin(), families_[node].end(),
                       [&](variable_id m) { return values[m.value()] != observed_patterns::absent; });
  }

  [[nodiscard]] std::size_t cell_of(std::span<const std::uint32_t> values, std::size_t node) const {
    std::vector<std::size_t> member_values;
    for (auto m : families_[node]) member_values.push_back(values[m.value()]);
    return detail::cell_of(fixed_[node], member_values);
  }

  /// The estimation options with dense tables: the E-step reads every value of each table.
  [[nodiscard]] estimate_options dense_estimation() const {
    auto options = fitting_->estimation;
    options.sparse = false;
    return options;
  }

  [[nodiscard]] bayesian_network maximize(const std::vector<expected_count_table>& counts) const {
    std::vector<cpt<double>> tables;
    for (std::size_t i = 0; i < counts.size(); ++i) {
      tables.push_back(estimate(counts[i], prior_of(index_at<variable_id>(i)), dense_estimation()));
    }
    return bayesian_network(*structure_, std::move(tables));
  }

  /// The available-case estimate with one pseudo-count more per cell, with random tables for
  /// the families of latent variables.
  [[nodiscard]] bayesian_network start(std::size_t restart) const {
    if (options_->start) return *options_->start;
    std::vector<cpt<double>> smoothed;
    for (std::size_t i = 0; i < fixed_.size(); ++i) {
      auto alpha = alpha_[i];
      for (auto& a : alpha) a += 1.0;
      smoothed.push_back(estimate(fixed_[i], pseudo_counts_prior{std::move(alpha)}, dense_estimation()));
    }
    bayesian_network network(*structure_, std::move(smoothed));
    if (!has_latent_) return network;
    std::mt19937_64 random(options_->seed ^ (0x9E3779B97F4A7C15ULL * (restart + 1)));
    std::vector<cpt<double>> tables(network.tables().begin(), network.tables().end());
    for (std::size_t i = 0; i < tables.size(); ++i) {
      if (!latent_family_[i]) continue;
      auto values = std::vector<double>(tables[i].values().begin(), tables[i].values().end());
      const auto j = tables[i].child_cardinality();
      for (std::size_t u = 0; u < tables[i].configurations(); ++u) {
        double sum = 0.0;
        for (std::size_t x = 0; x < j; ++x) {
          values[u * j + x] = 0.5 + uniform01(random);
          sum += values[u * j + x];
        }
        for (std::size_t x = 0; x < j; ++x) values[u * j + x] /= sum;
      }
      tables[i] = cpt<double>(tables[i].child(), tables[i].parents(), std::move(values));
    }
    return bayesian_network(*structure_, std::move(tables));
  }

  [[nodiscard]] em_result run_from(bayesian_network network, std::size_t restart) const {
    em_result result;
    result.restart = restart;
    double previous = 0.0;
    for (std::size_t iteration = 0;; ++iteration) {
      auto expected = expect(network);
      const double objective =
          (options_->kind == em_kind::hard ? expected.completed_log_likelihood : expected.log_likelihood) +
          prior_term(network, alpha_);
      if (options_->on_step) options_->on_step({restart, iteration, expected.log_likelihood, objective});
      result.iterations = iteration;
      result.log_likelihood = expected.log_likelihood;
      result.objective = objective;
      result.expected_counts = std::move(expected.counts);
      if (iteration > 0 && std::abs(objective - previous) <= options_->tolerance * std::abs(previous)) {
        result.converged = true;
        break;
      }
      if (iteration == options_->max_iterations) break;
      previous = objective;
      network = maximize(result.expected_counts);
    }
    result.network = std::move(network);
    return result;
  }

  /// The E-step under `network`: the fixed counts plus each incomplete pattern's expected counts.
  [[nodiscard]] expectation expect(const bayesian_network& network) const {
    const std::size_t blocks = std::min<std::size_t>(64, (incomplete_.size() + 63) / 64);
    std::vector<expectation> sums(blocks);
    parallel_options parallel;
    parallel.threads = options_->threads;
    parallel.min_items_per_thread = 1;
    const auto make_engine = [&] {
      // The engines live within this step, the network beyond it: lent, not copied.
      if constexpr (std::constructible_from<Engine, std::shared_ptr<const bayesian_network>>) {
        return Engine(borrowed(network));
      } else {
        return Engine(network);
      }
    };
    const auto add_block = [&](Engine& engine, std::size_t b) {
      sums[b].counts = empty_counts(*structure_);
      const std::size_t begin = incomplete_.size() * b / blocks;
      const std::size_t end = incomplete_.size() * (b + 1) / blocks;
      for (std::size_t k = begin; k < end; ++k) add_pattern(engine, incomplete_[k], sums[b]);
    };
    if constexpr (requires(const Engine& e) { e.fresh(); }) {
      // An engine that keeps messages answers with bits that depend on what it was asked
      // before: each block starts from a fresh one of the tree compiled once, so that the sums
      // do not depend on which thread ran which blocks.
      const auto compiled = make_engine();
      parallel_for(blocks, parallel, [&](item_range range) {
        for (std::size_t b = range.begin; b < range.end; ++b) {
          auto engine = compiled.fresh();
          add_block(engine, b);
        }
      });
    } else {
      static_cast<void>(parallel_for(blocks, parallel, make_engine, [&](Engine& engine, item_range range) {
        for (std::size_t b = range.begin; b < range.end; ++b) add_block(engine, b);
      }));
    }
    expectation total;
    total.counts = fixed_;
    total.log_likelihood = complete_log_likelihood(network);
    total.completed_log_likelihood = total.log_likelihood;
    for (const auto& block : sums) {
      add_counts(total.counts, block.counts);
      total.log_likelihood += block.log_likelihood;
      total.completed_log_likelihood += block.completed_log_likelihood;
    }
    return total;
  }

  /// ln P of the patterns without a missing value, straight from the tables.
  [[nodiscard]] double complete_log_likelihood(const bayesian_network& network) const {
    double sum = 0.0;
    std::size_t next_incomplete = 0;
    for (std::size_t p = 0; p < patterns_.size(); ++p) {
      if (next_incomplete < incomplete_.size() && incomplete_[next_incomplete] == p) {
        ++next_incomplete;
        continue;
      }
      const auto values = patterns_.of(p);
      double log_p = 0.0;
      for (std::size_t i = 0; i < network.size(); ++i)
        log_p += std::log(network.tables()[i].values()[cell_of(values, i)]);
      sum += patterns_.rows[p] * log_p;
    }
    return sum;
  }

  void add_pattern(Engine& engine, std::size_t p, expectation& into) const {
    const auto values = patterns_.of(p);
    const double rows = patterns_.rows[p];
    evidence_set observed;
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (values[i] != observed_patterns::absent) {
        observed.hard.push_back({index_at<variable_id>(i), state_index(values[i])});
      }
    }
    engine.set_evidence(std::move(observed));
    const double log_evidence = engine.log_probability_of_evidence();
    if (!std::isfinite(log_evidence)) {
      throw data_error(
          "EM: a row of the data has probability 0 under the current tables (a value the tables rule out)");
    }
    into.log_likelihood += rows * log_evidence;
    if constexpr (MpeEngine<Engine>) {
      if (options_->kind == em_kind::hard) {
        add_completion(engine.mpe({}), values, rows, into);
        return;
      }
    }
    for (std::size_t i = 0; i < families_.size(); ++i) {
      if (family_observed(values, i)) continue;
      add_family(engine, values, rows, i, into);
    }
  }

  /// Hard EM: the pattern completed by its most probable values, counted.
  void add_completion(const mpe_result& best, std::span<const std::uint32_t> values, double rows,
                      expectation& into) const {
    std::vector<std::uint32_t> completed(values.begin(), values.end());
    std::size_t k = 0;
    for (std::size_t i = 0; i < completed.size(); ++i) {
      if (completed[i] == observed_patterns::absent) {
        completed[i] = static_cast<std::uint32_t>(best.states[k++].value());
      }
    }
    into.completed_log_likelihood += rows * best.log_joint_probability;
    for (std::size_t i = 0; i < families_.size(); ++i) {
      if (!family_observed(values, i)) into.counts[i].counts()[cell_of(completed, i)] += rows;
    }
  }

  /// Soft EM: P(the family's missing members | the pattern), spread over its cells.
  void add_family(Engine& engine, std::span<const std::uint32_t> values, double rows, std::size_t i,
                  expectation& into) const {
    std::vector<variable_id> hidden;
    std::vector<std::size_t> member_values;
    std::vector<std::size_t> hidden_slots;
    for (std::size_t k = 0; k < families_[i].size(); ++k) {
      const auto m = families_[i][k];
      member_values.push_back(values[m.value()] == observed_patterns::absent ? 0 : values[m.value()]);
      if (values[m.value()] == observed_patterns::absent) {
        hidden.push_back(m);
        hidden_slots.push_back(k);
      }
    }
    const auto answer = engine.joint(hidden);
    const auto probabilities = answer.table.values();
    auto cells = into.counts[i].counts();
    for (std::size_t index = 0; index < probabilities.size(); ++index) {
      std::size_t rest = index;
      for (std::size_t h = hidden.size(); h-- > 0;) {
        const auto card = structure_->at(hidden[h]).cardinality();
        member_values[hidden_slots[h]] = rest % card;
        rest /= card;
      }
      cells[detail::cell_of(into.counts[i], member_values)] += rows * probabilities[index];
    }
  }

  const network_structure* structure_;
  const fit_options* fitting_;
  const em_options* options_;
  observed_patterns patterns_;
  std::vector<std::vector<variable_id>> families_;
  std::size_t rows_;
  std::vector<std::vector<double>> alpha_;
  std::vector<bool> latent_family_;
  bool has_latent_ = false;
  /// Counts of the families the patterns observe whole, the same at every iteration.
  std::vector<expected_count_table> fixed_;
  /// The patterns with a missing value, in order.
  std::vector<std::size_t> incomplete_;
};

}  // namespace detail

/// EM for the tables of `structure` from `data`, whose columns hold the states of the
/// structure's observed variables (missing values allowed); a variable of the structure with no
/// column is latent. `Engine` answers the E-step's queries (any InferenceEngine constructible
/// from a network; hard EM needs an MpeEngine). Throws data_error for a column whose states
/// differ from the structure's or a row the tables give probability 0, model_error for a prior
/// that does not fit.
template <class Engine = junction_tree_engine<>>
requires InferenceEngine<Engine> && std::constructible_from<Engine, const bayesian_network&>
[[nodiscard]] em_result expectation_maximization(const network_structure& structure, const dataset& data,
                                                 const fit_options& fitting = {}, const em_options& options = {}) {
  if (options.kind == em_kind::hard) {
    if constexpr (!MpeEngine<Engine>) {
      throw model_error("hard EM needs an engine that finds the most probable explanation (ve or jt)");
    }
  }
  if (!std::isfinite(options.tolerance) || options.tolerance < 0.0) {
    throw model_error("the EM tolerance must be a finite number >= 0, got " + text::format_double(options.tolerance));
  }
  for (const auto& [name, prior] : fitting.node_priors) {
    if (!structure.contains(name)) {
      throw model_error("a prior is given for '" + name + "', which is not in the network");
    }
  }
  if (data.rows() == 0) throw data_error("EM needs at least one row of data");
  if (options.start && options.start->structure() != structure) {
    throw model_error("the network EM is to start from has another structure than the one fitted");
  }
  return detail::em_runner<Engine>(structure, data, fitting, options).run();
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/expectation_maximization.ipp"
#endif
