#include "pgm/learn/score.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "pgm/learn/family_score_cache.hpp"
#include "pgm/learn/network_score.hpp"

namespace pgm::score_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// child c in {0,1}, parent p in {a,b,c} (c unseen): rows (a,0) (a,1) (a,1) (b,0) (b,0) (b,0) (b,1).
dataset small() {
  dataset data;
  data.add(discrete_column(variable("p", {"a", "b", "c"}), std::vector<unsigned>{0, 0, 0, 1, 1, 1, 1}));
  data.add(discrete_column(variable("c", {"0", "1"}), std::vector<unsigned>{0, 1, 1, 0, 0, 0, 1}));
  return data;
}

double score_of(const dataset& data, score_choice choice) {
  const std::vector<std::string> parents{"p"};
  return family_score(count_family(data, "c", parents), choice);
}

TEST(score_test, hand_computed_family_terms) {
  const auto data = small();
  const double loglik = std::log(1.0 / 3) + 2 * std::log(2.0 / 3) + 3 * std::log(3.0 / 4) + std::log(1.0 / 4);
  EXPECT_NEAR(score_of(data, {score_type::loglik}), loglik, 1e-12);
  // 3 free parameters: (2 - 1) states x 3 configurations, the unseen one included.
  EXPECT_NEAR(score_of(data, {score_type::aic}), loglik - 3, 1e-12);
  EXPECT_NEAR(score_of(data, {score_type::aic, 1.0, 2.5}), loglik - 7.5, 1e-12);
  EXPECT_NEAR(score_of(data, {score_type::bic}), loglik - std::log(7.0) / 2 * 3, 1e-12);
  // K2: prod_u (r-1)!/(N_u+r-1)! prod_x M! = (1!2!/4!) (3!1!/5!) = 1/240.
  EXPECT_NEAR(score_of(data, {score_type::k2}), std::log(1.0 / 240), 1e-12);
  // BDeu, iss 1: a = 1/6 per cell, 1/3 per configuration: (27/28)(1/6)(7/36) (81/280)(91/216)(1/6) = 13/20480.
  EXPECT_NEAR(score_of(data, {score_type::bdeu}), std::log(13.0 / 20480), 1e-12);
  // A root: p's counts (3, 4, 0); BDeu with iss 3 is then K2 with a = 1 per cell.
  const auto root = count_family(data, "p", {});
  EXPECT_NEAR(family_score(root, {score_type::bdeu, 3.0}), family_score(root, {score_type::k2}), 1e-12);
  EXPECT_NEAR(family_score(root, {score_type::k2}), std::log(2.0 * 3 * 2 * 3 * 4 / (9 * 8 * 7 * 6 * 5 * 4 * 3)), 1e-12);
}

