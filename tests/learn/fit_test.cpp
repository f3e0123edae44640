#include "pgm/learn/fit.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>

#include "pgm/testing/random_network.hpp"

namespace pgm::fit_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// The MLE of one node computed from scratch, row by row, with no pgm counting code.
std::vector<double> naive_mle(const dataset& data, const network_structure& s, variable_id node) {
  const auto& child = data.discrete(s.at(node).name());
  const auto parents = s.parents(node);
  std::map<std::pair<std::vector<std::uint32_t>, std::uint32_t>, double> joint;
  std::map<std::vector<std::uint32_t>, double> marginal;
  for (std::size_t r = 0; r < data.rows(); ++r) {
    std::vector<std::uint32_t> u;
    for (auto p : parents) u.push_back(data.discrete(s.at(p).name()).code(r));
    joint[{u, child.code(r)}] += 1;
    marginal[u] += 1;
  }
  const cpt<double> shape(s.at(node), s.parent_variables(node));
  std::vector<double> values(shape.size());
  const auto j = child.var().cardinality();
  for (std::size_t u = 0; u < shape.configurations(); ++u) {
    const auto codes = shape.parent_codes(config_index(u));
    const std::vector<std::uint32_t> key(codes.begin(), codes.end());
    for (std::size_t x = 0; x < j; ++x) {
      const auto m = marginal.find(key);
      values[u * j + x] =
          m == marginal.end() ? 1.0 / static_cast<double>(j) : joint[{key, static_cast<std::uint32_t>(x)}] / m->second;
    }
  }
  return values;
}

TEST(fit_test, mle_equals_an_independent_naive_fit_on_random_networks) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const auto truth = testing::random_network(seed, {.nodes = 9, .max_parents = 3, .max_states = 4});
    const auto data = sample(truth, 3000, seed + 100);
    const auto fitted = fit(truth.structure(), data);
    for (std::size_t i = 0; i < truth.size(); ++i) {
      const variable_id node = index_at<variable_id>(i);
      const auto expected = naive_mle(data, truth.structure(), node);
      const auto got = fitted.table(node).values();
      ASSERT_EQ(got.size(), expected.size());
      for (std::size_t k = 0; k < got.size(); ++k) EXPECT_EQ(got[k], expected[k]) << "seed " << seed << " node " << i;
    }
  }
}

TEST(fit_test, converges_to_the_generating_network) {
  const auto truth = testing::random_network(42, {.nodes = 6, .max_parents = 2, .max_states = 3});
  const auto fitted = fit(truth.structure(), sample(truth, 400000, 7));
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    const auto a = truth.table(node).values();
    const auto b = fitted.table(node).values();
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 0.02);
  }
}

TEST(fit_test, node_priors_override_the_default) {
  const variable a("a", {"0", "1"});
  const variable b("b", {"0", "1"});
  dataset data;
  data.add(discrete_column(a, std::vector<unsigned>{0, 0, 1}));
  data.add(discrete_column(b, std::vector<unsigned>{1, 1, 0}));
  const network_structure s({a, b}, {{"a", "b"}});
  fit_options options;
  options.prior = k2_prior{};
  options.node_priors.emplace("b", weighted_prior{cpt<double>(b, {a}, {0.5, 0.5, 0.1, 0.9}), 2.0});
  const auto net = fit(s, data, options);
  EXPECT_DOUBLE_EQ(net.table("a").probability("0", std::initializer_list<std::string>{}), 3.0 / 5);
  EXPECT_DOUBLE_EQ(net.table("b").probability("1", {"0"}), (1.0 + 2.0) / 4);
  EXPECT_DOUBLE_EQ(net.table("b").probability("1", {"1"}), (1.8 + 0.0) / 3);
  options.node_priors.emplace("zz", k2_prior{});
  EXPECT_THAT([&] { static_cast<void>(fit(s, data, options)); }, ThrowsMessage<model_error>(HasSubstr("'zz'")));
}

TEST(fit_test, structure_from_data_and_its_errors) {
  dataset data("runs.csv");
  data.add(discrete_column(variable("x", {"0", "1"}), std::vector<unsigned>{0, 1}));
  data.add(discrete_column(variable("y", {"0", "1"}), std::vector<unsigned>{1, 1}));
  data.add(continuous_column("z", {0.5, 0.7}));
  const auto s = structure_from_data(data, {{"y", "x"}});
  EXPECT_EQ(s.variables().front().name(), "x");  // data column order
  EXPECT_THAT(
      [&] {
        static_cast<void>(structure_from_data(data, {{"x", "w"}}));
      },
      ThrowsMessage<data_error>(HasSubstr("runs.csv: there is no column 'w'")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(structure_from_data(data, {{"x", "z"}}));
      },
      ThrowsMessage<data_error>(HasSubstr("'z' holds continuous values")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(structure_from_data(data, {{"x", "y"}, {"y", "x"}}));
      },
      ThrowsMessage<not_a_dag>(HasSubstr("y -> x -> y")));
}

TEST(fit_test, states_must_match_the_model) {
  dataset data("runs.csv");
  data.add(discrete_column(variable("x", {"0", "1"}), std::vector<unsigned>{0, 1}));
  const network_structure s(std::vector<variable>{variable("x", {"0", "1", "2"})});
  EXPECT_THAT([&] { static_cast<void>(fit(s, data)); },
              ThrowsMessage<data_error>(HasSubstr("column 'x' has the states {0, 1} but the model expects {0, 1, 2}")));
}

TEST(fit_test, empty_data_gives_uniform_tables) {
  const variable a("a", {"0", "1", "2"});
  dataset data;
  data.add(discrete_column(a, std::vector<unsigned>{}));
  const auto net = fit(network_structure(std::vector<variable>{a}), data);
  for (double v : net.table("a").values()) EXPECT_EQ(v, 1.0 / 3);
}

}  // namespace
}  // namespace pgm::fit_tests
