#pragma once
/// \file
/// Score-based structure search over DAGs (pgm/learn/score.hpp): greedy hill climbing with
/// arc additions, deletions and reversals, tabu search, and random restarts with perturbation.
///
/// Moves. Each step scans the moves in a fixed order — every addition i -> j (i, then j, in
/// node order), then every deletion, then every reversal, as bnlearn's hc() does — and takes a
/// move only when its score gain exceeds the best one so far by more than `tolerance`
/// (sqrt(DBL_EPSILON), bnlearn's): ties go to the earliest move in that order. Gains come from a
/// table delta[i][j] = score(j, pa(j) xor {i}) - score(j, pa(j)), refreshed only for the nodes a
/// move changed, and family scores come from a cache keyed by (node, parent set)
/// (pgm/learn/family_score_cache.hpp). The families to score are scored in parallel, each into its
/// own slot, and the scan is sequential, so the search is the same for any number of threads.
///
/// Acyclicity is kept incrementally: `reach` holds, for every node, the set of its descendants
/// (a bit set per node). Adding i -> j is legal when j does not reach i; reversing i -> j is
/// legal when no other parent of j is reachable from i. An addition updates the sets of i and
/// its ancestors; a deletion or a reversal recomputes them in one pass in topological order.
///
/// Tabu search (bnlearn's tabu(), tabu list length 10, max.tabu 10): the last `tabu` networks
/// visited are remembered; a step takes the best improving move to a network not among them, or
/// when there is none the best move of any gain (the least loss), at most `max_tabu` times in a
/// row without improving on the best network seen, which is the result.
///
/// Random restarts (bnlearn's restart and perturb): after the search converges, the best network
/// so far is perturbed by `perturb` random legal moves (drawn with a generator seeded by the seed
/// and the restart's number) and searched again, `restarts` times; the best network is kept.

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/learn/background_knowledge.hpp"
#include "pgm/learn/family_score_cache.hpp"
#include "pgm/learn/score.hpp"

