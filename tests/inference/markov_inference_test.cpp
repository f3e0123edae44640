// The four tasks (pgm/inference/solve.hpp) on random Markov networks against brute force, on
// Bayesian networks against the engines, in log space where Z overflows a double, and the limits.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <thread>
#include <tuple>
#include <vector>

#include "pgm/core/graphical_model.hpp"
#include "pgm/inference/junction_tree_engine.hpp"
#include "pgm/inference/propagation.hpp"
#include "pgm/inference/solve.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/testing/random_markov_network.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm {
namespace markov_inference_test {

using ::testing::HasSubstr;

solve_options with_engine(solve_engine engine) {
  solve_options options;
  options.engine = engine;
  return options;
}

// Relative to the size of ln Z, as a double holds it.
double log_tolerance(double log_z) { return 1e-12 * std::max(1.0, std::abs(log_z)); }

TEST(markov_inference_test, every_task_equals_brute_force_on_random_models) {
  std::size_t impossible = 0;
  std::size_t checked = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    testing::random_markov_options shape;
    shape.variables = 3 + seed % 5;
    shape.factors = 2 + seed % 7;
    shape.zero_chance = seed % 3 == 0 ? 0.3 : 0.05;
    const auto model = testing::random_markov_network(seed, shape);
    std::vector<long> fixed;
    const auto observed = testing::random_hard_evidence(model, seed * 7919, fixed);
    const auto truth = testing::brute_force(model, fixed);
    for (const auto engine : {solve_engine::jt, solve_engine::ve}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", engine " + std::string(to_string(engine)));
      const auto options = with_engine(engine);
      const double log_z = log_partition(model, observed, options);
      if (truth.log_z == -INFINITY) {
        ++impossible;
        EXPECT_EQ(log_z, -INFINITY);
        EXPECT_THROW(static_cast<void>(all_marginals(model, observed, options)), impossible_evidence);
        EXPECT_THROW(static_cast<void>(most_probable_assignment(model, observed, options)), impossible_evidence);
        continue;
      }
      ++checked;
      EXPECT_NEAR(log_z, truth.log_z, log_tolerance(truth.log_z));
      const auto marginals = all_marginals(model, observed, options);
      ASSERT_EQ(marginals.size(), model.size());
      for (std::size_t i = 0; i < model.size(); ++i) {
        ASSERT_EQ(marginals[i].size(), truth.marginals[i].size());
        for (std::size_t s = 0; s < marginals[i].size(); ++s)
          EXPECT_NEAR(marginals[i][s], truth.marginals[i][s], 1e-12);
      }
      const auto map = most_probable_assignment(model, observed, options);
      EXPECT_NEAR(testing::log_value(model, map), truth.log_max, log_tolerance(truth.log_max));
      for (std::size_t i = 0; i < model.size(); ++i) {
        if (fixed[i] >= 0) {
          EXPECT_EQ(map[i], static_cast<std::size_t>(fixed[i]));
        }
      }
      std::vector<variable_id> query;
      for (std::size_t i = 0; i < model.size(); i += 2) query.push_back(index_at<variable_id>(i));
      const auto mmap = marginal_map(model, query, observed, options);
      const auto best = testing::brute_force_marginal_map(model, query, fixed);
      EXPECT_NEAR(testing::brute_force_query_value(model, query, mmap, fixed), best, log_tolerance(best));
    }
  }
  // The property is tested on both kinds of evidence.
  EXPECT_GT(checked, 80U);
  EXPECT_GT(impossible, 0U);
}

TEST(markov_inference_test, a_partition_function_beyond_a_double_is_exact_in_log_space) {
  testing::random_markov_options shape;
  shape.variables = 6;
  shape.factors = 40;
  shape.zero_chance = 0.0;
  shape.scale = 150.0;  // factors of e^±150, forty of them: Z far past e^709
  const auto model = testing::random_markov_network(3, shape);
  const std::vector<long> fixed(model.size(), -1);
  const auto truth = testing::brute_force(model, fixed);
  ASSERT_GT(truth.log_z, std::log(std::numeric_limits<double>::max()));
  solve_report report;
  EXPECT_NEAR(log_partition(model, {}, {}, &report), truth.log_z, log_tolerance(truth.log_z));
  EXPECT_TRUE(report.log_space);
  const auto marginals = all_marginals(model, {}, {});
  for (std::size_t i = 0; i < model.size(); ++i) {
    for (std::size_t s = 0; s < marginals[i].size(); ++s) EXPECT_NEAR(marginals[i][s], truth.marginals[i][s], 1e-12);
  }
  EXPECT_NEAR(testing::log_value(model, most_probable_assignment(model, {}, {})), truth.log_max,
              log_tolerance(truth.log_max));
}

