#include "pgm/learn/hill_climbing.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/learn/learn_structure.hpp"
#include "pgm/learn/network_score.hpp"
#include "pgm/learn/structural_hamming_distance.hpp"
#include "pgm/learn/structure_prior.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::hill_climbing_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::vector<const discrete_column*> columns_of(const dataset& data) {
  std::vector<const discrete_column*> columns;
  for (const auto& name : data.names()) columns.push_back(&data.discrete(name));
  return columns;
}

// The score of a DAG from scratch: a fresh cache, no deltas.
double full_score(const dataset& data, const std::vector<named_edge>& edges, const family_score& score) {
  std::vector<variable> variables;
  for (const auto& name : data.names()) variables.push_back(data.discrete(name).var());
  return score_network(network_structure(variables, edges), data, score, 1).total;
}

bool acyclic(const std::vector<std::string>& names, const std::vector<named_edge>& edges) {
  try {
    dag graph(names);
    for (const auto& e : edges) graph.add_edge(e.from, e.to);
    return true;
  } catch (const not_a_dag&) {
    return false;
  }
}

// Every single addition, deletion and reversal of `edges` that keeps a DAG within the
// knowledge and in-degree limit, checked with a full cycle check, scored from scratch.
void expect_local_optimum(const dataset& data, const search_result& result, const search_options& options) {
  const auto names = data.names();
  const edge_constraints constraints(options.knowledge, names);
  const double here = full_score(data, result.edges, options.score);
  EXPECT_NEAR(here, result.score, 1e-9 * std::abs(here));
  auto has = [&](const std::vector<named_edge>& edges, const std::string& a, const std::string& b) {
    return std::find(edges.begin(), edges.end(), named_edge{a, b}) != edges.end();
  };
  auto in_degree = [&](const std::vector<named_edge>& edges, const std::string& node) {
    return static_cast<std::size_t>(
        std::count_if(edges.begin(), edges.end(), [&](const auto& e) { return e.to == node; }));
  };
  std::size_t tried = 0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    for (std::size_t j = 0; j < names.size(); ++j) {
      if (i == j) continue;
      const auto& a = names[i];
      const auto& b = names[j];
      std::vector<std::vector<named_edge>> neighbours;
      if (!has(result.edges, a, b) && !has(result.edges, b, a) && constraints.allowed(i, j)) {
        auto added = result.edges;
        added.push_back({a, b});
        neighbours.push_back(added);
      }
      if (has(result.edges, a, b) && !constraints.required(i, j)) {
        auto removed = result.edges;
        removed.erase(std::find(removed.begin(), removed.end(), named_edge{a, b}));
        neighbours.push_back(removed);
        if (constraints.allowed(j, i)) {
          removed.push_back({b, a});
          neighbours.push_back(removed);
        }
      }
      for (const auto& edges : neighbours) {
        if (!acyclic(names, edges)) continue;
        bool fits = true;
        for (const auto& n : names) fits = fits && in_degree(edges, n) <= options.max_parents;
        if (!fits) continue;
        ++tried;
        EXPECT_LE(full_score(data, edges, options.score), here + 1e-7) << "a move from " << a << " to " << b;
      }
    }
  }
  EXPECT_GT(tried, 0u);
}

bayesian_network asia() { return read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / "asia.bif"); }

TEST(hill_climbing_test, ends_at_a_local_optimum_of_every_score) {
  const auto data = sample(asia(), 4000, 7);
  for (const auto* score : {"bic", "aic", "bdeu[iss=5]", "k2"}) {
    search_options options;
    options.score = make_score(score);
    const auto result = hill_climb(columns_of(data), options);
    EXPECT_GT(result.edges.size(), 3u) << score;
    expect_local_optimum(data, result, options);
  }
}

TEST(hill_climbing_test, local_optimum_on_random_networks_with_limits) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 7, .max_parents = 3});
    const auto data = sample(net, 1500, seed);
    search_options options;
    options.max_parents = 2;
    options.knowledge.forbidden = {{data.names()[0], data.names()[1]}};
    const auto result = hill_climb(columns_of(data), options);
    expect_local_optimum(data, result, options);
    for (const auto& e : result.edges) EXPECT_FALSE(e.from == data.names()[0] && e.to == data.names()[1]);
  }
}

