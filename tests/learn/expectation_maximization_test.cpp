// EM (pgm/learn/expectation_maximization.hpp) against an EM written here by brute force, the
// complete-data estimate, the truth of published and textbook networks, and its own objective.

#include "pgm/learn/expectation_maximization.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "pgm/inference/sampling.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/pipeline/fit_pipeline.hpp"
#include "support/enumeration.hpp"

namespace pgm::expectation_maximization_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// `data` with each value missing with probability `fraction` (`latent`: the whole column
/// dropped).
dataset with_gaps(const dataset& data, double fraction, std::uint64_t seed,
                  const std::vector<std::string>& latent = {}) {
  std::mt19937_64 random(seed);
  dataset gapped(data.source());
  for (const auto& name : data.names()) {
    if (std::find(latent.begin(), latent.end(), name) != latent.end()) continue;
    const auto& column = data.discrete(name);
    std::vector<std::uint8_t> codes(data.rows());
    std::size_t missing = 0;
    for (std::size_t row = 0; row < data.rows(); ++row) {
      const bool gap = uniform01(random) < fraction;
      codes[row] = gap ? missing_code<std::uint8_t> : static_cast<std::uint8_t>(column.code(row));
      missing += gap;
    }
    gapped.add(discrete_column(column.var(), code_vector(std::move(codes)), std::in_place, missing));
  }
  return gapped;
}

variable binary(const std::string& name) { return variable(name, {"0", "1"}); }

/// A → B, A → C, B → D, C → D over small variables, with tables far from uniform.
bayesian_network diamond() {
  const variable a("A", {"a0", "a1", "a2"});
  const auto b = binary("B");
  const auto c = binary("C");
  const auto d = binary("D");
  return bayesian_network::from_tables({
      cpt<double>(a, {}, {0.5, 0.3, 0.2}),
      cpt<double>(b, {a}, {0.9, 0.1, 0.4, 0.6, 0.2, 0.8}),
      cpt<double>(c, {a}, {0.7, 0.3, 0.25, 0.75, 0.5, 0.5}),
      cpt<double>(d, {b, c}, {0.95, 0.05, 0.6, 0.4, 0.3, 0.7, 0.1, 0.9}),
  });
}

/// One EM iteration by enumeration: each row's completions weighted by P(completion | row),
/// then MLE (with `alpha` pseudo-counts in every cell).
bayesian_network brute_force_iteration(const bayesian_network& network, const dataset& data, double alpha) {
  const auto n = network.size();
  std::vector<std::vector<double>> counts(n);
  for (std::size_t i = 0; i < n; ++i) counts[i].assign(network.tables()[i].size(), alpha);
  std::vector<variable_id> all;
  for (std::size_t i = 0; i < n; ++i) all.push_back(index_at<variable_id>(i));
  std::vector<std::size_t> cards;
  for (const auto& v : network.variables()) cards.push_back(v.cardinality());
  for (std::size_t row = 0; row < data.rows(); ++row) {
    std::vector<observation> observed;
    for (std::size_t i = 0; i < n; ++i) {
      const auto& name = network.variables()[i].name();
      if (data.contains(name) && !data.discrete(name).is_missing(row)) {
        observed.push_back({all[i], state_index(data.discrete(name).code(row))});
      }
    }
    auto joint = testing::enumerate_joint(network, all, observed);
    double total = 0.0;
    for (double p : joint) total += p;
    for (std::size_t index = 0; index < joint.size(); ++index) {
      if (joint[index] == 0.0) continue;
      std::vector<std::size_t> state(n);
      std::size_t rest = index;
      for (std::size_t i = n; i-- > 0;) {
        state[i] = rest % cards[i];
        rest /= cards[i];
      }
      for (std::size_t i = 0; i < n; ++i) {
        std::size_t u = 0;
        for (auto parent : network.graph().parents(all[i])) u = u * cards[parent.value()] + state[parent.value()];
        counts[i][u * cards[i] + state[i]] += joint[index] / total;
      }
    }
  }
  std::vector<cpt<double>> tables;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = network.tables()[i];
    auto values = counts[i];
    const auto j = t.child_cardinality();
    for (std::size_t u = 0; u < t.configurations(); ++u) {
      double sum = 0.0;
      for (std::size_t x = 0; x < j; ++x) sum += values[u * j + x];
      for (std::size_t x = 0; x < j; ++x)
        values[u * j + x] = sum > 0 ? values[u * j + x] / sum : 1.0 / static_cast<double>(j);
    }
    tables.emplace_back(t.child(), t.parents(), std::move(values));
  }
  return bayesian_network(network.structure(), std::move(tables));
}

