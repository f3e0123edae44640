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
#include "pgm/core/compilation.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/learn/background_knowledge.hpp"
#include "pgm/learn/family_score_cache.hpp"
#include "pgm/learn/score_registry.hpp"

namespace pgm {

struct search_options {
  /// Any family score (pgm/learn/score_registry.hpp); bic by default.
  family_score score;
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
  /// From 0 to max_favour_weight.
  double favour_weight = 0.0;
};

/// The largest structure-prior weight: more outweighs any data's score (a log-likelihood of 10⁹
/// rows is ~10¹⁰ nats), and bonuses summed over every edge stay far from a double's range.
inline constexpr double max_favour_weight = 1e12;

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

[[nodiscard]] PGM_DECL std::uint64_t splitmix64(std::uint64_t x) noexcept;

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
  PGM_DECL search_state(family_score_cache& cache, const edge_constraints& constraints, const search_options& options);

  [[nodiscard]] std::size_t size() const noexcept { return n_; }
  [[nodiscard]] bool has_edge(std::size_t i, std::size_t j) const { return edge_[i * n_ + j] != 0; }
  [[nodiscard]] const std::vector<std::size_t>& parents(std::size_t j) const { return parents_[j]; }
  [[nodiscard]] const std::vector<std::vector<std::size_t>>& all_parents() const noexcept { return parents_; }
  [[nodiscard]] double node_score(std::size_t j) const { return node_score_[j]; }
  [[nodiscard]] std::uint64_t hash() const noexcept { return hash_; }
  [[nodiscard]] const std::vector<unsigned char>& edges() const noexcept { return edge_; }

  /// The sum of the node scores, in node order, and of the structure prior's bonus.
  [[nodiscard]] PGM_DECL double total() const;

  /// The structure prior's bonus of the edges present, summed in edge order.
  [[nodiscard]] PGM_DECL double prior_bonus() const;

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
  PGM_DECL void load(const std::vector<std::vector<std::size_t>>& parents);

  /// Whether i may become a parent of j (knowledge, candidates and in-degree allowing).
  [[nodiscard]] PGM_DECL bool may_add(std::size_t i, std::size_t j) const;

  /// The gain of toggling i in pa(j); NaN when not a candidate.
  [[nodiscard]] double delta(std::size_t i, std::size_t j) const { return delta_[i * n_ + j]; }

  /// Whether the move keeps the graph acyclic and every constraint.
  [[nodiscard]] PGM_DECL bool legal(move_kind kind, std::size_t i, std::size_t j) const;

  /// The gain of a legal move.
  [[nodiscard]] PGM_DECL double gain(move_kind kind, std::size_t i, std::size_t j) const;

  /// The hash of the graph after the move (for the tabu list).
  [[nodiscard]] std::uint64_t hash_after(move_kind kind, std::size_t i, std::size_t j) const {
    const auto h = hash_ ^ zobrist_[i * n_ + j];
    return kind == move_kind::reverse ? h ^ zobrist_[j * n_ + i] : h;
  }

  /// Whether the graph after the move equals `graph` (an edge matrix).
  [[nodiscard]] PGM_DECL bool equal_after(move_kind kind, std::size_t i, std::size_t j,
                                          const std::vector<unsigned char>& graph) const;

  PGM_DECL void apply(move_kind kind, std::size_t i, std::size_t j);

 private:
  static double nan() { return std::numeric_limits<double>::quiet_NaN(); }

  // Whether i reaches j other than by the edge i -> j: through another parent of j.
  [[nodiscard]] PGM_DECL bool other_path(std::size_t i, std::size_t j) const;

  PGM_DECL void set_edge(std::size_t i, std::size_t j, bool present);

  // Descendant sets from scratch: nodes in reverse topological order, each the union of its
  // children and their sets.
  PGM_DECL void rebuild_reach();

  // Scores the families of `targets` and the gains of toggling each candidate parent.
  PGM_DECL void refresh(const std::vector<std::size_t>& targets);

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

  PGM_DECL void push(const search_state& state);
  [[nodiscard]] PGM_DECL bool holds(const search_state& state, move_kind kind, std::size_t i, std::size_t j) const;
};

/// The best legal move whose gain beats `threshold` by more than the tolerance, scanning
/// additions, deletions and reversals in node order; none when no move does.
[[nodiscard]] PGM_DECL std::optional<search_move> best_move(const search_state& state, double threshold,
                                                            const tabu_list* tabu);

/// Every legal move, in scan order (for perturbations and tests).
[[nodiscard]] PGM_DECL std::vector<search_move> legal_moves(const search_state& state);

/// Hill climbing (or tabu search) from the state's graph to a local optimum; returns the moves made.
PGM_DECL std::size_t climb(search_state& state, const search_options& options);

}  // namespace detail

/// Learns a DAG over `columns` (node i is columns[i]) by hill climbing, tabu search and restarts.
/// Throws model_error for bad options, knowledge naming unknown variables, or a start network
/// that is cyclic, names unknown variables, breaks the knowledge or the in-degree limit.
[[nodiscard]] PGM_DECL search_result hill_climb(std::span<const discrete_column* const> columns,
                                                const search_options& options = {});

/// Hill climbing over the named columns of a data set (all discrete).
[[nodiscard]] PGM_DECL search_result hill_climb(const dataset& data, std::span<const std::string> columns,
                                                const search_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/hill_climbing.ipp"
#endif
