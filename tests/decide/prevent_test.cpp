// Failure prevention on hand-built tables with known answers, against the plain per-
// configuration search on random tables, and the prevention metric on hand-computed cases.

#include "pgm/decide/prevent.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/enumeration.hpp"

namespace pgm::prevent_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::vector<std::string> two{"0", "1"};
const variable success("success", two);

/// A binary success table from P(success = 1 | u), configuration by configuration.
cpt<double> table_of(std::vector<variable> parents, const std::vector<double>& p_success) {
  std::vector<double> values;
  for (double p : p_success) {
    values.push_back(1.0 - p);
    values.push_back(p);
  }
  return cpt<double>(success, std::move(parents), values);
}

variable bins(const std::string& name, std::size_t k) {
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < k; ++i) labels.push_back(std::to_string(i));
  return variable(name, labels);
}

constexpr bool yes[] = {true};

TEST(prevent_test, nearest_above_epsilon_and_ties_to_the_higher_estimate) {
  const auto t = table_of({bins("x", 5)}, {0.1, 0.5, 0.85, 0.2, 0.9});
  // x=3 has x=2 (0.85) and x=4 (0.9) one step away: the higher wins.
  EXPECT_THAT(prevention_targets(t, 1, yes), ElementsAre(2, 2, 2, 4, 4));
}

TEST(prevent_test, none_above_epsilon_takes_the_best_nearest_first) {
  const auto t = table_of({bins("x", 5)}, {0.1, 0.3, 0.6, 0.6, 0.2});
  EXPECT_THAT(prevention_targets(t, 1, yes), ElementsAre(2, 2, 2, 3, 3));
}

TEST(prevent_test, at_epsilon_stays_and_a_target_must_exceed_it) {
  const auto t = table_of({bins("x", 3)}, {0.8, 0.1, 0.8});
  // 0.8 is not below ε, so those stay; x=1 finds nothing above ε and takes the best, the lower index.
  EXPECT_THAT(prevention_targets(t, 1, yes), ElementsAre(0, 0, 2));
}

TEST(prevent_test, non_controllable_parents_never_move) {
  // (c, x), x fastest. c=0: 0.1 0.9 0.2; c=1: 0.95 0.1 0.1.
  const auto t = table_of({bins("c", 2), bins("x", 3)}, {0.1, 0.9, 0.2, 0.95, 0.1, 0.1});
  const bool only_x[] = {false, true};
  const bool both[] = {true, true};
  EXPECT_THAT(prevention_targets(t, 1, only_x), ElementsAre(1, 1, 1, 3, 3, 3));
  // With c free, (0,0) has (0,1)=0.9 and (1,0)=0.95 one step away; (1,2) reaches (0,1) or (1,0) in two.
  EXPECT_THAT(prevention_targets(t, 1, both), ElementsAre(3, 1, 1, 3, 3, 3));
  const bool none[] = {false, false};
  EXPECT_THAT(prevention_targets(t, 1, none), ElementsAre(0, 1, 2, 3, 4, 5));
}

TEST(prevent_test, units_and_steps_can_disagree) {
  // x has narrow bins (midpoints -2, 0, 2), y wide ones (-20, 0, 20). From the centre, moving x
  // or y is one step each; y's target is better, but x's is ten times nearer in units.
  const auto x = variable::intervals("x", {-3, -1, 1, 3});
  const auto y = variable::intervals("y", {-30, -10, 10, 30});
  std::vector<double> p(9, 0.0);
  p[4] = 0.1;   // (1,1)
  p[1] = 0.85;  // (0,1): x moved
  p[3] = 0.9;   // (1,0): y moved
  const auto t = table_of({x, y}, p);
  const bool both[] = {true, true};
  EXPECT_EQ(prevention_target(t, 1, 4, both), 3u);
  EXPECT_EQ(prevention_target(t, 1, 4, both, {.epsilon = 0.8, .metric = prevention_options::distance::units}), 1u);
}