TEST(markov_inference_test, a_variable_in_no_factor_is_uniform_and_counts_in_z) {
  const markov_network model({variable("a", {"0", "1"}), variable("b", {"0", "1", "2"})},
                             {factor_table({variable_id(0)}, {2}, {1.0, 3.0})});
  for (const auto engine : {solve_engine::jt, solve_engine::ve}) {
    EXPECT_NEAR(log_partition(model, {}, with_engine(engine)), std::log(4.0 * 3.0), 1e-15);
    const auto marginals = all_marginals(model, {}, with_engine(engine));
    EXPECT_NEAR(marginals[0][1], 0.75, 1e-15);
    EXPECT_NEAR(marginals[1][2], 1.0 / 3.0, 1e-15);
  }
}

TEST(markov_inference_test, a_bayesian_network_answers_as_its_engines_do) {
  const auto network = read_bif(std::string(PGM_NETWORKS_DIR) + "/asia.bif");
  static_assert(GraphicalModel<bayesian_network>);
  evidence_set observed;
  observed.hard.push_back({network.id("xray"), network.at("xray").state("yes")});
  observed.hard.push_back({network.id("smoke"), network.at("smoke").state("no")});
  junction_tree_engine reference(network);
  reference.set_evidence(observed);
  EXPECT_NEAR(log_partition(network, observed), reference.log_probability_of_evidence(), 1e-14);
  const auto marginals = all_marginals(network, observed);
  for (std::size_t i = 0; i < network.size(); ++i) {
    const variable_id id = index_at<variable_id>(i);
    if (observed.fixes(id)) continue;
    const variable_id one[] = {id};
    const auto expected = reference.joint(one);
    for (std::size_t s = 0; s < marginals[i].size(); ++s)
      EXPECT_NEAR(marginals[i][s], expected.table.values()[s], 1e-14);
  }
  const auto map = most_probable_assignment(network, observed);
  const auto mpe = reference.mpe({});
  std::size_t k = 0;
  for (std::size_t i = 0; i < network.size(); ++i) {
    const variable_id id = index_at<variable_id>(i);
    if (!observed.fixes(id)) {
      EXPECT_EQ(map[i], mpe.states[k++].value());
    }
  }
}

TEST(markov_inference_test, a_tree_past_the_memory_limit_is_refused_before_it_is_built) {
  testing::random_markov_options shape;
  shape.variables = 14;
  shape.factors = 30;
  shape.min_states = 4;
  const auto model = testing::random_markov_network(5, shape);
  solve_options options;
  options.engine = solve_engine::jt;
  options.memory_limit_bytes = 1024;
  try {
    static_cast<void>(log_partition(model, {}, options));
    FAIL() << "expected memory_limit_exceeded";
  } catch (const memory_limit_exceeded& e) {
    EXPECT_THAT(e.what(), HasSubstr("cells"));
    EXPECT_THAT(e.what(), HasSubstr("largest table"));
    EXPECT_THAT(e.what(), HasSubstr("memory limit of 0 MiB"));
  }
  std::vector<variable_id> query{variable_id(0), variable_id(1)};
  EXPECT_THROW(static_cast<void>(marginal_map(model, query, {}, options)), memory_limit_exceeded);
}

