// The analytic back-end: the shape of its physics, determinism across thread counts, its
// Monte-Carlo rates against the integrated ground truth, and Table I's interval edges.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <sstream>

#include "pgm/data/discretizer.hpp"
#include "pgm/io/csv.hpp"
#include "sim/sim_support.hpp"

namespace pgm::sim::analytic_tests {
namespace {

using ::testing::HasSubstr;
using testing::pinned;
using testing::rate;
using testing::shipped;

const std::vector<double> offset_edges{-3, -1.4, -0.4, 0.4, 1.4, 3};

TEST(analytic_test, success_falls_as_offsets_grow) {
  const auto task = shipped("1-stack");
  double previous = 1.1;
  for (double x : {0.0, 1.0, 2.0, 2.4, 2.7, 3.0}) {
    const double p = rate(pinned(task, {{"xOff1", x}, {"yOff1", 0.0}, {"dropOff1", 2.0}}), "analytic", 20000);
    EXPECT_LE(p, previous) << x;
    previous = p;
  }
  EXPECT_LT(previous, 0.1);
  double ground_truth_previous = 1.1;
  for (std::size_t b : {2, 3, 4}) {
    const double p = analytic_success_probability(task, {{"xOff1", {offset_edges[b], offset_edges[b + 1]}}});
    EXPECT_LT(p, ground_truth_previous);
    ground_truth_previous = p;
  }
}

TEST(analytic_test, centred_stack_succeeds_and_a_cube_beyond_half_its_width_falls) {
  const auto two = shipped("2-stack");
  const std::map<std::string, double> centred{{"xOff1", 0.0}, {"yOff1", 0.0}, {"xOff2", 0.0}, {"yOff2", 0.0}};
  EXPECT_GT(rate(pinned(two, centred), "analytic", 20000), 0.99);
  EXPECT_GT(analytic_success_probability(
                two, {{"xOff1", {-0.4, 0.4}}, {"yOff1", {-0.4, 0.4}}, {"xOff2", {-0.4, 0.4}}, {"yOff2", {-0.4, 0.4}}}),
            0.98);
  // Beyond half the width (2.5 cm) the cube falls; release noise blurs the edge a little.
  EXPECT_LT(rate(pinned(shipped("1-stack"), {{"xOff1", 3.0}, {"dropOff1", 1.0}}), "analytic", 20000), 0.05);
  EXPECT_LT(analytic_success_probability(shipped("1-stack"), {{"xOff1", {2.7, 3.0}}}), 0.2);
  // Two cubes fail more often than one.
  EXPECT_LT(analytic_success_probability(two, {}) + 0.15, analytic_success_probability(shipped("1-stack"), {}));
}

TEST(analytic_test, sphere_lands_in_a_glass_and_the_plate_loses_more_than_the_bowl) {
  const std::map<std::string, double> centred{{"xOff", 0.0}, {"yOff", 0.0}, {"scalingFactor", 0.8}};
  for (const auto* name : {"drop-plate", "drop-bowl", "drop-glass"}) {
    EXPECT_GT(rate(pinned(shipped(name), centred), "analytic", 20000), 0.99) << name;
  }
  // Released 4.5 to 5.5 cm off the axis at scale 0.6, the sphere lands beyond the flat floor
  // (5.4 cm for the plate, 4.3 for the bowl) and hits the wall: the plate's shallow wall
  // throws it out, the bowl's steep one keeps it.
  auto loss = [](const std::string& name) {
    const auto task = pinned(shipped(name), {{"scalingFactor", 0.6}, {"yOff", 0.0}});
    simulate_options o;
    o.rows = 20000;
    o.seed = 8;
    o.threads = 2;
    const auto data = simulate(task, o);
    double landed = 0, lost = 0;
    for (std::size_t row = 0; row < data.rows(); ++row) {
      if (const double x = std::abs(data.continuous("xOff").values()[row]); x > 4.5 && x < 5.5) {
        landed += 1;
        lost += 1 - data.discrete("inside").code(row);
      }
    }
    return lost / landed;
  };
  EXPECT_GT(loss("drop-plate"), 0.5);
  EXPECT_LT(loss("drop-bowl"), 0.2);
  // Far off the axis the sphere misses.
  EXPECT_LT(
      rate(pinned(shipped("drop-glass"), {{"xOff", 6.0}, {"yOff", 6.0}, {"scalingFactor", 0.5}}), "analytic", 5000),
      0.01);
}

TEST(analytic_test, same_data_for_any_thread_count) {
  for (const auto* name : {"2-stack", "drop-plate", "1-stack-reality"}) {
    const auto task = shipped(name);
    simulate_options o;
    o.rows = 50'001;  // not a multiple of the chunk size
    o.seed = 42;
    o.threads = 1;
    const auto one = simulate(task, o);
    o.threads = 2;
    EXPECT_EQ(simulate(task, o), one) << name;
    o.threads = 5;
    EXPECT_EQ(simulate(task, o), one) << name;
    o.seed = 43;
    EXPECT_FALSE(simulate(task, o) == one) << name;
  }
}

// Rows made in blocks (first_row) are the rows of one run: pgm simulate writes its rows so.
TEST(analytic_test, a_run_in_blocks_gives_the_data_of_one_piece) {
  const auto task = shipped("2-stack");
  simulate_options o;
  o.rows = 10'000;
  o.seed = 7;
  const auto whole = simulate(task, o);
  std::ostringstream blocks;
  for (const std::size_t first : {0U, 3'000U, 3'001U, 9'999U}) {
    o.first_row = first;
    o.rows = (first == 0 ? 3'000U : first == 3'000U ? 1U : first == 3'001U ? 6'998U : 1U);
    const auto block = simulate(task, o);
    if (first == 0) {
      write_csv(block, blocks);
    } else {
      write_csv_rows(block, blocks);
    }
  }
  std::ostringstream one;
  write_csv(whole, one);
  EXPECT_EQ(blocks.str(), one.str());
}

TEST(analytic_test, columns_and_progress) {
  const auto task = shipped("1-stack");
  std::vector<std::size_t> reports;
  simulate_options o;
  o.rows = 20000;
  o.seed = 1;
  o.threads = 2;
  o.progress = [&](std::size_t done) { reports.push_back(done); };
  const auto data = simulate(task, o);
  EXPECT_EQ(data.names(), task.names());
  EXPECT_FALSE(data.is_discrete("xOff1"));
  EXPECT_EQ(data.discrete("onTop1").var().states(), (std::vector<std::string>{"0", "1"}));
  EXPECT_EQ(data.discrete("colorUp1").var().states(), (std::vector<std::string>{"Red", "Blue", "Green", "Orange"}));
  EXPECT_EQ(data.continuous("xOff1").tags().quantity, "x-offset");
  ASSERT_FALSE(reports.empty());
  EXPECT_EQ(reports.back(), 20000U);
  EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
  for (double v : data.continuous("xOff1").values()) ASSERT_TRUE(v >= -3 && v <= 3);
  for (double v : data.continuous("dropOff1").values()) ASSERT_TRUE(v >= 0.5 && v <= 10);
}

TEST(analytic_test, unknown_backend_is_an_error) {
  simulate_options o;
  o.backend = "unity";
  o.rows = 1;
  EXPECT_THAT([&] { (void)simulate(shipped("1-stack"), o); },
              ::testing::ThrowsMessage<unknown_name>(HasSubstr("unknown simulator back-end 'unity' (known: analytic")));
}

// Monte-Carlo rates per Table I box agree with the integrated probability within 4.5
// binomial standard errors plus the integration's 1e-3 (a 2e-4 false alarm rate over all boxes).
void expect_monte_carlo_matches(const task_definition& task, const std::string& outcome,
                                const std::vector<std::string>& names, const std::vector<std::vector<double>>& edges,
                                std::size_t rows) {
  const auto& name = task.name;
  simulate_options o;
  o.rows = rows;
  o.seed = 2024;
  o.threads = 2;
  const auto data = simulate(task, o);
  // Boxes over the product of each variable's own edges.
  std::size_t boxes = 1;
  for (const auto& e : edges) boxes *= e.size() - 1;
  std::vector<double> successes(boxes), counts(boxes);
  const auto& success = data.discrete(outcome);
  for (std::size_t row = 0; row < data.rows(); ++row) {
    std::size_t index = 0;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const double v = data.continuous(names[i]).values()[row];
      const auto b = static_cast<std::size_t>(std::upper_bound(edges[i].begin() + 1, edges[i].end() - 1, v) -
                                              (edges[i].begin() + 1));
      index = index * (edges[i].size() - 1) + b;
    }
    counts[index] += 1;
    successes[index] += success.code(row);
  }
  double worst = 0;
  for (std::size_t index = 0; index < boxes; ++index) {
    variable_box box;
    auto rest = index;
    for (std::size_t i = names.size(); i-- > 0;) {
      const auto bins = edges[i].size() - 1;
      box[names[i]] = {edges[i][rest % bins], edges[i][rest % bins + 1]};
      rest /= bins;
    }
    const double exact = analytic_outcome_probability(task, outcome, box);
    ASSERT_GT(counts[index], 500) << index;
    const double observed = successes[index] / counts[index];
    const double se = std::sqrt(std::max(exact * (1 - exact), 1e-4) / counts[index]);
    EXPECT_NEAR(observed, exact, 4.5 * se + 1e-3) << name << " box " << index;
    worst = std::max(worst, std::abs(observed - exact) / (se + 1e-12));
  }
  ::testing::Test::RecordProperty("worst_z_" + name, std::to_string(worst));
}

TEST(analytic_test, monte_carlo_agrees_with_integrated_probability) {
  expect_monte_carlo_matches(shipped("1-stack"), "onTop1", {"xOff1", "yOff1"}, {offset_edges, offset_edges}, 200'000);
  // 2-stack's onTop2 over (xOff1, xOff2), yOff integrated out, so boxes stay well filled.
  expect_monte_carlo_matches(shipped("2-stack"), "onTop2", {"xOff1", "xOff2"}, {offset_edges, offset_edges}, 200'000);
  expect_monte_carlo_matches(shipped("2-stack-reality"), "onTop2", {"xOff1", "xOff2"},
                             {{-1, 0.5, 1.5, 3}, {-1, 0.5, 1.5, 3}}, 45'000);
  // Three cubes: onTop2 and onTop3 over thirds of the first and last cube's x offsets.
  const std::vector<double> thirds{-3, -1, 1, 3};
  expect_monte_carlo_matches(testing::three_stack(), "onTop2", {"xOff1", "xOff2"}, {thirds, thirds}, 100'000);
  expect_monte_carlo_matches(testing::three_stack(), "onTop3", {"xOff1", "xOff3"}, {thirds, thirds}, 100'000);
  const std::vector<double> drop_edges{-6, -3.6, -1.2, 1.2, 3.6, 6};
  for (const auto* name : {"drop-plate", "drop-bowl", "drop-glass"}) {
    expect_monte_carlo_matches(shipped(name), "inside", {"xOff", "scalingFactor"},
                               {drop_edges, {0.4, 0.52, 0.64, 0.76, 0.88, 1.0}}, 100'000);
  }
}

TEST(analytic_test, integration_is_accurate_and_quick) {
  const auto two = shipped("2-stack");
  const integration_options fine{32, 64, 4096, 8192, 512, 16384};
  for (const auto& box :
       std::vector<variable_box>{{},
                                 {{"xOff1", {0.4, 1.4}}, {"xOff2", {-3, -1.4}}},
                                 {{"xOff1", {-0.4, 0.4}}, {"yOff1", {1.4, 3}}, {"dropOff2", {4.6, 10}}}}) {
    EXPECT_NEAR(analytic_outcome_probability(two, "onTop2", box),
                analytic_outcome_probability(two, "onTop2", box, fine), 1e-3);
  }
  const auto glass = shipped("drop-glass");
  const variable_box box{{"xOff", {1.2, 3.6}}, {"scalingFactor", {0.4, 0.52}}};
  EXPECT_NEAR(analytic_success_probability(glass, box), analytic_outcome_probability(glass, "inside", box, fine), 1e-3);
  for (const auto* name : {"drop-plate", "drop-bowl"}) {
    EXPECT_NEAR(analytic_success_probability(shipped(name), box),
                analytic_outcome_probability(shipped(name), "inside", box, fine), 1e-3)
        << name;
  }
  // Three cubes: a centre-of-mass condition cuts through the inner grid, so the trapezoidal
  // sums converge more slowly; a 4x finer grid moves them by less than 2e-3.
  const auto three = testing::three_stack();
  const variable_box third_box{{"xOff1", {1, 3}}, {"xOff3", {-1, 1}}};
  integration_options finer;
  finer.stacking_grid = 1024;
  EXPECT_NEAR(analytic_outcome_probability(three, "onTop3", third_box),
              analytic_outcome_probability(three, "onTop3", third_box, finer), 2e-3);
  EXPECT_THROW((void)analytic_success_probability(two, {{"colorUp1", {0, 1}}}), data_error);
  EXPECT_THROW((void)analytic_success_probability(shipped("2-stack-reality"), {{"xOff1", {3, 4}}}), data_error);
}

// Table I's edges for the offsets (±0.4, ±1.4 cm) and release heights (1.4, 2.2, 3.2, 4.6 cm)
// come back from quantile discretization of simulated data, within 0.1 and 0.15 cm.
TEST(analytic_test, quantile_edges_reproduce_table_one) {
  simulate_options o;
  o.rows = 100'000;
  o.seed = 5;
  o.threads = 2;
  const auto data = simulate(shipped("2-stack"), o);
  for (const auto* name : {"xOff1", "yOff1", "xOff2", "yOff2"}) {
    const auto edges = quantile_edges(data.continuous(name).values(), 5, name);
    ASSERT_EQ(edges.size(), 6U);
    const std::vector<double> table{-3.0, -1.4, -0.4, 0.4, 1.4, 3.0};
    for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(edges[i], table[i], 0.1) << name << " edge " << i;
  }
  for (const auto* name : {"dropOff1", "dropOff2"}) {
    const auto edges = quantile_edges(data.continuous(name).values(), 5, name);
    const std::vector<double> table{1.4, 2.2, 3.2, 4.6};
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(edges[i + 1], table[i], 0.15) << name << " edge " << i + 1;
  }
}

}  // namespace
}  // namespace pgm::sim::analytic_tests
