// A table read over two of its parents (pgm plot-table): with every other parent given it is
// the table itself; averaged, it equals P(node | x, y) by enumerating the joint; the rows
// behind each cell are the kept counts summed as asked; mistakes are refused.

#include "pgm/decide/table_slice.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "support/enumeration.hpp"

namespace pgm::table_slice_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// x (3 intervals) → z (2 states), and onTop ← x, y, z; z depends on x, so averaging z out is
/// not the plain mean over z.
bayesian_network three_parent_stack() {
  const auto x = variable::intervals("x", {-3, -1, 1, 3});
  const auto y = variable::intervals("y", {-3, 0, 3});
  const variable z("z", {"low", "high"});
  const variable on_top("onTop", {"0", "1"});
  std::vector<double> top;
  for (std::size_t u = 0; u < 12; ++u) {
    const double p = 0.05 + 0.07 * static_cast<double>(u);
    top.push_back(1 - p);
    top.push_back(p);
  }
  return bayesian_network::from_tables({cpt<double>(x, {}, {0.2, 0.5, 0.3}), cpt<double>(y, {}, {0.6, 0.4}),
                                        cpt<double>(z, {x}, {0.9, 0.1, 0.5, 0.5, 0.2, 0.8}),
                                        cpt<double>(on_top, {x, y, z}, top)});
}

TEST(table_slice_test, with_the_other_parents_given_it_is_the_table_itself) {
  const auto net = three_parent_stack();
  const auto slice = slice_table(net, {"onTop", "x", "y", {{"z", std::string("high")}}, false, std::nullopt});
  ASSERT_EQ(slice.probability.size(), 6U);
  EXPECT_EQ(slice.state, 1U);  // the last state by default
  const auto& table = net.table(node_of(net, "onTop"));
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 2; ++j) {
      const std::size_t u = (i * 2 + j) * 2 + 1;  // parents x, y, z; z = high
      EXPECT_EQ(slice.at(i, j), table.values()[u * 2 + 1]) << i << ' ' << j;
    }
  }
  const auto zero = slice_table(net, {"onTop", "y", "x", {{"z", std::string("low")}}, false, "0"});
  EXPECT_EQ(zero.at(1, 2), table.values()[((2 * 2 + 1) * 2 + 0) * 2 + 0]);  // axes swapped: y across
  EXPECT_FALSE(slice.rows.has_value());
}

TEST(table_slice_test, averaged_it_is_the_conditional_of_the_joint) {
  const auto net = three_parent_stack();
  const auto slice = slice_table(net, {"onTop", "x", "y", {}, true, std::nullopt});
  const std::vector<variable_id> query{node_of(net, "x"), node_of(net, "y"), node_of(net, "onTop")};
  const auto joint = testing::enumerate_joint(net, query, std::span<const observation>{});
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 2; ++j) {
      const std::size_t base = (i * 2 + j) * 2;
      EXPECT_NEAR(slice.at(i, j), joint[base + 1] / (joint[base] + joint[base + 1]), 1e-12);
    }
  }
}

TEST(table_slice_test, the_rows_behind_each_cell_are_the_counts_summed_as_asked) {
  const auto net = three_parent_stack();
  const auto& table = net.table(node_of(net, "onTop"));
  fit_statistics statistics;
  for (const auto& t : net.tables()) {
    expected_count_table counts(t.child(), t.parents());
    auto cells = counts.counts();
    for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = static_cast<double>(c % 5);
    statistics.counts.push_back(std::move(counts));
  }
  const auto& own = statistics.counts.back();
  ASSERT_EQ(own.configurations(), table.configurations());
  const auto given =
      slice_table(net, {"onTop", "x", "y", {{"z", std::string("low")}}, false, std::nullopt}, &statistics);
  const auto averaged = slice_table(net, {"onTop", "x", "y", {}, true, std::nullopt}, &statistics);
  ASSERT_TRUE(given.rows && averaged.rows);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 2; ++j) {
      const config_index low((i * 2 + j) * 2), high((i * 2 + j) * 2 + 1);
      EXPECT_EQ((*given.rows)[j * 3 + i], own.total(low));
      EXPECT_EQ((*averaged.rows)[j * 3 + i], own.total(low) + own.total(high));
    }
  }
}

TEST(table_slice_test, mistakes_are_refused_with_what_to_do) {
  const auto net = three_parent_stack();
  EXPECT_THAT(
      [&] {
        (void)slice_table(net, {"onTop", "x", "y", {}, false, std::nullopt});
      },
      ThrowsMessage<model_error>(HasSubstr("give z a state each (e.g. z=low), or average over them")));
  EXPECT_THAT(
      [&] {
        (void)slice_table(net, {"z", "x", "y", {}, true, std::nullopt});
      },
      ThrowsMessage<model_error>(HasSubstr("'y' is not a parent of 'z' (its parents: x)")));
  EXPECT_THAT(
      [&] {
        (void)slice_table(net, {"onTop", "x", "x", {}, true, std::nullopt});
      },
      ThrowsMessage<model_error>(HasSubstr("the two axes are both 'x'")));
  EXPECT_THAT(
      [&] {
        (void)slice_table(net, {"onTop", "x", "y", {{"x", 0.5}}, true, std::nullopt});
      },
      ThrowsMessage<model_error>(HasSubstr("'x' is an axis or the node itself")));
  EXPECT_THAT(
      [&] {
        (void)slice_table(net, {"onTop", "x", "y", {{"z", std::string("mid")}}, false, std::nullopt});
      },
      ThrowsMessage<model_error>(HasSubstr("has no state 'mid'")));
  EXPECT_THAT(
      [&] {
        (void)slice_table(net, {"onTop", "x", "y", {}, true, "2"});
      },
      ThrowsMessage<model_error>(HasSubstr("has no state '2'")));
  EXPECT_THAT(
      [&] {
        (void)slice_table(net, {"onTop", "w", "y", {}, true, std::nullopt});
      },
      ThrowsMessage<model_error>(HasSubstr("'w' is not a parent of 'onTop'")));
}

}  // namespace
}  // namespace pgm::table_slice_tests
