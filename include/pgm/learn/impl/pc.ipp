#pragma once
// The definitions of pgm/learn/pc.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/pc.hpp"

namespace pgm::detail {

PGM_DECL bool next_subset(std::vector<std::size_t>& pick, std::size_t n) {
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

PGM_DECL edge_outcome skeleton_worker::run(const edge_task& task, std::size_t level,
                                           const std::vector<std::vector<std::size_t>>& around) {
  edge_outcome outcome;
  const auto from_x = others(around[task.x], task.y);
  const auto from_y = others(around[task.y], task.x);
  if (search(task, level, from_x, nullptr, outcome)) return outcome;
  std::fill(tried_.begin(), tried_.end(), 0);
  for (auto v : from_x) tried_[v] = 1;
  search(task, level, from_y, &tried_, outcome);
  return outcome;
}

PGM_DECL std::vector<std::size_t> skeleton_worker::others(const std::vector<std::size_t>& nodes, std::size_t skip) {
  std::vector<std::size_t> result;
  for (auto v : nodes) {
    if (v != skip) result.push_back(v);
  }
  return result;
}

PGM_DECL bool skeleton_worker::search(const edge_task& task, std::size_t level,
                                      const std::vector<std::size_t>& candidates, const std::vector<char>* already,
                                      edge_outcome& outcome) {
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
    const auto result = options_.test(std::span<const std::uint64_t>(counts_), columns_[task.x]->var().cardinality(),
                                      columns_[task.y]->var().cardinality());
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

PGM_DECL void check_pc_options(const pc_options& options) {
  if (!(options.alpha > 0.0 && options.alpha < 1.0)) {
    throw model_error("alpha must lie strictly between 0 and 1, got " + text::format_short(options.alpha));
  }
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL skeleton_result pc_skeleton(std::span<const discrete_column* const> columns,
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

PGM_DECL pc_result pc_stable(std::span<const discrete_column* const> columns, const pc_options& options) {
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

PGM_DECL pc_result pc_stable(const dataset& data, std::span<const std::string> columns, const pc_options& options) {
  std::vector<const discrete_column*> picked;
  for (const auto& name : columns) picked.push_back(&data.discrete(name));
  return pc_stable(picked, options);
}

}  // namespace pgm
