#include "pgm/learn/estimate.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "pgm/learn/fit.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::estimate_tests {
namespace {

using ::testing::DoubleEq;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Pointwise;
using ::testing::ThrowsMessage;

// M: p=a: [1, 2]; p=b: [3, 1]; p=c: [0, 0].
count_table small_counts() {
  count_table counts(variable("c", {"0", "1"}), {variable("p", {"a", "b", "c"})});
  const std::vector<std::uint64_t> m{1, 2, 3, 1, 0, 0};
  std::copy(m.begin(), m.end(), counts.counts().begin());
  return counts;
}

std::vector<double> values(const cpt<double>& t) { return {t.values().begin(), t.values().end()}; }

TEST(estimate_test, mle_by_hand) {
  EXPECT_THAT(values(estimate_mle(small_counts())), Pointwise(DoubleEq(), {1.0 / 3, 2.0 / 3, 0.75, 0.25, 0.5, 0.5}));
}

TEST(estimate_test, mle_empty_configuration_is_uniform_over_j_states) {
  count_table counts(variable("c", {"x", "y", "z"}), {variable("p", {"a", "b"})});
  counts.counts()[0] = 2;
  const auto t = estimate_mle(counts);
  EXPECT_THAT(t.column(config_index(0)), ElementsAre(1.0, 0.0, 0.0));
  EXPECT_THAT(t.column(config_index(1)), ElementsAre(1.0 / 3, 1.0 / 3, 1.0 / 3));
}

TEST(estimate_test, empty_configuration_can_be_an_error) {
  estimate_options options;
  options.empty = empty_configuration::fail;
  EXPECT_THAT([&] { static_cast<void>(estimate_mle(small_counts(), options)); },
              ThrowsMessage<data_error>(HasSubstr("no data for 'c' given p=c")));
  // A prior fills the gap, so it is no error then.
  EXPECT_NO_THROW(static_cast<void>(estimate(small_counts(), k2_prior{}, options)));
}

TEST(estimate_test, dirichlet_k2_and_bdeu_by_hand) {
  const auto k2 = values(estimate(small_counts(), k2_prior{}));
  EXPECT_THAT(k2, Pointwise(DoubleEq(), {0.4, 0.6, 4.0 / 6, 2.0 / 6, 0.5, 0.5}));
  EXPECT_EQ(values(estimate(small_counts(), dirichlet_prior{1.0})), k2);
  // BDeu with N' = 6: α = 6 / (2·3) = 1, the same as K2.
  EXPECT_THAT(values(estimate(small_counts(), bdeu_prior{6.0})), Pointwise(DoubleEq(), k2));
  // N' = 3: α = 0.5.
  EXPECT_THAT(values(estimate(small_counts(), bdeu_prior{3.0})),
              Pointwise(DoubleEq(), {1.5 / 4, 2.5 / 4, 3.5 / 5, 1.5 / 5, 0.5, 0.5}));
  EXPECT_EQ(values(estimate(small_counts(), dirichlet_prior{0.0})), values(estimate_mle(small_counts())));
}

TEST(estimate_test, explicit_pseudo_counts) {
  const auto t = estimate(small_counts(), pseudo_counts_prior{{1, 0, 0, 2, 3, 1}});
  EXPECT_THAT(values(t), Pointwise(DoubleEq(), {2.0 / 4, 2.0 / 4, 3.0 / 6, 3.0 / 6, 0.75, 0.25}));
  EXPECT_THAT(
      [] {
        static_cast<void>(estimate(small_counts(), pseudo_counts_prior{{1, 2}}));
      },
      ThrowsMessage<model_error>(HasSubstr("need 6 values, got 2")));
  EXPECT_THAT(
      [] {
        static_cast<void>(estimate(small_counts(), pseudo_counts_prior{{1, 0, 0, 2, 3, -1}}));
      },
      ThrowsMessage<model_error>(HasSubstr("a pseudo-count must be a finite number ≥ 0, got -1")));
}

TEST(estimate_test, pseudo_counts_whose_sum_is_not_finite_are_refused) {
  // Each α = 1e308 is finite, but α·J = 2e308 is not: the table would be 0 everywhere.
  EXPECT_THAT([] { static_cast<void>(estimate(small_counts(), dirichlet_prior{1e308})); },
              ThrowsMessage<model_error>(HasSubstr("the pseudo-counts and counts of 'c' given p=a add up to more "
                                                   "than the largest finite number (1.7976931348623157e+308)")));
  EXPECT_THAT(
      [] {
        static_cast<void>(estimate(small_counts(), pseudo_counts_prior{{1, 1, 1e308, 1e308, 0, 0}}));
      },
      ThrowsMessage<model_error>(HasSubstr("of 'c' given p=b add up to more than the largest finite number")));
  // Just below the limit the table is still normalized.
  const auto near = values(estimate(small_counts(), dirichlet_prior{8e307}));
  EXPECT_THAT(near, Pointwise(DoubleEq(), {0.5, 0.5, 0.5, 0.5, 0.5, 0.5}));
}

cpt<double> prior_table() {
  return cpt<double>(variable("c", {"0", "1"}), {variable("p", {"a", "b", "c"})}, {0.2, 0.8, 0.9, 0.1, 0.6, 0.4});
}

TEST(estimate_test, weighted_prior_eq8_by_hand) {
  const auto t = estimate(small_counts(), weighted_prior{prior_table(), 5.0});
  // a: (5·0.2 + 1) / (5 + 3), (5·0.8 + 2) / 8; b: (4.5 + 3) / 9, (0.5 + 1) / 9; c: the prior.
  EXPECT_THAT(values(t), Pointwise(DoubleEq(), {0.25, 0.75, 7.5 / 9, 1.5 / 9, 0.6, 0.4}));
}

TEST(estimate_test, weighted_prior_shape_and_weight_are_checked) {
  const cpt<double> wrong(variable("c", {"0", "1"}), {variable("p", {"a", "b"})});
  EXPECT_THAT(
      [&] {
        static_cast<void>(estimate(small_counts(), weighted_prior{wrong, 1.0}));
      },
      ThrowsMessage<model_error>(HasSubstr("(2 states × 2 configurations) does not match the shape of 'c' (2 × 3)")));
  EXPECT_THAT(
      [] {
        static_cast<void>(estimate(small_counts(), weighted_prior{prior_table(), -1.0}));
      },
      ThrowsMessage<model_error>(HasSubstr("the prior weight w must be a finite number ≥ 0")));
  EXPECT_THROW(static_cast<void>(estimate(small_counts(), weighted_prior{prior_table(), std::nan("")})), model_error);
}

// A random prior table of the shape of `counts`.
cpt<double> random_prior(const count_table& counts, std::mt19937_64& engine) {
  std::vector<double> v(counts.counts().size());
  const auto j = counts.child_cardinality();
  std::exponential_distribution<double> gamma1(1.0);
  for (std::size_t u = 0; u < counts.configurations(); ++u) {
    double sum = 0;
    for (std::size_t x = 0; x < j; ++x) sum += v[u * j + x] = gamma1(engine);
    for (std::size_t x = 0; x < j; ++x) v[u * j + x] /= sum;
  }
  return cpt<double>(counts.child(), counts.parents(), v);
}

// Eq. 7/8 against its special cases on every family of random networks, bit for bit.
TEST(estimate_test, weighted_prior_identities_on_random_networks) {
  std::mt19937_64 engine(99);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto network = testing::random_network(seed, {.nodes = 7, .max_parents = 3});
    const auto data = sample(network, 400, seed);
    const auto empty = data.slice(0, 0);
    for (std::size_t i = 0; i < network.size(); ++i) {
      const variable_id node = index_at<variable_id>(i);
      const auto counts = count_node(network.structure(), node, data);
      const auto f = random_prior(counts, engine);
      // w = 0 is MLE.
      EXPECT_EQ(estimate(counts, weighted_prior{f, 0.0}), estimate_mle(counts));
      // M[u] = 0 gives the prior itself, for any w > 0.
      EXPECT_EQ(estimate(count_node(network.structure(), node, empty), weighted_prior{f, 3.7}), f);
      // Eq. 7 is eq. 6 with α = w·f (up to rounding of the column sum).
      const double w = 12.5;
      std::vector<double> alpha(f.values().begin(), f.values().end());
      for (auto& a : alpha) a *= w;
      const auto eq7 = estimate(counts, weighted_prior{f, w});
      const auto eq6 = estimate(counts, pseudo_counts_prior{alpha});
      for (std::size_t k = 0; k < eq7.size(); ++k) EXPECT_NEAR(eq7.values()[k], eq6.values()[k], 1e-14);
      // Where a configuration has data but the prior holds its column, the estimate lies
      // between the MLE and the prior.
      const auto mle = estimate_mle(counts);
      for (std::size_t u = 0; u < counts.configurations(); ++u) {
        if (counts.total(config_index(u)) == 0) continue;
        for (std::size_t x = 0; x < counts.child_cardinality(); ++x) {
          const auto k = u * counts.child_cardinality() + x;
          EXPECT_GE(eq7.values()[k], std::min(mle.values()[k], f.values()[k]) - 1e-15);
          EXPECT_LE(eq7.values()[k], std::max(mle.values()[k], f.values()[k]) + 1e-15);
        }
      }
    }
  }
}

