// The metrics by hand, the scenario file, and the protocol on a tiny scenario whose answers are
// known: a deterministic task where the prior is the truth.

#include "pgm/eval/experiment.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "eval/tiny_scenario.hpp"

namespace experiment_tests {
namespace {

using namespace pgm;
using pgm::test::deterministic_tasks;
using pgm::test::tiny_scenario;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(metrics_test, every_metric_reads_back_from_its_name) {
  for (auto metric : experiment_metrics) EXPECT_EQ(parse_experiment_metric(to_string(metric)), metric);
  EXPECT_THAT([] { static_cast<void>(parse_experiment_metric("chosen_W")); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown metric 'chosen_W'; did you mean 'chosen_w'?")));
}

TEST(metrics_test, max_and_mean_difference_by_hand) {
  const variable x("x", {"a", "b", "c"}), ok("ok", {"0", "1"});
  const cpt<double> estimate(ok, {x}, {0.5, 0.5, 0.1, 0.9, 0.3, 0.7});
  const cpt<double> truth(ok, {x}, {0.2, 0.8, 0.1, 0.9, 0.9, 0.1});
  const auto d = success_parameter_difference(estimate, truth, 1);
  EXPECT_DOUBLE_EQ(d.max, 0.6);
  EXPECT_DOUBLE_EQ(d.mean, (0.3 + 0.0 + 0.6) / 3);
  EXPECT_LE(d.mean, d.max);
}

double value_of(const std::vector<experiment_point>& points, const std::string& strategy, const std::string& w,
                std::size_t rows, experiment_metric metric, std::size_t rep = 0) {
  for (const auto& p : points) {
    if (p.strategy == strategy && p.weight == w && p.rows == rows && p.metric == metric && p.repetition == rep)
      return p.value;
  }
  ADD_FAILURE() << "no point " << strategy << " w=" << w << " |D|=" << rows << " " << to_string(metric);
  return NAN;
}

TEST(experiment_test, a_prior_equal_to_the_truth_is_exact_at_zero_data) {
  const auto s = parse_scenario(tiny_scenario, "tiny.json");
  const auto points = run_experiment(s, deterministic_tasks(), {.threads = 1});
  for (std::size_t rep = 0; rep < 3; ++rep) {
    // Minimal-Replacement's prior is min(P(x1 ok), P(x2 ok)) = the truth exactly.
    EXPECT_EQ(value_of(points, "minimal", "5", 0, experiment_metric::max_difference, rep), 0.0);
    EXPECT_EQ(value_of(points, "minimal", "5", 0, experiment_metric::failure_prevention, rep), 1.0);
    // MLE without data is 1/2 everywhere: off by 1/2, and prevents nothing.
    EXPECT_EQ(value_of(points, "mle", "0", 0, experiment_metric::max_difference, rep), 0.5);
    EXPECT_EQ(value_of(points, "oracle", "0", 0, experiment_metric::failure_prevention, rep), 1.0);
    EXPECT_LT(value_of(points, "mle", "0", 0, experiment_metric::failure_prevention, rep), 0.5);
    // Direct-Replacement ignores the second cube: wrong where x2 = 2, i.e. by 1 there.
    EXPECT_EQ(value_of(points, "direct", "5", 0, experiment_metric::max_difference, rep), 1.0);
    // With data, MLE is exact wherever D has rows, so its mean difference falls.
    EXPECT_LT(value_of(points, "mle", "0", 40, experiment_metric::mean_difference, rep),
              value_of(points, "mle", "0", 0, experiment_metric::mean_difference, rep));
  }
  // |D| runs over 0, 10, 20, 30, 40.
  std::set<std::size_t> sizes;
  for (const auto& p : points) sizes.insert(p.rows);
  EXPECT_EQ(sizes, (std::set<std::size_t>{0, 10, 20, 30, 40}));
}

TEST(experiment_test, the_same_seed_gives_the_same_points_for_any_thread_count) {
  const auto s = parse_scenario(tiny_scenario, "tiny.json");
  const auto one = run_experiment(s, deterministic_tasks(), {.seed = 7, .threads = 1});
  const auto two = run_experiment(s, deterministic_tasks(), {.seed = 7, .threads = 2});
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].value, two[i].value) << i;
    EXPECT_EQ(one[i].metric, two[i].metric);
  }
  const auto other = run_experiment(s, deterministic_tasks(), {.seed = 8, .threads = 2});
  bool differs = false;
  for (std::size_t i = 0; i < one.size(); ++i) differs |= one[i].value != other[i].value;
  EXPECT_TRUE(differs) << "another seed draws other splits";
}

// Failure prevention moves configurations predicted below the scenario's ε: another ε moves
// others, so the prevention numbers change and nothing else does.
TEST(experiment_test, prevention_uses_the_scenarios_epsilon) {
  const auto usual = parse_scenario(tiny_scenario, "tiny.json");
  ASSERT_EQ(usual.epsilon, 0.8);
  std::string text = tiny_scenario;
  text.insert(text.rfind('}'), R"(, "epsilon": 0.3)");
  const auto low = parse_scenario(text, "tiny.json");
  ASSERT_EQ(low.epsilon, 0.3);
  const auto a = run_experiment(usual, deterministic_tasks(), {.seed = 7, .threads = 1});
  const auto b = run_experiment(low, deterministic_tasks(), {.seed = 7, .threads = 1});
  ASSERT_EQ(a.size(), b.size());
  std::size_t changed = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].metric, b[i].metric);
    if (a[i].metric == experiment_metric::failure_prevention) {
      changed += a[i].value != b[i].value;
    } else {
      EXPECT_EQ(a[i].value, b[i].value) << to_string(a[i].metric);
    }
  }
  EXPECT_GT(changed, 0U);
  // The scenario's ε wins over the options' default.
  experiment_options other{.seed = 7, .threads = 1};
  other.prevention.epsilon = 0.3;
  const auto c = run_experiment(usual, deterministic_tasks(), other);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].value, c[i].value) << i;
}