namespace pgm {

struct search_options {
  score_choice score;
  /// The most parents a node may have.
  std::size_t max_parents = std::numeric_limits<std::size_t>::max();
  /// Tiers and forbidden edges restrict the moves; required edges are in the start network
  /// and never deleted nor reversed.
  background_knowledge knowledge;
  /// The network the search starts from (empty: the empty graph).
  std::vector<named_edge> start;
  /// Tabu list length; 0 is plain hill climbing.
  std::size_t tabu = 0;
  /// Moves in a row that do not improve on the best network before tabu search stops.
  std::size_t max_tabu = 10;
  std::size_t restarts = 0;
  /// Random moves of each restart's perturbation.
  std::size_t perturb = 1;
  std::uint64_t seed = 1;
  /// The most moves of one search (each restart and tabu step counts one).
  std::size_t max_iterations = std::numeric_limits<std::size_t>::max();
  /// Worker threads; 0 uses every hardware thread. The result is the same for any number.
  unsigned threads = 0;
  /// Which parents are considered: candidates[i * n + j] != 0 when i may become a parent of j
  /// (a hybrid's skeleton); empty: every one.
  std::vector<unsigned char> candidates;
  /// A structure prior: each of these edges adds `favour_weight` to the score while it is in the
  /// network (pgm/learn/structure_prior.hpp maps a related task's network to them).
  std::vector<named_edge> favoured;
  double favour_weight = 0.0;
};

struct search_result {
  /// The learned DAG, edges ordered by (parent, child) in column order.
  std::vector<named_edge> edges;
  /// The objective: the sum of the node scores and the structure prior's bonus.
  double score = 0.0;
  /// The structure prior's part of `score` (favour_weight per favoured edge present).
  double prior_bonus = 0.0;
  /// Each node's term, in column order.
  std::vector<double> node_scores;
  /// Moves made, over all restarts.
  std::size_t moves = 0;
  std::size_t restarts = 0;
  /// Families counted and scored, and family scores found in the cache.
  std::size_t families_scored = 0;
  std::size_t cache_hits = 0;
};

namespace detail {

/// bnlearn's MACHINE_TOL.
inline const double search_tolerance = std::sqrt(DBL_EPSILON);

[[nodiscard]] inline std::uint64_t splitmix64(std::uint64_t x) noexcept {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

enum class move_kind { add, remove, reverse };

struct search_move {
  move_kind kind = move_kind::add;
  std::size_t from = 0;
  std::size_t to = 0;
  double gain = 0.0;
};

/// A DAG over n nodes with its descendant sets, its family scores and the score gain of
/// toggling each candidate parent.
class search_state {
 public:
  search_state(family_score_cache& cache, const edge_constraints& constraints, const search_options& options)
      : cache_(cache),
        constraints_(constraints),
        options_(options),
        n_(cache.size()),
        words_((n_ + 63) / 64),
        edge_(n_ * n_, 0),
        parents_(n_),
        reach_(n_ * words_, 0),
        delta_(n_ * n_, nan()),
        node_score_(n_, 0.0),
        zobrist_(n_ * n_),
        bonus_(n_ * n_, 0.0) {
    for (std::size_t k = 0; k < zobrist_.size(); ++k) zobrist_[k] = splitmix64(k * 0x2545f4914f6cdd1dULL + 24);
  }

  [[nodiscard]] std::size_t size() const noexcept { return n_; }
  [[nodiscard]] bool has_edge(std::size_t i, std::size_t j) const { return edge_[i * n_ + j] != 0; }
  [[nodiscard]] const std::vector<std::size_t>& parents(std::size_t j) const { return parents_[j]; }
  [[nodiscard]] const std::vector<std::vector<std::size_t>>& all_parents() const noexcept { return parents_; }
  [[nodiscard]] double node_score(std::size_t j) const { return node_score_[j]; }
  [[nodiscard]] std::uint64_t hash() const noexcept { return hash_; }
  [[nodiscard]] const std::vector<unsigned char>& edges() const noexcept { return edge_; }

  /// The sum of the node scores, in node order, and of the structure prior's bonus.
  [[nodiscard]] double total() const {
    double sum = 0.0;
    for (auto s : node_score_) sum += s;
    return sum + prior_bonus();
  }

  /// The structure prior's bonus of the edges present, summed in edge order.
  [[nodiscard]] double prior_bonus() const {
    double sum = 0.0;
    if (!has_bonus_) return sum;
    for (std::size_t k = 0; k < edge_.size(); ++k) {
      if (edge_[k]) sum += bonus_[k];
    }
    return sum;
  }

  /// Sets the bonus of every edge i -> j (n * n values).
  void set_bonus(std::vector<double> bonus) {
    bonus_ = std::move(bonus);
    has_bonus_ = std::any_of(bonus_.begin(), bonus_.end(), [](double b) { return b != 0.0; });
  }

  /// Whether a ~> b by a directed path of one edge or more.
  [[nodiscard]] bool reaches(std::size_t a, std::size_t b) const {
    return (reach_[a * words_ + b / 64] >> (b % 64)) & 1U;
  }

  /// Sets the graph to `parents` (a DAG) and scores every family and candidate.
  void load(const std::vector<std::vector<std::size_t>>& parents) {
    std::fill(edge_.begin(), edge_.end(), 0);
    hash_ = 0;
    for (std::size_t j = 0; j < n_; ++j) {
      parents_[j] = parents[j];
      std::sort(parents_[j].begin(), parents_[j].end());
      for (auto i : parents_[j]) {
        edge_[i * n_ + j] = 1;
        hash_ ^= zobrist_[i * n_ + j];
      }
    }
    rebuild_reach();
    std::vector<std::size_t> all(n_);
    for (std::size_t j = 0; j < n_; ++j) all[j] = j;
    refresh(all);
  }

  /// Whether i may become a parent of j (knowledge, candidates and in-degree allowing).
  [[nodiscard]] bool may_add(std::size_t i, std::size_t j) const {
    if (!constraints_.allowed(i, j)) return false;
    if (!options_.candidates.empty() && !options_.candidates[i * n_ + j]) return false;
    return parents_[j].size() < options_.max_parents;
  }

  /// The gain of toggling i in pa(j); NaN when not a candidate.
  [[nodiscard]] double delta(std::size_t i, std::size_t j) const { return delta_[i * n_ + j]; }

  /// Whether the move keeps the graph acyclic and every constraint.
  [[nodiscard]] bool legal(move_kind kind, std::size_t i, std::size_t j) const {
    switch (kind) {
      case move_kind::add:
        return !has_edge(i, j) && !has_edge(j, i) && may_add(i, j) && !reaches(j, i);
      case move_kind::remove:
        return has_edge(i, j) && !constraints_.required(i, j);
      case move_kind::reverse:
        return has_edge(i, j) && !constraints_.required(i, j) && may_add(j, i) && !other_path(i, j);
    }
    return false;
  }

  /// The gain of a legal move.
  [[nodiscard]] double gain(move_kind kind, std::size_t i, std::size_t j) const {
    if (kind != move_kind::reverse) return delta(i, j);
    double value = delta(i, j) + delta(j, i);
    if (std::abs(value) < search_tolerance) value = 0.0;
    return value;
  }

  /// The hash of the graph after the move (for the tabu list).
  [[nodiscard]] std::uint64_t hash_after(move_kind kind, std::size_t i, std::size_t j) const {
    const auto h = hash_ ^ zobrist_[i * n_ + j];
    return kind == move_kind::reverse ? h ^ zobrist_[j * n_ + i] : h;
  }

  /// Whether the graph after the move equals `graph` (an edge matrix).
  [[nodiscard]] bool equal_after(move_kind kind, std::size_t i, std::size_t j,
                                 const std::vector<unsigned char>& graph) const {
    for (std::size_t k = 0; k < edge_.size(); ++k) {
      unsigned char e = edge_[k];
      if (k == i * n_ + j) e ^= 1;
      if (kind == move_kind::reverse && k == j * n_ + i) e ^= 1;
      if (e != graph[k]) return false;
    }
    return true;
  }

  void apply(move_kind kind, std::size_t i, std::size_t j) {
    switch (kind) {
      case move_kind::add:
        set_edge(i, j, true);
        // i and every ancestor of i now reach j and j's descendants.
        for (std::size_t x = 0; x < n_; ++x) {
          if (x != i && !reaches(x, i)) continue;
          reach_[x * words_ + j / 64] |= std::uint64_t{1} << (j % 64);
          for (std::size_t w = 0; w < words_; ++w) reach_[x * words_ + w] |= reach_[j * words_ + w];
        }
        refresh(std::vector<std::size_t>{j});
        break;
      case move_kind::remove:
        set_edge(i, j, false);
        rebuild_reach();
        refresh(std::vector<std::size_t>{j});
        break;
      case move_kind::reverse:
        set_edge(i, j, false);
        set_edge(j, i, true);
        rebuild_reach();
        refresh(std::vector<std::size_t>{std::min(i, j), std::max(i, j)});
        break;
    }
  }

 private:
  static double nan() { return std::numeric_limits<double>::quiet_NaN(); }

  // Whether i reaches j other than by the edge i -> j: through another parent of j.
  [[nodiscard]] bool other_path(std::size_t i, std::size_t j) const {
    for (auto p : parents_[j]) {
      if (p != i && reaches(i, p)) return true;
    }
    return false;
  }

  void set_edge(std::size_t i, std::size_t j, bool present) {
    edge_[i * n_ + j] = present ? 1 : 0;
    hash_ ^= zobrist_[i * n_ + j];
    auto& pa = parents_[j];
    if (present) {
      pa.insert(std::lower_bound(pa.begin(), pa.end(), i), i);
    } else {
      pa.erase(std::find(pa.begin(), pa.end(), i));
    }
  }

  // Descendant sets from scratch: nodes in reverse topological order, each the union of its
  // children and their sets.
  void rebuild_reach() {
    std::fill(reach_.begin(), reach_.end(), 0);
    std::vector<std::size_t> indegree(n_), order;
    order.reserve(n_);
    for (std::size_t j = 0; j < n_; ++j) {
      indegree[j] = parents_[j].size();
      if (indegree[j] == 0) order.push_back(j);
    }
    for (std::size_t k = 0; k < order.size(); ++k) {
      const auto v = order[k];
      for (std::size_t c = 0; c < n_; ++c) {
        if (has_edge(v, c) && --indegree[c] == 0) order.push_back(c);
      }
    }
    PGM_ASSERT(order.size() == n_, "the search's graph has a cycle");
    for (std::size_t k = order.size(); k-- > 0;) {
      const auto v = order[k];
      for (std::size_t c = 0; c < n_; ++c) {
        if (!has_edge(v, c)) continue;
        reach_[v * words_ + c / 64] |= std::uint64_t{1} << (c % 64);
        for (std::size_t w = 0; w < words_; ++w) reach_[v * words_ + w] |= reach_[c * words_ + w];
      }
    }
  }

  // Scores the families of `targets` and the gains of toggling each candidate parent.
  void refresh(const std::vector<std::size_t>& targets) {
    std::vector<family_key> keys;
    std::vector<std::size_t> slots;  // delta slot, or n*n + j for node j's own family
    for (auto j : targets) {
      keys.push_back({j, parents_[j]});
      slots.push_back(n_ * n_ + j);
      for (std::size_t i = 0; i < n_; ++i) {
        delta_[i * n_ + j] = nan();
        if (i == j) continue;
        const bool present = has_edge(i, j);
        if (!present && !may_add(i, j)) continue;
        family_key key{j, parents_[j]};
        if (present) {
          key.parents.erase(std::find(key.parents.begin(), key.parents.end(), i));
        } else {
          key.parents.insert(std::lower_bound(key.parents.begin(), key.parents.end(), i), i);
        }
        keys.push_back(std::move(key));
        slots.push_back(i * n_ + j);
      }
    }
    const auto values = cache_.score_all(keys);
    for (std::size_t k = 0; k < keys.size(); ++k) {
      if (slots[k] >= n_ * n_) node_score_[slots[k] - n_ * n_] = values[k];
    }
    for (std::size_t k = 0; k < keys.size(); ++k) {
      if (slots[k] < n_ * n_) {
        const auto slot = slots[k];
        delta_[slot] = values[k] - node_score_[slot % n_] + (edge_[slot] ? -bonus_[slot] : bonus_[slot]);
      }
    }
  }

  family_score_cache& cache_;
  const edge_constraints& constraints_;
  const search_options& options_;
  std::size_t n_;
  std::size_t words_;
  std::vector<unsigned char> edge_;
  std::vector<std::vector<std::size_t>> parents_;
  std::vector<std::uint64_t> reach_;
  std::vector<double> delta_;
  std::vector<double> node_score_;
  std::vector<std::uint64_t> zobrist_;
  std::uint64_t hash_ = 0;
  std::vector<double> bonus_;
  bool has_bonus_ = false;
};

/// The networks a tabu search visited last.
struct tabu_list {
  std::size_t length = 0;
  std::vector<std::pair<std::uint64_t, std::vector<unsigned char>>> graphs;
  std::size_t next = 0;

  void push(const search_state& state) {
    if (length == 0) return;
    if (graphs.size() < length) {
      graphs.emplace_back(state.hash(), state.edges());
    } else {
      graphs[next] = {state.hash(), state.edges()};
    }
    next = (next + 1) % length;
  }
  [[nodiscard]] bool holds(const search_state& state, move_kind kind, std::size_t i, std::size_t j) const {
    const auto h = state.hash_after(kind, i, j);
    for (const auto& [hash, graph] : graphs) {
      if (hash == h && state.equal_after(kind, i, j, graph)) return true;
    }
    return false;
  }
};

/// The best legal move whose gain beats `threshold` by more than the tolerance, scanning
/// additions, deletions and reversals in node order; none when no move does.
[[nodiscard]] inline std::optional<search_move> best_move(const search_state& state, double threshold,
                                                          const tabu_list* tabu) {
  std::optional<search_move> best;
  double bar = threshold;
  const std::size_t n = state.size();
  for (auto kind : {move_kind::add, move_kind::remove, move_kind::reverse}) {
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        if (i == j) continue;
        // Cheap checks first: the gain, then legality and the tabu list.
        if (kind == move_kind::add ? state.has_edge(i, j) || state.has_edge(j, i) : !state.has_edge(i, j)) continue;
        const double g = state.gain(kind, i, j);
        if (std::isnan(g) || !(g - bar > search_tolerance)) continue;
        if (!state.legal(kind, i, j)) continue;
        if (tabu && tabu->holds(state, kind, i, j)) continue;
        best = search_move{kind, i, j, g};
        bar = g;
      }
    }
  }
  return best;
}

/// Every legal move, in scan order (for perturbations and tests).
[[nodiscard]] inline std::vector<search_move> legal_moves(const search_state& state) {
  std::vector<search_move> moves;
  const std::size_t n = state.size();
  for (auto kind : {move_kind::add, move_kind::remove, move_kind::reverse}) {
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        if (i != j && state.legal(kind, i, j)) moves.push_back({kind, i, j, 0.0});
      }
    }
  }
  return moves;
}