TEST(markov_inference_test, the_order_search_is_seeded_budgeted_and_never_worse_than_greedy) {
  testing::random_markov_options shape;
  shape.variables = 30;
  shape.factors = 45;
  shape.max_arity = 3;
  const auto model = testing::random_markov_network(11, shape);
  const auto cards = cardinalities_of(model);
  const auto graph = interaction_graph_of(model.size(), scopes_of(model));
  const auto greedy = greedy_elimination(graph, cards, elimination_heuristic::min_fill);
  const auto searched =
      searched_elimination(graph, cards, elimination_heuristic::min_fill, {.restarts = 20, .seed = 7});
  const auto again = searched_elimination(graph, cards, elimination_heuristic::min_fill, {.restarts = 20, .seed = 7});
  EXPECT_LE(elimination_cells(searched, cards), elimination_cells(greedy, cards));
  EXPECT_EQ(searched.order, again.order);
  // Every order eliminates every variable once.
  auto sorted = searched.order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::size_t> all(model.size());
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(sorted, all);
  // The restarts stop where their work would pass work_per_cell times the best tree's cells.
  EXPECT_GT(greedy.work, model.size());
  const auto none = searched_elimination(graph, cards, elimination_heuristic::min_fill,
                                         {.restarts = 20, .seed = 7, .work_per_cell = 0.0});
  EXPECT_EQ(none.order, greedy.order);
  const auto ample = searched_elimination(graph, cards, elimination_heuristic::min_fill,
                                          {.restarts = 20, .seed = 7, .work_per_cell = 1e9});
  EXPECT_EQ(ample.order, searched.order);
}

// A Markov network of these scopes over variables of these cardinalities, its values drawn as
// exp(U[-scale, scale]) with some zeros.
markov_network model_of(const std::vector<std::size_t>& cards, const std::vector<std::vector<std::size_t>>& scopes,
                        std::uint64_t seed, double scale) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<variable> variables;
  for (std::size_t i = 0; i < cards.size(); ++i) {
    std::vector<std::string> labels;
    for (std::size_t s = 0; s < cards[i]; ++s) labels.push_back(std::to_string(s));
    variables.emplace_back("v" + std::to_string(i), labels);
  }
  std::vector<factor_table> factors;
  for (const auto& scope : scopes) {
    std::vector<variable_id> ids;
    std::vector<std::size_t> scope_cards;
    std::size_t cells = 1;
    for (auto v : scope) {
      ids.push_back(index_at<variable_id>(v));
      scope_cards.push_back(cards[v]);
      cells *= cards[v];
    }
    std::vector<double> values(cells);
    for (auto& v : values) v = unit(engine) < 0.1 ? 0.0 : std::exp((2 * unit(engine) - 1) * scale);
    factors.emplace_back(std::move(ids), std::move(scope_cards), std::move(values));
  }
  return markov_network(std::move(variables), std::move(factors));
}

// Six binary variables under forty factors of one or two of them, every value e^U[low, high].
markov_network small_valued_model(std::uint64_t seed, double low, double high) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> exponent(low, high);
  std::vector<variable> variables;
  for (int i = 0; i < 6; ++i) variables.emplace_back("v" + std::to_string(i), std::vector<std::string>{"0", "1"});
  std::vector<factor_table> factors;
  for (std::size_t f = 0; f < 40; ++f) {
    std::vector<variable_id> scope{index_at<variable_id>(f % 6)};
    if (f % 3 != 0) scope.push_back(index_at<variable_id>((f * 5 + 1) % 6));
    if (scope.size() == 2 && scope[0] == scope[1]) scope.pop_back();
    std::vector<double> values(std::size_t{1} << scope.size());
    for (auto& v : values) v = std::exp(exponent(engine));
    std::vector<std::size_t> cards(scope.size(), 2);
    factors.emplace_back(std::move(scope), std::move(cards), std::move(values));
  }
  return markov_network(std::move(variables), std::move(factors));
}