TEST(hill_climbing_test, same_result_on_any_number_of_threads) {
  const auto data = sample(testing::random_network(11, {.nodes = 9}), 3000, 5);
  for (std::size_t tabu : {0, 10}) {
    search_options options;
    options.tabu = tabu;
    options.restarts = 3;
    options.perturb = 3;
    options.seed = 42;
    options.threads = 1;
    const auto one = hill_climb(columns_of(data), options);
    options.threads = 2;
    const auto two = hill_climb(columns_of(data), options);
    options.threads = 5;
    const auto five = hill_climb(columns_of(data), options);
    EXPECT_EQ(one.edges, two.edges);
    EXPECT_EQ(one.edges, five.edges);
    EXPECT_EQ(one.score, two.score);
    EXPECT_EQ(one.moves, five.moves);
  }
}

TEST(hill_climbing_test, tabu_and_restarts_do_no_worse_than_plain_climbing) {
  const auto data = sample(testing::random_network(3, {.nodes = 10}), 2000, 9);
  search_options options;
  const auto plain = hill_climb(columns_of(data), options);
  options.tabu = 10;
  const auto tabu = hill_climb(columns_of(data), options);
  EXPECT_GE(tabu.score, plain.score - 1e-9);
  options.tabu = 0;
  options.restarts = 5;
  options.perturb = 4;
  const auto restarted = hill_climb(columns_of(data), options);
  EXPECT_GE(restarted.score, plain.score - 1e-9);
  EXPECT_EQ(restarted.restarts, 5u);
  expect_local_optimum(data, restarted, options);
  // The cache saves work: every restart comes back to families scored before.
  EXPECT_GT(restarted.cache_hits, 0u);
}

TEST(hill_climbing_test, descendant_sets_follow_every_move) {
  // The incremental reachability against a search from scratch, over random legal moves.
  const auto data = sample(testing::random_network(5, {.nodes = 8}), 200, 1);
  const auto columns = columns_of(data);
  family_score_cache cache(columns, {});
  const edge_constraints constraints(8);
  const search_options options;
  detail::search_state state(cache, constraints, options);
  state.load(std::vector<std::vector<std::size_t>>(8));
  std::mt19937_64 rng(3);
  for (int step = 0; step < 300; ++step) {
    const auto moves = detail::legal_moves(state);
    ASSERT_FALSE(moves.empty());
    const auto& move = moves[rng() % moves.size()];
    state.apply(move.kind, move.from, move.to);
    for (std::size_t a = 0; a < 8; ++a) {
      std::vector<char> seen(8, 0);
      std::vector<std::size_t> stack{a};
      while (!stack.empty()) {
        const auto v = stack.back();
        stack.pop_back();
        for (std::size_t c = 0; c < 8; ++c) {
          if (state.has_edge(v, c) && !seen[c]) {
            seen[c] = 1;
            stack.push_back(c);
          }
        }
      }
      for (std::size_t b = 0; b < 8; ++b) ASSERT_EQ(state.reaches(a, b), seen[b] != 0) << a << " ~> " << b;
    }
    // The family scores and gains are those of the current graph.
    for (std::size_t j = 0; j < 8; ++j) {
      EXPECT_EQ(state.node_score(j), cache.score({j, state.parents(j)}));
    }
  }
}

TEST(hill_climbing_test, knowledge_start_network_and_errors) {
  const auto data = sample(asia(), 3000, 2);
  const auto names = data.names();
  search_options options;
  options.knowledge.required = {{"asia", "either"}};
  options.knowledge.tiers = {{"asia", "smoke"}, {"tub", "lung", "bronc", "either"}, {"xray", "dysp"}};
  const auto result = hill_climb(columns_of(data), options);
  EXPECT_NE(std::find(result.edges.begin(), result.edges.end(), named_edge{"asia", "either"}), result.edges.end());
  const auto tier = [&](const std::string& v) {
    for (std::size_t t = 0; t < options.knowledge.tiers.size(); ++t) {
      const auto& names_in = options.knowledge.tiers[t];
      if (std::find(names_in.begin(), names_in.end(), v) != names_in.end()) return t;
    }
    return std::size_t{99};
  };
  for (const auto& e : result.edges) EXPECT_LE(tier(e.from), tier(e.to)) << e.from << "->" << e.to;
  expect_local_optimum(data, result, options);

  // From the true network, hill climbing ends no worse than it.
  search_options from_truth;
  const auto truth = asia().structure().edges();
  from_truth.start = truth;
  const auto climbed = hill_climb(columns_of(data), from_truth);
  EXPECT_GE(climbed.score, full_score(data, truth, {}) - 1e-9);

  search_options bad;
  bad.start = {{"asia", "tub"}, {"tub", "asia"}};
  EXPECT_THROW(static_cast<void>(hill_climb(columns_of(data), bad)), not_a_dag);
  bad.start = {{"asia", "nope"}};
  EXPECT_THAT([&] { static_cast<void>(hill_climb(columns_of(data), bad)); },
              ThrowsMessage<model_error>(HasSubstr("edge asia->nope names a variable not in the data")));
  bad.start = {{"xray", "asia"}};
  bad.knowledge = options.knowledge;
  EXPECT_THAT([&] { static_cast<void>(hill_climb(columns_of(data), bad)); },
              ThrowsMessage<model_error>(HasSubstr("has the edge xray->asia, which the background knowledge forbids")));
  bad = {};
  bad.start = {{"asia", "either"}, {"tub", "either"}, {"lung", "either"}};
  bad.max_parents = 2;
  EXPECT_THAT(
      [&] { static_cast<void>(hill_climb(columns_of(data), bad)); },
      ThrowsMessage<model_error>(HasSubstr("'either' has 3 parents in the start network, more than the maximum 2")));
}