void expect_tables_near(const bayesian_network& a, const bayesian_network& b, double tolerance) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto x = a.tables()[i].values();
    const auto y = b.tables()[i].values();
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t c = 0; c < x.size(); ++c)
      EXPECT_NEAR(x[c], y[c], tolerance) << a.variables()[i].name() << " " << c;
  }
}

TEST(expectation_maximization, with_no_missing_value_it_is_the_complete_data_estimate_after_one_iteration) {
  const auto truth = diamond();
  const auto data = sample(truth, 500, 3);
  for (const parameter_prior& prior : {parameter_prior(no_prior{}), parameter_prior(bdeu_prior{4.0})}) {
    fit_options fitting;
    fitting.prior = prior;
    const auto complete = fit(truth.structure(), data, fitting);
    const auto one = expectation_maximization(truth.structure(), data, fitting, {.max_iterations = 1});
    EXPECT_EQ(one.network, complete);  // to the last bit
    // Left to itself, the second M-step changes nothing and it stops there.
    const auto result = expectation_maximization(truth.structure(), data, fitting);
    EXPECT_EQ(result.network, complete);
    EXPECT_EQ(result.iterations, 2U);
    EXPECT_TRUE(result.converged);
    EXPECT_EQ(result.incomplete_patterns, 0U);
  }
}

TEST(expectation_maximization, equals_an_em_by_enumeration_from_the_same_start) {
  const auto truth = diamond();
  const auto data = with_gaps(sample(truth, 400, 5), 0.3, 11);
  for (const double alpha : {0.0, 1.0}) {
    fit_options fitting;
    if (alpha > 0) fitting.prior = dirichlet_prior{alpha};
    // The start: the available-case estimate, which EM starts from by itself.
    const auto start = expectation_maximization(truth.structure(), data, fitting, {.max_iterations = 0}).network;
    auto expected = start;
    for (int i = 0; i < 15; ++i) expected = brute_force_iteration(expected, data, alpha);
    em_options options{.tolerance = 0.0, .max_iterations = 15};
    const auto result = expectation_maximization(truth.structure(), data, fitting, options);
    EXPECT_EQ(result.iterations, 15U);
    expect_tables_near(result.network, expected, 1e-9);
    // The same with variable elimination answering the E-step, and from an explicit start.
    options.start = &start;
    expect_tables_near(
        expectation_maximization<variable_elimination<>>(truth.structure(), data, fitting, options).network, expected,
        1e-9);
  }
}

TEST(expectation_maximization, a_latent_variable_is_estimated_from_a_random_start_equal_to_enumeration) {
  const auto truth = diamond();
  const auto data = with_gaps(sample(truth, 300, 7), 0.1, 13, {"A"});  // A never observed
  std::vector<em_step> steps;
  em_options options{.tolerance = 0.0, .max_iterations = 10, .seed = 4};
  options.on_step = [&](const em_step& step) { steps.push_back(step); };
  const auto result = expectation_maximization(truth.structure(), data, {}, options);
  ASSERT_EQ(steps.size(), 11U);
  // Replay from the start EM drew: the first step's tables are those before any M-step.
  em_options first = options;
  first.max_iterations = 0;
  first.on_step = nullptr;
  auto expected = expectation_maximization(truth.structure(), data, {}, first).network;
  for (int i = 0; i < 10; ++i) expected = brute_force_iteration(expected, data, 0.0);
  expect_tables_near(result.network, expected, 1e-9);
}