TEST(score_test, names_and_bad_options) {
  EXPECT_EQ(parse_score_type("bde"), score_type::bdeu);
  for (auto type : {score_type::loglik, score_type::aic, score_type::bic, score_type::bdeu, score_type::k2}) {
    EXPECT_EQ(parse_score_type(to_string(type)), type);
  }
  EXPECT_THAT([] { static_cast<void>(parse_score_type("mdl")); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown score 'mdl' (known: bic, aic, bdeu, k2, loglik, bde)")));
  EXPECT_THAT(
      [] {
        check_score_choice({score_type::bdeu, 0.0});
      },
      ThrowsMessage<model_error>(HasSubstr("iss) must be a finite number > 0, got 0")));
  EXPECT_THAT(
      [] {
        check_score_choice({score_type::aic, 1.0, -1.0});
      },
      ThrowsMessage<model_error>(HasSubstr("AIC penalty k must be")));
}

TEST(score_test, an_imaginary_sample_size_beyond_a_doubles_lgamma_has_its_limit) {
  const auto data = small();
  // As iss grows the Dirichlet prior becomes the uniform table: BDeu tends to N ln(1/r) = 7 ln(1/2).
  for (const double iss : {1e8, 1e12, 1e100, 1e306, 1.7e308}) {
    const double score = score_of(data, {score_type::bdeu, iss});
    ASSERT_TRUE(std::isfinite(score)) << iss;
    EXPECT_NEAR(score, 7 * std::log(0.5), 1e-6) << iss;
  }
  // Stirling's side and lgamma's side of the switch (a = 10⁷) agree: ln Γ(a + n) − ln Γ(a).
  for (const double n : {0.0, 1.0, 7.0, 1000.0, 1e6}) {
    const double below = detail::log_gamma_ratio(9999999.5)(n);
    const double above = detail::log_gamma_ratio(1e7)(n);
    // d/da of the ratio is about n/a: half a unit of a moves it by n/(2·10⁷).
    EXPECT_NEAR(above - below, n / 2e7, 1e-9 * std::max(1.0, std::abs(above))) << n;
    // And Σ ln(a + k) for a whole n, summed directly.
    if (n <= 1000.0) {
      double direct = 0.0;
      for (double k = 0; k < n; ++k) direct += std::log(1e7 + k);
      EXPECT_NEAR(above, direct, 1e-12 * std::max(1.0, direct)) << n;
    }
  }
}

// Independent formulations over the rows themselves: the log-likelihood as the sum of each
// row's log p(x | u) at the MLE, the Dirichlet scores by the chain rule as each row's
// predictive probability given the rows before it.
struct row_formulas {
  double loglik = 0, dirichlet_k2 = 0, dirichlet_bdeu = 0;
};

row_formulas by_rows(const std::vector<std::vector<unsigned>>& codes, const std::vector<std::size_t>& cards,
                     std::size_t child, const std::vector<std::size_t>& parents, double iss) {
  const std::size_t rows = codes[child].size();
  std::size_t q = 1;
  for (auto p : parents) q *= cards[p];
  const double r = static_cast<double>(cards[child]);
  std::map<std::vector<unsigned>, double> n_u, n_xu;
  auto config = [&](std::size_t row) {
    std::vector<unsigned> u;
    for (auto p : parents) u.push_back(codes[p][row]);
    return u;
  };
  for (std::size_t row = 0; row < rows; ++row) {
    auto u = config(row);
    n_u[u] += 1;
    u.push_back(codes[child][row]);
    n_xu[u] += 1;
  }
  row_formulas f;
  std::map<std::vector<unsigned>, double> seen_u, seen_xu;
  const double a_bdeu = iss / (r * static_cast<double>(q));
  for (std::size_t row = 0; row < rows; ++row) {
    auto u = config(row);
    auto xu = u;
    xu.push_back(codes[child][row]);
    f.loglik += std::log(n_xu[xu] / n_u[u]);
    f.dirichlet_k2 += std::log((1.0 + seen_xu[xu]) / (r + seen_u[u]));
    f.dirichlet_bdeu += std::log((a_bdeu + seen_xu[xu]) / (a_bdeu * r + seen_u[u]));
    seen_u[u] += 1;
    seen_xu[xu] += 1;
  }
  return f;
}

TEST(score_test, equals_independent_formulas_on_random_families) {
  std::mt19937_64 rng(24);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t nodes = 4;
    const std::size_t rows = 1 + rng() % 300;
    std::vector<std::size_t> cards(nodes);
    std::vector<std::vector<unsigned>> codes(nodes);
    dataset data;
    std::vector<const discrete_column*> columns;
    for (std::size_t v = 0; v < nodes; ++v) {
      cards[v] = 2 + rng() % 3;
      for (std::size_t row = 0; row < rows; ++row) codes[v].push_back(static_cast<unsigned>(rng() % cards[v]));
      std::vector<std::string> states;
      for (std::size_t s = 0; s < cards[v]; ++s) states.push_back(std::to_string(s));
      data.add(discrete_column(variable("v" + std::to_string(v), states), codes[v]));
    }
    for (std::size_t v = 0; v < nodes; ++v) columns.push_back(&data.discrete("v" + std::to_string(v)));
    const std::size_t child = rng() % nodes;
    std::vector<std::size_t> parents;
    for (std::size_t v = 0; v < nodes; ++v) {
      if (v != child && rng() % 2) parents.push_back(v);
    }
    const double iss = 0.5 + static_cast<double>(rng() % 20);
    const auto f = by_rows(codes, cards, child, parents, iss);
    double params = static_cast<double>(cards[child] - 1);
    for (auto p : parents) params *= static_cast<double>(cards[p]);
    const family_key key{child, parents};
    const double tol = 1e-9 * (1 + std::abs(f.loglik));
    EXPECT_NEAR(family_score_cache(columns, {score_type::loglik}).score(key), f.loglik, tol);
    EXPECT_NEAR(family_score_cache(columns, {score_type::aic}).score(key), f.loglik - params, tol);
    EXPECT_NEAR(family_score_cache(columns, {score_type::bic}).score(key),
                f.loglik - std::log(static_cast<double>(rows)) / 2 * params, tol);
    EXPECT_NEAR(family_score_cache(columns, {score_type::k2}).score(key), f.dirichlet_k2, tol);
    EXPECT_NEAR(family_score_cache(columns, {score_type::bdeu, iss}).score(key), f.dirichlet_bdeu, tol);
  }
}

TEST(score_test, cache_remembers_families_and_is_the_same_on_any_threads) {
  const auto data = small();
  const std::vector<const discrete_column*> columns{&data.discrete("p"), &data.discrete("c")};
  family_score_cache one(columns, {score_type::bdeu, 2.0}, 1);
  family_score_cache two(columns, {score_type::bdeu, 2.0}, 2);
  const std::vector<family_key> keys{{1, {0}}, {0, {}}, {1, {}}, {0, {1}}, {1, {0}}};
  const auto a = one.score_all(keys);
  const auto b = two.score_all(keys);
  EXPECT_EQ(a, b);
  EXPECT_EQ(a[0], a[4]);
  EXPECT_EQ(one.computed(), 4u);
  static_cast<void>(one.score({0, {1}}));
  EXPECT_EQ(one.computed(), 4u);
  EXPECT_GE(one.hits(), 1u);
}

TEST(score_test, network_score_is_the_sum_of_its_families) {
  const auto data = small();
  const network_structure structure({data.discrete("p").var(), data.discrete("c").var()}, {{"p", "c"}});
  const auto result = score_network(structure, data, {score_type::bic});
  ASSERT_EQ(result.nodes.size(), 2u);
  EXPECT_DOUBLE_EQ(result.nodes[1], score_of(data, {score_type::bic}));
  EXPECT_DOUBLE_EQ(result.total, result.nodes[0] + result.nodes[1]);
  // Score equivalence: p -> c and c -> p are the same class, so BIC and BDeu agree on them.
  const network_structure reversed({data.discrete("p").var(), data.discrete("c").var()}, {{"c", "p"}});
  for (auto type : {score_type::bic, score_type::bdeu, score_type::loglik}) {
    EXPECT_NEAR(score_network(reversed, data, {type}).total, score_network(structure, data, {type}).total, 1e-12);
  }
  const network_structure other({variable("p", {"a", "b"}), data.discrete("c").var()}, {});
  EXPECT_THAT([&] { static_cast<void>(score_network(other, data)); },
              ThrowsMessage<data_error>(HasSubstr("column 'p' has 3 states, the model's variable 2")));
}

}  // namespace
}  // namespace pgm::score_tests
