#pragma once
/// \file
/// The conformance kit of transfer strategies: a GoogleTest suite that holds a strategy, by its
/// registered name, to what every prior must be, on the paper's transfer shapes with random
/// tables (a 2-stack's second cube from the first; a task to itself; a prior parent marginalized
/// out; coarser target intervals matched by overlap): a table in the target
/// node's shape whose columns are distributions; sources() that name configurations of the prior
/// table with positive weights summing to one, and whose mixture is the column; the same prior for
/// the same problem. Instantiate it in one test source of a program that links GoogleTest:
///
///     #include <pgm/testing/strategy_conformance.hpp>
///     using pgm::testing::strategy_conformance;  // the macro takes the suite's name unqualified
///     INSTANTIATE_TEST_SUITE_P(mine, strategy_conformance, ::testing::Values("blend"),
///                              pgm::testing::strategy_name);
///
/// or over every registered strategy with `::testing::ValuesIn(registered_strategy_names())`.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/correspondence.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/testing/case_names.hpp"
#include "pgm/testing/random_network.hpp"
#include "pgm/transfer/registry.hpp"
#include "pgm/transfer/transfer_problem.hpp"

namespace pgm::testing {

/// Every strategy the registry holds when the tests are set up.
[[nodiscard]] inline std::vector<std::string> registered_strategy_names() {
  return transfer_registry::instance().names();
}

/// The strategy's name as a test name.
[[nodiscard]] inline std::string strategy_name(const ::testing::TestParamInfo<std::string>& info) {
  return test_name(info.param);
}

/// The inputs of one transfer, held together (a transfer_problem refers to its prior network).
struct transfer_case {
  std::string label;
  bayesian_network prior;
  std::string prior_node;
  variable child;
  std::vector<variable> parents;
  correspondence map;
  transfer_options options;

  [[nodiscard]] transfer_problem problem() const { return {prior, prior_node, child, parents, map, options}; }
};

/// A binary outcome's table over `parents` with a success probability drawn for each configuration.
[[nodiscard]] inline cpt<double> random_outcome_table(const variable& child, std::vector<variable> parents,
                                                      std::mt19937_64& random) {
  std::size_t configurations = 1;
  for (const auto& p : parents) configurations *= p.cardinality();
  std::uniform_real_distribution<double> success(0.02, 0.98);
  std::vector<double> values;
  for (std::size_t u = 0; u < configurations; ++u) {
    const double p = success(random);
    values.push_back(1.0 - p);
    values.push_back(p);
  }
  return {child, std::move(parents), std::move(values)};
}

/// A network of uniform roots `parents` and the outcome `child` under them.
[[nodiscard]] inline bayesian_network outcome_network(const variable& child, const std::vector<variable>& parents,
                                                      std::mt19937_64& random) {
  std::vector<cpt<double>> tables;
  for (const auto& p : parents)
    tables.emplace_back(p, std::vector<variable>{},
                        std::vector<double>(p.cardinality(), 1.0 / static_cast<double>(p.cardinality())));
  tables.push_back(random_outcome_table(child, parents, random));
  return bayesian_network::from_tables(std::move(tables));
}

/// The kit's problems for `seed`: the paper's shapes with random tables and interval edges.
[[nodiscard]] inline std::vector<transfer_case> transfer_cases(std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> width(0.5, 1.5);
  const auto offset = [&](const std::string& name, std::size_t bins) {
    std::vector<double> edges{-3.0};
    for (std::size_t b = 0; b < bins; ++b) edges.push_back(edges.back() + width(random));
    return variable::intervals(name, edges);
  };
  const std::size_t bins = 2 + seed % 4;
  const variable on_top_1("onTop1", {"0", "1"}), on_top_2("onTop2", {"0", "1"});
  const auto x1 = offset("xOff1", bins), y1 = offset("yOff1", bins);
  std::vector<transfer_case> cases;
  // The paper's 2-stack: direct reads the first cube's offsets, cross the second's as the first's.
  cases.push_back({"2-stack",
                   outcome_network(on_top_1, {x1, y1}, random),
                   "onTop1",
                   on_top_2,
                   {x1, y1, offset("xOff2", bins), offset("yOff2", bins)},
                   parse_correspondence("onTop2=onTop1, xOff2~xOff1, yOff2~yOff1"),
                   {}});
  const auto stack = cases.front().prior;  // a copy: the cases grow
  // A task to itself, from a random network's node with its parents (each its own counterpart
  // for cross as well).
  const auto net = random_network(seed, {.nodes = 5, .max_parents = 3, .max_states = 3});
  const auto& last = net.variables().back();
  const auto own_parents = net.table(net.id(last.name())).parents();
  std::string own_map = last.name() + "=" + last.name();
  for (const auto& p : own_parents) own_map += ", " + p.name() + "~" + p.name();
  transfer_options own_states;
  own_states.success_state = "s1";  // what Minimal-Replacement compares
  cases.push_back({"itself", net, last.name(), last, own_parents, parse_correspondence(own_map), own_states});
  // A prior parent marginalized out by the prior network's marginal.
  cases.push_back({"yOff1 marginalized",
                   stack,
                   "onTop1",
                   on_top_1,
                   {x1},
                   parse_correspondence("onTop1=onTop1, xOff1~xOff1, yOff1@*"),
                   {}});
  // Coarser target intervals, each prior interval weighted by its overlap.
  const auto& edges = x1.edges();
  const variable coarse = variable::intervals("xOff1", {edges.front(), edges[edges.size() / 2], edges.back()});
  transfer_options overlap;
  overlap.matching = state_matching::overlap;
  cases.push_back({"overlap matching",
                   stack,
                   "onTop1",
                   on_top_1,
                   {coarse, y1},
                   parse_correspondence("onTop1=onTop1, xOff1~xOff1, yOff1~yOff1"),
                   overlap});
  return cases;
}

class strategy_conformance : public ::testing::TestWithParam<std::string> {
 protected:
  static constexpr std::uint64_t seeds = 8;