TEST(expectation_maximization, the_objective_never_decreases_soft_or_hard_with_or_without_a_prior) {
  const auto truth = diamond();
  const auto data = with_gaps(sample(truth, 2000, 17), 0.25, 19, {"A"});
  for (const auto kind : {em_kind::soft, em_kind::hard}) {
    for (const parameter_prior& prior : {parameter_prior(no_prior{}), parameter_prior(dirichlet_prior{2.0})}) {
      fit_options fitting;
      fitting.prior = prior;
      std::vector<double> objectives;
      em_options options{.kind = kind, .tolerance = 0.0, .max_iterations = 30, .restarts = 2, .seed = 1};
      options.on_step = [&](const em_step& step) {
        if (step.restart == 1) objectives.push_back(step.objective);
      };
      const auto result = expectation_maximization(truth.structure(), data, fitting, options);
      // Tolerance 0 stops only where the objective no longer moves (hard EM reaches its fixed
      // point in a few steps).
      ASSERT_GE(objectives.size(), 3U);
      ASSERT_LE(objectives.size(), 31U);
      for (std::size_t i = 1; i < objectives.size(); ++i) {
        EXPECT_GE(objectives[i], objectives[i - 1] - 1e-9 * std::abs(objectives[i - 1]))
            << (kind == em_kind::hard ? "hard" : "soft") << " iteration " << i;
      }
      EXPECT_TRUE(std::isfinite(result.log_likelihood));
      EXPECT_LE(result.log_likelihood, 0.0);
    }
  }
}

TEST(expectation_maximization, stops_on_the_relative_tolerance_and_is_the_same_for_any_number_of_threads) {
  const auto truth = diamond();
  const auto data = with_gaps(sample(truth, 3000, 23), 0.2, 29, {"A"});
  std::vector<double> objectives;
  em_options options{.tolerance = 1e-6, .max_iterations = 500, .restarts = 3, .seed = 2, .threads = 1};
  options.on_step = [&](const em_step& step) {
    if (step.restart == 0) objectives.push_back(step.objective);
  };
  const auto one = expectation_maximization(truth.structure(), data, {}, options);
  options.threads = 2;
  options.on_step = nullptr;
  const auto two = expectation_maximization(truth.structure(), data, {}, options);
  EXPECT_EQ(one.network, two.network);
  EXPECT_EQ(one.log_likelihood, two.log_likelihood);
  ASSERT_GE(objectives.size(), 3U);
  if (one.restart == 0) {
    EXPECT_TRUE(one.converged);
    const auto n = objectives.size();
    EXPECT_LE(std::abs(objectives[n - 1] - objectives[n - 2]), 1e-6 * std::abs(objectives[n - 2]));
    EXPECT_GT(std::abs(objectives[n - 2] - objectives[n - 3]), 1e-6 * std::abs(objectives[n - 3]));
  }
}

/// Σ |θ - θ_true| over every cell of every table.
double distance(const bayesian_network& a, const bayesian_network& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t c = 0; c < a.tables()[i].size(); ++c) {
      sum += std::abs(a.tables()[i].values()[c] - b.tables()[i].values()[c]);
    }
  }
  return sum;
}

TEST(expectation_maximization, on_alarm_with_a_fifth_of_the_values_missing_it_beats_the_available_case_estimate) {
  const auto alarm = read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / "alarm.bif");
  const auto data = with_gaps(sample(alarm, 2000, 31), 0.2, 37);
  fit_options fitting;
  fitting.prior = bdeu_prior{1.0};
  // What --missing available fits: each family counted over the rows where it is whole.
  fit_request request;
  request.structure = alarm.structure();
  request.options = fitting;
  request.missing.policy = missing_policy::available;
  dataset_source source(data);
  const auto available = fit(source, request).network;
  const auto start = expectation_maximization(alarm.structure(), data, fitting, {.max_iterations = 0});
  const auto em = expectation_maximization(alarm.structure(), data, fitting, {.max_iterations = 8});
  EXPECT_GT(em.log_likelihood, start.log_likelihood);
  EXPECT_LT(distance(em.network, alarm), 0.9 * distance(available, alarm))
      << "EM " << distance(em.network, alarm) << ", available-case " << distance(available, alarm);
}

// The MLE of the complete rows alone can rule out a value that only rows with a gap hold; EM's
// start has a pseudo-count more per cell, so that every row is possible and stays so.
TEST(expectation_maximization, an_mle_fit_of_sparse_data_starts_where_every_row_is_possible) {
  const auto alarm = read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / "alarm.bif");
  const auto data = with_gaps(sample(alarm, 1000, 11), 0.2, 1000);
  std::vector<double> objectives;
  em_options options{.max_iterations = 5};
  options.on_step = [&](const em_step& step) { objectives.push_back(step.objective); };
  const auto em = expectation_maximization(alarm.structure(), data, {}, options);
  EXPECT_TRUE(std::isfinite(em.log_likelihood));
  for (std::size_t k = 1; k < objectives.size(); ++k) EXPECT_GE(objectives[k], objectives[k - 1]);
}

