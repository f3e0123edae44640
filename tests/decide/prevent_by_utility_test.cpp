// Prevention as a decision: the move of highest expected utility, solved as an influence
// diagram, against enumeration of every reachable configuration; the limits where it becomes
// the most successful move (costs that only break ties) and where it stays (costs that outweigh).

#include "pgm/decide/prevent_by_utility.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "pgm/core/mixed_radix.hpp"
#include "pgm/decide/prevent.hpp"
#include "pgm/decide/solve_decisions.hpp"

namespace pgm::prevent_by_utility_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// P(success | parents) over `parents` interval variables of 2–5 bins, random.
cpt<double> random_success_table(unsigned seed, std::size_t parents) {
  std::mt19937 rng(seed);
  std::vector<variable> vars;
  for (std::size_t p = 0; p < parents; ++p) {
    std::vector<double> edges{0};
    for (std::size_t b = 0, bins = 2 + rng() % 4; b < bins; ++b) {
      edges.push_back(edges.back() + std::uniform_real_distribution<double>(0.5, 2)(rng));
    }
    vars.push_back(variable::intervals("x" + std::to_string(p), edges));
  }
  std::size_t configurations = 1;
  for (const auto& v : vars) configurations *= v.cardinality();
  std::vector<double> values;
  for (std::size_t c = 0; c < configurations; ++c) {
    const double p = std::uniform_real_distribution<double>(0, 1)(rng);
    values.push_back(1 - p);
    values.push_back(p);
  }
  return cpt<double>(variable("ok", {"0", "1"}), vars, values);
}

/// The best expected utility over every configuration that moves only controllable variables.
double best_by_enumeration(const cpt<double>& table, std::size_t u, const std::vector<bool>& controllable,
                           const move_costs& costs) {
  const auto from = table.parent_codes(config_index(u));
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < table.parent_radix().size(); ++c) {
    const auto to = table.parent_codes(config_index(c));
    double cost = 0;
    bool reachable = true;
    for (std::size_t p = 0; p < to.size(); ++p) {
      if (to[p] == from[p]) continue;
      reachable = reachable && controllable[p];
      const auto& v = table.parents()[p];
      const auto rate = costs.cost.contains(v.name()) ? costs.cost.at(v.name()) : 0.0;
      const double distance =
          costs.unit == move_costs::per::steps
              ? std::abs(static_cast<double>(to[p]) - static_cast<double>(from[p]))
              : std::abs(*v.midpoint(index_at<state_index>(to[p])) - *v.midpoint(index_at<state_index>(from[p])));
      cost += rate * distance;
    }
    if (reachable) best = std::max(best, costs.reward * table(state_index(1), config_index(c)) - cost);
  }
  return best;
}

/// std::vector<bool> has no contiguous storage; spans need real bools.
struct mask {
  explicit mask(const std::vector<bool>& flags) : values(flags.begin(), flags.end()) {}
  std::span<const bool> span() const { return {reinterpret_cast<const bool*>(values.data()), values.size()}; }
  std::vector<char> values;
};

