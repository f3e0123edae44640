// Greedy elimination keeps its scores up to date step by step; these tests check it against the
// plain rule, every remaining vertex scored afresh at every step, on random graphs, for every
// heuristic, with ties broken by index and by seed, with some vertices not eliminated.

#include "pgm/inference/triangulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "pgm/detail/splitmix.hpp"

namespace pgm {
namespace triangulation_test {

/// The greedy rule as written: each step scores every remaining vertex on the graph as it is.
std::vector<std::size_t> plain_greedy_order(std::size_t n, std::vector<std::pair<std::size_t, std::size_t>> edges,
                                            const std::vector<std::size_t>& cards, elimination_heuristic heuristic,
                                            const std::vector<bool>& eliminate, std::uint64_t tie_seed) {
  std::vector<std::vector<bool>> adjacent(n, std::vector<bool>(n, false));
  for (auto [a, b] : edges) {
    if (a != b) adjacent[a][b] = adjacent[b][a] = true;
  }
  std::vector<bool> gone(n, false);
  auto neighbours_of = [&](std::size_t v) {
    std::vector<std::size_t> around;
    for (std::size_t w = 0; w < n; ++w) {
      if (!gone[w] && adjacent[v][w]) around.push_back(w);
    }
    return around;
  };
  auto score = [&](std::size_t v) -> std::tuple<double, double> {
    const auto around = neighbours_of(v);
    double fill = 0.0;
    for (std::size_t i = 0; i < around.size(); ++i) {
      for (std::size_t j = i + 1; j < around.size(); ++j) fill += adjacent[around[i]][around[j]] ? 0.0 : 1.0;
    }
    double weight = static_cast<double>(cards[v]);
    for (auto w : around) weight *= static_cast<double>(cards[w]);
    const auto degree = static_cast<double>(around.size());
    switch (heuristic) {
      case elimination_heuristic::min_fill:
        return {fill, degree};
      case elimination_heuristic::min_degree:
        return {degree, 0.0};
      case elimination_heuristic::min_weight:
        return {weight, fill};
    }
    return {0.0, 0.0};
  };
  std::vector<std::size_t> order;
  std::uint64_t draws = 0;
  const auto count = static_cast<std::size_t>(std::count(eliminate.begin(), eliminate.end(), true));
  while (order.size() < count) {
    std::size_t best = n;
    std::size_t tied = 0;
    std::tuple<double, double> best_score;
    for (std::size_t v = 0; v < n; ++v) {
      if (!eliminate[v] || gone[v]) continue;
      const auto s = score(v);
      if (best == n || s < best_score) {
        best = v;
        best_score = s;
        tied = 1;
      } else if (tie_seed != 0 && s == best_score) {
        if (detail::mix_seed(tie_seed, draws++) % ++tied == 0) best = v;
      }
    }
    const auto around = neighbours_of(best);
    for (auto a : around) {
      for (auto b : around) {
        if (a != b) adjacent[a][b] = true;
      }
    }
    gone[best] = true;
    order.push_back(best);
  }
  return order;
}

TEST(triangulation_test, kept_scores_choose_as_scoring_every_vertex_afresh_does) {
  std::mt19937_64 random(2026);
  std::size_t compared = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const std::size_t n = 5 + random() % 40;
    const double density = 0.05 + 0.3 * static_cast<double>(random() % 100) / 100.0;
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    interaction_graph graph(n);
    std::bernoulli_distribution draw(density);
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = a + 1; b < n; ++b) {
        if (draw(random)) {
          edges.emplace_back(a, b);
          boost::add_edge(a, b, graph);
        }
      }
    }
    std::vector<std::size_t> cards(n);
    for (auto& c : cards) c = 2 + random() % 3;
    std::vector<bool> eliminate(n, true);
    if (trial % 3 == 0) {
      for (std::size_t v = 0; v < n; ++v) eliminate[v] = random() % 4 != 0;
    }
    std::unique_ptr<bool[]> flags(new bool[n]);
    for (std::size_t v = 0; v < n; ++v) flags[v] = eliminate[v];
    for (auto heuristic : all_elimination_heuristics) {
      for (std::uint64_t seed : {std::uint64_t{0}, static_cast<std::uint64_t>(trial) * 7 + 1}) {
        const auto kept = greedy_elimination(graph, cards, heuristic, std::span<const bool>(flags.get(), n), seed);
        EXPECT_EQ(kept.order, plain_greedy_order(n, edges, cards, heuristic, eliminate, seed))
            << "trial " << trial << ", " << to_string(heuristic) << ", seed " << seed;
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 120U * 3U * 2U);
}

TEST(triangulation_test, the_cliques_and_fill_in_are_those_the_order_makes) {
  // A 4-cycle a-b-c-d: eliminating a first joins b and d, one fill-in edge.
  interaction_graph graph(4);
  boost::add_edge(0, 1, graph);
  boost::add_edge(1, 2, graph);
  boost::add_edge(2, 3, graph);
  boost::add_edge(3, 0, graph);
  const std::vector<std::size_t> cards{2, 3, 2, 5};
  const auto e = greedy_elimination(graph, cards, elimination_heuristic::min_fill);
  EXPECT_EQ(e.fill_in_edges, 1U);
  ASSERT_EQ(e.order.size(), 4U);
  EXPECT_EQ(e.order.front(), 0U);  // every vertex would add one edge; ties to the lowest index
  EXPECT_EQ(e.cliques.front(), (std::vector<std::size_t>{0, 1, 3}));
  // Then b, c, d each close a triangle: cliques {1,2,3}, {2,3}, {3}.
  EXPECT_EQ(elimination_cells(e, cards), 2U * 3U * 5U + 3U * 2U * 5U + 2U * 5U + 5U);
}

}  // namespace triangulation_test
}  // namespace pgm
