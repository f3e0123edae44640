// Hard evidence entered into the factors: slices, renumbering and the constants left over, by
// hand on a small model (every task's answers through it are checked against brute force in
// markov_inference_test).

#include "pgm/inference/evidence_reduction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pgm {
namespace evidence_reduction_test {

variable_id id(int i) { return index_at<variable_id>(i); }
state_index state(int s) { return index_at<state_index>(s); }

// a (2 states), b (3), c (2); factors {a, b}, {b, c}, {a}, the last variable fastest.
markov_network three_variables(double a0b2 = 0.6) {
  return markov_network(
      {variable("a", {"0", "1"}), variable("b", {"0", "1", "2"}), variable("c", {"0", "1"})},
      {factor_table({id(0), id(1)}, {2, 3}, {0.1, 0.2, a0b2, 0.4, 0.5, 0.9}),
       factor_table({id(1), id(2)}, {3, 2}, {1.0, 2.0, 3.0, 4.0, 5.0, 6.0}), factor_table({id(0)}, {2}, {7.0, 8.0})});
}

TEST(evidence_reduction_test, observed_variables_leave_and_their_factors_are_sliced) {
  evidence_set observed;
  observed.hard.push_back({id(1), state(1)});
  const auto reduced = reduce_by_evidence(three_variables(), observed);
  ASSERT_TRUE(reduced.has_value());
  EXPECT_EQ(reduced->original, (std::vector<variable_id>{id(0), id(2)}));
  ASSERT_EQ(reduced->model.size(), 2U);
  EXPECT_EQ(reduced->model.variables()[1].name(), "c");
  ASSERT_EQ(reduced->model.factor_count(), 3U);
  EXPECT_EQ(reduced->model.factor(0).scope(), (std::vector<variable_id>{id(0)}));
  EXPECT_EQ(reduced->model.factor(0).values(), (std::vector<double>{0.2, 0.5}));
  EXPECT_EQ(reduced->model.factor(1).scope(), (std::vector<variable_id>{id(1)}));
  EXPECT_EQ(reduced->model.factor(1).values(), (std::vector<double>{3.0, 4.0}));
  EXPECT_EQ(reduced->model.factor(2).values(), (std::vector<double>{7.0, 8.0}));
  EXPECT_EQ(reduced->log_constant, 0.0);
  EXPECT_FALSE(reduced->impossible);
}

TEST(evidence_reduction_test, factors_over_observed_variables_only_become_a_constant) {
  evidence_set observed;
  observed.hard.push_back({id(0), state(0)});
  observed.hard.push_back({id(1), state(2)});
  const auto reduced = reduce_by_evidence(three_variables(), observed);
  ASSERT_TRUE(reduced.has_value());
  EXPECT_EQ(reduced->original, (std::vector<variable_id>{id(2)}));
  ASSERT_EQ(reduced->model.factor_count(), 1U);
  EXPECT_EQ(reduced->model.factor(0).values(), (std::vector<double>{5.0, 6.0}));
  EXPECT_NEAR(reduced->log_constant, std::log(0.6) + std::log(7.0), 1e-15);
  EXPECT_FALSE(reduced->impossible);

  const auto zero = reduce_by_evidence(three_variables(0.0), observed);
  ASSERT_TRUE(zero.has_value());
  EXPECT_TRUE(zero->impossible);
}

TEST(evidence_reduction_test, nothing_is_reduced_without_hard_evidence_alone_or_with_nothing_left) {
  const auto model = three_variables();
  EXPECT_FALSE(reduce_by_evidence(model, {}).has_value());
  evidence_set soft;
  soft.hard.push_back({id(0), state(1)});
  soft.soft.push_back({id(1), {0.2, 0.3, 0.5}});
  EXPECT_FALSE(reduce_by_evidence(model, soft).has_value());
  evidence_set all;
  for (int i = 0; i < 3; ++i) all.hard.push_back({id(i), state(0)});
  EXPECT_FALSE(reduce_by_evidence(model, all).has_value());
}

}  // namespace evidence_reduction_test
}  // namespace pgm
