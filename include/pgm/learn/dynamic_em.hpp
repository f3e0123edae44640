#pragma once
/// \file
/// Expectation–maximization for the tied tables of a dynamic network (pgm/learn/fit_dynamic.hpp)
/// from episodes with gaps: values missing at some steps, and latent template variables (in the
/// structure, in no column: a hidden Markov model's state is one).
///
/// As static EM (pgm/learn/expectation_maximization.hpp), with an episode where that has a row:
/// the episodes are grouped by their length and pattern of observed values, and each distinct
/// pattern is one set of evidence on the network unrolled over its length. Its junction tree
/// gives each family's expected counts at every step, added into the first slice's table at
/// t = 0 and into the one tied transition table at every later step; a family the pattern
/// observes whole at a step adds its count as complete data do. The M-step estimates every table
/// from the expected counts under its prior (a transferred one makes it MAP-EM with the paper's
/// prior), so the log-likelihood plus the prior's term Σ α ln θ rises at every iteration.
///
/// Start, stop and determinism as for static EM: the available-case estimate with one
/// pseudo-count more per cell, random tables (and `restarts` starts) for the families of latent
/// variables; the patterns are cut into at most 64 blocks whatever the threads, so the result is
/// the same to the last bit for any number of them. For a hidden Markov model this is the
/// Baum–Welch algorithm.

#include <cstddef>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/expectation_maximization.hpp"
#include "pgm/learn/fit_dynamic.hpp"

namespace pgm {

struct dynamic_em_options {
  /// Tolerance, iterations, random starts, seed, threads and progress as for static EM. Soft EM
  /// only; `em.start` is not read (see `start`).
  em_options em;
  /// Tables to start from instead (a warm start; the structure must be the same): one start.
  const dynamic_network* start = nullptr;
};

struct dynamic_em_result {
  dynamic_network model;
  /// ln P(observed values of every episode | model).
  double log_likelihood = 0.0;
  double objective = 0.0;
  /// M-steps of the start kept, and whether it stopped by the tolerance.
  std::size_t iterations = 0;
  bool converged = false;
  std::size_t restart = 0;
  std::size_t episodes = 0;
  std::size_t steps = 0;  ///< rows of the long form
  /// Distinct episodes (by length and observed values), and how many of them miss a value.
  std::size_t patterns = 0;
  std::size_t incomplete_patterns = 0;
  /// The expected counts under the model's last E-step: the first slice's tables, then each
  /// template variable's transition table, in template order.
  std::vector<expected_count_table> initial;
  std::vector<expected_count_table> transition;
};

/// One line on how EM went, as `pgm fit --dynamic --missing em` prints it.
[[nodiscard]] PGM_DECL std::string summary_of(const dynamic_em_result& em);

/// EM for the tables of `structure` from the long-form `data` (pgm/data/episodes.hpp), missing
/// values allowed; a template variable with no column is latent. Priors, the empty-configuration
/// rule and the episode columns come from `options`. Throws data_error for malformed episodes,
/// a column whose states differ from the structure's or an episode the tables give probability
/// 0; model_error for hard EM, a start of another structure, or a prior that does not fit;
/// table_too_large for a family past the dense limit.
[[nodiscard]] PGM_DECL dynamic_em_result dynamic_expectation_maximization(const dynamic_structure& structure,
                                                                          const dataset& data,
                                                                          const dynamic_fit_options& options = {},
                                                                          const dynamic_em_options& em = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/dynamic_em.ipp"
#endif
