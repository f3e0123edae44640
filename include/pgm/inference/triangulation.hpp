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
///   min_weight — (clique cells, fill-in edges)     smallest table, cells = Π cardinalities
/// Scores are kept per vertex: the eliminated vertex's neighbours are scored again, and the
/// vertices next to both ends of a fill-in edge have their fill-in lowered by one, the only
/// changes an elimination makes.

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
#include <utility>
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
  std::vector<char> candidate(n, 1);
  if (!eliminate.empty()) {
    for (std::size_t v = 0; v < n; ++v) candidate[v] = eliminate[v] ? 1 : 0;
  }

  elimination result;
  // fill[v]: the pairs of v's remaining neighbours not yet joined (min_fill, min_weight).
  const bool counts_fill = heuristic != elimination_heuristic::min_degree;
  std::vector<std::size_t> fill(n, 0);
  auto count_fill = [&](std::size_t v) {
    const auto& around = neighbours[v];
    std::size_t missing = 0;
    result.work += around.size() * around.size() / 2 + 1;
    for (std::size_t i = 0; i < around.size(); ++i) {
      for (std::size_t j = i + 1; j < around.size(); ++j) missing += adjacent.test(around[i], around[j]) ? 0 : 1;
    }
    fill[v] = missing;
  };
  // Scores are integers (edges, neighbours, cells), compared as pairs.
  using cost = std::pair<std::size_t, std::size_t>;
  auto cost_of = [&](std::size_t v) -> cost {
    const auto degree = neighbours[v].size();
    switch (heuristic) {
      case elimination_heuristic::min_fill:
        return {fill[v], degree};
      case elimination_heuristic::min_degree:
        return {degree, 0};
      case elimination_heuristic::min_weight: {
        std::size_t cells = cardinalities[v];
        for (auto w : neighbours[v]) cells = detail::saturating_multiply(cells, cardinalities[w]);
        return {cells, fill[v]};
      }
    }
    return {0, 0};
  };
  std::vector<cost> costs(n);
  // The vertices still to eliminate, ascending (ties go to the first).
  std::vector<std::size_t> pending;
  for (std::size_t v = 0; v < n; ++v) {
    if (candidate[v]) {
      if (counts_fill) count_fill(v);
      costs[v] = cost_of(v);
      pending.push_back(v);
    }
  }

  result.order.reserve(pending.size());
  result.cliques.reserve(pending.size());
  std::vector<std::pair<std::size_t, std::size_t>> joined;
  std::vector<std::size_t> lowered;
  std::vector<char> mark(n, 0);
  std::uint64_t draws = 0;
  while (!pending.empty()) {
    std::size_t at = 0;
    std::size_t tied = 1;
    result.work += pending.size();
    for (std::size_t i = 1; i < pending.size(); ++i) {
      const auto& c = costs[pending[i]];
      if (c < costs[pending[at]]) {
        at = i;
        tied = 1;
      } else if (tie_seed != 0 && c == costs[pending[at]]) {
        // Reservoir sampling: each of the tied vertices is kept with probability 1/tied.
        if (detail::mix_seed(tie_seed, draws++) % ++tied == 0) at = i;
      }
    }
    const std::size_t best = pending[at];
    pending.erase(pending.begin() + static_cast<std::ptrdiff_t>(at));
    auto& around = neighbours[best];
    result.work += around.size() * around.size() / 2;
    joined.clear();
    for (std::size_t i = 0; i < around.size(); ++i) {
      for (std::size_t j = i + 1; j < around.size(); ++j) {
        const auto a = around[i];
        const auto b = around[j];
        if (!adjacent.test(a, b)) {
          adjacent.set(a, b);
          neighbours[a].push_back(b);
          neighbours[b].push_back(a);
          joined.emplace_back(a, b);
        }
      }
    }
    result.fill_in_edges += joined.size();
    std::vector<std::size_t> clique = around;
    clique.push_back(best);
    std::sort(clique.begin(), clique.end());
    result.order.push_back(best);
    result.cliques.push_back(std::move(clique));
    // Only the eliminated vertex's neighbours lose a neighbour or gain one, and are scored
    // again; any other vertex's fill drops by one for each new edge that joins two of its
    // neighbours, and nothing else of its score changes.
    constexpr char neighbour = 1;
    constexpr char lowered_once = 2;
    for (auto w : around) {
      auto& list = neighbours[w];
      list.erase(std::find(list.begin(), list.end(), best));
      mark[w] = neighbour;
    }
    lowered.clear();
    if (counts_fill) {
      for (auto [a, b] : joined) {
        const bool a_shorter = neighbours[a].size() <= neighbours[b].size();
        const auto& shorter = a_shorter ? neighbours[a] : neighbours[b];
        const auto other = a_shorter ? b : a;
        result.work += shorter.size();
        for (auto x : shorter) {
          if (mark[x] == neighbour || x == other || !adjacent.test(x, other)) continue;
          --fill[x];
          if (mark[x] != lowered_once) {
            mark[x] = lowered_once;
            lowered.push_back(x);
          }
        }
      }
    }
    for (auto w : around) {
      mark[w] = 0;
      if (!candidate[w]) continue;
      if (counts_fill) count_fill(w);
      costs[w] = cost_of(w);
    }
    for (auto x : lowered) {
      mark[x] = 0;
      if (candidate[x]) costs[x] = cost_of(x);
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