// Forty factors with values down to e^-20 could together reach e^-800, past a double's range, but
// the products a model of them makes stay far above it: solved in probabilities. Forty factors
// of values near e^-28 do leave it (Z about e^-1120): the flags say so, and logarithms answer.
TEST(markov_inference_test, small_values_stay_in_probabilities_until_a_product_leaves_the_range) {
  const std::vector<long> fixed(6, -1);
  for (const auto& [low, high, in_logs] : {std::tuple{-20.0, 0.0, false}, std::tuple{-28.5, -27.5, true}}) {
    const auto model = small_valued_model(5, low, high);
    const auto truth = testing::brute_force(model, fixed);
    solve_report report;
    solve_options options;
    options.engine = solve_engine::jt;
    EXPECT_NEAR(log_partition(model, {}, options, &report), truth.log_z, log_tolerance(truth.log_z));
    EXPECT_EQ(report.log_space, in_logs) << "values e^[" << low << ", " << high << "]";
    const auto marginals = all_marginals(model, {}, options, &report);
    EXPECT_EQ(report.log_space, in_logs);
    for (std::size_t i = 0; i < model.size(); ++i) {
      for (std::size_t s = 0; s < 2; ++s) EXPECT_NEAR(marginals[i][s], truth.marginals[i][s], 1e-12);
    }
    EXPECT_NEAR(testing::log_value(model, most_probable_assignment(model, {}, options, &report)), truth.log_max,
                log_tolerance(truth.log_max));
    EXPECT_EQ(report.log_space, in_logs);
  }
}

// A complete bipartite model, whose cliques hold pairwise factors that all end at their last
// variable, and a hub whose clique has a neighbour per pair of its variables: the paths of
// propagation that cut a product at the last variable's states and that divide folds out.
TEST(markov_inference_test, bipartite_and_hub_models_equal_brute_force) {
  std::vector<std::vector<std::size_t>> bipartite;
  for (std::size_t a = 0; a < 3; ++a) {
    bipartite.push_back({a});
    for (std::size_t b = 3; b < 7; ++b) bipartite.push_back({a, b});
  }
  std::vector<std::vector<std::size_t>> hub{{0, 1, 2, 3}};
  std::size_t leaf = 4;
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = i + 1; j < 4; ++j) hub.push_back({i, j, leaf++});
  }
  const std::vector<std::size_t> bipartite_cards{2, 3, 2, 3, 2, 2, 3};
  const std::vector<std::size_t> hub_cards{2, 3, 2, 2, 2, 3, 2, 2, 3, 2};
  std::size_t log_space = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    const bool is_hub = seed % 2 == 0;
    const double scale = seed % 3 == 0 ? 400.0 : 1.5;  // 400: Z past a double, so in logarithms
    const auto model =
        is_hub ? model_of(hub_cards, hub, seed, scale) : model_of(bipartite_cards, bipartite, seed, scale);
    std::vector<long> fixed;
    const auto observed = seed % 4 == 1 ? testing::random_hard_evidence(model, seed, fixed) : evidence_set{};
    if (fixed.empty()) fixed.assign(model.size(), -1);
    const auto truth = testing::brute_force(model, fixed);
    if (truth.log_z == -INFINITY) continue;
    SCOPED_TRACE("seed " + std::to_string(seed));
    solve_report report;
    const auto options = with_engine(solve_engine::jt);
    EXPECT_NEAR(log_partition(model, observed, options, &report), truth.log_z, log_tolerance(truth.log_z));
    log_space += report.log_space ? 1 : 0;
    const auto marginals = all_marginals(model, observed, options);
    for (std::size_t i = 0; i < model.size(); ++i) {
      for (std::size_t s = 0; s < marginals[i].size(); ++s) EXPECT_NEAR(marginals[i][s], truth.marginals[i][s], 1e-12);
    }
  }
  EXPECT_GT(log_space, 0U);
}