// A user's parameter prior: the ParameterPrior concept accepts and rejects the right types, and
// a prior of one's own plugs into estimate() and fit() like the built-in ones.

// Pseudo-count `weight` on the child's last state and 1 elsewhere, whatever the parents.
struct favour_last_state {
  double weight = 3.0;
  [[nodiscard]] static std::string_view name() { return "favour-last"; }
  [[nodiscard]] std::vector<double> pseudo_counts(const variable& child, const std::vector<variable>& parents) const {
    std::size_t configurations = 1;
    for (const auto& p : parents) configurations *= p.cardinality();
    std::vector<double> alpha(configurations * child.cardinality(), 1.0);
    for (std::size_t u = 0; u < configurations; ++u) alpha[(u + 1) * child.cardinality() - 1] = weight;
    return alpha;
  }
};

// Gives a fixed list, right or wrong for the family.
struct fixed_counts {
  std::vector<double> alpha;
  [[nodiscard]] static std::string_view name() { return "fixed"; }
  [[nodiscard]] std::vector<double> pseudo_counts(const variable&, const std::vector<variable>&) const { return alpha; }
};

struct no_name {
  std::vector<double> pseudo_counts(const variable&, const std::vector<variable>&) const;
};
struct mutating_call {
  static std::string_view name();
  std::vector<double> pseudo_counts(const variable&, const std::vector<variable>&);  // not const
};
struct wrong_result {
  static std::string_view name();
  std::vector<float> pseudo_counts(const variable&, const std::vector<variable>&) const;
};
static_assert(ParameterPrior<favour_last_state>);
static_assert(!ParameterPrior<no_name>);
static_assert(!ParameterPrior<mutating_call>);
static_assert(!ParameterPrior<wrong_result>);
static_assert(ParameterPrior<k2_prior> && ParameterPrior<weighted_prior>);  // the built-ins are models too
static_assert(std::is_convertible_v<favour_last_state, parameter_prior>);

