#pragma once
/// \file
/// Adjustment: which sets of variables identify the effect of X on Y from observational data,
/// and the estimate they give.
///
/// - Back-door criterion (Pearl) for Z relative to (X, Y): no node of Z descends from X, and Z
///   d-separates X from Y in the graph without X's outgoing edges.
/// - Minimal back-door sets: every set satisfying it with no proper subset that does, looked for
///   among the ancestors of X ∪ Y that do not descend from X (where every minimal one lies), by
///   increasing size, up to a limit on the sets examined (`complete` says whether it was reached).
/// - Front-door criterion for M relative to (X, Y): M intercepts every directed path from X to Y,
///   X has no unblocked back-door path to M, and X blocks every back-door path from M to Y.
/// - The adjustment formula from data, P(y | do(x)) = Σ_z P(y | x, z) P(z), counted from a data
///   set: the estimate one makes when the graph is trusted but not the tables. A stratum z where
///   x never occurs cannot be estimated (positivity); its probability mass is reported.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pgm/causal/d_separation.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/sufficient_statistics.hpp"

namespace pgm {

namespace detail {

/// The nodes `next` leads to from `start`, repeatedly (the start nodes included).
template <class Next>
[[nodiscard]] std::vector<bool> reachable(const dag& graph, std::span<const variable_id> start, Next next) {
  std::vector<bool> reached(graph.size(), false);
  std::vector<variable_id> stack(start.begin(), start.end());
  while (!stack.empty()) {
    const auto v = stack.back();
    stack.pop_back();
    if (reached[v.value()]) continue;
    reached[v.value()] = true;
    for (auto w : next(v)) stack.push_back(w);
  }
  return reached;
}

/// The nodes reachable from `from` along directed edges (themselves included).
[[nodiscard]] inline std::vector<bool> descendants(const dag& graph, std::span<const variable_id> from) {
  return reachable(graph, from, [&](variable_id v) { return graph.children(v); });
}

/// The nodes from which a directed path leads into `of` (themselves included).
[[nodiscard]] inline std::vector<bool> ancestors(const dag& graph, std::span<const variable_id> of) {
  return reachable(graph, of, [&](variable_id v) { return graph.parents(v); });
}

/// The graph without the edges out of `nodes`.
[[nodiscard]] PGM_DECL dag without_edges_out_of(const dag& graph, std::span<const variable_id> nodes);

}  // namespace detail

/// Whether Z satisfies the back-door criterion relative to (X, Y).
[[nodiscard]] PGM_DECL bool satisfies_backdoor(const dag& graph, std::span<const variable_id> x,
                                               std::span<const variable_id> y, std::span<const variable_id> z);

/// Whether M satisfies the front-door criterion relative to (X, Y).
[[nodiscard]] PGM_DECL bool satisfies_frontdoor(const dag& graph, std::span<const variable_id> x,
                                                std::span<const variable_id> y, std::span<const variable_id> m);

/// The minimal back-door sets of (X, Y), each sorted by id, in order of size then ids.
struct backdoor_sets {
  std::vector<std::vector<variable_id>> sets;
  /// Whether every candidate subset was examined (false: `limit` cut the search).
  bool complete = true;
  std::size_t examined = 0;
};

[[nodiscard]] PGM_DECL backdoor_sets minimal_backdoor_sets(const dag& graph, std::span<const variable_id> x,
                                                           std::span<const variable_id> y, std::size_t limit = 100'000);

/// P(Y | do(X = x)) for every x, by the adjustment formula over Z from the data's counts.
struct adjusted_estimate {
  /// values[x·|Y| + y] = P(Y = y | do(X = x)); a column is uniform where no stratum supports x.
  std::vector<double> values;
  std::size_t x_states = 0;
  std::size_t y_states = 0;
  /// For each x, the share of the data in strata z where x never occurs (the positivity
  /// violation); the estimate there leaves those strata out and renormalizes.
  std::vector<double> unsupported;
  std::size_t rows = 0;
};

/// Counts (Z…, X, Y) in `data` (discrete columns) and evaluates the adjustment formula. Throws
/// data_error for a missing or continuous column, model_error for X or Y among Z or X = Y.
[[nodiscard]] PGM_DECL adjusted_estimate adjust(const dataset& data, const std::string& x, const std::string& y,
                                                std::span<const std::string> z, const count_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/causal/impl/adjustment.ipp"
#endif