// All marginals at once come from one walk down the tree, each message down a belief's fold
// divided by the message that came up (propagation::beliefs_down). Between calls the evidence
// moves, so some messages are kept and some are not; and a subset of the variables takes only
// the part of the tree on the way to their homes.
TEST(markov_inference_test, marginals_from_one_walk_down_equal_each_on_its_own) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    testing::random_markov_options shape;
    shape.variables = 6 + seed % 5;
    shape.factors = 5 + seed % 6;
    shape.zero_chance = seed % 4 == 0 ? 0.3 : 0.0;
    const auto model = testing::random_markov_network(seed, shape);
    auto tree = std::make_shared<const junction_tree>(model);
    propagation<sum_product<double>> walked(tree, model);
    std::vector<variable_id> every;
    std::vector<variable_id> some;
    for (std::size_t i = 0; i < model.size(); ++i) {
      every.push_back(index_at<variable_id>(i));
      if (i % 3 == 1) some.push_back(every.back());
    }
    for (std::uint64_t round = 0; round < 3; ++round) {
      std::vector<long> fixed;
      const auto observed = testing::random_hard_evidence(model, seed * 31 + round, fixed);
      walked.set_evidence(observed);
      propagation<sum_product<double>> alone(tree, model);
      alone.set_evidence(observed);
      for (const auto* nodes : {&some, &every}) {
        const auto together = walked.marginals(*nodes);
        ASSERT_EQ(together.size(), nodes->size());
        for (std::size_t k = 0; k < nodes->size(); ++k) {
          const auto expected = alone.marginal((*nodes)[k]);
          ASSERT_EQ(together[k].size(), expected.size());
          for (std::size_t s = 0; s < expected.size(); ++s) {
            EXPECT_NEAR(together[k][s], expected[s], 1e-12 * std::max(1.0, std::abs(expected[s])));
          }
        }
      }
    }
  }
}

// A clique with four separators sends its messages from one belief, dividing each group's
// messages out again (propagation::divide_out); where one of them is zero (x_i observed where its
// factor with the hub's variable is zero) the message holds only under that evidence. Queried one
// variable at a time, as the evidence moves, every marginal stays brute force's.
TEST(markov_inference_test, messages_divided_by_zero_are_dropped_when_the_evidence_moves) {
  std::vector<variable> variables;
  for (const char* name : {"a", "b", "c", "d", "x1", "x2", "x3", "x4"}) variables.push_back(variable(name, {"0", "1"}));
  std::mt19937_64 engine(11);
  std::uniform_real_distribution<double> value(0.5, 2.0);
  std::vector<double> hub(16);
  for (auto& v : hub) v = value(engine);
  std::vector<factor_table> factors{
      factor_table({variable_id(0), variable_id(1), variable_id(2), variable_id(3)}, {2, 2, 2, 2}, hub)};
  for (variable_id::rep i = 0; i < 4; ++i) {
    // x_i = 1 rules out the hub's variable i at 0.
    factors.push_back(
        factor_table({variable_id(i), variable_id(i + 4)}, {2, 2}, {value(engine), 0.0, value(engine), value(engine)}));
  }
  const markov_network model(variables, factors);
  auto tree = std::make_shared<const junction_tree>(model);
  propagation<sum_product<double>> kept(tree, model);
  const std::vector<std::vector<long>> rounds = {{-1, -1, -1, -1, 1, -1, -1, -1},
                                                 {-1, -1, -1, -1, 0, 1, -1, -1},
                                                 {-1, -1, -1, -1, -1, -1, 1, 1},
                                                 {-1, -1, -1, -1, 1, 0, 0, -1},
                                                 {-1, -1, -1, -1, -1, -1, -1, -1}};
  for (const auto& fixed : rounds) {
    evidence_set observed;
    for (std::size_t i = 0; i < fixed.size(); ++i) {
      if (fixed[i] >= 0) {
        observed.hard.push_back({index_at<variable_id>(i), index_at<state_index>(fixed[i])});
      }
    }
    kept.set_evidence(observed);
    const auto truth = testing::brute_force(model, fixed);
    // The x's first: by the time x1 asks for the hub's message, every message into the hub is
    // known, and that message comes from the one belief.
    for (std::size_t i = model.size(); i-- > 0;) {
      const auto sums = kept.marginal(index_at<variable_id>(i));
      const double total = sums[0] + sums[1];
      for (std::size_t s = 0; s < 2; ++s) EXPECT_NEAR(sums[s] / total, truth.marginals[i][s], 1e-12);
    }
  }
}