TEST(parameter_prior_test, a_users_prior_estimates_as_its_pseudo_counts_do) {
  const auto mine = values(estimate(small_counts(), favour_last_state{}));
  EXPECT_EQ(mine, values(estimate(small_counts(), pseudo_counts_prior{{1, 3, 1, 3, 1, 3}})));
  // (1 + 1) / (4 + 3), (3 + 2) / (4 + 3), …; no data: the prior, 1/4 and 3/4.
  EXPECT_DOUBLE_EQ(mine[0], 2.0 / 7);
  EXPECT_DOUBLE_EQ(mine[3], 4.0 / 8);
  EXPECT_DOUBLE_EQ(mine[5], 3.0 / 4);
}

TEST(parameter_prior_test, a_users_prior_fits_a_network_globally_and_per_node) {
  const variable a("a", {"no", "yes"});
  const variable b("b", {"no", "yes"});
  dataset data;
  data.add(discrete_column(a, std::vector<unsigned>{0, 1, 1, 1}));
  data.add(discrete_column(b, std::vector<unsigned>{0, 0, 1, 1}));
  const network_structure structure({a, b}, {{"a", "b"}});
  const auto everywhere = fit(structure, data, {.prior = favour_last_state{}});
  EXPECT_DOUBLE_EQ(everywhere.table("a").probability("yes", {}), (3.0 + 3) / (4 + 4));
  EXPECT_DOUBLE_EQ(everywhere.table("b").probability("yes", {"yes"}), (2.0 + 3) / (3 + 4));
  fit_options options;
  options.node_priors.emplace("b", favour_last_state{10});
  const auto one_node = fit(structure, data, options);
  EXPECT_DOUBLE_EQ(one_node.table("a").probability("yes", {}), 3.0 / 4);  // MLE
  EXPECT_DOUBLE_EQ(one_node.table("b").probability("yes", {"no"}), (0.0 + 10) / (1 + 11));
}

TEST(parameter_prior_test, errors_name_the_prior_and_the_node) {
  EXPECT_THAT(
      [] {
        (void)estimate(small_counts(), fixed_counts{{1, 2}});
      },
      ThrowsMessage<model_error>(HasSubstr("the prior 'fixed': the pseudo-counts of 'c' need 6 values, got 2")));
  EXPECT_THAT(
      [] {
        (void)estimate(small_counts(), fixed_counts{{1, 1, 1, -2, 1, 1}});
      },
      ThrowsMessage<model_error>(HasSubstr("the prior 'fixed': a pseudo-count must be a finite number ≥ 0, got -2")));
}

}  // namespace
}  // namespace pgm::estimate_tests
