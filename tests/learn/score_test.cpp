#include "pgm/learn/score.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "pgm/learn/family_score_cache.hpp"
#include "pgm/learn/network_score.hpp"
#include "pgm/learn/score_registry.hpp"

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

double score_of(const dataset& data, std::string_view score) {
  const std::vector<std::string> parents{"p"};
  return make_score(score)(count_family(data, "c", parents));
}

TEST(score_test, hand_computed_family_terms) {
  const auto data = small();
  const double loglik = std::log(1.0 / 3) + 2 * std::log(2.0 / 3) + 3 * std::log(3.0 / 4) + std::log(1.0 / 4);
  EXPECT_NEAR(score_of(data, "loglik"), loglik, 1e-12);
  // 3 free parameters: (2 - 1) states x 3 configurations, the unseen one included.
  EXPECT_NEAR(score_of(data, "aic"), loglik - 3, 1e-12);
  EXPECT_NEAR(score_of(data, "aic[k=2.5]"), loglik - 7.5, 1e-12);
  EXPECT_NEAR(score_of(data, "bic"), loglik - std::log(7.0) / 2 * 3, 1e-12);
  // K2: prod_u (r-1)!/(N_u+r-1)! prod_x M! = (1!2!/4!) (3!1!/5!) = 1/240.
  EXPECT_NEAR(score_of(data, "k2"), std::log(1.0 / 240), 1e-12);
  // BDeu, iss 1: a = 1/6 per cell, 1/3 per configuration: (27/28)(1/6)(7/36) (81/280)(91/216)(1/6) = 13/20480.
  EXPECT_NEAR(score_of(data, "bdeu"), std::log(13.0 / 20480), 1e-12);
  // A root: p's counts (3, 4, 0); BDeu with iss 3 is then K2 with a = 1 per cell.
  const auto root = count_family(data, "p", {});
  EXPECT_NEAR(bdeu_score(3.0)(root), k2_score()(root), 1e-12);
  EXPECT_NEAR(make_score("bdeu[iss=3]")(root), make_score("k2")(root), 1e-12);
  EXPECT_NEAR(k2_score()(root), std::log(2.0 * 3 * 2 * 3 * 4 / (9 * 8 * 7 * 6 * 5 * 4 * 3)), 1e-12);
}

