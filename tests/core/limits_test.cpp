// The limit of table cells (pgm/core/limits.hpp): refused before anything is allocated.

#include "pgm/core/limits.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "pgm/core/cpt.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

namespace pgm {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

variable many(const std::string& name, std::size_t states) {
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < states; ++i) labels.push_back(std::to_string(i));
  return variable(name, std::move(labels));
}

TEST(limits_test, table_cells_up_to_the_limit_are_counted) {
  EXPECT_EQ(checked_table_cells("y", 2, max_table_cells / 2), max_table_cells);
  EXPECT_EQ(checked_table_cells("y", 3, 0), 0u);
}

TEST(limits_test, a_table_beyond_the_limit_names_it) {
  EXPECT_THAT([] { static_cast<void>(checked_table_cells("y", 2, max_table_cells / 2 + 1)); },
              ThrowsMessage<table_too_large>(HasSubstr(
                  "the table of 'y' would have 16777218 cells (2 states × 8388609 parent configurations), more than "
                  "pgm's limit of 16777216 cells per table (docs/limits.md)")));
  // A product beyond 2^64 is never formed.
  EXPECT_THAT([] { static_cast<void>(checked_table_cells("y", std::numeric_limits<std::size_t>::max(), 3)); },
              ThrowsMessage<table_too_large>(HasSubstr("more than 2^64 cells")));
}

TEST(limits_test, uniform_tables_and_count_tables_are_refused_before_they_are_allocated) {
  // 1000 × 1000 × 1000 = 10^9 cells: 8 GB if it were allocated.
  const auto first = many("a", 1000), second = many("b", 1000), child = many("y", 1000);
  EXPECT_THAT(
      [&] {
        cpt<double> table(child, {first, second});
      },
      ThrowsMessage<table_too_large>(HasSubstr("'y' would have 1000000000 cells")));
  EXPECT_THAT(
      [&] {
        count_table counts(child, {first, second});
      },
      ThrowsMessage<table_too_large>(HasSubstr("1000000000 cells")));
  EXPECT_NO_THROW(count_table(child, {first}));
}

}  // namespace
}  // namespace pgm