/// Hill climbing (or tabu search) from the state's graph to a local optimum; returns the moves made.
inline std::size_t climb(search_state& state, const search_options& options) {
  std::size_t moves = 0;
  if (options.tabu == 0) {
    while (moves < options.max_iterations) {
      const auto move = best_move(state, 0.0, nullptr);
      if (!move) break;
      state.apply(move->kind, move->from, move->to);
      ++moves;
    }
    return moves;
  }
  tabu_list tabu{options.tabu, {}, 0};
  tabu.push(state);
  auto best = state.all_parents();
  double best_score = state.total();
  std::size_t loss = 0;
  bool at_best = true;
  while (moves < options.max_iterations) {
    auto move = best_move(state, 0.0, &tabu);
    if (!move) {
      if (loss >= options.max_tabu) break;
      ++loss;
      move = best_move(state, -std::numeric_limits<double>::infinity(), &tabu);
      if (!move) break;
    }
    state.apply(move->kind, move->from, move->to);
    ++moves;
    tabu.push(state);
    at_best = false;
    if (state.total() - best_score > search_tolerance) {
      best = state.all_parents();
      best_score = state.total();
      loss = 0;
      at_best = true;
    }
  }
  if (!at_best) state.load(best);
  return moves;
}

}  // namespace detail