// With move costs, both rules' moves are costed and the rule of highest expected utility is
// scored beside the ε-rule; the points without costs stay what they were. On θ* itself the
// utility rule is best by the truth, so its net utility is never below the ε-rule's.
TEST(experiment_test, move_costs_score_the_rule_of_highest_expected_utility_beside_the_epsilon_rule) {
  const auto s = parse_scenario(tiny_scenario, "tiny.json");
  const auto plain = run_experiment(s, deterministic_tasks(), {.seed = 7, .threads = 1});
  std::vector<std::string> notes;
  experiment_options costed{.seed = 7, .threads = 1};
  costed.costs = move_costs{.reward = 1, .cost = {{"x1", 0.1}, {"x2", 0.1}, {"x9", 1}}};
  costed.note = [&](const std::string& text) { notes.push_back(text); };
  const auto points = run_experiment(s, deterministic_tasks(), costed);
  EXPECT_THAT(notes, ::testing::Contains(HasSubstr("the cost of moving 'x9' is left out")));
  std::vector<experiment_point> without;
  std::map<std::tuple<std::string, std::string, std::size_t, std::size_t>, std::map<experiment_metric, double>> by;
  for (const auto& p : points) {
    const bool new_metric = p.metric == experiment_metric::prevention_cost ||
                            p.metric == experiment_metric::utility_prevention ||
                            p.metric == experiment_metric::utility_prevention_cost;
    if (!new_metric) without.push_back(p);
    by[{p.strategy, p.weight, p.rows, p.repetition}][p.metric] = p.value;
  }
  ASSERT_EQ(without.size(), plain.size());
  for (std::size_t i = 0; i < plain.size(); ++i) EXPECT_EQ(without[i].value, plain[i].value) << i;
  std::size_t oracles = 0;
  for (const auto& [key, m] : by) {
    ASSERT_EQ(m.count(experiment_metric::utility_prevention), 1U);
    ASSERT_EQ(m.count(experiment_metric::prevention_cost), 1U);
    const double cost = m.at(experiment_metric::utility_prevention_cost);
    EXPECT_GE(cost, 0.0);
    EXPECT_GE(m.at(experiment_metric::prevention_cost), 0.0);
    if (std::get<0>(key) != "oracle") continue;
    ++oracles;
    const double by_epsilon = m.at(experiment_metric::failure_prevention) - m.at(experiment_metric::prevention_cost);
    EXPECT_GE(m.at(experiment_metric::utility_prevention) - cost, by_epsilon - 1e-12);
    // The deterministic task: a run fails only at an offset of 2, and moving it a step or two
    // costs far less than the success it gains, so every failure is moved to success.
    EXPECT_DOUBLE_EQ(m.at(experiment_metric::utility_prevention), 1.0);
  }
  EXPECT_GT(oracles, 0U);
}

