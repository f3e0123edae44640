// Prevention during a task of several actions (pgm/decide/prevent_over_time.hpp): the best
// setting of the controllable variables at the next step, against brute-force enumeration of the
// unrolled network under each setting as an intervention.

#include "pgm/decide/prevent_over_time.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "support/enumeration.hpp"
#include "support/random_dynamic_network.hpp"

namespace pgm::prevent_over_time_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

observation seen(std::size_t variable, std::size_t state) {
  return {index_at<variable_id>(variable), index_at<state_index>(state)};
}

// P(v2 = 0 at steps k … T−1 | episode, do(v0@k = c)) for every state c of v0, by enumeration.
std::vector<double> enumerated(const dynamic_network& model, const std::vector<evidence_set>& steps, std::size_t k,
                               std::size_t horizon) {
  const auto unrolled = model.unroll(horizon);
  const auto at = [&](std::size_t v, std::size_t t) {
    return unrolled.id(model.variables()[v].name() + "@" + std::to_string(t));
  };
  evidence_set episode;
  for (std::size_t t = 0; t < steps.size(); ++t) {
    for (const auto& o : steps[t].hard) episode.hard.push_back({at(o.variable.value(), t), o.state});
  }
  std::vector<double> answer;
  for (std::size_t c = 0; c < model.variables()[0].cardinality(); ++c) {
    auto given = episode;
    given.intervened.push_back({at(0, k), index_at<state_index>(c)});
    double total = 0.0, success = 0.0;
    auto with_success = given;
    for (std::size_t t = k; t < horizon; ++t) with_success.hard.push_back({at(2, t), state_index(0)});
    testing::enumerate_states(unrolled, given, [&](const auto&, double p) { total += p; });
    testing::enumerate_states(unrolled, with_success, [&](const auto&, double p) { success += p; });
    answer.push_back(success / total);
  }
  return answer;
}

TEST(prevent_over_time, the_best_setting_is_the_enumerated_maximum_on_random_dynamic_networks) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto model = testing::random_dynamic(seed, 3);
    const std::size_t k = 1 + seed % 2;
    prevention_over_time_request request;
    request.success = {model.variables()[2].name(), model.variables()[2].states()[0]};
    request.controllable = {variable_id(0)};
    request.horizon = k + 2;
    request.steps.resize(k);
    for (std::size_t t = 0; t < k; ++t) request.steps[t].hard = {seen(2, 0), seen(1, (seed + t) % 2)};
    const auto answer = prevent_over_time(model, request);
    EXPECT_EQ(answer.step, k) << seed;
    EXPECT_EQ(answer.horizon, k + 2) << seed;
    EXPECT_FALSE(answer.planned) << seed;
    const auto expected = enumerated(model, request.steps, k, k + 2);
    std::size_t best = 0;
    for (std::size_t c = 1; c < expected.size(); ++c) best = expected[c] > expected[best] ? c : best;
    EXPECT_NEAR(answer.after, expected[best], 1e-12) << seed;
    ASSERT_EQ(answer.best.size(), 1U);
    EXPECT_NEAR(expected[model.variables()[0].state(answer.best[0].second).value()], expected[best], 1e-12) << seed;
    EXPECT_GE(answer.after, answer.before - 1e-15) << seed;

    // With a plan at step k, `before` is the plan's own probability, and an equal setting keeps it.
    const std::size_t planned = (seed + 1) % model.variables()[0].cardinality();
    request.steps.push_back({});
    request.steps.back().hard = {seen(0, planned)};
    const auto with_plan = prevent_over_time(model, request);
    EXPECT_TRUE(with_plan.planned);
    EXPECT_NEAR(with_plan.before, expected[planned], 1e-12) << seed;
    EXPECT_NEAR(with_plan.after, expected[best], 1e-12) << seed;
    if (expected[planned] >= expected[best] * (1 - 1e-13)) {
      EXPECT_EQ(with_plan.best[0].second, model.variables()[0].states()[planned]) << seed;
    }
  }
}

TEST(prevent_over_time, without_a_horizon_the_next_step_alone_is_judged) {
  const auto model = testing::random_dynamic(5, 3);
  prevention_over_time_request request;
  request.success = {model.variables()[2].name(), model.variables()[2].states()[0]};
  request.controllable = {variable_id(0)};
  request.steps.resize(1);
  request.steps[0].hard = {seen(2, 0)};
  const auto answer = prevent_over_time(model, request);
  EXPECT_EQ(answer.horizon, 2U);
  const auto expected = enumerated(model, request.steps, 1, 2);
  EXPECT_NEAR(answer.after, *std::max_element(expected.begin(), expected.end()), 1e-12);
}

TEST(prevent_over_time, what_cannot_be_decided_is_refused_by_name) {
  const auto model = testing::random_dynamic(3, 3);
  prevention_over_time_request request;
  request.success = {model.variables()[2].name(), model.variables()[2].states()[0]};
  request.controllable = {variable_id(2)};
  EXPECT_THAT([&] { (void)prevent_over_time(model, request); },
              ThrowsMessage<model_error>(HasSubstr("the success variable 'v2' is controllable")));
  request.controllable = {variable_id(0)};
  request.steps.resize(3);
  request.steps[0].hard = {seen(2, 0)};
  EXPECT_THAT([&] { (void)prevent_over_time(model, request); },
              ThrowsMessage<model_error>(HasSubstr("the episode has steps past step 1")));
  request.steps.resize(1);
  request.horizon = 1;
  EXPECT_THAT([&] { (void)prevent_over_time(model, request); },
              ThrowsMessage<model_error>(HasSubstr("the horizon of 1 steps ends before step 1")));
}

}  // namespace
}  // namespace pgm::prevent_over_time_tests
