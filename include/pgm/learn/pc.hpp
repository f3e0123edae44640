#pragma once
/// \file
/// PC-stable structure learning (Spirtes, Glymour & Scheines; the order-independent skeleton
/// of Colombo & Maathuis 2014), in aGrUM's phases: `pc_skeleton` removes the edges that a
/// conditional independence test explains away and records the separating sets; the
/// orientation phases (pgm/learn/orientation.hpp) turn the skeleton into a CPDAG.
///
/// Order independence: at each level ℓ (conditioning sets of size ℓ), every node's adjacency
/// set is frozen before any test runs, and all edges are tested against the frozen sets;
/// removals take effect at the end of the level. Each edge x - y (x before y) is one task:
/// subsets of adj(x) \ {y} in lexicographic order, then those of adj(y) \ {x} not already
/// tried; the first independence removes the edge. A task depends only on the frozen sets and
/// the data, so a level's tasks run in parallel (pgm/detail/parallel_for.hpp), each outcome in
/// its task's slot, and the result is the same for any number of threads. A level with fewer
/// tasks than threads lends the idle threads to the counting within each test.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/learn/background_knowledge.hpp"
#include "pgm/learn/cpdag.hpp"
#include "pgm/learn/independence_test_registry.hpp"
#include "pgm/learn/orientation.hpp"

namespace pgm {

struct pc_options {
  /// Any independence test (pgm/learn/independence_test_registry.hpp); chi2 by default, with
  /// Yates' correction as pgmpy applies it and bnlearn's rows per cell as options.
  independence_test test;
  /// Significance level: an edge is removed when some test has p > alpha.
  double alpha = 0.01;
  /// The largest conditioning set tried.
  std::size_t max_conditioning = 3;
  /// Worker threads; 0 uses every hardware thread. The result is the same for any number.
  unsigned threads = 0;
  background_knowledge knowledge;
};

/// Why two nodes are not adjacent.
struct separation {
  variable_id x;  ///< the earlier node
  variable_id y;  ///< the later node
  /// The conditioning set of the test that removed the edge.
  std::vector<variable_id> given;
  ci_result test;
  /// Removed up front by background knowledge (both directions forbidden); no test ran.
  bool by_knowledge = false;
};

struct skeleton_result {
  /// The skeleton: every edge undirected.
  cpdag graph;
  separation_sets sepsets;
  /// One entry per non-adjacent pair, ordered by (x, y).
  std::vector<separation> removed;
  /// Tests run, over all levels.
  std::size_t tests = 0;
};

struct pc_result {
  cpdag graph;
  separation_sets sepsets;
  std::vector<separation> removed;
  std::size_t tests = 0;
  /// Orientation conflicts, as sentences (empty when the data were consistent).
  std::vector<std::string> conflicts;
};

namespace detail {

/// pc_skeleton's tasks share nothing but the frozen adjacency and the data.
struct edge_task {
  std::size_t x;
  std::size_t y;
};

struct edge_outcome {
  bool removed = false;
  std::vector<std::size_t> given;
  ci_result test;
  std::size_t tests = 0;
};

/// Advances `pick` (strictly increasing indices below n) to the next k-subset in
/// lexicographic order; false after the last one.
PGM_DECL bool next_subset(std::vector<std::size_t>& pick, std::size_t n);

class skeleton_worker {
 public:
  /// `count_threads` > 1 splits each test's counting over that many threads, for levels
  /// with fewer tasks than threads.
  skeleton_worker(std::span<const discrete_column* const> columns, const pc_options& options, unsigned count_threads)
      : columns_(columns), options_(options), count_threads_(count_threads), tried_(columns.size(), 0) {}

  /// Tests x - y at `level` against the frozen adjacency `around`.
  PGM_DECL edge_outcome run(const edge_task& task, std::size_t level,
                            const std::vector<std::vector<std::size_t>>& around);

 private:
  PGM_DECL static std::vector<std::size_t> others(const std::vector<std::size_t>& nodes, std::size_t skip);

  // Tries every level-subset of `candidates`, except those inside `already` (tested from the
  // other end). Returns whether one separates x and y.
  PGM_DECL bool search(const edge_task& task, std::size_t level, const std::vector<std::size_t>& candidates,
                       const std::vector<char>* already, edge_outcome& outcome);

  std::span<const discrete_column* const> columns_;
  const pc_options& options_;
  unsigned count_threads_;
  std::vector<char> tried_;
  std::vector<const discrete_column*> given_;
  std::vector<std::uint64_t> counts_;
};

PGM_DECL void check_pc_options(const pc_options& options);

}  // namespace detail

/// The PC-stable skeleton over `columns` (node i is columns[i]).
[[nodiscard]] PGM_DECL skeleton_result pc_skeleton(std::span<const discrete_column* const> columns,
                                                   const edge_constraints& constraints, const pc_options& options);

/// PC-stable over `columns`: the skeleton, then background knowledge, v-structures and
/// Meek's rules. Throws model_error for bad options or knowledge naming unknown variables.
[[nodiscard]] PGM_DECL pc_result pc_stable(std::span<const discrete_column* const> columns,
                                           const pc_options& options = {});

/// PC-stable over the named columns of a data set. Throws data_error for a missing or
/// continuous column.
[[nodiscard]] PGM_DECL pc_result pc_stable(const dataset& data, std::span<const std::string> columns,
                                           const pc_options& options = {});

/// PC-stable over every column of a data set (all must be discrete).
[[nodiscard]] inline pc_result pc_stable(const dataset& data, const pc_options& options = {}) {
  const auto names = data.names();
  return pc_stable(data, names, options);
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/pc.ipp"
#endif