TEST(prevent_test, rejects_bad_input) {
  const auto t = table_of({bins("x", 3)}, {0.1, 0.5, 0.9});
  EXPECT_THAT([&] { static_cast<void>(prevention_targets(t, 2, yes)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("out of range")));
  const bool two_flags[] = {true, true};
  EXPECT_THAT([&] { static_cast<void>(prevention_targets(t, 1, two_flags)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("1 parents, got 2 controllable flags")));
  const auto colour = variable("colour", {"Red", "Blue"});
  const auto c = table_of({colour}, {0.1, 0.9});
  EXPECT_THAT(
      [&] {
        static_cast<void>(
            prevention_targets(c, 1, yes, {.epsilon = 0.8, .metric = prevention_options::distance::units}));
      },
      ::testing::ThrowsMessage<model_error>(HasSubstr("'colour' has no interval edges")));
  EXPECT_THROW(static_cast<void>(prevention_targets(t, 1, yes, {.epsilon = 1.5})), model_error);
  // No prediction exceeds 1, so ε = 1 is refused rather than every change falling short of it.
  EXPECT_THAT([&] { static_cast<void>(prevention_targets(t, 1, yes, {.epsilon = 1.0})); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("epsilon must be at least 0 and below 1")));
}

std::vector<double> random_estimates(std::mt19937_64& random, std::size_t n, int mode) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> p(n);
  for (auto& v : p) {
    v = unit(random);
    if (mode == 1) v = std::round(v * 4) / 4;        // many ties
    if (mode == 2) v *= 0.79;                        // nothing above ε
    if (mode == 3) v = std::round(v * 2) / 2 * 0.7;  // nothing above ε, many ties
  }
  return p;
}

TEST(prevent_test, matches_a_plain_search_from_each_configuration) {
  std::mt19937_64 random(11);
  const std::vector<variable> parents{bins("a", 5), bins("b", 5), bins("c", 5), bins("d", 5)};
  for (int trial = 0; trial < 40; ++trial) {
    const auto t = table_of(parents, random_estimates(random, 625, trial % 4));
    bool mask[4];
    for (auto& m : mask) m = (random() % 4) != 0;
    SCOPED_TRACE("trial " + std::to_string(trial));
    EXPECT_EQ(prevention_targets(t, 1, mask), testing::naive_prevention_targets(t, 1, mask, 0.8));
  }
}

TEST(prevent_test, units_match_an_exhaustive_scan) {
  std::mt19937_64 random(5);
  const std::vector<variable> parents{variable::intervals("a", {-3, -1.4, -0.4, 0.4, 1.4, 3}),
                                      variable::intervals("b", {0, 1.4, 2.2, 3.2, 4.6, 9}),
                                      variable::intervals("c", {-6, -3, 0, 3, 6})};
  const prevention_options units{.epsilon = 0.8, .metric = prevention_options::distance::units};
  for (int trial = 0; trial < 20; ++trial) {
    const auto p = random_estimates(random, 100, trial % 4);
    const auto t = table_of(parents, p);
    bool mask[3];
    for (auto& m : mask) m = (random() % 3) != 0;
    const auto got = prevention_targets(t, 1, mask, units);
    for (std::size_t u = 0; u < 100; ++u) {
      if (!(p[u] < 0.8)) {
        EXPECT_EQ(got[u], u);
        continue;
      }
      const auto from = t.parent_codes(config_index(u));
      auto reachable = [&](std::size_t v) {
        const auto to = t.parent_codes(config_index(v));
        for (std::size_t d = 0; d < 3; ++d) {
          if (!mask[d] && to[d] != from[d]) return false;
        }
        return true;
      };
      double top = -1;
      bool any_above = false;
      for (std::size_t v = 0; v < 100; ++v) {
        if (!reachable(v)) continue;
        top = std::max(top, p[v]);
        any_above = any_above || p[v] > 0.8;
      }
      std::size_t best = 0;
      double best_distance = INFINITY;
      for (std::size_t v = 0; v < 100; ++v) {
        if (!reachable(v) || !(any_above ? p[v] > 0.8 : p[v] == top)) continue;
        const auto to = t.parent_codes(config_index(v));
        double d = 0;
        for (std::size_t k = 0; k < 3; ++k) {
          const auto& var = parents[k];
          const double gap =
              *var.midpoint(index_at<state_index>(to[k])) - *var.midpoint(index_at<state_index>(from[k]));
          d += gap * gap;
        }
        if (d < best_distance - 1e-9 ||
            (std::abs(d - best_distance) <= 1e-9 && (p[v] > p[best] || (p[v] == p[best] && v < best)))) {
          best = v;
          best_distance = std::min(best_distance, d);
        }
      }
      EXPECT_EQ(got[u], best) << "trial " << trial << " u " << u;
    }
  }
}

TEST(prevention_rate_test, hand_computed) {
  const auto truth = table_of({bins("x", 3)}, {0.2, 0.9, 0.7});
  const auto estimate = table_of({bins("x", 3)}, {0.5, 0.85, 0.95});
  const double weights[] = {1, 1, 2};
  // Estimated: x0 → x1 (0.9), x1 stays (0.9), x2 stays (0.7): (0.9 + 0.9 + 2·0.7) / 4.
  EXPECT_NEAR(failure_prevention_rate(estimate, truth, 1, yes, weights), 0.8, 1e-12);
  // Oracle: x2 (0.7) is moved to x1 too: (0.9 + 0.9 + 2·0.9) / 4.
  EXPECT_NEAR(failure_prevention_rate(truth, truth, 1, yes, weights), 0.9, 1e-12);
}

TEST(prevention_rate_test, the_oracle_is_not_an_upper_bound) {
  const auto truth = table_of({bins("x", 3)}, {0.1, 0.82, 0.99});
  const auto cautious = table_of({bins("x", 3)}, {0.1, 0.5, 0.9});
  const double weights[] = {1, 1, 1};
  const double oracle = failure_prevention_rate(truth, truth, 1, yes, weights);
  const double conservative = failure_prevention_rate(cautious, truth, 1, yes, weights);
  EXPECT_NEAR(oracle, (0.82 + 0.82 + 0.99) / 3, 1e-12);
  EXPECT_NEAR(conservative, 0.99, 1e-12);
  EXPECT_GT(conservative, oracle);
}

TEST(prevention_rate_test, rejects_mismatches) {
  const auto t3 = table_of({bins("x", 3)}, {0.1, 0.5, 0.9});
  const auto t4 = table_of({bins("x", 4)}, {0.1, 0.5, 0.9, 0.9});
  const double w3[] = {1, 1, 1};
  const double w2[] = {1, 1};
  const double zero[] = {0, 0, 0};
  const double negative[] = {1, -1, 1};
  EXPECT_THAT([&] { static_cast<void>(failure_prevention_rate(t3, t4, 1, yes, w3)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("differ in shape")));
  EXPECT_THAT([&] { static_cast<void>(failure_prevention_rate(t3, t3, 1, yes, w2)); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("expected 3 configuration weights, got 2")));
  EXPECT_THROW(static_cast<void>(failure_prevention_rate(t3, t3, 1, yes, zero)), model_error);
  EXPECT_THROW(static_cast<void>(failure_prevention_rate(t3, t3, 1, yes, negative)), model_error);
}

}  // namespace
}  // namespace pgm::prevent_tests
