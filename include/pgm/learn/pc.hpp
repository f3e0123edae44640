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

#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/learn/background_knowledge.hpp"
#include "pgm/learn/cpdag.hpp"
#include "pgm/learn/independence_test.hpp"
#include "pgm/learn/orientation.hpp"

namespace pgm {

struct pc_options {
  ci_test test = ci_test::chi_square;
  /// Yates' correction of 2 x 2 strata, as pgmpy applies it (off by default).
  continuity_correction correction = continuity_correction::none;
  /// Independence without a test below this many rows per cell, as bnlearn decides sparse
  /// tables (0, the default: always test).
  double min_rows_per_cell = 0.0;
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
inline bool next_subset(std::vector<std::size_t>& pick, std::size_t n) {
  const std::size_t k = pick.size();
  for (std::size_t i = k; i-- > 0;) {
    if (pick[i] < n - k + i) {
      ++pick[i];
      for (std::size_t j = i + 1; j < k; ++j) pick[j] = pick[j - 1] + 1;
      return true;
    }
  }
  return false;
}

class skeleton_worker {
 public:
  /// `count_threads` > 1 splits each test's counting over that many threads, for levels
  /// with fewer tasks than threads.
  skeleton_worker(std::span<const discrete_column* const> columns, const pc_options& options, unsigned count_threads)
      : columns_(columns), options_(options), count_threads_(count_threads), tried_(columns.size(), 0) {}

  /// Tests x - y at `level` against the frozen adjacency `around`.
  edge_outcome run(const edge_task& task, std::size_t level, const std::vector<std::vector<std::size_t>>& around) {
    edge_outcome outcome;
    const auto from_x = others(around[task.x], task.y);
    const auto from_y = others(around[task.y], task.x);
    if (search(task, level, from_x, nullptr, outcome)) return outcome;
    std::fill(tried_.begin(), tried_.end(), 0);
    for (auto v : from_x) tried_[v] = 1;
    search(task, level, from_y, &tried_, outcome);
    return outcome;
  }

 private:
  static std::vector<std::size_t> others(const std::vector<std::size_t>& nodes, std::size_t skip) {
    std::vector<std::size_t> result;
    for (auto v : nodes) {
      if (v != skip) result.push_back(v);
    }
    return result;
  }

  // Tries every level-subset of `candidates`, except those inside `already` (tested from the
  // other end). Returns whether one separates x and y.
  bool search(const edge_task& task, std::size_t level, const std::vector<std::size_t>& candidates,
              const std::vector<char>* already, edge_outcome& outcome) {
    if (candidates.size() < level) return false;
    std::vector<std::size_t> pick(level);
    for (std::size_t i = 0; i < level; ++i) pick[i] = i;
    do {
      if (already) {
        bool inside = true;
        for (auto i : pick) inside = inside && (*already)[candidates[i]];
        if (inside) continue;
      }
      given_.clear();
      for (auto i : pick) given_.push_back(columns_[candidates[i]]);
      count_ci_table(*columns_[task.x], *columns_[task.y], given_, counts_, count_threads_);
      const auto result =
          test_independence(counts_, columns_[task.x]->var().cardinality(), columns_[task.y]->var().cardinality(),
                            {options_.test, options_.correction, options_.min_rows_per_cell});
      ++outcome.tests;
      if (result.independent(options_.alpha)) {
        outcome.removed = true;
        outcome.test = result;
        for (auto i : pick) outcome.given.push_back(candidates[i]);
        return true;
      }
    } while (next_subset(pick, candidates.size()));
    return false;
  }

