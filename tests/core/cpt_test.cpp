#include "pgm/core/cpt.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace pgm::cpt_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

const variable on_top("onTop1", {"0", "1"});
const variable x_off("xOff1", {"l", "c", "r"});
const variable y_off("yOff1", {"l", "r"});

TEST(cpt_test, uniform_table) {
  const cpt<double> t(on_top, {x_off, y_off});
  EXPECT_EQ(t.configurations(), 6u);
  EXPECT_EQ(t.size(), 12u);
  for (double v : t.values()) EXPECT_EQ(v, 0.5);
}

TEST(cpt_test, values_are_configuration_major_last_parent_fastest) {
  // Columns for (l,l) (l,r) (c,l) (c,r) (r,l) (r,r).
  const cpt<double> t(on_top, {x_off, y_off}, {0.9, 0.1, 0.8, 0.2, 0.3, 0.7, 0.25, 0.75, 0.5, 0.5, 0.0, 1.0});
  EXPECT_DOUBLE_EQ(t.probability("1", {"c", "r"}), 0.75);
  EXPECT_DOUBLE_EQ(t.probability("0", {"l", "r"}), 0.8);
  const std::vector<std::size_t> codes{2, 1};
  EXPECT_EQ(t.configuration(codes), config_index(5));
  EXPECT_THAT(t.column(config_index(5)), ElementsAre(0.0, 1.0));
  EXPECT_EQ(t.parent_codes(config_index(3)), (std::vector<std::size_t>{1, 1}));
  EXPECT_DOUBLE_EQ(t(state_index(1), config_index(2)), 0.7);
}

TEST(cpt_test, rejects_tables_that_are_not_distributions) {
  EXPECT_THAT(
      [] {
        cpt<double>(on_top, {y_off}, {0.5, 0.5, 0.5});
      },
      ThrowsMessage<model_error>(HasSubstr("needs 4 values (2 states × 2 parent configurations), got 3")));
  EXPECT_THAT(
      [] {
        cpt<double>(on_top, {y_off}, {0.5, 0.5, 0.6, 0.5});
      },
      ThrowsMessage<model_error>(HasSubstr("given yOff1=r sums to 1.1")));
  EXPECT_THAT(
      [] {
        cpt<double>(on_top, {y_off}, {1.5, -0.5, 0.5, 0.5});
      },
      ThrowsMessage<model_error>(HasSubstr("not a probability given yOff1=l")));
  EXPECT_THAT(
      [] {
        cpt<double>(on_top, {y_off}, {std::nan(""), 1, 0.5, 0.5});
      },
      ThrowsMessage<model_error>(HasSubstr("not a probability")));
}

TEST(cpt_test, rejects_bad_parents_and_lookups) {
  EXPECT_THAT([] { cpt<double>(on_top, {on_top}); }, ThrowsMessage<model_error>(HasSubstr("its own parent")));
  EXPECT_THAT([] { cpt<double>(on_top, {y_off, y_off}); }, ThrowsMessage<model_error>(HasSubstr("twice")));
  const cpt<double> t(on_top, {y_off});
  EXPECT_THAT(
      [&] {
        static_cast<void>(t.probability("1", {"l", "r"}));
      },
      ThrowsMessage<model_error>(HasSubstr("has 1 parents, got states for 2")));
  EXPECT_THAT([&] { static_cast<void>(t.probability("1", {"x"})); },
              ThrowsMessage<model_error>(HasSubstr("no state 'x'")));
}

TEST(cpt_test, tolerance_admits_rounded_files_only) {
  EXPECT_NO_THROW(cpt<double>(on_top, {}, {0.3333333, 0.6666666}));
  EXPECT_THROW(cpt<double>(on_top, {}, {0.333, 0.666}), model_error);
  EXPECT_NO_THROW(cpt<double>(on_top, {}, {0.333, 0.666}, 0.01));
}

TEST(cpt_test, float_tables) {
  const cpt<float> t(on_top, {}, {0.25f, 0.75f});
  EXPECT_FLOAT_EQ(t.probability("1", std::initializer_list<std::string>{}), 0.75f);
}

}  // namespace
}  // namespace pgm::cpt_tests