// Messages up the tree with values below a double's normal range: the beliefs divided by them
// on the way down lose digits only where their mass is too small to move a marginal.
TEST(markov_inference_test, marginals_stay_exact_where_messages_fall_below_the_normal_range) {
  const markov_network model({variable("a", {"0", "1"}), variable("b", {"0", "1"}), variable("c", {"0", "1"})},
                             {factor_table({variable_id(0), variable_id(1)}, {2, 2}, {1.0, 1e-310, 2.0, 3e-310}),
                              factor_table({variable_id(1), variable_id(2)}, {2, 2}, {1.0, 2.0, 1e-310, 3e-310}),
                              factor_table({variable_id(2)}, {2}, {1.0, 4.0})});
  const std::vector<long> fixed(model.size(), -1);
  const auto truth = testing::brute_force(model, fixed);
  junction_tree_engine engine(model);
  const variable_id every[] = {variable_id(0), variable_id(1), variable_id(2)};
  const auto marginals = engine.marginals(every);
  for (std::size_t i = 0; i < model.size(); ++i) {
    for (std::size_t s = 0; s < 2; ++s) {
      EXPECT_NEAR(marginals[i].table.values()[s], truth.marginals[i][s], 1e-15);
    }
  }
}

TEST(markov_inference_test, engines_parse_their_names) {
  EXPECT_EQ(parse_solve_engine("jt"), solve_engine::jt);
  EXPECT_EQ(parse_elimination_heuristic("min-weight"), elimination_heuristic::min_weight);
  try {
    static_cast<void>(parse_solve_engine("jtt"));
    FAIL();
  } catch (const unknown_name& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown engine 'jtt' (known: auto, jt, ve, bp, gibbs)"));
  }
}

// A user's semiring through both exact engines: the tropical (min, +) semiring of docs/extending.md.
struct min_sum {
  using value_type = double;
  static constexpr bool idempotent = true;
  static constexpr double zero() noexcept { return std::numeric_limits<double>::infinity(); }
  static constexpr double one() noexcept { return 0.0; }
  static constexpr double plus(double a, double b) noexcept { return std::min(a, b); }
  static constexpr double times(double a, double b) noexcept { return a + b; }
  static double from_probability(double p) noexcept { return -std::log(p); }
  static double to_probability(double cost) noexcept { return std::exp(-cost); }
};
static_assert(Semiring<min_sum>);

TEST(markov_inference_test, a_users_semiring_runs_through_elimination_and_the_junction_tree) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto model = testing::random_markov_network(seed);
    auto tree = std::make_shared<const junction_tree>(model);
    propagation<min_sum> by_tree(tree, model);
    for (std::size_t i = 0; i < model.size(); ++i) {
      const variable_id x[] = {index_at<variable_id>(i)};
      const auto by_elimination = joint_in<min_sum>(model, x, {});
      const auto from_tree = by_tree.marginal(x[0]);
      for (std::size_t s = 0; s < model.variables()[i].cardinality(); ++s) {
        std::vector<long> fixed(model.size(), -1);
        fixed[i] = static_cast<long>(s);
        const double best = -testing::brute_force(model, fixed).log_max;  // the lowest cost
        if (std::isinf(best)) {
          EXPECT_TRUE(std::isinf(by_elimination.values()[s]));
          EXPECT_TRUE(std::isinf(from_tree[s]));
          continue;
        }
        EXPECT_NEAR(by_elimination.values()[s], best, 1e-12 * std::max(1.0, std::abs(best)));
        EXPECT_NEAR(from_tree[s], best, 1e-12 * std::max(1.0, std::abs(best)));
      }
    }
  }
}

// A model of a user's own: not a markov_network, only what the GraphicalModel concept asks.
class forwarding_model {
 public:
  explicit forwarding_model(markov_network model) : model_(std::move(model)) {}
  [[nodiscard]] const std::vector<variable>& variables() const { return model_.variables(); }
  [[nodiscard]] std::size_t size() const { return model_.size(); }
  [[nodiscard]] variable_id id(std::string_view name) const { return model_.id(name); }
  [[nodiscard]] std::size_t factor_count() const { return model_.factor_count(); }
  [[nodiscard]] std::vector<variable_id> factor_scope(std::size_t f) const { return model_.factor_scope(f); }
  [[nodiscard]] const factor_table& factor(std::size_t f) const { return model_.factor(f); }

 private:
  markov_network model_;
};
static_assert(GraphicalModel<forwarding_model> && !DirectedModel<forwarding_model>);