TEST(score_test, names_options_and_bad_choices) {
  EXPECT_EQ(make_score("bde").text(), "bdeu[iss=1]");
  EXPECT_EQ(make_score(" bdeu [ iss = 2.5 ] ").text(), "bdeu[iss=2.5]");
  EXPECT_EQ(family_score().text(), "bic");
  for (const auto* built_in : {"aic[k=1]", "bdeu[iss=1]", "bic", "k2", "loglik"}) {
    EXPECT_THAT(scores().listing(), ::testing::Contains(built_in));
  }
  for (const auto& listed : scores().listing()) EXPECT_EQ(make_score(listed).text(), listed);
  EXPECT_THAT(
      [] { static_cast<void>(make_score("mdl")); },
      ThrowsMessage<unknown_name>(HasSubstr("unknown score 'mdl' (known: aic, bdeu, bic, heavy-bic, k2, loglik)")));
  EXPECT_THAT([] { static_cast<void>(make_score("bdeu[iss=0]")); },
              ThrowsMessage<model_error>(HasSubstr("option iss of the score 'bdeu' must be a number > 0, got '0'")));
  EXPECT_THAT([] { static_cast<void>(make_score("aic[k=-1]")); },
              ThrowsMessage<model_error>(HasSubstr("option k of the score 'aic' must be a number >= 0, got '-1'")));
  EXPECT_THAT([] { static_cast<void>(make_score("bdeu[iss=1,5]")); },
              ThrowsMessage<model_error>(HasSubstr("expected KEY=VALUE at column 12")));
  EXPECT_THAT([] { static_cast<void>(make_score("bdeu[alpha=1]")); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown bdeu option 'alpha' (known: iss)")));
  EXPECT_THAT([] { static_cast<void>(make_score("bic[iss=1]")); },
              ThrowsMessage<model_error>(HasSubstr("the score 'bic' takes no options, got 'iss'")));
}

// A user's score, as docs/extending.md shows it: BIC with a heavier penalty, in one struct and
// one registration line.
struct heavy_bic {
  static std::vector<option_declaration> options() {
    return {number_option("weight", 2.0, "times BIC's penalty").greater_than(0.0)};
  }
  explicit heavy_bic(const option_values& options) : weight(options.number("weight")) {}
  double operator()(const count_table& counts) const {
    const double penalty = std::log(static_cast<double>(counts.total())) / 2.0 * weight;
    return family_loglik(counts) - penalty * family_parameters(counts);
  }
  double weight;
};

const register_score<heavy_bic> registered("heavy-bic", "BIC with a penalty `weight` times as heavy");

TEST(score_test, a_users_score_is_chosen_by_name_with_its_options) {
  const auto data = small();
  const auto counts = count_family(data, "c", std::vector<std::string>{"p"});
  EXPECT_NEAR(make_score("heavy-bic[weight=1]")(counts), make_score("bic")(counts), 1e-12);
  EXPECT_NEAR(make_score("heavy-bic")(counts), family_loglik(counts) - std::log(7.0) * 3, 1e-12);
  EXPECT_EQ(make_score("heavy-bic").text(), "heavy-bic[weight=2]");
  EXPECT_THAT(scores().listing(), ::testing::Contains("heavy-bic[weight=2]"));
  EXPECT_THAT([] { static_cast<void>(make_score("heavy-bic[weight=0]")); },
              ThrowsMessage<model_error>(HasSubstr("option weight of the score 'heavy-bic' must be a number > 0")));
  EXPECT_THAT([] { register_score<heavy_bic>("bic", "again"); },
              ThrowsMessage<model_error>(HasSubstr("a score named 'bic' is registered already")));
}

TEST(score_test, an_imaginary_sample_size_beyond_a_doubles_lgamma_has_its_limit) {
  const auto data = small();
  // As iss grows the Dirichlet prior becomes the uniform table: BDeu tends to N ln(1/r) = 7 ln(1/2).
  for (const double iss : {1e8, 1e12, 1e100, 1e306, 1.7e308}) {
    const double score = make_score("bdeu[iss=" + text::format_double(iss) +
                                    "]")(count_family(data, "c", std::vector<std::string>{"p"}));
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
    EXPECT_NEAR(family_score_cache(columns, make_score("loglik")).score(key), f.loglik, tol);
    EXPECT_NEAR(family_score_cache(columns, make_score("aic")).score(key), f.loglik - params, tol);
    EXPECT_NEAR(family_score_cache(columns, make_score("bic")).score(key),
                f.loglik - std::log(static_cast<double>(rows)) / 2 * params, tol);
    EXPECT_NEAR(family_score_cache(columns, make_score("k2")).score(key), f.dirichlet_k2, tol);
    EXPECT_NEAR(family_score_cache(columns, make_score("bdeu[iss=" + text::format_double(iss) + "]")).score(key),
                f.dirichlet_bdeu, tol);
  }
}

TEST(score_test, cache_remembers_families_and_is_the_same_on_any_threads) {
  const auto data = small();
  const std::vector<const discrete_column*> columns{&data.discrete("p"), &data.discrete("c")};
  family_score_cache one(columns, make_score("bdeu[iss=2]"), 1);
  family_score_cache two(columns, make_score("bdeu[iss=2]"), 2);
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
  const auto result = score_network(structure, data, make_score("bic"));
  ASSERT_EQ(result.nodes.size(), 2u);
  EXPECT_DOUBLE_EQ(result.nodes[1], score_of(data, "bic"));
  EXPECT_DOUBLE_EQ(result.total, result.nodes[0] + result.nodes[1]);
  // Score equivalence: p -> c and c -> p are the same class, so BIC and BDeu agree on them.
  const network_structure reversed({data.discrete("p").var(), data.discrete("c").var()}, {{"c", "p"}});
  for (const auto* name : {"bic", "bdeu", "loglik"}) {
    const auto score = make_score(name);
    EXPECT_NEAR(score_network(reversed, data, score).total, score_network(structure, data, score).total, 1e-12);
  }
  const network_structure other({variable("p", {"a", "b"}), data.discrete("c").var()}, {});
  EXPECT_THAT([&] { static_cast<void>(score_network(other, data)); },
              ThrowsMessage<data_error>(HasSubstr("column 'p' has 3 states, the model's variable 2")));
}

}  // namespace
}  // namespace pgm::score_tests
