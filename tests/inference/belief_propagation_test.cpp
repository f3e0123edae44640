// Loopy belief propagation (pgm/inference/belief_propagation.hpp): exact on models whose factor
// graph is a tree, both schedules, with evidence; on loopy models close to the exact answer
// when it converges, and honest when it does not; and as solve's bp and auto engines.

#include "pgm/inference/belief_propagation.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "pgm/inference/factor_gibbs.hpp"
#include "pgm/inference/solve.hpp"
#include "pgm/testing/random_markov_network.hpp"

namespace pgm {
namespace belief_propagation_test {

using ::testing::HasSubstr;

// A model whose factor graph is a tree: each factor joins one variable already placed to one or
// two new ones, and unary factors anywhere.
markov_network random_factor_tree(std::uint64_t seed, std::size_t variables) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<variable> vars;
  std::vector<std::size_t> cards;
  for (std::size_t i = 0; i < variables; ++i) {
    cards.push_back(2 + engine() % 3);
    std::vector<std::string> states;
    for (std::size_t s = 0; s < cards.back(); ++s) states.push_back(std::to_string(s));
    vars.emplace_back("x" + std::to_string(i), states);
  }
  std::vector<factor_table> factors;
  auto add = [&](std::vector<variable_id> scope) {
    std::vector<std::size_t> scope_cards;
    std::size_t cells = 1;
    for (auto v : scope) {
      scope_cards.push_back(cards[v.value()]);
      cells *= cards[v.value()];
    }
    std::vector<double> values(cells);
    for (auto& v : values) v = unit(engine) < 0.1 ? 0.0 : std::exp(3 * (2 * unit(engine) - 1));
    factors.emplace_back(std::move(scope), std::move(scope_cards), std::move(values));
  };
  std::size_t placed = 1;
  while (placed < variables) {
    const auto anchor = index_at<variable_id>(engine() % placed);
    std::vector<variable_id> scope{anchor};
    const auto fresh = std::min<std::size_t>(1 + engine() % 2, variables - placed);
    for (std::size_t k = 0; k < fresh; ++k) scope.push_back(index_at<variable_id>(placed++));
    std::shuffle(scope.begin(), scope.end(), engine);
    add(std::move(scope));
  }
  for (std::size_t k = 0; k < variables / 2; ++k) add({index_at<variable_id>(engine() % variables)});
  return markov_network(std::move(vars), std::move(factors));
}

TEST(belief_propagation_test, is_exact_on_a_factor_tree_with_both_schedules) {
  std::size_t checked = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const auto model = random_factor_tree(seed, 4 + seed % 5);
    std::vector<long> fixed(model.size(), -1);
    evidence_set observed;
    if (seed % 2 == 0) {
      fixed[1] = 0;
      observed.hard.push_back({variable_id(1), state_index(0)});
    }
    const auto truth = testing::brute_force(model, fixed);
    for (const auto schedule : all_bp_schedules) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::string(to_string(schedule)));
      bp_options options;
      options.schedule = schedule;
      options.tolerance = 1e-13;
      if (truth.log_z == -INFINITY) {
        EXPECT_THROW(static_cast<void>(belief_propagation(model, observed, options)), impossible_evidence);
        continue;
      }
      const auto result = belief_propagation(model, observed, options);
      EXPECT_TRUE(result.converged);
      EXPECT_NEAR(result.log_partition, truth.log_z, 1e-9 * std::max(1.0, std::abs(truth.log_z)));
      for (std::size_t i = 0; i < model.size(); ++i) {
        for (std::size_t s = 0; s < truth.marginals[i].size(); ++s) {
          EXPECT_NEAR(result.marginals[i][s], truth.marginals[i][s], 1e-9);
        }
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 40U);
}

TEST(belief_propagation_test, on_a_loopy_model_it_is_close_and_says_whether_it_converged) {
  testing::random_markov_options shape;
  shape.variables = 8;
  shape.factors = 10;
  shape.max_arity = 2;
  shape.zero_chance = 0.0;
  shape.scale = 0.5;  // weak couplings: BP converges and is accurate
  const auto model = testing::random_markov_network(4, shape);
  const auto truth = testing::brute_force(model, std::vector<long>(model.size(), -1));
  for (const auto schedule : all_bp_schedules) {
    bp_options options;
    options.schedule = schedule;
    options.damping = schedule == bp_schedule::parallel ? 0.3 : 0.0;
    const auto result = belief_propagation(model, {}, options);
    EXPECT_TRUE(result.converged);
    EXPECT_LE(result.residual, options.tolerance);
    EXPECT_NEAR(result.log_partition, truth.log_z, 0.05);
    for (std::size_t i = 0; i < model.size(); ++i) {
      for (std::size_t s = 0; s < truth.marginals[i].size(); ++s) {
        EXPECT_NEAR(result.marginals[i][s], truth.marginals[i][s], 0.05);
      }
    }
  }
  bp_options short_run;
  short_run.max_iterations = 1;
  short_run.schedule = bp_schedule::parallel;
  const auto cut = belief_propagation(model, {}, short_run);
  EXPECT_FALSE(cut.converged);
  EXPECT_EQ(cut.iterations, 1U);
  EXPECT_GT(cut.residual, short_run.tolerance);
  EXPECT_FALSE(cut.timed_out);
  // A time limit already past stops either schedule at its first look at the clock.
  for (const auto schedule : all_bp_schedules) {
    bp_options no_time;
    no_time.schedule = schedule;
    no_time.tolerance = 1e-300;
    no_time.time_limit_seconds = 0.0;
    const auto stopped = belief_propagation(model, {}, no_time);
    EXPECT_TRUE(stopped.timed_out);
    EXPECT_FALSE(stopped.converged);
    EXPECT_LE(stopped.iterations, 1U);
    EXPECT_EQ(stopped.marginals.size(), model.size());
  }
  factor_gibbs_options no_time;
  no_time.time_limit_seconds = 0.0;
  const auto sampled = factor_gibbs(model, {}, no_time);
  EXPECT_TRUE(sampled.timed_out);
  EXPECT_EQ(sampled.sweeps, 0U);
  for (const auto& marginal : sampled.marginals) {
    EXPECT_EQ(std::count(marginal.begin(), marginal.end(), 1.0), 1);  // the state the chain reached
  }
}