TEST(markov_inference_test, a_users_own_model_type_runs_through_every_exact_engine) {
  std::size_t impossible = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    testing::random_markov_options shape;
    shape.variables = 3 + seed % 4;
    shape.factors = 2 + seed % 5;
    shape.zero_chance = seed % 3 == 0 ? 0.3 : 0.05;
    const auto markov = testing::random_markov_network(seed, shape);
    const forwarding_model model(markov);
    std::vector<long> fixed;
    const auto observed = testing::random_hard_evidence(markov, seed * 7919, fixed);
    const auto truth = testing::brute_force(markov, fixed);
    SCOPED_TRACE("seed " + std::to_string(seed));
    auto by_ve = std::make_shared<variable_elimination<forwarding_model>>(model);
    junction_tree_engine<forwarding_model> by_jt(model);
    by_ve->set_evidence(observed);
    by_jt.set_evidence(observed);
    if (truth.log_z == -INFINITY) {
      ++impossible;
      EXPECT_THROW(static_cast<void>(all_marginals(model, observed)), impossible_evidence);
      const variable_id first[] = {variable_id(0)};
      if (fixed[0] < 0) {
        EXPECT_THROW(static_cast<void>(by_ve->joint(first)), impossible_evidence);
        EXPECT_THROW(static_cast<void>(by_jt.joint(first)), impossible_evidence);
      }
      continue;
    }
    EXPECT_NEAR(log_partition(model, observed), truth.log_z, log_tolerance(truth.log_z));
    // An engine's P(evidence) is Z with the evidence over Z without it.
    const double log_p = truth.log_z - testing::brute_force(markov, std::vector<long>(model.size(), -1)).log_z;
    EXPECT_NEAR(by_jt.log_probability_of_evidence(), log_p, log_tolerance(truth.log_z));
    EXPECT_NEAR(by_ve->log_probability_of_evidence(), log_p, log_tolerance(truth.log_z));
    const auto marginals = all_marginals(model, observed);
    for (std::size_t i = 0; i < model.size(); ++i) {
      if (fixed[i] >= 0) continue;
      const variable_id x[] = {index_at<variable_id>(i)};
      const auto from_ve = by_ve->joint(x);
      const auto from_jt = by_jt.joint(x);
      for (std::size_t s = 0; s < truth.marginals[i].size(); ++s) {
        EXPECT_NEAR(marginals[i][s], truth.marginals[i][s], 1e-12);
        EXPECT_NEAR(from_ve.table.values()[s], truth.marginals[i][s], 1e-12);
        EXPECT_NEAR(from_jt.table.values()[s], truth.marginals[i][s], 1e-12);
      }
    }
    const auto map = most_probable_assignment(model, observed);
    EXPECT_NEAR(testing::log_value(markov, map), truth.log_max, log_tolerance(truth.log_max));
  }
  EXPECT_GT(impossible, 0U);
}

TEST(markov_inference_test, variable_elimination_answers_two_threads_at_once) {
  const auto network = read_bif(std::string(PGM_NETWORKS_DIR) + "/child.bif");
  variable_elimination engine(network);
  std::vector<std::vector<double>> alone(network.size());
  for (std::size_t i = 0; i < network.size(); ++i) {
    const variable_id one[] = {index_at<variable_id>(i)};
    const auto answer = variable_elimination(network).joint(one);
    alone[i].assign(answer.table.values().begin(), answer.table.values().end());
  }
  // Both threads fill the engine's table cache on first use, then read it.
  std::vector<std::vector<double>> first(network.size()), second(network.size());
  auto ask = [&](std::vector<std::vector<double>>& into) {
    for (std::size_t i = 0; i < network.size(); ++i) {
      const variable_id one[] = {index_at<variable_id>(i)};
      const auto answer = engine.joint(one);
      into[i].assign(answer.table.values().begin(), answer.table.values().end());
    }
  };
  std::thread a(ask, std::ref(first));
  std::thread b(ask, std::ref(second));
  a.join();
  b.join();
  EXPECT_EQ(first, alone);
  EXPECT_EQ(second, alone);
}

}  // namespace markov_inference_test
}  // namespace pgm
