// Chi-square and G² tests: hand-computed statistics, the empty-cell rule for degrees of
// freedom, p-values against closed forms (df 1 and 2), and the tests on sampled data.

#include "pgm/learn/independence_test.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "pgm/inference/sampling.hpp"
#include "pgm/learn/independence_test_registry.hpp"
#include "pgm/learn/pc.hpp"

namespace pgm::independence_test_tests {
namespace {

using ::testing::HasSubstr;

// Lays out O[x][y] per stratum as test_independence reads it: x fastest, then y.
std::vector<std::uint64_t> stack(const std::vector<std::vector<std::vector<std::uint64_t>>>& strata) {
  std::vector<std::uint64_t> counts;
  for (const auto& table : strata) {
    const auto xs = table.size();
    const auto ys = table[0].size();
    for (std::size_t y = 0; y < ys; ++y) {
      for (std::size_t x = 0; x < xs; ++x) counts.push_back(table[x][y]);
    }
  }
  return counts;
}

TEST(independence_test, two_by_two_by_hand) {
  // O = [[10, 20], [30, 40]], n = 100: X² = n (ad − bc)² / (r1 r2 c1 c2) = 100·200²/(30·70·40·60) = 50/63.
  const auto counts = stack({{{10, 20}, {30, 40}}});
  const auto chi = test_independence(counts, 2, 2, ci_test::chi_square);
  EXPECT_NEAR(chi.statistic, 50.0 / 63.0, 1e-12);
  EXPECT_EQ(chi.df, 1.0);
  EXPECT_EQ(chi.rows, 100u);
  // df 1: P(χ² ≥ s) = erfc(sqrt(s / 2)).
  EXPECT_NEAR(chi.p_value, std::erfc(std::sqrt(chi.statistic / 2)), 1e-12);
  // G² = 2 Σ O ln(O/E) with E = 12, 18, 28, 42.
  const double g2 =
      2 * (10 * std::log(10.0 / 12) + 20 * std::log(20.0 / 18) + 30 * std::log(30.0 / 28) + 40 * std::log(40.0 / 42));
  const auto g = test_independence(counts, 2, 2, ci_test::g_squared);
  EXPECT_NEAR(g.statistic, g2, 1e-12);
  EXPECT_NEAR(g.statistic, 0.8043486460964835, 1e-12);
  EXPECT_NEAR(g.p_value, 0.36979636792989634, 1e-12);
}

TEST(independence_test, textbook_two_by_three) {
  // A 2 × 3 gender × party identification table of the kind categorical-data textbooks open
  // with; the reference values were computed independently (Python, float64): X² = 12.569,
  // G² = 12.601, df 2, P ≈ 0.0019.
  const auto counts = stack({{{495, 272, 590}, {330, 265, 498}}});
  const auto chi = test_independence(counts, 2, 3, ci_test::chi_square);
  const auto g = test_independence(counts, 2, 3, ci_test::g_squared);
  EXPECT_NEAR(chi.statistic, 12.569256167968339, 1e-9);
  EXPECT_NEAR(g.statistic, 12.600901365469444, 1e-9);
  EXPECT_EQ(chi.df, 2.0);
  // df 2: P(χ² ≥ s) = exp(−s / 2).
  EXPECT_NEAR(chi.p_value, std::exp(-chi.statistic / 2), 1e-12);
  EXPECT_NEAR(g.p_value, std::exp(-g.statistic / 2), 1e-12);
  EXPECT_NEAR(chi.p_value, 0.00186, 1e-5);
}

TEST(independence_test, strata_add_up) {
  const std::vector<std::vector<std::uint64_t>> a{{10, 20}, {30, 40}};
  // Two 2 × 2 strata: statistic and df are the sums of the strata's.
  const auto one = test_independence(stack({a}), 2, 2, ci_test::g_squared);
  const std::vector<std::vector<std::uint64_t>> c{{5, 1}, {2, 9}};
  const auto two = test_independence(stack({c}), 2, 2, ci_test::g_squared);
  const auto both = test_independence(stack({a, c}), 2, 2, ci_test::g_squared);
  EXPECT_NEAR(both.statistic, one.statistic + two.statistic, 1e-12);
  EXPECT_EQ(both.df, 2.0);
  EXPECT_EQ(both.rows, 117u);
  // df 2 again has a closed form.
  EXPECT_NEAR(both.p_value, std::exp(-both.statistic / 2), 1e-12);
}

TEST(independence_test, degrees_of_freedom_skip_empty_rows_columns_and_strata) {
  // Stratum 1: 3 × 3 with x = 2 never seen → (2 − 1)(3 − 1) = 2.
  // Stratum 2: empty → 0. Stratum 3: full 3 × 3 → 4. Stratum 4: one row only → 0.
  const auto counts = stack({
      {{4, 5, 6}, {7, 8, 1}, {0, 0, 0}},
      {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}},
      {{1, 2, 3}, {4, 5, 6}, {7, 8, 10}},
      {{0, 0, 0}, {3, 9, 2}, {0, 0, 0}},
  });
  for (auto test : {ci_test::chi_square, ci_test::g_squared}) {
    const auto r = test_independence(counts, 3, 3, test);
    EXPECT_EQ(r.df, 6.0);
    EXPECT_EQ(r.rows, 31u + 46u + 14u);
  }
  // The zero row adds nothing to the statistic: stratum 1 equals its 2 × 3 part.
  const auto full = test_independence(stack({{{4, 5, 6}, {7, 8, 1}, {0, 0, 0}}}), 3, 3, ci_test::chi_square);
  const auto part = test_independence(stack({{{4, 5, 6}, {7, 8, 1}}}), 2, 3, ci_test::chi_square);
  EXPECT_EQ(full.statistic, part.statistic);
  EXPECT_EQ(full.df, part.df);
}

TEST(independence_test, no_degrees_of_freedom_means_p_one) {
  const auto counts = stack({{{0, 0}, {5, 7}}});  // x constant
  const auto r = test_independence(counts, 2, 2, ci_test::chi_square);
  EXPECT_EQ(r.df, 0.0);
  EXPECT_EQ(r.p_value, 1.0);
  EXPECT_TRUE(r.independent(0.05));
  EXPECT_EQ(test_independence(std::vector<std::uint64_t>(8, 0), 2, 2, ci_test::g_squared).p_value, 1.0);
}

TEST(independence_test, perfectly_independent_table) {
  const auto r = test_independence(stack({{{10, 20}, {20, 40}}}), 2, 2, ci_test::g_squared);
  EXPECT_NEAR(r.statistic, 0.0, 1e-12);
  EXPECT_GE(r.statistic, 0.0);
  EXPECT_EQ(r.p_value, 1.0);
}

TEST(independence_test, p_values_from_boost) {
  EXPECT_NEAR(chi_square_p_value(3.841458820694124, 1), 0.05, 1e-12);
  EXPECT_NEAR(chi_square_p_value(9.487729036781154, 4), 0.05, 1e-12);
  EXPECT_EQ(chi_square_p_value(0.0, 3), 1.0);
  EXPECT_EQ(chi_square_p_value(5.0, 0), 1.0);
}

TEST(independence_test, bad_shapes_and_names) {
  EXPECT_THROW(static_cast<void>(test_independence(std::vector<std::uint64_t>(5), 2, 2, ci_test::chi_square)),
               model_error);
  EXPECT_EQ(make_independence_test("g2").text(), "g2[correction=none,min_rows_per_cell=0]");
  EXPECT_EQ(independence_test().name(), "chi2");
  try {
    static_cast<void>(make_independence_test("fisher"));
    FAIL();
  } catch (const unknown_name& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown independence test 'fisher' (known: cautious, chi2, g2)"));
  }
  EXPECT_THAT([] { static_cast<void>(make_independence_test("chi2[correction=fisher]")); },
              ::testing::ThrowsMessage<model_error>(
                  HasSubstr("option correction of the independence test 'chi2' must be one of none, yates, got "
                            "'fisher'")));
}

// Each registered test equals the kernel with the options it was chosen with.
TEST(independence_test, a_test_chosen_by_name_is_the_kernel_with_its_options) {
  const std::vector<std::uint64_t> counts{10, 31, 30, 90, 3, 9, 8, 30};
  const auto at = [&](const char* text) { return make_independence_test(text)(counts, 2, 2); };
  EXPECT_EQ(at("chi2"), test_independence(counts, 2, 2, ci_test::chi_square));
  EXPECT_EQ(at("g2"), test_independence(counts, 2, 2, ci_test::g_squared));
  EXPECT_EQ(at("g2[correction=yates]"),
            test_independence(counts, 2, 2, {.test = ci_test::g_squared, .correction = continuity_correction::yates}));
  EXPECT_EQ(at("chi2[min_rows_per_cell=30]"), test_independence(counts, 2, 2, {.min_rows_per_cell = 30}));
  EXPECT_TRUE(at("chi2[min_rows_per_cell=30]").too_few_rows);
}

TEST(independence_test, yates_moves_each_count_half_a_unit_toward_its_expectation) {
  // O = [[10, 20], [30, 40]], E = [[12, 18], [28, 42]]: the corrected counts are 10.5, 19.5,
  // 29.5 and 40.5, and X² = n (|ad − bc| − n/2)² / (r1 r2 c1 c2) = 100·150²/(30·70·40·60).
  const auto counts = stack({{{10, 20}, {30, 40}}});
  const ci_test_options yates{.correction = continuity_correction::yates};
  const auto chi = test_independence(counts, 2, 2, yates);
  EXPECT_NEAR(chi.statistic, 100.0 * 150 * 150 / (30.0 * 70 * 40 * 60), 1e-12);
  EXPECT_EQ(chi.df, 1.0);
  EXPECT_NEAR(chi.p_value, std::erfc(std::sqrt(chi.statistic / 2)), 1e-12);
  const auto g =
      test_independence(counts, 2, 2, {.test = ci_test::g_squared, .correction = continuity_correction::yates});
  const double corrected_g = 2 * (10.5 * std::log(10.5 / 12) + 19.5 * std::log(19.5 / 18) + 29.5 * std::log(29.5 / 28) +
                                  40.5 * std::log(40.5 / 42));
  EXPECT_NEAR(g.statistic, corrected_g, 1e-12);
  // A count within half a unit of its expectation moves onto it, not past it: 10.25 expected.
  const auto close = test_independence(stack({{{10, 31}, {30, 90}}}), 2, 2, yates);
  const double e00 = 41.0 * 40 / 161;
  EXPECT_LT(std::abs(e00 - 10), 0.5);
  EXPECT_NEAR(close.statistic, 0.0, 1e-12);
}

TEST(independence_test, yates_corrects_only_strata_with_one_degree_of_freedom) {
  // Stratum 1 has two x states and two y states seen (df 1), stratum 2 three x states (df 2).
  const std::vector<std::vector<std::vector<std::uint64_t>>> one{{{10, 20}, {30, 40}, {0, 0}}};
  const std::vector<std::vector<std::vector<std::uint64_t>>> two{{{4, 9}, {7, 8}, {12, 3}}};
  const ci_test_options yates{.correction = continuity_correction::yates};
  const auto both = test_independence(stack({one[0], two[0]}), 3, 2, yates);
  const auto first = test_independence(stack(one), 3, 2, yates);
  const auto second_plain = test_independence(stack(two), 3, 2, ci_test::chi_square);
  EXPECT_NEAR(first.statistic, 100.0 * 150 * 150 / (30.0 * 70 * 40 * 60), 1e-12);
  EXPECT_EQ(test_independence(stack(two), 3, 2, yates), second_plain);
  EXPECT_NEAR(both.statistic, first.statistic + second_plain.statistic, 1e-12);
  EXPECT_EQ(both.df, 3.0);
  EXPECT_EQ(to_string(continuity_correction::yates), "yates");
}

TEST(independence_test, too_few_rows_per_cell_declares_independence) {
  // 100 rows in a 2 x 2 table of 2 strata (8 cells, one stratum empty): 12.5 rows per cell.
  const auto counts = stack({{{10, 40}, {40, 10}}, {{0, 0}, {0, 0}}});
  const auto tested = test_independence(counts, 2, 2, {.min_rows_per_cell = 12.5});
  EXPECT_FALSE(tested.too_few_rows);
  EXPECT_LT(tested.p_value, 1e-6);
  const auto sparse = test_independence(counts, 2, 2, {.min_rows_per_cell = 12.51});
  EXPECT_TRUE(sparse.too_few_rows);
  EXPECT_EQ(sparse.p_value, 1.0);
  EXPECT_EQ(sparse.statistic, tested.statistic);  // the statistic is still reported
  EXPECT_TRUE(sparse.independent(0.05));
  EXPECT_THAT([&] { static_cast<void>(test_independence(counts, 2, 2, {.min_rows_per_cell = -1})); },
              ::testing::ThrowsMessage<model_error>(
                  HasSubstr("the minimum rows per cell must be a finite number >= 0, got -1")));
}

// a -> b -> c with strong tables.
bayesian_network chain() {
  const variable a("a", {"0", "1", "2"});
  const variable b("b", {"0", "1"});
  const variable c("c", {"0", "1", "2"});
  network_structure s({a, b, c}, {{"a", "b"}, {"b", "c"}});
  return bayesian_network(s, {cpt<double>(a, {}, {0.3, 0.3, 0.4}), cpt<double>(b, {a}, {0.9, 0.1, 0.5, 0.5, 0.1, 0.9}),
                              cpt<double>(c, {b}, {0.7, 0.2, 0.1, 0.1, 0.2, 0.7})});
}

TEST(independence_test, on_sampled_data_counts_from_columns) {
  const auto data = sample(chain(), 20000, 7);
  const std::vector<std::string> none;
  const std::vector<std::string> b{"b"};
  for (auto test : {ci_test::chi_square, ci_test::g_squared}) {
    EXPECT_LT(test_independence(data, "a", "c", none, test).p_value, 1e-10);
    const auto given_b = test_independence(data, "a", "c", b, test);
    EXPECT_GT(given_b.p_value, 0.001);
    EXPECT_EQ(given_b.df, 8.0);  // 2 strata of (3 − 1)(3 − 1)
    EXPECT_EQ(given_b.rows, 20000u);
  }
  // The same statistic whatever the roles of x and y.
  const auto xy = test_independence(data, "a", "c", b, ci_test::chi_square);
  const auto yx = test_independence(data, "c", "a", b, ci_test::chi_square);
  EXPECT_NEAR(xy.statistic, yx.statistic, 1e-9 * xy.statistic);
  EXPECT_EQ(xy.df, yx.df);
  EXPECT_THROW(static_cast<void>(test_independence(data, "a", "q", none, ci_test::chi_square)), data_error);
}

TEST(independence_test, counting_threads_give_the_same_table) {
  const auto data = sample(chain(), 300000, 8);  // enough rows for the threaded path
  const std::vector<const discrete_column*> given{&data.discrete("b")};
  std::vector<std::uint64_t> one;
  std::vector<std::uint64_t> three;
  detail::count_ci_table(data.discrete("a"), data.discrete("c"), given, one, 1);
  detail::count_ci_table(data.discrete("a"), data.discrete("c"), given, three, 3);
  EXPECT_EQ(one, three);
  EXPECT_EQ(one.size(), 18u);
  std::uint64_t total = 0;
  for (auto c : one) total += c;
  EXPECT_EQ(total, 300000u);
}

// A user's test, in one struct and one registration line: independence declared whenever the
// table has fewer rows than `rows`, chi-square otherwise.
struct cautious_test {
  static std::vector<option_declaration> options() { return {count_option("rows", 100, "the fewest rows tested")}; }
  explicit cautious_test(const option_values& options) : rows(options.count("rows")) {}
  ci_result operator()(std::span<const std::uint64_t> counts, std::size_t x_states, std::size_t y_states) const {
    auto result = test_independence(counts, x_states, y_states, ci_test::chi_square);
    if (result.rows < rows) result = {.rows = result.rows, .too_few_rows = true};
    return result;
  }
  std::size_t rows;
};

const register_independence_test<cautious_test> registered("cautious", "chi-square from `rows` rows on");

TEST(independence_test, a_users_test_serves_pc_by_name) {
  const auto data = sample(chain(), 5000, 3);
  pc_options options;
  options.test = make_independence_test("cautious[rows=1000000]");
  const auto never = pc_stable(data, options);
  EXPECT_TRUE(never.graph.undirected_edges().empty() && never.graph.directed_edges().empty());
  options.test = make_independence_test("cautious[rows=0]");
  options.threads = 1;
  const auto always = pc_stable(data, options);
  options.test = make_independence_test("chi2");
  EXPECT_EQ(always.graph, pc_stable(data, options).graph);
  EXPECT_EQ(always.tests, pc_stable(data, options).tests);
}

}  // namespace
}  // namespace pgm::independence_test_tests