TEST(expectation_maximization, recovers_a_latent_class_up_to_a_permutation_of_its_states) {
  // A latent class H with three noisy binary indicators, the textbook mixture.
  const auto h = binary("H");
  const auto truth = bayesian_network::from_tables({
      cpt<double>(h, {}, {0.3, 0.7}),
      cpt<double>(binary("X1"), {h}, {0.9, 0.1, 0.2, 0.8}),
      cpt<double>(binary("X2"), {h}, {0.85, 0.15, 0.1, 0.9}),
      cpt<double>(binary("X3"), {h}, {0.8, 0.2, 0.3, 0.7}),
  });
  const auto data = with_gaps(sample(truth, 20000, 41), 0.0, 43, {"H"});
  const auto result = expectation_maximization(truth.structure(), data, {}, {.restarts = 5, .seed = 9});
  // Match H's states: its prior decides which estimated state is the true state 0.
  const auto& estimated = result.network.tables();
  const bool swapped = std::abs(estimated[0].values()[0] - 0.3) > std::abs(estimated[0].values()[1] - 0.3);
  const auto matched = [&](std::size_t node, std::size_t u, std::size_t x) {
    return estimated[node].values()[(swapped ? 1 - u : u) * 2 + x];
  };
  EXPECT_NEAR(estimated[0].values()[swapped ? 1 : 0], 0.3, 0.03);
  for (std::size_t node = 1; node < 4; ++node) {
    for (std::size_t u = 0; u < 2; ++u) {
      EXPECT_NEAR(matched(node, u, 0), truth.tables()[node].values()[u * 2], 0.03) << node << " " << u;
    }
  }
}

TEST(expectation_maximization, refuses_what_it_cannot_fit) {
  const auto truth = diamond();
  const auto data = sample(truth, 10, 1);
  EXPECT_THAT([&] { static_cast<void>(expectation_maximization(truth.structure(), data.slice(0, 0))); },
              ThrowsMessage<data_error>(HasSubstr("EM needs at least one row of data")));
  EXPECT_THAT([&] { static_cast<void>(expectation_maximization(truth.structure(), data, {}, {.tolerance = -1.0})); },
              ThrowsMessage<model_error>(HasSubstr("the EM tolerance must be a finite number >= 0")));
  dataset other;
  other.add(discrete_column(variable("B", {"x", "y"}), std::vector<std::uint8_t>{0, 1}));
  EXPECT_THAT([&] { static_cast<void>(expectation_maximization(truth.structure(), other)); },
              ThrowsMessage<data_error>(HasSubstr("column 'B' has the states {x, y} but the network expects {0, 1}")));
  const auto unrelated = bayesian_network::from_tables({cpt<double>(binary("B"), {}, {0.5, 0.5})});
  EXPECT_THAT([&] { static_cast<void>(expectation_maximization(truth.structure(), data, {}, {.start = &unrelated})); },
              ThrowsMessage<model_error>(HasSubstr("another structure")));
  // A family past the limit of a dense table is refused by name before anything is allocated
  // (issue 49: "out of memory").
  std::vector<variable> variables{binary("C")};
  std::vector<named_edge> edges;
  dataset wide;
  wide.add(discrete_column(binary("C"), std::vector<std::uint8_t>{0, 1}));
  for (int p = 0; p < 40; ++p) {
    variables.push_back(binary("P" + std::to_string(p)));
    edges.push_back({"P" + std::to_string(p), "C"});
    wide.add(discrete_column(variables.back(), std::vector<std::uint8_t>{1, 0}));
  }
  EXPECT_THAT([&] { static_cast<void>(expectation_maximization(network_structure(variables, edges), wide)); },
              ThrowsMessage<table_too_large>(HasSubstr(
                  "EM holds every table dense, and the table of 'C' with 40 parents has 2199023255552 cells")));
}

}  // namespace
}  // namespace pgm::expectation_maximization_tests