TEST(prevent_by_utility_test, the_best_move_equals_enumeration_of_every_reachable_configuration) {
  for (unsigned seed = 0; seed < 80; ++seed) {
    SCOPED_TRACE(seed);
    std::mt19937 rng(seed + 1000);
    const auto table = random_success_table(seed, 2 + seed % 3);
    std::vector<bool> controllable(table.parents().size());
    for (std::size_t p = 0; p < controllable.size(); ++p) controllable[p] = rng() % 3 != 0;
    move_costs costs;
    costs.reward = std::uniform_real_distribution<double>(0, 100)(rng);
    costs.unit = seed % 2 ? move_costs::per::units : move_costs::per::steps;
    for (std::size_t p = 0; p < controllable.size(); ++p) {
      if (controllable[p] && rng() % 4 != 0) {
        costs.cost[table.parents()[p].name()] = std::uniform_real_distribution<double>(0, 20)(rng);
      }
    }
    const auto u = rng() % table.parent_radix().size();
    const mask flags(controllable);
    const auto move = best_move(table, 1, u, flags.span(), costs);
    const double expected = best_by_enumeration(table, u, controllable, costs);
    EXPECT_NEAR(move.expected_utility, expected, 1e-12 * std::max(1.0, std::abs(expected)));
    // The plan's influence diagram, solved as any other, is worth the same (where it decides).
    if (std::find(controllable.begin(), controllable.end(), true) != controllable.end()) {
      const auto solved = solve_decisions(prevention_diagram(table, 1, u, flags.span(), costs));
      EXPECT_NEAR(solved.meu, expected, 1e-12 * std::max(1.0, std::abs(expected)));
    }
    EXPECT_NEAR(move.expected_utility, costs.reward * move.success_probability - move.cost,
                1e-12 * costs.reward + 1e-12);
    // Only controllable variables move.
    const auto from = table.parent_codes(config_index(u));
    const auto to = table.parent_codes(config_index(move.target));
    for (std::size_t p = 0; p < from.size(); ++p) {
      if (!controllable[p]) {
        EXPECT_EQ(to[p], from[p]);
      }
    }
  }
}

TEST(prevent_by_utility_test, costs_that_only_break_ties_give_the_most_successful_move_and_the_nearest_of_equals) {
  for (unsigned seed = 0; seed < 40; ++seed) {
    SCOPED_TRACE(seed);
    const auto table = random_success_table(seed, 3);
    const std::vector<bool> all(3, true);
    const mask flags(all);
    move_costs costs;
    costs.reward = 1e6;
    for (const auto& v : table.parents()) costs.cost[v.name()] = 1e-6;
    const auto u = seed % table.parent_radix().size();
    const auto move = best_move(table, 1, u, flags.span(), costs);
    double most = 0;
    for (std::size_t c = 0; c < table.parent_radix().size(); ++c)
      most = std::max(most, table(state_index(1), config_index(c)));
    EXPECT_EQ(move.success_probability, most);
  }
}

TEST(prevent_by_utility_test, a_move_that_costs_more_than_it_gains_is_not_made) {
  // Two parents of three bins; only the centre succeeds often. From a corner, ε = 0.8 moves
  // two steps; at a cost of 45 per step against a reward of 100 the gain (0.9 − 0.1)·100 = 80
  // does not pay for 90, so the robot stays; at 30 per step it moves; at 40 the two are worth
  // the same, and it stays.
  const auto x = variable::intervals("x", {-3, -1, 1, 3});
  const auto y = variable::intervals("y", {-3, -1, 1, 3});
  std::vector<double> values;
  for (std::size_t c = 0; c < 9; ++c) {
    const double p = c == 4 ? 0.9 : 0.1;
    values.push_back(1 - p);
    values.push_back(p);
  }
  const cpt<double> table(variable("ok", {"0", "1"}), {x, y}, values);
  const std::vector<bool> both{true, true};
  const mask flags(both);
  EXPECT_EQ(prevention_target(table, 1, 0, flags.span(), {.epsilon = 0.8}), 4u);
  move_costs costs{.reward = 100, .cost = {{"x", 45}, {"y", 45}}};
  const auto stays = best_move(table, 1, 0, flags.span(), costs);
  EXPECT_EQ(stays.target, 0u);
  EXPECT_DOUBLE_EQ(stays.expected_utility, 10);
  costs.cost = {{"x", 40}, {"y", 40}};
  EXPECT_EQ(best_move(table, 1, 0, flags.span(), costs).target, 0u);
  costs.cost = {{"x", 30}, {"y", 30}};
  const auto moves = best_move(table, 1, 0, flags.span(), costs);
  EXPECT_EQ(moves.target, 4u);
  EXPECT_DOUBLE_EQ(moves.cost, 60);
  EXPECT_DOUBLE_EQ(moves.expected_utility, 30);
  // Per unit: each step moves a midpoint by 2 units.
  costs = {.reward = 100, .cost = {{"x", 15}, {"y", 15}}, .unit = move_costs::per::units};
  EXPECT_DOUBLE_EQ(best_move(table, 1, 0, flags.span(), costs).cost, 60);
  // Free variables that gain nothing stay put.
  const std::vector<bool> only_x{true, false};
  const mask x_only(only_x);
  EXPECT_EQ(best_move(table, 1, 0, x_only.span(), {.reward = 100}).target, 0u);
}