TEST(experiment_test, the_split_is_a_uniform_random_subset_fixed_by_the_seed) {
  constexpr std::size_t rows = 20, train = 5, seeds = 4000;
  std::vector<std::size_t> chosen(rows, 0);
  for (std::uint64_t seed = 0; seed < seeds; ++seed) {
    const auto order = split_rows(rows, train, seed);
    ASSERT_EQ(order, split_rows(rows, train, seed));
    auto sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t r = 0; r < rows; ++r) ASSERT_EQ(sorted[r], r) << "a permutation of the rows";
    for (std::size_t i = 0; i < train; ++i) ++chosen[order[i]];
  }
  EXPECT_NE(split_rows(rows, train, 1), split_rows(rows, train, 2));
  // Each row is in D with probability train/rows = 1/4: within 5 standard deviations.
  const double expected = seeds * 0.25, deviation = std::sqrt(seeds * 0.25 * 0.75);
  for (std::size_t r = 0; r < rows; ++r) EXPECT_NEAR(static_cast<double>(chosen[r]), expected, 5 * deviation) << r;
  EXPECT_EQ(split_rows(3, 3, 7).size(), 3U);
}

TEST(experiment_test, a_target_node_without_its_success_state_is_an_error_naming_it) {
  const auto s = parse_scenario(pgm::test::tiny_scenario, "tiny.json");
  auto source = deterministic_tasks();
  const auto facts = source.facts;
  for (const std::string state : {"", "2"}) {
    source.facts = [&](const std::string& task, const std::string& node) {
      auto f = facts(task, node);
      f.success_state = state;
      return f;
    };
    EXPECT_THAT(
        [&] { static_cast<void>(run_experiment(s, source, {.threads = 1})); },
        ThrowsMessage<data_error>(HasSubstr("task 'two': 'ok2' has no success state" +
                                            (state.empty() ? "" : " '" + state + "'") + " (its states: 0, 1)")));
  }
}

TEST(experiment_test, aggregation_gives_mean_and_sample_deviation) {
  std::vector<experiment_point> points;
  for (double v : {1.0, 2.0, 3.0}) points.push_back({"s", "t", "mle", "0", 0, 0, experiment_metric::max_difference, v});
  const auto summary = aggregate(points);
  ASSERT_EQ(summary.size(), 1U);
  EXPECT_DOUBLE_EQ(summary[0].mean, 2.0);
  EXPECT_DOUBLE_EQ(summary[0].standard_deviation, 1.0);
  EXPECT_EQ(summary[0].repetitions, 3U);
}

TEST(scenario_test, errors_name_the_file_and_the_key) {
  EXPECT_THAT([] { static_cast<void>(parse_scenario(R"({"format": "pgm-scenario", "version": 1})", "s.json")); },
              ThrowsMessage<data_error>(HasSubstr("s.json: /: the key 'name' is missing")));
  EXPECT_THAT([] { static_cast<void>(parse_scenario("{\n  \"format\": ", "s.json")); },
              ThrowsMessage<parse_error>(HasSubstr("s.json:2")));
  std::string bad = tiny_scenario;
  bad.replace(bad.find("\"weights\": [0, 5]"), 17, "\"weights\": [0, -5]");
  EXPECT_THAT([&] { static_cast<void>(parse_scenario(bad, "s.json")); },
              ThrowsMessage<data_error>(HasSubstr("/weights: weights must be finite and ≥ 0")));
  // A misspelt optional key would change nothing without a word: it is an error (issue 28).
  std::string typo = tiny_scenario;
  typo.replace(typo.find("\"weights\""), 9, "\"repetitons\": 2, \"weights\"");
  EXPECT_THAT([&] { static_cast<void>(parse_scenario(typo, "s.json")); },
              ThrowsMessage<data_error>(HasSubstr(
                  "s.json: /repetitons: unknown key 'repetitons'; did you mean 'repetitions'? (the keys here: format, "
                  "version, name, title, order, prior, target, map, strategies, weights, bins, subsets, repetitions, "
                  "epsilon)")));
  std::string nested = tiny_scenario;
  nested.replace(nested.find("\"train_rows\""), 12, "\"train_row\"");
  EXPECT_THAT([&] { static_cast<void>(parse_scenario(nested, "s.json")); },
              ThrowsMessage<data_error>(HasSubstr("/target/tasks/0/train_row: unknown key 'train_row'; did you mean "
                                                  "'train_rows'?")));
}

TEST(scenario_test, the_shipped_scenarios_load) {
  for (const auto* name :
       {"2-stack-sim", "2-stack-reality", "2-stack-sim-to-real", "sphere-dropping", "stack-to-drop"}) {
    const auto s =
        load_scenario(std::filesystem::path(PGM_SOURCE_DIR) / "tasks" / "scenarios" / (std::string(name) + ".json"));
    EXPECT_EQ(s.name, name);
    EXPECT_EQ(s.repetitions, 20U);
    EXPECT_EQ(s.subsets, 20U);
  }
}

}  // namespace
}  // namespace experiment_tests
