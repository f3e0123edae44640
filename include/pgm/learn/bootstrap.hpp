#pragma once
/// \file
/// Bootstrap structure learning, as bnlearn's `boot.strength` and `averaged.network`: learn on
/// `replicates` resamples of the rows (drawn with replacement, each seeded by the seed and its
/// number, in parallel through the one parallel-for, each result in its own slot), then report for
/// every pair of nodes how often they were adjacent (strength) and, when they were, how often in
/// each direction. The averaged network keeps the arcs whose strength exceeds a threshold (or is
/// 1) and whose direction is at least 1/2, strongest first, leaving out an arc that would close a
/// cycle or whose reverse is already in.
///
/// The default threshold is bnlearn's (Scutari & Nagarajan 2013): with F the empirical CDF of the
/// strengths of all ordered pairs, p0 minimizes the L1 distance ∫_0^1 |F(t) − p| dt (the smallest
/// minimizer, where the minimum is flat), and the threshold is the strengths' p0 quantile (the
/// smallest strength s with F(s) >= p0).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/learn/hill_climbing.hpp"
#include "pgm/learn/learn_structure.hpp"

namespace pgm {

struct bootstrap_options {
  std::size_t replicates = 100;
  std::uint64_t seed = 1;
  /// The averaged network's threshold on strength; none: bnlearn's L1 rule.
  std::optional<double> threshold;
};

struct arc_strength {
  std::string from;
  std::string to;
  /// The fraction of replicates in which from and to are adjacent.
  double strength = 0.0;
  /// Of those, the fraction with from -> to.
  double direction = 0.0;
};

struct bootstrap_result {
  /// Every ordered pair of distinct nodes, by (from, to) in column order.
  std::vector<arc_strength> arcs;
  double threshold = 0.0;
  /// The averaged network's arcs, by (from, to) in column order.
  std::vector<named_edge> averaged;
  std::size_t replicates = 0;
};

namespace detail {

/// The rows `picked` of `data`, as a data set with the same variables.
[[nodiscard]] PGM_DECL dataset resample_rows(const dataset& data, std::span<const std::string> names,
                                             const std::vector<std::size_t>& picked);

/// bnlearn's L1 threshold over the strengths of every ordered pair.
[[nodiscard]] PGM_DECL double l1_threshold(std::vector<double> strengths);

/// Replicate r's draw of `count` indices in [0, count) with replacement, from `seed`.
[[nodiscard]] PGM_DECL std::vector<std::size_t> bootstrap_draw(std::uint64_t seed, std::size_t r, std::size_t count);

/// The strengths, threshold and averaged network of the replicates' arcs: found[r][i·n + j] is
/// 1 where replicate r learned names[i] -> names[j].
[[nodiscard]] PGM_DECL bootstrap_result summarize_replicates(std::span<const std::string> names,
                                                             const std::vector<std::vector<unsigned char>>& found,
                                                             const bootstrap_options& options);

/// Throws model_error for no replicates or a threshold outside [0, 1].
PGM_DECL void check_bootstrap_options(const bootstrap_options& options);

}  // namespace detail

/// Learns with `learner` on `options.replicates` bootstrap resamples of the named columns, in
/// parallel on `context.threads`. Throws model_error for no replicates or a threshold outside
/// [0, 1], and whatever learning throws.
[[nodiscard]] PGM_DECL bootstrap_result bootstrap_structure(const dataset& data, std::span<const std::string> names,
                                                            const structure_learner& learner,
                                                            const structure_context& context,
                                                            const bootstrap_options& options);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/bootstrap.ipp"
#endif