TEST(prevent_by_utility_test, bad_costs_are_refused_by_name) {
  const auto table = random_success_table(1, 2);
  const std::vector<bool> first{true, false};
  const mask flags(first);
  EXPECT_THAT(
      [&] {
        (void)best_move(table, 1, 0, flags.span(), {.cost = {{"x1", 1}}});
      },
      ThrowsMessage<model_error>(HasSubstr("'x1', which is not a controllable parent of 'ok'")));
  EXPECT_THAT(
      [&] {
        (void)best_move(table, 1, 0, flags.span(), {.cost = {{"x0", -1}}});
      },
      ThrowsMessage<model_error>(HasSubstr("must be a finite number ≥ 0")));
  const cpt<double> categorical(variable("ok", {"0", "1"}), {variable("colour", {"Red", "Blue"})},
                                {0.5, 0.5, 0.2, 0.8});
  const bool yes[] = {true};
  EXPECT_THAT(
      [&] {
        (void)best_move(categorical, 1, 0, yes, {.cost = {{"colour", 1}}, .unit = move_costs::per::units});
      },
      ThrowsMessage<model_error>(HasSubstr("'colour' has no units")));
  EXPECT_EQ(best_move(categorical, 1, 0, yes, {.reward = 10, .cost = {{"colour", 1}}}).target, 1u);
}

TEST(prevent_by_utility_test, the_best_moves_of_a_whole_table_are_best_move_at_each_configuration) {
  for (unsigned seed = 0; seed < 30; ++seed) {
    SCOPED_TRACE(seed);
    std::mt19937 rng(seed + 2000);
    const auto table = random_success_table(seed + 500, 2 + seed % 3);
    std::vector<bool> controllable(table.parents().size());
    for (std::size_t p = 0; p < controllable.size(); ++p) controllable[p] = rng() % 3 != 0;
    move_costs costs{.reward = std::uniform_real_distribution<double>(0, 100)(rng)};
    costs.unit = seed % 2 ? move_costs::per::units : move_costs::per::steps;
    for (std::size_t p = 0; p < controllable.size(); ++p) {
      if (controllable[p] && rng() % 4 != 0) {
        costs.cost[table.parents()[p].name()] = std::uniform_real_distribution<double>(0, 20)(rng);
      }
    }
    const mask flags(controllable);
    const auto moves = best_moves(table, 1, flags.span(), costs);
    ASSERT_EQ(moves.size(), table.configurations());
    for (std::size_t u = 0; u < moves.size(); ++u) {
      const auto one = best_move(table, 1, u, flags.span(), costs);
      EXPECT_EQ(moves[u].target, one.target) << u;
      EXPECT_EQ(moves[u].expected_utility, one.expected_utility) << u;
      EXPECT_NEAR(moves[u].expected_utility, costs.reward * moves[u].success_probability - moves[u].cost,
                  1e-12 * std::max(1.0, std::abs(one.expected_utility)));
      EXPECT_EQ(moves[u].success_probability, table(state_index(1), config_index(moves[u].target)));
    }
  }
}