  std::span<const discrete_column* const> columns_;
  const pc_options& options_;
  unsigned count_threads_;
  std::vector<char> tried_;
  std::vector<const discrete_column*> given_;
  std::vector<std::uint64_t> counts_;
};

inline void check_pc_options(const pc_options& options) {
  if (!(options.alpha > 0.0 && options.alpha < 1.0)) {
    throw model_error("alpha must lie strictly between 0 and 1, got " + detail::format_short(options.alpha));
  }
  if (!(options.min_rows_per_cell >= 0.0) || !std::isfinite(options.min_rows_per_cell)) {
    throw model_error("the minimum rows per cell must be a finite number >= 0, got " +
                      detail::format_short(options.min_rows_per_cell));
  }
}

}  // namespace detail

/// The PC-stable skeleton over `columns` (node i is columns[i]).
[[nodiscard]] inline skeleton_result pc_skeleton(std::span<const discrete_column* const> columns,
                                                 const edge_constraints& constraints, const pc_options& options) {
  detail::check_pc_options(options);
  const std::size_t n = columns.size();
  std::vector<std::string> names;
  for (const auto* c : columns) names.push_back(c->name());
  for (const auto* c : columns) {
    if (c->size() != columns.front()->size()) {
      throw data_error("column '" + c->name() + "' has " + std::to_string(c->size()) + " rows, '" +
                       columns.front()->name() + "' " + std::to_string(columns.front()->size()));
    }
  }
  if (constraints.size() != n) throw model_error("the constraints are for another set of variables");

  skeleton_result result{cpdag(names), separation_sets(n), {}, 0};
  auto& graph = result.graph;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (constraints.may_be_adjacent(i, j)) {
        graph.add_undirected(detail::node(i), detail::node(j));
      } else {
        result.removed.push_back({detail::node(i), detail::node(j), {}, {}, true});
      }
    }
  }

  const unsigned threads = detail::resolve_threads(options.threads);
  std::vector<std::vector<std::size_t>> around(n);
  for (std::size_t level = 0; level <= options.max_conditioning; ++level) {
    // Freeze the adjacency sets of this level.
    for (std::size_t i = 0; i < n; ++i) {
      around[i].clear();
      for (auto v : graph.adjacent_nodes(detail::node(i))) around[i].push_back(v.value());
    }
    std::vector<detail::edge_task> tasks;
    for (std::size_t i = 0; i < n; ++i) {
      for (auto j : around[i]) {
        if (j < i || constraints.must_be_adjacent(i, j)) continue;
        if (around[i].size() - 1 >= level || around[j].size() - 1 >= level) tasks.push_back({i, j});
      }
    }
    if (tasks.empty()) break;

    std::vector<detail::edge_outcome> outcomes(tasks.size());
    // Parallel over tasks; when there are fewer tasks than threads, over rows within each test.
    const auto used = static_cast<unsigned>(std::min<std::size_t>(threads, tasks.size()));
    const unsigned count_threads = std::max(1u, threads / std::max(1u, used));
    static_cast<void>(detail::parallel_for(
        tasks.size(), {.threads = used}, [&] { return detail::skeleton_worker(columns, options, count_threads); },
        [&](detail::skeleton_worker& worker, detail::item_range chunk) {
          for (std::size_t t = chunk.begin; t < chunk.end; ++t) outcomes[t] = worker.run(tasks[t], level, around);
        }));

    for (std::size_t t = 0; t < tasks.size(); ++t) {
      auto& outcome = outcomes[t];
      result.tests += outcome.tests;
      if (!outcome.removed) continue;
      const auto x = detail::node(tasks[t].x);
      const auto y = detail::node(tasks[t].y);
      std::vector<variable_id> given;
      for (auto g : outcome.given) given.push_back(detail::node(g));
      graph.remove(x, y);
      result.sepsets.set(x, y, given);
      result.removed.push_back({x, y, std::move(given), outcome.test, false});
    }
  }
  std::sort(result.removed.begin(), result.removed.end(),
            [](const separation& a, const separation& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  return result;
}

/// PC-stable over `columns`: the skeleton, then background knowledge, v-structures and
/// Meek's rules. Throws model_error for bad options or knowledge naming unknown variables.
[[nodiscard]] inline pc_result pc_stable(std::span<const discrete_column* const> columns,
                                         const pc_options& options = {}) {
  std::vector<std::string> names;
  for (const auto* c : columns) names.push_back(c->name());
  const edge_constraints constraints(options.knowledge, names);
  auto skeleton = pc_skeleton(columns, constraints, options);
  pc_result result{
      std::move(skeleton.graph), std::move(skeleton.sepsets), std::move(skeleton.removed), skeleton.tests, {}};
  orient_by_knowledge(result.graph, constraints);
  orient_v_structures(result.graph, result.sepsets, result.conflicts);
  apply_meek_rules(result.graph, result.conflicts);
  return result;
}

/// PC-stable over the named columns of a data set. Throws data_error for a missing or
/// continuous column.
[[nodiscard]] inline pc_result pc_stable(const dataset& data, std::span<const std::string> columns,
                                         const pc_options& options = {}) {
  std::vector<const discrete_column*> picked;
  for (const auto& name : columns) picked.push_back(&data.discrete(name));
  return pc_stable(picked, options);
}

/// PC-stable over every column of a data set (all must be discrete).
[[nodiscard]] inline pc_result pc_stable(const dataset& data, const pc_options& options = {}) {
  const auto names = data.names();
  return pc_stable(data, names, options);
}

}  // namespace pgm
