// The one order of a column's states (numbers by value, other labels alphabetically) and the
// binning of columns as `pgm discretize` and pgm.discretize choose them.

#include "pgm/data/state_order.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pgm/data/bin_columns.hpp"

namespace pgm::state_order_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Pair;
using ::testing::ThrowsMessage;

TEST(state_order_test, numbers_by_value_and_one_state_per_number) {
  const std::vector<std::string> labels{"10", "9", "1.0", "1", "-2"};
  const auto order = order_states(labels);
  EXPECT_TRUE(order.numeric);
  EXPECT_THAT(order.states, ElementsAre("-2", "1.0", "9", "10"));  // "1" is "1.0", met first
  EXPECT_THAT(order.state_of, ElementsAre(3, 2, 1, 1, 0));
}

// Issue 28: labels are one state only when they are the same text or exactly the same number;
// numbers that one double cannot tell apart stay two states.
TEST(state_order_test, numbers_are_compared_exactly_not_as_doubles) {
  const std::vector<std::string> labels{"9007199254740993",
                                        "9007199254740992",
                                        "0.10000000000000001",
                                        "0.1",
                                        "-0",
                                        "0",
                                        "1e2",
                                        "100.00",
                                        "-1.5",
                                        "-1",
                                        "1e-400",
                                        "+7"};
  const auto order = order_states(labels);
  ASSERT_TRUE(order.numeric);
  EXPECT_THAT(order.states, ElementsAre("-1.5", "-1", "-0", "1e-400", "0.1", "0.10000000000000001", "+7", "1e2",
                                        "9007199254740992", "9007199254740993"));
  EXPECT_THAT(order.state_of, ElementsAre(9, 8, 5, 4, 2, 2, 7, 7, 0, 1, 3, 6));
}

TEST(state_order_test, exact_decimals_by_hand) {
  const auto value = [](const char* text) { return *detail::exact_decimal_of(text); };
  EXPECT_EQ(value("100"), (detail::exact_decimal{false, "1", 3}));
  EXPECT_EQ(value("1e2"), value("100.0"));
  EXPECT_EQ(value("0.00150"), (detail::exact_decimal{false, "15", -2}));
  EXPECT_EQ(value(".5"), value("5e-1"));
  EXPECT_EQ(value("5."), value("5"));
  EXPECT_EQ(value("-0.0e7"), detail::exact_decimal{});
  EXPECT_EQ(detail::compare_exact(value("-2"), value("-10")), 1);
  EXPECT_EQ(detail::compare_exact(value("12"), value("123")), -1);
  EXPECT_EQ(detail::compare_exact(value("0.99"), value("1")), -1);
  for (const char* text : {"", "-", "e5", "1e", "1e+", "0x10", "nan", "1,5", "1.2.3"}) {
    EXPECT_FALSE(detail::exact_decimal_of(text)) << text;
  }
}

TEST(state_order_test, other_labels_alphabetically_by_bytes) {
  const auto order = order_states(std::vector<std::string>{"b", "Red", "10", "B"});
  EXPECT_FALSE(order.numeric);
  EXPECT_THAT(order.states, ElementsAre("10", "B", "Red", "b"));
  EXPECT_THAT(order.state_of, ElementsAre(3, 2, 0, 1));
}

TEST(state_order_test, a_number_that_is_not_finite_orders_nothing) {
  const auto order = order_states(std::vector<std::string>{"1", "nan", "inf"});
  ASSERT_TRUE(order.non_finite.has_value());
  EXPECT_EQ(*order.non_finite, 1U);
  EXPECT_TRUE(order.states.empty());
}

dataset two_columns() {
  dataset data;
  std::vector<double> many;
  std::vector<double> few;
  for (int i = 0; i < 100; ++i) {
    many.push_back(i * 0.5);
    few.push_back(i % 2);
  }
  data.add(continuous_column("x", many));
  data.add(continuous_column("ok", few));
  return data;
}

TEST(bin_columns_test, by_default_bins_columns_with_more_values_than_bins) {
  const auto result = bin_columns(two_columns(), {.bins = 4});
  ASSERT_EQ(result.edges.size(), 1U);
  EXPECT_EQ(result.edges.at("x").cardinality(), 4U);
  EXPECT_THAT(result.left, ElementsAre(Pair("ok", 2U)));
  EXPECT_EQ(result.data.discrete("x").var().cardinality(), 4U);
}

TEST(bin_columns_test, saved_edges_bin_new_data_the_same_way) {
  const auto fitted = bin_columns(two_columns(), {.columns = {"x"}, .bins = 3});
  const auto again = bin_columns(two_columns(), {.saved = fitted.edges, .saved_source = "edges.json"});
  EXPECT_EQ(again.edges.at("x").edges(), fitted.edges.at("x").edges());
}

TEST(bin_columns_test, errors_name_what_is_missing) {
  EXPECT_THAT([] { (void)bin_columns(two_columns(), {.bins = 200}); },
              ThrowsMessage<data_error>(HasSubstr("no numeric column has more than 200 distinct values")));
  const auto fitted = bin_columns(two_columns(), {.columns = {"x"}, .bins = 3});
  EXPECT_THAT(
      [&] { (void)bin_columns(two_columns(), {.columns = {"ok"}, .saved = fitted.edges, .saved_source = "e.json"}); },
      ThrowsMessage<data_error>(HasSubstr("'e.json' has no edges for 'ok'")));
}

}  // namespace
}  // namespace pgm::state_order_tests