TEST(prevent_by_utility_test, the_outcome_of_a_rule_is_its_success_by_the_truth_less_what_its_moves_cost) {
  // Three bins of x; the estimate believes in x = 2, the truth in x = 1.
  const auto x = variable::intervals("x", {0, 1, 2, 3});
  const cpt<double> estimate(variable("ok", {"0", "1"}), {x}, {0.9, 0.1, 0.5, 0.5, 0.1, 0.9});
  const cpt<double> truth(variable("ok", {"0", "1"}), {x}, {0.8, 0.2, 0.3, 0.7, 0.6, 0.4});
  const bool yes[] = {true};
  const std::vector<double> weights{1, 2, 1};
  const move_costs costs{.reward = 10, .cost = {{"x", 1}}};
  // ε = 0.8: every configuration moves to x = 2 (2, 1 and 0 steps).
  const auto by_epsilon = prevention_targets(estimate, 1, yes, {.epsilon = 0.8});
  EXPECT_EQ(by_epsilon, (std::vector<std::size_t>{2, 2, 2}));
  const auto outcome = prevention_outcome_of(by_epsilon, truth, 1, yes, weights, costs);
  EXPECT_DOUBLE_EQ(outcome.success, 0.4);
  EXPECT_DOUBLE_EQ(outcome.cost, (2 * 1 + 1 * 2 + 0 * 1) / 4.0);
  EXPECT_DOUBLE_EQ(outcome.utility, 10 * 0.4 - 1);
  EXPECT_DOUBLE_EQ(outcome.success, failure_prevention_rate(estimate, truth, 1, yes, weights, {.epsilon = 0.8}));
  // By utility on the estimate: from x = 0, 10·0.9 − 2 = 7 beats 10·0.5 − 1 = 4 and 1; from
  // x = 1, 9 − 1 = 8 beats 5.
  const auto moves = best_moves(estimate, 1, yes, costs);
  std::vector<std::size_t> by_utility;
  for (const auto& move : moves) by_utility.push_back(move.target);
  EXPECT_EQ(by_utility, (std::vector<std::size_t>{2, 2, 2}));
  // At 5 a step no move pays: from x = 0, 9 − 10 = −1 and 5 − 5 = 0 against 1 for staying;
  // from x = 1, 9 − 5 = 4 against 5.
  const auto dear = best_moves(estimate, 1, yes, {.reward = 10, .cost = {{"x", 5}}});
  EXPECT_EQ(dear[0].target, 0u);
  EXPECT_EQ(dear[1].target, 1u);
  const auto stayed = prevention_outcome_of(std::vector<std::size_t>{0, 1, 2}, truth, 1, yes, weights, costs);
  EXPECT_DOUBLE_EQ(stayed.success, (0.2 + 2 * 0.7 + 0.4) / 4);
  EXPECT_DOUBLE_EQ(stayed.cost, 0);
  // Bad input.
  const bool no[] = {false};
  EXPECT_THAT([&] { (void)prevention_outcome_of(by_epsilon, truth, 1, no, weights, {}); },
              ThrowsMessage<model_error>(HasSubstr("moves 'x', which is not controllable")));
  EXPECT_THAT(
      [&] {
        (void)prevention_outcome_of(std::vector<std::size_t>{2, 2}, truth, 1, yes, weights, {});
      },
      ThrowsMessage<model_error>(HasSubstr("expected 3 prevention targets, got 2")));
  EXPECT_THAT(
      [&] {
        (void)prevention_outcome_of(std::vector<std::size_t>{2, 2, 7}, truth, 1, yes, weights, {});
      },
      ThrowsMessage<model_error>(HasSubstr("prevention target 7 is out of range")));
  EXPECT_THAT(
      [&] {
        (void)prevention_outcome_of(by_epsilon, truth, 1, yes, std::vector<double>{0, 0, 0}, {});
      },
      ThrowsMessage<model_error>(HasSubstr("sum to zero")));
  EXPECT_THAT([&] { (void)best_moves(estimate, 2, yes, costs); },
              ThrowsMessage<model_error>(HasSubstr("success state 2 is out of range")));
}

}  // namespace
}  // namespace pgm::prevent_by_utility_tests
