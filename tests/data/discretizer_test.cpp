#include "pgm/data/discretizer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <random>

namespace pgm::discretizer_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(discretizer_test, quantile_edges_interpolate_order_statistics) {
  // 0..10: the quintiles by linear interpolation (NumPy's default) are 2, 4, 6, 8.
  std::vector<double> values;
  for (int i = 10; i >= 0; --i) values.push_back(i);
  EXPECT_THAT(quantile_edges(values, 5), ElementsAre(0, 2, 4, 6, 8, 10));
  // 1..4 in quarters: h = 3k/4 → 1, 1.75, 2.5, 3.25, 4.
  EXPECT_THAT(quantile_edges(std::vector<double>{4, 1, 3, 2}, 4), ElementsAre(1, 1.75, 2.5, 3.25, 4));
}

TEST(discretizer_test, quantile_edges_of_a_normal_match_its_quantiles) {
  std::mt19937_64 engine(11);
  std::normal_distribution<double> normal(0.0, 1.6);
  std::vector<double> values(200000);
  for (auto& v : values) v = normal(engine);
  const auto edges = quantile_edges(values, 5);
  const boost::math::normal_distribution<double> reference(0.0, 1.6);
  ASSERT_EQ(edges.size(), 6u);
  for (int k = 1; k < 5; ++k) {
    EXPECT_NEAR(edges[k], boost::math::quantile(reference, k / 5.0), 0.02) << "edge " << k;
  }
  // Each bin holds a fifth of the data.
  const auto v = variable::intervals("x", edges);
  std::vector<int> counts(5);
  for (double x : values) ++counts[v.bin(x).value()];
  for (int c : counts) EXPECT_NEAR(c, 40000, 1);
}

TEST(discretizer_test, equal_width_edges) {
  EXPECT_THAT(equal_width_edges(std::vector<double>{-6, 6, 0}, 4), ElementsAre(-6, -3, 0, 3, 6));
}

TEST(discretizer_test, ties_merge_bins_and_a_constant_column_is_an_error) {
  EXPECT_THAT(quantile_edges(std::vector<double>{0, 0, 0, 0, 0, 0, 1, 2}, 4), ElementsAre(0, 0.25, 2));
  EXPECT_THAT(
      [] {
        static_cast<void>(quantile_edges(std::vector<double>{3, 3, 3}, 5, "z"));
      },
      ThrowsMessage<data_error>(HasSubstr("column 'z' holds a single value")));
  EXPECT_THAT([] { static_cast<void>(quantile_edges(std::vector<double>{}, 5, "z")); },
              ThrowsMessage<data_error>(HasSubstr("no values")));
  EXPECT_THAT(
      [] {
        static_cast<void>(quantile_edges(std::vector<double>{1, -HUGE_VAL}, 5, "z"));
      },
      ThrowsMessage<data_error>(HasSubstr("column 'z' row 2: cannot discretize a value that is not finite")));
}

TEST(discretizer_test, fitted_on_one_set_applied_to_another) {
  dataset train;
  train.add(continuous_column("x", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, {"x-offset", "cm", "cubeUp1"}));
  const std::vector<std::string> columns{"x"};
  const auto d = fit_discretization(train, columns, binning::quantile, 5);
  EXPECT_THAT(d.at("x").edges(), ElementsAre(0, 2, 4, 6, 8, 10));
  EXPECT_EQ(d.at("x").tags().unit, "cm");

  dataset other;
  other.add(continuous_column("x", {-50, 2, 5.5, 9.99, 10, 1e9}));
  const auto binned = apply_discretization(other, d);
  const auto& x = binned.discrete("x");
  std::vector<std::uint32_t> codes;
  for (std::size_t r = 0; r < x.size(); ++r) codes.push_back(x.code(r));
  EXPECT_THAT(codes, ElementsAre(0, 1, 2, 4, 4, 4));
  EXPECT_EQ(x.var(), d.at("x"));
  // Applying twice is harmless; a discrete column with other states is not.
  EXPECT_EQ(apply_discretization(binned, d), binned);
  dataset clash;
  clash.add(discrete_column(variable("x", {"a"}), std::vector<unsigned>{0}));
  EXPECT_THROW(static_cast<void>(apply_discretization(clash, d)), data_error);
}

}  // namespace
}  // namespace pgm::discretizer_tests