  /// Calls `check(problem, case, prior)` on every problem of every seed.
  template <class Check>
  void for_each_prior(Check&& check) const {
    const auto strategy = transfer_registry::instance().at(GetParam());
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
      for (const auto& c : transfer_cases(seed)) {
        SCOPED_TRACE(c.label + ", seed " + std::to_string(seed));
        const auto problem = c.problem();
        check(problem, c, strategy(problem));
      }
    }
  }
};

TEST_P(strategy_conformance, priors_are_distributions_in_the_target_shape) {
  for_each_prior([](const transfer_problem&, const transfer_case& c, const transferred_prior& prior) {
    const auto& table = prior.table();
    EXPECT_EQ(table.child(), c.child);
    EXPECT_EQ(table.parents(), c.parents);
    for (std::size_t u = 0; u < table.configurations(); ++u) {
      double sum = 0.0;
      for (double p : table.column(index_at<config_index>(u))) {
        EXPECT_TRUE(p >= 0.0 && p <= 1.0) << "configuration " << u << ": " << p;
        sum += p;
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << "configuration " << u;
    }
  });
}

TEST_P(strategy_conformance, each_column_is_the_mixture_its_sources_name) {
  for_each_prior([](const transfer_problem& problem, const transfer_case&, const transferred_prior& prior) {
    const auto& source_table = problem.prior_table();
    EXPECT_EQ(prior.prior_parents(), source_table.parents());
    const auto& table = prior.table();
    for (std::size_t u = 0; u < table.configurations(); ++u) {
      const config_index target = index_at<config_index>(u);
      const auto sources = prior.sources(target);
      ASSERT_FALSE(sources.empty()) << "configuration " << u;
      std::vector<double> mixture(table.child_cardinality(), 0.0);
      double weights = 0.0;
      for (const auto& term : sources) {
        ASSERT_LT(term.configuration, source_table.configurations()) << "configuration " << u;
        EXPECT_GT(term.weight, 0.0) << "configuration " << u;
        weights += term.weight;
        const auto column = source_table.column(index_at<config_index>(term.configuration));
        for (std::size_t x = 0; x < mixture.size(); ++x) mixture[x] += term.weight * column[x];
      }
      EXPECT_NEAR(weights, 1.0, 1e-12) << "configuration " << u;
      for (std::size_t x = 0; x < mixture.size(); ++x) {
        EXPECT_NEAR(table.column(target)[x], mixture[x], 1e-12) << "configuration " << u << ", state " << x;
      }
    }
  });
}

TEST_P(strategy_conformance, the_same_problem_gives_the_same_prior) {
  const auto strategy = transfer_registry::instance().at(GetParam());
  for_each_prior([&](const transfer_problem& problem, const transfer_case&, const transferred_prior& prior) {
    const auto again = strategy(problem);
    EXPECT_EQ(again.table(), prior.table());
    for (std::size_t u = 0; u < prior.table().configurations(); ++u) {
      const config_index c = index_at<config_index>(u);
      EXPECT_TRUE(std::ranges::equal(again.sources(c), prior.sources(c))) << "configuration " << u;
    }
  });
}

}  // namespace pgm::testing
