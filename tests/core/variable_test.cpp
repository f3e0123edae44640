#include "pgm/core/variable.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/strong_index.hpp"

namespace pgm::variable_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(variable_test, keeps_states_in_order) {
  const variable v("colour", {"Red", "Blue", "Green"});
  EXPECT_EQ(v.cardinality(), 3u);
  EXPECT_EQ(v.state("Blue"), state_index(1));
  EXPECT_EQ(v.label(state_index(2)), "Green");
  EXPECT_FALSE(v.find_state("Pink"));
  EXPECT_FALSE(v.has_intervals());
}

TEST(variable_test, unknown_state_names_variable_and_states) {
  const variable v("colour", {"Red", "Blue"});
  EXPECT_THAT([&] { static_cast<void>(v.state("Pink")); },
              ThrowsMessage<model_error>(HasSubstr("variable 'colour' has no state 'Pink' (states: Red, Blue)")));
}

TEST(variable_test, rejects_bad_definitions) {
  EXPECT_THAT([] { variable("", {"a"}); }, ThrowsMessage<model_error>(HasSubstr("needs a name")));
  EXPECT_THAT([] { variable("x", {}); }, ThrowsMessage<model_error>(HasSubstr("has no states")));
  EXPECT_THAT([] { variable("x", {"a", "b", "a"}); }, ThrowsMessage<model_error>(HasSubstr("state 'a' twice")));
  EXPECT_THAT([] { variable("x y", {"a"}); }, ThrowsMessage<model_error>(HasSubstr("whitespace")));
  EXPECT_THAT([] { variable("x", {""}); }, ThrowsMessage<model_error>(HasSubstr("empty state label")));
}

TEST(variable_test, intervals_bin_values_left_closed_with_open_outer_bins) {
  const auto v = variable::intervals("xOff1", {-3.0, -1.4, -0.4, 0.4, 1.4, 3.0});
  EXPECT_EQ(v.states(), (std::vector<std::string>{"0", "1", "2", "3", "4"}));
  EXPECT_EQ(v.bin(-100.0), state_index(0));
  EXPECT_EQ(v.bin(-3.0), state_index(0));
  EXPECT_EQ(v.bin(-1.4), state_index(1));  // an inner edge belongs to the bin above it
  EXPECT_EQ(v.bin(0.0), state_index(2));
  EXPECT_EQ(v.bin(1.3999), state_index(3));
  EXPECT_EQ(v.bin(3.0), state_index(4));
  EXPECT_EQ(v.bin(99.0), state_index(4));
  EXPECT_DOUBLE_EQ(*v.midpoint(state_index(0)), -2.2);
  EXPECT_DOUBLE_EQ(*v.midpoint(state_index(2)), 0.0);
}

TEST(variable_test, midpoint_of_numeric_labels_and_none_for_categories) {
  const variable grid("xOff1", {"0", "0.9", "2.2"});
  EXPECT_DOUBLE_EQ(*grid.midpoint(state_index(1)), 0.9);
  const variable colour("c", {"Red"});
  EXPECT_FALSE(colour.midpoint(state_index(0)));
}

TEST(variable_test, rejects_bad_edges) {
  EXPECT_THAT(
      [] {
        static_cast<void>(variable::intervals("x", {1.0, 1.0, 2.0}));
      },
      ThrowsMessage<model_error>(HasSubstr("strictly increasing")));
  EXPECT_THAT(
      [] {
        static_cast<void>(variable::with_edges("x", {"a", "b"}, {0.0, 1.0}));
      },
      ThrowsMessage<model_error>(HasSubstr("2 states need 3 interval edges, got 2")));
  EXPECT_THAT(
      [] {
        static_cast<void>(variable::intervals("x", {0.0, std::nan("")}));
      },
      ThrowsMessage<model_error>(HasSubstr("finite")));
}

TEST(variable_test, equality_covers_states_edges_and_tags) {
  const variable a("x", {"0", "1"});
  EXPECT_EQ(a, variable("x", {"0", "1"}));
  EXPECT_NE(a, variable("x", {"1", "0"}));
  EXPECT_NE(a, a.with_tags({"x-offset", "cm", "cubeUp1"}));
  EXPECT_NE(a, variable::with_edges("x", {"0", "1"}, {0, 1, 2}));
}

TEST(mixed_radix_test, last_digit_varies_fastest) {
  const mixed_radix radix({2, 3, 4});
  EXPECT_EQ(radix.size(), 24u);
  EXPECT_EQ(radix.strides(), (std::vector<std::size_t>{12, 4, 1}));
  const std::vector<std::size_t> digits{1, 2, 3};
  EXPECT_EQ(radix.encode(digits), 23u);
  for (std::size_t i = 0; i < radix.size(); ++i) EXPECT_EQ(radix.encode(radix.decode(i)), i);
  EXPECT_EQ(radix.decode(5), (std::vector<std::size_t>{0, 1, 1}));
}

TEST(mixed_radix_test, empty_radix_has_one_configuration) {
  EXPECT_EQ(mixed_radix(std::vector<std::size_t>{}).size(), 1u);
  EXPECT_EQ(mixed_radix().size(), 1u);
}

TEST(mixed_radix_test, overflow_is_an_error) {
  EXPECT_THAT([] { mixed_radix(std::vector<std::size_t>(70, 2)); }, ThrowsMessage<model_error>(HasSubstr("overflows")));
}

TEST(strong_index_test, positions_become_indices_in_one_conversion) {
  static_assert(index_at<variable_id>(7) == variable_id(7) && index_at<config_index>(9).value() == 9);
  std::vector<std::uint32_t> seen;
  for (auto v : ids(4)) seen.push_back(v.value());
  EXPECT_EQ(seen, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  std::vector<state_index> states(indices<state_index>(3).begin(), indices<state_index>(3).end());
  EXPECT_EQ(states, (std::vector<state_index>{state_index(0), state_index(1), state_index(2)}));
  EXPECT_TRUE(std::ranges::empty(ids(0)));
}

}  // namespace
}  // namespace pgm::variable_tests
