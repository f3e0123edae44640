#pragma once
/// \file
/// Triangulation by greedy elimination: the order in which exact inference eliminates
/// variables, and the cliques that order creates. `moral_graph` turns a network into the
/// undirected Boost.Graph graph of its factors' interactions (each node joined to its parents,
/// parents married); `greedy_elimination` runs on any Boost.Graph graph that lists vertices and
/// adjacent vertices, so a user's own interaction graph works too.
///
/// Each step eliminates the remaining vertex of least cost, joining its remaining neighbours
/// ("fill-in" edges). Costs, compared as tuples, ties by the lower vertex index:
///   min_fill   — (fill-in edges, neighbours)       fewest new edges
///   min_degree — (neighbours)                      fewest neighbours
///   min_weight — (clique weight, fill-in edges)    smallest table, weight = Π cardinalities
/// Scores are kept per vertex and recomputed only within two steps of the eliminated one, the
/// only vertices whose fill-in or weight can change.

#include <algorithm>
#include <array>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/graph_concepts.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/splitmix.hpp"

namespace pgm {

enum class elimination_heuristic {
  min_fill,    ///< fewest new edges among the neighbours; ties by degree, then id
  min_degree,  ///< fewest neighbours; ties by id
  min_weight   ///< smallest product of cardinalities of the clique; ties by fill-in, then id
};

inline constexpr std::array all_elimination_heuristics{
    elimination_heuristic::min_fill, elimination_heuristic::min_degree, elimination_heuristic::min_weight};

[[nodiscard]] constexpr std::string_view to_string(elimination_heuristic heuristic) noexcept {
  switch (heuristic) {
    case elimination_heuristic::min_fill:
      return "min-fill";
    case elimination_heuristic::min_degree:
      return "min-degree";
    case elimination_heuristic::min_weight:
      return "min-weight";
  }
  return "?";
}

/// "min-fill", "min-degree" or "min-weight"; throws unknown_name otherwise.
[[nodiscard]] inline elimination_heuristic parse_elimination_heuristic(std::string_view text) {
  return parse_choice("elimination heuristic", text, all_elimination_heuristics);
}

[[nodiscard]] inline std::vector<std::string> known_elimination_heuristics() {
  return names_of(all_elimination_heuristics);
}

/// The undirected graph of a network's factors: vertex i is node i.
using interaction_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;

/// Each node joined to its parents and its parents to each other.
[[nodiscard]] PGM_DECL interaction_graph moral_graph(const bayesian_network& network);

/// The graph of `n` variables in which two are joined when some scope holds both: a model's
/// factors' interactions (a Bayesian network's families give its moral graph).
[[nodiscard]] PGM_DECL interaction_graph interaction_graph_of(std::size_t n,
                                                              std::span<const std::vector<variable_id>> scopes);

/// The result of eliminating vertices in a greedy order.
struct elimination {
  /// The eliminated vertices, in order.
  std::vector<std::size_t> order;
  /// cliques[k]: order[k] with its neighbours still present when it went, ascending.
  std::vector<std::vector<std::size_t>> cliques;
  std::size_t fill_in_edges = 0;
  /// The steps taken (vertices scanned, adjacencies tested): the search's time on any machine.
  std::size_t work = 0;
};

namespace detail {

/// A symmetric adjacency matrix of bits: O(1) edge tests, words of 64 vertices at a time.
class bit_adjacency {
 public:
  explicit bit_adjacency(std::size_t n) : words_((n + 63) / 64), bits_(n * words_, 0) {}
  [[nodiscard]] bool test(std::size_t a, std::size_t b) const noexcept {
    return (bits_[a * words_ + b / 64] >> (b % 64)) & 1U;
  }
  void set(std::size_t a, std::size_t b) noexcept {
    bits_[a * words_ + b / 64] |= std::uint64_t{1} << (b % 64);
    bits_[b * words_ + a / 64] |= std::uint64_t{1} << (a % 64);
  }