TEST(belief_propagation_test, soft_evidence_and_interventions) {
  const auto model = random_factor_tree(9, 5);
  evidence_set observed;
  observed.soft.push_back({variable_id(2), std::vector<double>(model.variables()[2].cardinality(), 0.0)});
  observed.soft.back().weights[0] = 2.0;
  observed.soft.back().weights[1] = 1.0;
  const auto result = belief_propagation(model, observed);
  const auto exact = all_marginals(model, observed);
  for (std::size_t i = 0; i < model.size(); ++i) {
    for (std::size_t s = 0; s < exact[i].size(); ++s) EXPECT_NEAR(result.marginals[i][s], exact[i][s], 1e-9);
  }
  evidence_set intervened;
  intervened.intervened.push_back({variable_id(0), state_index(0)});
  EXPECT_THROW(static_cast<void>(belief_propagation(model, intervened)), model_error);
}

TEST(belief_propagation_test, solve_runs_bp_by_name_and_auto_past_the_memory_limit) {
  const auto model = random_factor_tree(3, 9);
  solve_options options;
  options.engine = solve_engine::bp;
  solve_report report;
  const auto log_z = log_partition(model, {}, options, &report);
  EXPECT_EQ(report.engine, "bp");
  EXPECT_FALSE(report.exact);
  EXPECT_TRUE(report.converged);
  EXPECT_NEAR(log_z, log_partition(model, {}), 1e-9);
  EXPECT_THAT([&] { static_cast<void>(most_probable_assignment(model, {}, options)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("bp answers MAR (bp PR too)")));

  options.engine = solve_engine::automatic;
  options.memory_limit_bytes = 16;  // no tree fits
  solve_report automatic;
  const auto marginals = all_marginals(model, {}, options, &automatic);
  EXPECT_EQ(automatic.engine, "bp");
  EXPECT_THAT(automatic.note, HasSubstr("auto chose bp"));
  EXPECT_EQ(marginals.size(), model.size());
  EXPECT_THROW(static_cast<void>(most_probable_assignment(model, {}, options)), memory_limit_exceeded);
}

// Gibbs sampling on a Markov network (pgm/inference/factor_gibbs.hpp): close to the exact
// marginals with positive factors, the same numbers for a seed, and honest about zeros.
TEST(factor_gibbs_test, estimates_the_exact_marginals_and_repeats_for_a_seed) {
  testing::random_markov_options shape;
  shape.variables = 6;
  shape.factors = 8;
  shape.max_arity = 3;
  shape.zero_chance = 0.0;
  shape.scale = 1.0;
  const auto model = testing::random_markov_network(21, shape);
  std::vector<long> fixed(model.size(), -1);
  fixed[2] = 1;
  evidence_set observed;
  observed.hard.push_back({variable_id(2), state_index(1)});
  const auto truth = testing::brute_force(model, fixed);
  factor_gibbs_options options;
  options.sweeps = 40'000;
  options.seed = 7;
  const auto sampled = factor_gibbs(model, observed, options);
  EXPECT_EQ(sampled.stuck_draws, 0U);
  for (std::size_t i = 0; i < model.size(); ++i) {
    for (std::size_t s = 0; s < truth.marginals[i].size(); ++s) {
      EXPECT_NEAR(sampled.marginals[i][s], truth.marginals[i][s], 0.02) << "variable " << i << ", state " << s;
    }
  }
  EXPECT_EQ(factor_gibbs(model, observed, options).marginals, sampled.marginals);
  options.seed = 8;
  EXPECT_NE(factor_gibbs(model, observed, options).marginals, sampled.marginals);
  // As solve's engine: MAR only.
  solve_options solve;
  solve.engine = solve_engine::gibbs;
  solve_report report;
  static_cast<void>(all_marginals(model, observed, solve, &report));
  EXPECT_EQ(report.engine, "gibbs");
  EXPECT_FALSE(report.exact);
  EXPECT_THROW(static_cast<void>(log_partition(model, observed, solve)), model_error);
}

TEST(factor_gibbs_test, a_conditional_with_no_positive_state_is_counted) {
  // a and b must differ and must be equal: no state has weight, every draw is stuck.
  const markov_network model({variable("a", {"0", "1"}), variable("b", {"0", "1"})},
                             {factor_table({variable_id(0), variable_id(1)}, {2, 2}, {0, 1, 1, 0}),
                              factor_table({variable_id(0), variable_id(1)}, {2, 2}, {1, 0, 0, 1})});
  factor_gibbs_options options;
  options.sweeps = 10;
  options.burn_in = 0;
  const auto sampled = factor_gibbs(model, {}, options);
  EXPECT_EQ(sampled.stuck_draws, 20U);
}

}  // namespace belief_propagation_test
}  // namespace pgm