TEST(structure_prior_test, mapped_edges_and_their_bonus) {
  // 1-Stack's network carried over to 2-Stack by the paper's map.
  const std::vector<named_edge> prior{{"xOff1", "onTop1"}, {"yOff1", "onTop1"}};
  const auto map = parse_correspondence("onTop2=onTop1,xOff2~xOff1,yOff2~yOff1");
  const std::vector<std::string> target{"xOff1", "yOff1", "onTop1", "xOff2", "yOff2", "onTop2", "colour"};
  EXPECT_EQ(mapped_prior_edges(prior, map, target), (std::vector<named_edge>{{"xOff1", "onTop1"},
                                                                             {"xOff1", "onTop2"},
                                                                             {"yOff1", "onTop1"},
                                                                             {"yOff1", "onTop2"},
                                                                             {"xOff2", "onTop1"},
                                                                             {"xOff2", "onTop2"},
                                                                             {"yOff2", "onTop1"},
                                                                             {"yOff2", "onTop2"}}));
  EXPECT_TRUE(mapped_prior_edges(prior, {}, {"a", "b"}).empty());

  // On asia with few rows: a large weight puts the favoured edges in; weight 0 changes nothing;
  // the result is a local optimum of score + bonus; the bonus is reported apart.
  const auto net = asia();
  const auto data = sample(net, 60, 3);
  search_options plain;
  const auto scratch = hill_climb(columns_of(data), plain);
  search_options favoured;
  favoured.favoured = net.structure().edges();
  favoured.favour_weight = 0.0;
  const auto zero = hill_climb(columns_of(data), favoured);
  EXPECT_EQ(zero.edges, scratch.edges);
  EXPECT_EQ(zero.prior_bonus, 0.0);
  favoured.favour_weight = 1000.0;
  const auto strong = hill_climb(columns_of(data), favoured);
  for (const auto& e : net.structure().edges()) {
    EXPECT_NE(std::find(strong.edges.begin(), strong.edges.end(), e), strong.edges.end()) << e.from << "->" << e.to;
  }
  EXPECT_DOUBLE_EQ(strong.prior_bonus, 1000.0 * static_cast<double>(net.structure().edges().size()));
  EXPECT_NEAR(strong.score - strong.prior_bonus, full_score(data, strong.edges, {}), 1e-9 * std::abs(strong.score));
  favoured.favour_weight = 3.0;
  const auto mild = hill_climb(columns_of(data), favoured);
  std::size_t matching = 0;
  for (const auto& e : mild.edges) {
    matching += std::find(favoured.favoured.begin(), favoured.favoured.end(), e) != favoured.favoured.end();
  }
  EXPECT_NEAR(mild.prior_bonus, 3.0 * static_cast<double>(matching), 1e-12);
  EXPECT_NEAR(mild.score - mild.prior_bonus, full_score(data, mild.edges, {}), 1e-9 * std::abs(mild.score));
  favoured.favour_weight = -1;
  EXPECT_THAT([&] { static_cast<void>(hill_climb(columns_of(data), favoured)); },
              ThrowsMessage<model_error>(HasSubstr("weight must be a number from 0 to 1e+12, got -1")));
  // Past the bound a few edges' bonuses would overflow the score (issue #49: "bic = -nan").
  favoured.favour_weight = 1e308;
  EXPECT_THAT([&] { static_cast<void>(hill_climb(columns_of(data), favoured)); },
              ThrowsMessage<model_error>(HasSubstr("got 1e+308")));
}

}  // namespace
}  // namespace pgm::hill_climbing_tests