 private:
  std::size_t words_;
  std::vector<std::uint64_t> bits_;
};

}  // namespace detail

/// Eliminates the vertices flagged in `eliminate` (all when empty) of `graph` greedily by
/// `heuristic`; `cardinalities` (one per vertex) weigh cliques for min_weight. The vertices not
/// eliminated stay, as neighbours only. Ties go to the lower vertex index, or, with a non-zero
/// `tie_seed`, to one of the tied vertices drawn from that seed (an order search's restarts).
template <class Graph>
[[nodiscard]] elimination greedy_elimination(const Graph& graph, std::span<const std::size_t> cardinalities,
                                             elimination_heuristic heuristic, std::span<const bool> eliminate = {},
                                             std::uint64_t tie_seed = 0) {
  BOOST_CONCEPT_ASSERT((boost::VertexListGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((boost::AdjacencyGraphConcept<Graph>));
  const std::size_t n = boost::num_vertices(graph);
  PGM_ASSERT(cardinalities.size() == n, "one cardinality per vertex");
  PGM_ASSERT(eliminate.empty() || eliminate.size() == n, "one flag per vertex");
  const auto index = boost::get(boost::vertex_index, graph);

  detail::bit_adjacency adjacent(n);
  std::vector<std::vector<std::size_t>> neighbours(n);
  for (auto v : boost::make_iterator_range(boost::vertices(graph))) {
    for (auto w : boost::make_iterator_range(boost::adjacent_vertices(v, graph))) {
      const std::size_t a = index[v];
      const std::size_t b = index[w];
      if (a != b && !adjacent.test(a, b)) {
        adjacent.set(a, b);
        neighbours[a].push_back(b);
        neighbours[b].push_back(a);
      }
    }
  }
  std::vector<char> gone(n, 0);
  std::vector<char> candidate(n, 1);
  if (!eliminate.empty()) {
    for (std::size_t v = 0; v < n; ++v) candidate[v] = eliminate[v] ? 1 : 0;
  }
  std::vector<double> log_card(n);
  for (std::size_t v = 0; v < n; ++v) log_card[v] = std::log(static_cast<double>(cardinalities[v]));

  elimination result;
  using cost = std::tuple<double, double>;
  auto score = [&](std::size_t v) -> cost {
    const auto& around = neighbours[v];
    double fill = 0.0;
    result.work += around.size() * around.size() / 2 + 1;
    if (heuristic != elimination_heuristic::min_degree) {
      for (std::size_t i = 0; i < around.size(); ++i) {
        for (std::size_t j = i + 1; j < around.size(); ++j) fill += adjacent.test(around[i], around[j]) ? 0.0 : 1.0;
      }
    }
    const auto degree = static_cast<double>(around.size());
    switch (heuristic) {
      case elimination_heuristic::min_fill:
        return {fill, degree};
      case elimination_heuristic::min_degree:
        return {degree, 0.0};
      case elimination_heuristic::min_weight: {
        double weight = log_card[v];
        for (auto w : around) weight += log_card[w];
        return {weight, fill};
      }
    }
    return {0.0, 0.0};
  };
  std::vector<cost> costs(n);
  std::size_t remaining = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (candidate[v]) {
      costs[v] = score(v);
      ++remaining;
    }
  }

  result.order.reserve(remaining);
  result.cliques.reserve(remaining);
  std::vector<std::size_t> touched;
  std::vector<char> mark(n, 0);
  std::uint64_t draws = 0;
  while (remaining-- > 0) {
    std::size_t best = n;
    std::size_t tied = 0;
    result.work += n;
    for (std::size_t v = 0; v < n; ++v) {
      if (!candidate[v] || gone[v]) continue;
      if (best == n || costs[v] < costs[best]) {
        best = v;
        tied = 1;
      } else if (tie_seed != 0 && costs[v] == costs[best]) {
        // Reservoir sampling: each of the tied vertices is kept with probability 1/tied.
        if (detail::mix_seed(tie_seed, draws++) % ++tied == 0) best = v;
      }
    }
    auto& around = neighbours[best];
    result.work += around.size() * around.size() / 2;
    for (std::size_t i = 0; i < around.size(); ++i) {
      for (std::size_t j = i + 1; j < around.size(); ++j) {
        const auto a = around[i];
        const auto b = around[j];
        if (!adjacent.test(a, b)) {
          adjacent.set(a, b);
          neighbours[a].push_back(b);
          neighbours[b].push_back(a);
          ++result.fill_in_edges;
        }
      }
    }
    std::vector<std::size_t> clique = around;
    clique.push_back(best);
    std::sort(clique.begin(), clique.end());
    result.order.push_back(best);
    result.cliques.push_back(std::move(clique));
    gone[best] = 1;
    // The eliminated vertex leaves its neighbours' lists; their scores and those of their
    // neighbours change.
    touched.clear();
    for (auto w : around) {
      auto& list = neighbours[w];
      list.erase(std::find(list.begin(), list.end(), best));
      for (auto x : list) {
        if (!mark[x]) {
          mark[x] = 1;
          touched.push_back(x);
        }
      }
      if (!mark[w]) {
        mark[w] = 1;
        touched.push_back(w);
      }
    }
    for (auto x : touched) {
      mark[x] = 0;
      if (candidate[x] && !gone[x]) costs[x] = score(x);
    }
    around.clear();
  }
  return result;
}

/// The cells of the tables an elimination creates, together (saturating).
[[nodiscard]] inline std::size_t elimination_cells(const elimination& e, std::span<const std::size_t> cardinalities) {
  std::size_t total = 0;
  for (const auto& clique : e.cliques) {
    std::size_t cells = 1;
    for (auto v : clique) cells = detail::saturating_multiply(cells, cardinalities[v]);
    total = detail::saturating_add(total, cells);
  }
  return total;
}

/// How hard to look for an elimination order: greedy once, or greedy with `restarts` more runs
/// that break ties at random (seeded, so the same seed gives the same order), keeping the order
/// whose tables are smallest together, as Merlin and the Julia solvers search. The restarts stop
/// early once their work (elimination::work) would pass `work_per_cell` times the cells of the
/// best order so far: a search need not cost more than the propagation it could shorten, and
/// counting steps rather than seconds keeps one seed one order on any machine.
struct order_search {
  std::size_t restarts = 0;
  std::uint64_t seed = 1;
  double work_per_cell = std::numeric_limits<double>::infinity();
};

/// The best of the greedy orders `search` asks for (ties in size to the earlier run).
template <class Graph>
[[nodiscard]] elimination searched_elimination(const Graph& graph, std::span<const std::size_t> cardinalities,
                                               elimination_heuristic heuristic, const order_search& search) {
  auto best = greedy_elimination(graph, cardinalities, heuristic);
  auto best_cells = elimination_cells(best, cardinalities);
  const auto one_run = static_cast<double>(best.work);
  double spent = 0.0;
  for (std::size_t r = 0; r < search.restarts; ++r) {
    spent += one_run;
    if (spent > search.work_per_cell * static_cast<double>(best_cells)) break;
    auto next = greedy_elimination(graph, cardinalities, heuristic, {}, detail::mix_seed(search.seed, r) | 1U);
    const auto cells = elimination_cells(next, cardinalities);
    if (cells < best_cells) {
      best = std::move(next);
      best_cells = cells;
    }
  }
  return best;
}

/// The cardinality of every variable of `model`, in id order.
template <GraphicalModel M>
[[nodiscard]] std::vector<std::size_t> cardinalities_of(const M& model) {
  std::vector<std::size_t> cards;
  cards.reserve(model.size());
  for (const auto& v : model.variables()) cards.push_back(v.cardinality());
  return cards;
}

/// Every factor's scope, in factor order.
template <GraphicalModel M>
[[nodiscard]] std::vector<std::vector<variable_id>> scopes_of(const M& model) {
  std::vector<std::vector<variable_id>> scopes;
  scopes.reserve(model.factor_count());
  for (std::size_t f = 0; f < model.factor_count(); ++f) scopes.push_back(model.factor_scope(f));
  return scopes;
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/triangulation.ipp"
#endif