/// Learns a DAG over `columns` (node i is columns[i]) by hill climbing, tabu search and restarts.
/// Throws model_error for bad options, knowledge naming unknown variables, or a start network
/// that is cyclic, names unknown variables, breaks the knowledge or the in-degree limit.
[[nodiscard]] inline search_result hill_climb(std::span<const discrete_column* const> columns,
                                              const search_options& options = {}) {
  const std::size_t n = columns.size();
  std::vector<std::string> names;
  for (const auto* c : columns) names.push_back(c->name());
  const edge_constraints constraints(options.knowledge, names);
  if (!options.candidates.empty() && options.candidates.size() != n * n) {
    throw model_error("the candidate parents are for another set of variables");
  }
  family_score_cache cache(columns, options.score, options.threads);

  // The start network: the given edges and the required ones.
  std::map<std::string, std::size_t, std::less<>> index;
  for (std::size_t i = 0; i < n; ++i) index.emplace(names[i], i);
  std::vector<std::vector<std::size_t>> start(n);
  auto start_edge = [&](std::size_t i, std::size_t j) {
    if (std::find(start[j].begin(), start[j].end(), i) == start[j].end()) start[j].push_back(i);
  };
  for (const auto& e : options.start) {
    const auto from = index.find(e.from);
    const auto to = index.find(e.to);
    for (const auto& it : {from, to}) {
      if (it == index.end()) {
        throw model_error("the start network's edge " + e.from + "->" + e.to + " names a variable not in the data (" +
                          detail::list_for_message(names) + ")");
      }
    }
    if (!constraints.allowed(from->second, to->second)) {
      throw model_error("the start network has the edge " + e.from + "->" + e.to +
                        ", which the background knowledge forbids");
    }
    start_edge(from->second, to->second);
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (!constraints.required(i, j)) continue;
      if (std::find(start[i].begin(), start[i].end(), j) != start[i].end()) {
        throw model_error("edge " + names[i] + "->" + names[j] + " is required, but the start network has " + names[j] +
                          "->" + names[i]);
      }
      start_edge(i, j);
    }
  }
  {
    std::vector<named_edge> edges;
    for (std::size_t j = 0; j < n; ++j) {
      if (start[j].size() > options.max_parents) {
        throw model_error("'" + names[j] + "' has " + std::to_string(start[j].size()) +
                          " parents in the start network, more than the maximum " +
                          std::to_string(options.max_parents));
      }
      for (auto i : start[j]) edges.push_back({names[i], names[j]});
    }
    dag check(names);
    for (const auto& e : edges) check.add_edge(e.from, e.to);  // throws not_a_dag on a cycle
  }

  detail::search_state state(cache, constraints, options);
  if (!options.favoured.empty()) {
    if (!(options.favour_weight >= 0.0) || !std::isfinite(options.favour_weight)) {
      throw model_error("the structure prior's weight must be a finite number >= 0, got " +
                        detail::format_short(options.favour_weight));
    }
    std::vector<double> bonus(n * n, 0.0);
    for (const auto& e : options.favoured) {
      const auto from = index.find(e.from);
      const auto to = index.find(e.to);
      if (from == index.end() || to == index.end() || from->second == to->second) {
        throw model_error("the favoured edge " + e.from + "->" + e.to + " is not between two variables of the data");
      }
      bonus[from->second * n + to->second] = options.favour_weight;
    }
    state.set_bonus(std::move(bonus));
  }
  state.load(start);
  search_result result;
  result.moves = detail::climb(state, options);
  auto best = state.all_parents();
  double best_score = state.total();
  for (std::size_t r = 0; r < options.restarts; ++r) {
    // Perturb the best network so far with random legal moves, then climb again.
    std::uint64_t stream = detail::splitmix64(options.seed ^ detail::splitmix64(r + 1));
    for (std::size_t p = 0; p < options.perturb; ++p) {
      const auto moves = detail::legal_moves(state);
      if (moves.empty()) break;
      stream = detail::splitmix64(stream);
      const auto& move = moves[stream % moves.size()];
      state.apply(move.kind, move.from, move.to);
    }
    result.moves += detail::climb(state, options);
    ++result.restarts;
    if (state.total() - best_score > detail::search_tolerance) {
      best = state.all_parents();
      best_score = state.total();
    } else {
      state.load(best);
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (state.has_edge(i, j)) result.edges.push_back({names[i], names[j]});
    }
  }
  for (std::size_t j = 0; j < n; ++j) result.node_scores.push_back(state.node_score(j));
  result.score = state.total();
  result.prior_bonus = state.prior_bonus();
  result.families_scored = cache.computed();
  result.cache_hits = cache.hits();
  return result;
}

/// Hill climbing over the named columns of a data set (all discrete).
[[nodiscard]] inline search_result hill_climb(const dataset& data, std::span<const std::string> columns,
                                              const search_options& options = {}) {
  std::vector<const discrete_column*> picked;
  for (const auto& name : columns) picked.push_back(&data.discrete(name));
  return hill_climb(picked, options);
}

}  // namespace pgm
